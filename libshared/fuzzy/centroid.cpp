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
  if (implication == Implication::product) return {{p.a, p.b, p.c, p.d}, {0, h, h, 0}};
  // Clipped at h: the edges reach h a fraction h of the way up.
  return {{p.a, p.a + h * (p.b - p.a), p.d - h * (p.d - p.c), p.d}, {0, h, h, 0}};
}

/// The straight line a term follows on (l, r), an interval with none of the
/// term's corners strictly inside: its values at l and r.
std::array<double, 2> line_on(const Corners& c, double l, double r) {
  if (r <= c.x[0] || l >= c.x[3]) return {0, 0};
  for (int k = 0; k < 3; ++k) {
    if (c.x[k] <= l && r <= c.x[k + 1] && c.x[k] < c.x[k + 1]) {
      const double slope = (c.y[k + 1] - c.y[k]) / (c.x[k + 1] - c.x[k]);
      return {c.y[k] + slope * (l - c.x[k]), c.y[k] + slope * (r - c.x[k])};
    }
  }
  return {0, 0};  // not reached for a valid interval
}

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
    integrate_piece(x0, cur[0] + s * cur_rise, x1, next_s >= 1 ? cur[1] : cur[0] + next_s * cur_rise, ref, area, moment);
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

CentroidResult exact_centroid(std::span<const ImpliedTerm> terms, Implication implication, double min, double max) {
  // Reused between calls: evaluation allocates nothing once warm.
  thread_local std::vector<Corners> shapes;
  thread_local std::vector<double> breaks;
  thread_local std::vector<std::array<double, 2>> lines;
  shapes.clear();
  breaks.assign({min, max});
  for (const ImpliedTerm& t : terms) {
    if (!(t.level > 0)) continue;
    shapes.push_back(corners(t, implication));
    for (double x : shapes.back().x)
      if (x > min && x < max) breaks.push_back(x);
  }
  std::sort(breaks.begin(), breaks.end());
  breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());

  const double ref = 0.5 * (min + max);  // moments about the middle keep their digits
  double area = 0, moment = 0;
  lines.resize(shapes.size());
  for (std::size_t k = 0; k + 1 < breaks.size(); ++k) {
    const double l = breaks[k], r = breaks[k + 1];
    for (std::size_t j = 0; j < shapes.size(); ++j) lines[j] = line_on(shapes[j], l, r);
    if (!lines.empty()) integrate_envelope(lines, l, r, ref, area, moment);
  }
  if (!(area > 0)) return {kNaN, 0};
  return {ref + moment / area, area};
}

}  // namespace tk::fuzzy
