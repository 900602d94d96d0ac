/// @file sample_grid.cpp
/// @brief The discrete centroid's inner loops, written so that GCC turns
/// them into packed SIMD (no branches, no division).
#include "fuzzy/sample_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace tk::fuzzy {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// 1 / (hi - lo), +inf for a vertical edge: the formula below then gives 1
/// on the edge's inner side and 0 outside, as Trapezoid does.
double inverse_width(double lo, double hi) { return hi > lo ? 1 / (hi - lo) : kInf; }

// The comparisons are written `a < b ? a : b` so that, where a product is
// 0 * inf = NaN (an x exactly on a vertical edge), the other operand wins:
// the same values as Trapezoid::operator() gives there.
inline double min2(double a, double b) { return a < b ? a : b; }
inline double max2(double a, double b) { return a > b ? a : b; }

template <Implication I>
void raise_to_term(const double* __restrict x, double* __restrict y, const GridTerm& t, double h) {
  std::ptrdiff_t i = t.first;
#if defined(__SSE2__)
  // Two samples at a time. MINPD(a, b) is exactly `a < b ? a : b` (b when
  // either is NaN), MAXPD likewise, so the values equal the scalar loop's.
  const __m128d a = _mm_set1_pd(t.a), d = _mm_set1_pd(t.d), rise = _mm_set1_pd(t.rise), fall = _mm_set1_pd(t.fall);
  const __m128d one = _mm_set1_pd(1.0), zero = _mm_setzero_pd(), level = _mm_set1_pd(h);
  for (; i + 1 < t.end; i += 2) {
    const __m128d xi = _mm_loadu_pd(x + i);
    const __m128d up = _mm_mul_pd(_mm_sub_pd(xi, a), rise), down = _mm_mul_pd(_mm_sub_pd(d, xi), fall);
    const __m128d mu = _mm_max_pd(_mm_min_pd(_mm_min_pd(up, down), one), zero);
    const __m128d implied = I == Implication::minimum ? _mm_min_pd(mu, level) : _mm_mul_pd(mu, level);
    _mm_storeu_pd(y + i, _mm_max_pd(_mm_loadu_pd(y + i), implied));
  }
#endif
  for (; i < t.end; ++i) {
    const double mu = max2(min2(min2((x[i] - t.a) * t.rise, (t.d - x[i]) * t.fall), 1.0), 0.0);
    y[i] = max2(y[i], I == Implication::minimum ? min2(mu, h) : mu * h);
  }
}

}  // namespace

SampleGrid::SampleGrid(double min, double max, int resolution)
    : min_(min), dx_((max - min) / resolution), x_(static_cast<std::size_t>(resolution)), y_(x_.size()) {
  for (int i = 0; i < resolution; ++i) x_[static_cast<std::size_t>(i)] = min + (i + 0.5) * dx_;
}

GridTerm SampleGrid::prepare(const Trapezoid& term) const {
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(x_.size());
  GridTerm t;
  t.a = term.a;
  t.d = term.d;
  t.rise = inverse_width(term.a, term.b);
  t.fall = inverse_width(term.c, term.d);
  // Widened by a sample each side: outside [a, d] the formula gives 0 anyway.
  const double first = std::floor((term.a - min_) / dx_ - 0.5), end = std::ceil((term.d - min_) / dx_ - 0.5) + 1;
  t.first = static_cast<std::ptrdiff_t>(std::clamp(first, 0.0, static_cast<double>(n)));
  t.end = static_cast<std::ptrdiff_t>(std::clamp(end, 0.0, static_cast<double>(n)));
  return t;
}

CentroidResult SampleGrid::centroid(std::span<const GridTerm> terms, std::span<const double> levels,
                                    Implication implication) {
  // The fired terms' sample spans, merged: only they are cleared and summed.
  spans_.clear();
  for (std::size_t k = 0; k < terms.size(); ++k)
    if (levels[k] > 0 && terms[k].first < terms[k].end) spans_.emplace_back(terms[k].first, terms[k].end);
  if (spans_.empty()) return {kNaN, 0};
  std::sort(spans_.begin(), spans_.end());
  std::size_t merged = 0;
  for (std::size_t k = 1; k < spans_.size(); ++k) {
    if (spans_[k].first <= spans_[merged].second)
      spans_[merged].second = std::max(spans_[merged].second, spans_[k].second);
    else spans_[++merged] = spans_[k];
  }
  spans_.resize(merged + 1);

  double* y = y_.data();
  const double* x = x_.data();
  for (const auto& [from, to] : spans_) std::fill(y + from, y + to, 0.0);
  for (std::size_t k = 0; k < terms.size(); ++k) {
    if (!(levels[k] > 0)) continue;
    if (implication == Implication::minimum) raise_to_term<Implication::minimum>(x, y, terms[k], levels[k]);
    else raise_to_term<Implication::product>(x, y, terms[k], levels[k]);
  }
  // Two running sums each, so that the additions overlap in the pipeline.
  double area[2] = {0, 0}, moment[2] = {0, 0};
  for (const auto& [from, to] : spans_) {
    std::ptrdiff_t i = from;
    for (; i + 1 < to; i += 2) {
      area[0] += y[i];
      moment[0] += x[i] * y[i];
      area[1] += y[i + 1];
      moment[1] += x[i + 1] * y[i + 1];
    }
    if (i < to) {
      area[0] += y[i];
      moment[0] += x[i] * y[i];
    }
  }
  const double total = area[0] + area[1];
  if (!(total > 0)) return {kNaN, 0};
  return {(moment[0] + moment[1]) / total, total * dx_};
}

CentroidResult SampleGrid::centroid(std::span<const ImpliedTerm> terms, Implication implication) {
  std::vector<GridTerm> prepared;
  std::vector<double> levels;
  for (const ImpliedTerm& t : terms) {
    prepared.push_back(prepare(t.shape));
    levels.push_back(t.level);
  }
  return centroid(prepared, levels, implication);
}

}  // namespace tk::fuzzy
