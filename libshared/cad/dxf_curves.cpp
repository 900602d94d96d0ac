/// @file dxf_curves.cpp
/// @brief Ellipse and NURBS flattening for the DXF reader.
#include "cad/dxf_curves.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace tk::cad::dxf {

void flatten_ellipse(Point centre, Point major, Point minor, double start, double span, double tolerance,
                     std::size_t max_points, std::vector<Point>& out) {
  out.clear();
  const double radius = std::max(std::hypot(major.x, major.y), std::hypot(minor.x, minor.y));
  if (!(radius > 0) || max_points < 2) return;
  // Sagitta of a chord over dt on a circle of that radius: 2 r sin^2(dt/4).
  const double relative = std::min(tolerance / radius, 1.0);
  double step = relative > 0 ? 4 * std::asin(std::sqrt(relative / 2)) : 0;
  step = std::min(step, std::numbers::pi / 2);
  const double pieces = step > 0 ? std::ceil(span / step) : HUGE_VAL;
  const std::size_t count = pieces < static_cast<double>(max_points - 1)
                                ? std::max<std::size_t>(1, static_cast<std::size_t>(pieces))
                                : max_points - 1;
  const auto at = [&](double t) {
    const double c = std::cos(t), s = std::sin(t);
    return Point{centre.x + c * major.x + s * minor.x, centre.y + c * major.y + s * minor.y};
  };
  for (std::size_t i = 0; i <= count; ++i)
    out.push_back(at(start + span * static_cast<double>(i) / static_cast<double>(count)));
  if (span >= 2 * std::numbers::pi) out.back() = out.front();
}

namespace {

/// Evaluates a NURBS curve whose knots and weights are known to be valid.
class Nurbs {
 public:
  Nurbs(int degree, std::span<const double> knots, std::span<const double> weights, std::span<const Point> control)
      : p_(degree), u_(knots), w_(weights), c_(control) {}

  /// The point at u in the span [knots[k], knots[k+1]] (de Boor in
  /// homogeneous coordinates).
  Point at(std::size_t k, double u) const {
    std::array<double, kMaxSplineDegree + 1> x{}, y{}, w{};
    const std::size_t p = static_cast<std::size_t>(p_);
    for (std::size_t j = 0; j <= p; ++j) {
      const std::size_t i = k - p + j;
      const double weight = w_.empty() ? 1.0 : w_[i];
      x[j] = c_[i].x * weight;
      y[j] = c_[i].y * weight;
      w[j] = weight;
    }
    for (std::size_t r = 1; r <= p; ++r)
      for (std::size_t j = p; j >= r; --j) {
        const std::size_t i = k - p + j;
        // The denominator spans [knots[k], knots[k+1]] at least, so it is positive.
        const double alpha = (u - u_[i]) / (u_[i + p - r + 1] - u_[i]);
        x[j] = (1 - alpha) * x[j - 1] + alpha * x[j];
        y[j] = (1 - alpha) * y[j - 1] + alpha * y[j];
        w[j] = (1 - alpha) * w[j - 1] + alpha * w[j];
      }
    return {x[p] / w[p], y[p] / w[p]};
  }

 private:
  int p_;
  std::span<const double> u_, w_;
  std::span<const Point> c_;
};

/// Distance from q to the segment a-b.
double distance_to_chord(Point q, Point a, Point b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double length2 = dx * dx + dy * dy;
  double t = length2 > 0 ? ((q.x - a.x) * dx + (q.y - a.y) * dy) / length2 : 0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(q.x - (a.x + t * dx), q.y - (a.y + t * dy));
}

constexpr int kMaxDepth = 24;

struct Flattener {
  const Nurbs& curve;
  double tolerance;
  std::size_t max_points;
  std::vector<Point>& out;
  std::size_t spans_left = 0;  ///< knot spans after the current one

  /// Appends the points after p0 up to p1 for [u0, u1] in span k. Every
  /// piece still pending (at most one per level above, and one per span
  /// left) will add a point, so a split is allowed only while those fit.
  void refine(std::size_t k, double u0, Point p0, double u1, Point p1, int depth) {
    const double um = (u0 + u1) / 2;
    const Point pm = curve.at(k, um);
    const std::size_t least = out.size() + static_cast<std::size_t>(depth) + 2 + spans_left;
    const bool flat = depth >= kMaxDepth || least > max_points ||
                      (distance_to_chord(pm, p0, p1) <= tolerance &&
                       distance_to_chord(curve.at(k, (u0 + um) / 2), p0, p1) <= tolerance &&
                       distance_to_chord(curve.at(k, (um + u1) / 2), p0, p1) <= tolerance);
    if (flat) {
      out.push_back(p1);
      return;
    }
    refine(k, u0, p0, um, pm, depth + 1);
    refine(k, um, pm, u1, p1, depth + 1);
  }
};

}  // namespace

SplineResult flatten_spline(int degree, std::span<const double> knots, std::span<const double> weights,
                            std::span<const Point> control, double tolerance, std::size_t max_points,
                            std::vector<Point>& out) {
  out.clear();
  if (degree < 1 || degree > kMaxSplineDegree) return SplineResult::invalid;
  const std::size_t p = static_cast<std::size_t>(degree), n = control.size();
  if (n < p + 1) return SplineResult::invalid;
  if (n > max_points) return SplineResult::too_large;
  if (!weights.empty()) {
    if (weights.size() != n) return SplineResult::invalid;
    for (double w : weights)
      if (!(w > 0) || !std::isfinite(w)) return SplineResult::invalid;
  }
  std::vector<double> uniform;
  if (knots.empty()) {  // open uniform: degree + 1 zeros, 1 .. n - p - 1, degree + 1 times n - p
    for (std::size_t i = 0; i < n + p + 1; ++i) uniform.push_back(static_cast<double>(std::clamp(i, p, n) - p));
    knots = uniform;
  }
  if (knots.size() != n + p + 1) return SplineResult::invalid;
  for (std::size_t i = 0; i < knots.size(); ++i)
    if (!std::isfinite(knots[i]) || (i > 0 && knots[i] < knots[i - 1])) return SplineResult::invalid;
  if (!(knots[p] < knots[n])) return SplineResult::invalid;

  const Nurbs curve(degree, knots, weights, control);
  Flattener flattener{curve, tolerance, max_points, out};
  std::size_t first = p;
  while (!(knots[first] < knots[first + 1])) ++first;
  out.push_back(curve.at(first, knots[p]));
  for (std::size_t k = first; k < n; ++k)
    if (knots[k] < knots[k + 1]) ++flattener.spans_left;
  for (std::size_t k = first; k < n; ++k) {
    if (!(knots[k] < knots[k + 1])) continue;
    --flattener.spans_left;
    flattener.refine(k, knots[k], out.back(), knots[k + 1], curve.at(k, knots[k + 1]), 0);
  }
  return SplineResult::ok;
}

}  // namespace tk::cad::dxf
