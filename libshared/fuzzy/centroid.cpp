/// @file centroid.cpp
/// @brief Discrete and exact centroids of a max-aggregated Mamdani output.
#include "fuzzy/centroid.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "fuzzy/sample_grid.hpp"

namespace tk::fuzzy {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// An implied term as the polyline of its four corners.
struct Corners {
  std::array<double, 4> x;
  std::array<double, 4> y;
};

Corners corners(const ImpliedTerm& term, Implication implication) {
  const Trapezoid& p = term.shape;
  const double h = term.level;
  if (implication == Implication::product) return Corners{{p.a, p.b, p.c, p.d}, {0, h, h, 0}};
  // Clipped at h: the edges reach h a fraction h of the way up.
  return Corners{{p.a, p.a + h * (p.b - p.a), p.d - h * (p.d - p.c), p.d}, {0, h, h, 0}};
}

struct Scratch {
  std::vector<Corners> shapes;
  std::vector<int> segment;  ///< per shape: the corner its current piece starts at (-1: before it)
  std::vector<double> breaks;
  std::vector<std::array<double, 2>> lines;
};

/// Adds the integrals of y and (x - ref) y over the segment (x0, y0)-(x1, y1).
void integrate_piece(double x0, double y0, double x1, double y1, double ref, double& area, double& moment) {
  const double w = x1 - x0;
  area += 0.5 * (y0 + y1) * w;
  moment += w / 6 * ((x0 - ref) * (2 * y0 + y1) + (x1 - ref) * (y0 + 2 * y1));
}

/// Integrates the upper envelope of straight lines over [l, r]; line j runs
/// from lines[j][0] at l to lines[j][1] at r.
void integrate_envelope(std::span<const std::array<double, 2>> lines, double l, double r, double ref, double& area,
                        double& moment) {
  // Start with the highest line at l (on a tie, the one rising fastest).
  std::size_t current = 0;
  for (std::size_t j = 1; j < lines.size(); ++j) {
    const auto& a = lines[j];
    const auto& b = lines[current];
    if (a[0] > b[0] || (a[0] == b[0] && a[1] - a[0] > b[1] - b[0])) current = j;
  }
  double s = 0;  // position in [0, 1] along the interval
  while (s < 1) {
    const auto& cur = lines[current];
    const double cur_rise = cur[1] - cur[0];
    double next_s = 1;
    std::size_t next = current;
    for (std::size_t j = 0; j < lines.size(); ++j) {
      const double rise = lines[j][1] - lines[j][0];
      if (j == current || rise <= cur_rise) continue;
      // Line j overtakes the current one where the two meet.
      const double meet = (lines[j][0] - cur[0]) / (cur_rise - rise);
      if (meet > s && meet < next_s) {
        next_s = meet;
        next = j;
      }
    }
    const double x0 = l + s * (r - l), x1 = next_s >= 1 ? r : l + next_s * (r - l);
    integrate_piece(x0, cur[0] + s * cur_rise, x1, next_s >= 1 ? cur[1] : cur[0] + next_s * cur_rise, ref, area,
                    moment);
    s = next_s;
    current = next;
  }
}

}  // namespace

double aggregate_membership(std::span<const ImpliedTerm> terms, Implication implication, double x) {
  double y = 0;
  for (const ImpliedTerm& t : terms) {
    const double mu = t.shape(x);
    y = std::max(y, implication == Implication::minimum ? std::min(t.level, mu) : t.level * mu);
  }
  return y;
}

CentroidResult discrete_centroid(std::span<const ImpliedTerm> terms, Implication implication, double min, double max,
                                 int resolution) {
  SampleGrid grid(min, max, resolution);
  return grid.centroid(terms, implication);
}

namespace {

/// The value on (l, r) of a shape's piece that covers it, as a line: its
/// ends at l and r. k is the corner the piece starts at (-1 or 3: outside).
std::array<double, 2> piece_on(const Corners& c, int k, double l, double r) {
  if (k < 0 || k >= 3 || !(c.x[k + 1] > c.x[k])) return {0, 0};
  const double slope = (c.y[k + 1] - c.y[k]) / (c.x[k + 1] - c.x[k]);
  return {c.y[k] + slope * (l - c.x[k]), c.y[k] + slope * (r - c.x[k])};
}

/// Integrates the envelope of `shapes` over [lo, hi] by sweeping their corners.
void sweep(std::span<const Corners> shapes, double lo, double hi, double ref, Scratch& scratch, double& area,
           double& moment) {
  std::vector<int>& segment = scratch.segment;
  std::vector<double>& breaks = scratch.breaks;
  std::vector<std::array<double, 2>>& lines = scratch.lines;
  breaks.clear();
  breaks.push_back(lo);
  breaks.push_back(hi);
  for (const Corners& c : shapes)
    for (double x : c.x)
      if (x > lo && x < hi) breaks.push_back(x);
  // Few points: insertion sort beats std::sort here.
  for (std::size_t i = 1; i < breaks.size(); ++i)
    for (std::size_t j = i; j > 0 && breaks[j] < breaks[j - 1]; --j) std::swap(breaks[j], breaks[j - 1]);
  segment.assign(shapes.size(), -1);
  for (std::size_t k = 0; k + 1 < breaks.size(); ++k) {
    const double l = breaks[k], r = breaks[k + 1];
    if (!(r > l)) continue;
    // Every corner is a break, so on (l, r) each shape follows one straight piece.
    lines.clear();
    for (std::size_t j = 0; j < shapes.size(); ++j) {
      const Corners& c = shapes[j];
      int& p = segment[j];
      while (p < 3 && c.x[p + 1] <= l) ++p;
      if (p < 0 || p >= 3) continue;  // outside the term: 0
      lines.push_back(piece_on(c, p, l, r));
    }
    if (lines.size() == 1) integrate_piece(l, lines[0][0], r, lines[0][1], ref, area, moment);
    else if (!lines.empty()) integrate_envelope(lines, l, r, ref, area, moment);
  }
}

/// sweep() for the common case of two overlapping terms, without scratch
/// storage: their corners merged in order, two lines per interval, at most
/// one crossing between them.
void sweep_pair(const Corners& f, const Corners& g, double lo, double hi, double ref, double& area, double& moment) {
  std::array<double, 10> breaks{};
  std::size_t n = 0, i = 0, j = 0;
  breaks[n++] = lo;
  while (i < 4 || j < 4) {
    const double x = (j >= 4 || (i < 4 && f.x[i] <= g.x[j])) ? f.x[i++] : g.x[j++];
    if (x > breaks[n - 1] && x < hi) breaks[n++] = x;
  }
  breaks[n++] = hi;
  int kf = -1, kg = -1;
  for (std::size_t b = 0; b + 1 < n; ++b) {
    const double l = breaks[b], r = breaks[b + 1];
    while (kf < 3 && f.x[kf + 1] <= l) ++kf;
    while (kg < 3 && g.x[kg + 1] <= l) ++kg;
    const auto p = piece_on(f, kf, l, r), q = piece_on(g, kg, l, r);
    const double d0 = p[0] - q[0], d1 = p[1] - q[1];
    if ((d0 > 0 && d1 < 0) || (d0 < 0 && d1 > 0)) {
      const double t = d0 / (d0 - d1), xm = l + t * (r - l), ym = p[0] + t * (p[1] - p[0]);
      integrate_piece(l, std::max(p[0], q[0]), xm, ym, ref, area, moment);
      integrate_piece(xm, ym, r, std::max(p[1], q[1]), ref, area, moment);
    } else {
      const bool first = d0 + d1 >= 0;  // the same line is on top at both ends
      integrate_piece(l, first ? p[0] : q[0], r, first ? p[1] : q[1], ref, area, moment);
    }
  }
}

}  // namespace

CentroidResult exact_centroid(std::span<const ImpliedTerm> terms, Implication implication, double min, double max) {
  const double ref = 0.5 * (min + max);  // moments about the middle keep their digits
  double area = 0, moment = 0;
  // Reused between calls: evaluation allocates nothing once warm.
  thread_local Scratch scratch;
  std::vector<Corners>& shapes = scratch.shapes;
  shapes.clear();
  for (const ImpliedTerm& t : terms)
    if (t.level > 0) shapes.push_back(corners(t, implication));
  // By where they start, so that terms whose supports overlap come together
  // (a caller that keeps its terms in that order saves the sort).
  const auto by_start = [](const Corners& a, const Corners& b) { return a.x[0] < b.x[0]; };
  if (!std::is_sorted(shapes.begin(), shapes.end(), by_start)) std::sort(shapes.begin(), shapes.end(), by_start);
  for (std::size_t first = 0; first < shapes.size();) {
    // A cluster: the terms whose supports overlap the first one's, in a chain.
    double end = shapes[first].x[3];
    std::size_t last = first + 1;
    while (last < shapes.size() && shapes[last].x[0] < end) end = std::max(end, shapes[last++].x[3]);
    const double lo = shapes[first].x[0];
    if (last == first + 1 && lo >= min && end <= max) {
      // A lone term inside the range: a trapezoid of height h with corners
      // a, b, c, d, area h (d + c - b - a) / 2 and first moment
      // h (d^2 + dc + c^2 - b^2 - ba - a^2) / 6, taken about ref.
      const Corners& t = shapes[first];
      const double a = t.x[0] - ref, b = t.x[1] - ref, c = t.x[2] - ref, d = t.x[3] - ref, h = t.y[1];
      area += 0.5 * h * (d + c - b - a);
      moment += h / 6 * (d * d + d * c + c * c - b * b - b * a - a * a);
    } else if (end > min && lo < max) {
      if (last == first + 2)
        sweep_pair(shapes[first], shapes[first + 1], std::max(lo, min), std::min(end, max), ref, area, moment);
      else
        sweep(std::span<const Corners>(shapes.data() + first, last - first), std::max(lo, min), std::min(end, max), ref,
              scratch, area, moment);
    }
    first = last;
  }
  if (!(area > 0)) return {kNaN, 0};
  return {ref + moment / area, area};
}

}  // namespace tk::fuzzy
