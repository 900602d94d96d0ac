/// @file sample_grid.cpp
/// @brief The discrete centroid's inner loops, written so that GCC turns
/// them into packed SIMD (no branches, no division).
#include "fuzzy/sample_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tk::fuzzy {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// 1 / (hi - lo), +inf for a vertical edge: the formula below then gives 1
/// on the edge's inner side and 0 outside, as Trapezoid does.
double inverse_width(double lo, double hi) { return hi > lo ? 1 / (hi - lo) : kInf; }

// The comparisons are written `a < b ? a : b` so that, where a product is
// 0 * inf = NaN (an x exactly on a vertical edge), the other operand wins:
// the same values as Trapezoid::operator() gives there.
inline double min2(double a, double b) { return a < b ? a : b; }
inline double max2(double a, double b) { return a > b ? a : b; }

}  // namespace

SampleGrid::SampleGrid(double min, double max, int resolution)
    : min_(min), dx_((max - min) / resolution), x_(static_cast<std::size_t>(resolution)), y_(x_.size()) {
  for (int i = 0; i < resolution; ++i) x_[static_cast<std::size_t>(i)] = min + (i + 0.5) * dx_;
}

CentroidResult SampleGrid::centroid(std::span<const ImpliedTerm> terms, Implication implication) {
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(x_.size());
  // The samples a term can reach: i with x_i in [a, d], widened by one.
  auto first_sample = [&](double a) {
    return std::clamp<std::ptrdiff_t>(static_cast<std::ptrdiff_t>(std::floor((a - min_) / dx_ - 0.5)), 0, n);
  };
  auto end_sample = [&](double d) {
    return std::clamp<std::ptrdiff_t>(static_cast<std::ptrdiff_t>(std::ceil((d - min_) / dx_ - 0.5)) + 1, 0, n);
  };
  std::ptrdiff_t lo = n, hi = 0;
  for (const ImpliedTerm& t : terms) {
    if (!(t.level > 0)) continue;
    lo = std::min(lo, first_sample(t.shape.a));
    hi = std::max(hi, end_sample(t.shape.d));
  }
  if (lo >= hi) return {std::numeric_limits<double>::quiet_NaN(), 0};

  double* y = y_.data();
  const double* x = x_.data();
  std::fill(y + lo, y + hi, 0.0);
  for (const ImpliedTerm& t : terms) {
    if (!(t.level > 0)) continue;
    const Trapezoid& p = t.shape;
    const double a = p.a, d = p.d, h = t.level;
    const double rise = inverse_width(p.a, p.b), fall = inverse_width(p.c, p.d);
    const std::ptrdiff_t from = first_sample(p.a), to = end_sample(p.d);
    if (implication == Implication::minimum) {
      for (std::ptrdiff_t i = from; i < to; ++i) {
        const double mu = max2(min2(min2((x[i] - a) * rise, (d - x[i]) * fall), 1.0), 0.0);
        y[i] = max2(y[i], min2(mu, h));
      }
    } else {
      for (std::ptrdiff_t i = from; i < to; ++i) {
        const double mu = max2(min2(min2((x[i] - a) * rise, (d - x[i]) * fall), 1.0), 0.0);
        y[i] = max2(y[i], mu * h);
      }
    }
  }
  double area = 0, moment = 0;
  for (std::ptrdiff_t i = lo; i < hi; ++i) {
    area += y[i];
    moment += x[i] * y[i];
  }
  if (!(area > 0)) return {std::numeric_limits<double>::quiet_NaN(), 0};
  return {moment / area, area * dx_};
}

}  // namespace tk::fuzzy
