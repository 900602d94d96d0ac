/// @file pulse_estimate.cpp
#include "motion/pulse_estimate.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "motion/arc_geometry.hpp"

namespace tk::motion {
namespace {

/// The integral of |sin| from 0 to phi (signed): 2 per half turn, and the
/// variation of cos over [a, b] is its difference.
double sine_area(double phi) {
  const double half_turns = std::floor(phi / std::numbers::pi);
  return 2 * half_turns + 1 - std::cos(phi - std::numbers::pi * half_turns);
}

/// How far cos (phase 0) or sin (phase π/2) travels over the angles from
/// `from`, `sweep` radians on in either direction.
double variation(double from, double sweep, double turn, double phase) {
  const double a = from - phase, b = from - phase + turn * sweep;
  return std::abs(sine_area(std::max(a, b)) - sine_area(std::min(a, b)));
}

}  // namespace

double implied_pulses(const Motion& motion, const std::array<double, 3>& steps_per_mm) {
  if (motion.kind == MotionKind::dwell) return 0;
  double pulses = 0;
  if (motion.kind != MotionKind::arc) {
    for (int axis = 0; axis < 3; ++axis)
      pulses += std::abs(std::round(motion.end[axis] * steps_per_mm[axis]) -
                         std::round(motion.start[axis] * steps_per_mm[axis]));
    return pulses;
  }
  const ArcGeometry g = arc_geometry(motion);
  const double radius = std::max(g.r_start, g.r_end), spiral = std::abs(g.r_end - g.r_start);
  pulses += (radius * variation(g.start_angle, g.sweep, g.turn, 0) + spiral) * steps_per_mm[g.a0];
  pulses += (radius * variation(g.start_angle, g.sweep, g.turn, std::numbers::pi / 2) + spiral) * steps_per_mm[g.a1];
  pulses += std::abs(g.z_rise) * steps_per_mm[g.a2];
  return pulses;
}

}  // namespace tk::motion
