/// @file arc_geometry.cpp
#include "motion/arc_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "io/error.hpp"

namespace tk::motion {

ArcGeometry arc_geometry(const Motion& m) {
  ArcGeometry g;
  g.a0 = m.axis0;
  g.a1 = m.axis1;
  g.a2 = m.axis2;
  g.c0 = m.center[g.a0];
  g.c1 = m.center[g.a1];
  const double s0 = m.start[g.a0] - g.c0, s1 = m.start[g.a1] - g.c1;
  const double e0 = m.end[g.a0] - g.c0, e1 = m.end[g.a1] - g.c1;
  g.r_start = std::hypot(s0, s1);
  g.r_end = std::hypot(e0, e1);
  g.turn = m.clockwise ? -1.0 : 1.0;
  g.start_angle = std::atan2(s1, s0);
  double sweep = g.turn * (std::atan2(e1, e0) - g.start_angle);
  while (sweep <= 0) sweep += kTwoPi;
  while (sweep > kTwoPi) sweep -= kTwoPi;
  if (std::hypot(e0 - s0, e1 - s1) <= 1e-9 * std::max(1.0, g.r_start)) sweep = kTwoPi;
  g.sweep = sweep + kTwoPi * static_cast<double>(m.turns);
  g.z_start = m.start[g.a2];
  g.z_rise = m.end[g.a2] - m.start[g.a2];
  g.length = std::hypot(0.5 * (g.r_start + g.r_end) * g.sweep, g.z_rise);
  g.radius_per_radian = (g.r_end - g.r_start) / g.sweep;
  g.rise_per_radian = g.z_rise / g.sweep;
  return g;
}

Vec3 ArcGeometry::tangent(double phi) const {
  const double angle = start_angle + turn * phi, r = radius(phi);
  Vec3 t;
  t[a0] = -turn * r * std::sin(angle);
  t[a1] = turn * r * std::cos(angle);
  t[a2] = rise_per_radian;
  const double norm = std::sqrt(t.x * t.x + t.y * t.y + t.z * t.z);
  if (norm > 0) {
    t.x /= norm;
    t.y /= norm;
    t.z /= norm;
  }
  return t;
}

double arc_sweep(const Motion& arc) { return arc_geometry(arc).sweep; }

void check_arc_radii(double start_radius, double end_radius, bool inches) {
  const double tolerance = inches ? 0.0005 * kMmPerInch : 0.005;
  if (std::min(start_radius, end_radius) < tolerance)
    throw Error(
        fmt::format("zero-radius arc (radius {:g} mm at the start, {:g} mm at the end)", start_radius, end_radius));
  const double difference = std::abs(end_radius - start_radius);
  const double limit = inches ? 0.05 * kMmPerInch : 0.5;
  if (difference > limit || (difference > tolerance && difference > 0.001 * std::max(start_radius, end_radius)))
    throw Error(fmt::format("radius to end of arc differs from radius to start: {:.4f} mm and {:.4f} mm", end_radius,
                            start_radius));
}

}  // namespace tk::motion
