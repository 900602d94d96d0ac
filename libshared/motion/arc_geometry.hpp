/// @file arc_geometry.hpp
/// @brief An arc or helix motion as a path parametrised by its swept angle
/// phi in [0, sweep]: radius R(phi) from the start radius to the end radius
/// (LinuxCNC accepts ends slightly off the circle and spirals between
/// them), and a linear rise on the plane's normal axis.
#pragma once

#include "motion/gcode.hpp"

namespace tk::motion {

struct ArcGeometry {
  int a0 = 0, a1 = 1, a2 = 2;  ///< plane axes and normal
  double c0 = 0, c1 = 0;       ///< centre in the plane (mm)
  double start_angle = 0;      ///< of the start point, radians
  double sweep = 0;            ///< > 0, radians, extra turns included
  double turn = 1;             ///< +1 counter-clockwise, -1 clockwise (seen from +a2)
  double r_start = 0, r_end = 0;
  double z_start = 0, z_rise = 0;
  double length = 0;  ///< mm along the helix

  double radius_per_radian = 0, rise_per_radian = 0;  ///< (r_end - r_start) / sweep, z_rise / sweep

  double radius(double phi) const { return r_start + radius_per_radian * phi; }
  double height(double phi) const { return z_start + rise_per_radian * phi; }
  /// Unit tangent (in the motion's direction) at angle phi.
  Vec3 tangent(double phi) const;
};

/// Start and end equal in the plane make a full circle (plus `turns`).
ArcGeometry arc_geometry(const Motion& arc);

/// LinuxCNC's check of an arc's two radii (mm): throws tk::Error for a zero
/// radius, or when they differ by more than 0.5 mm, or by more than
/// 0.005 mm and 0.1% (programs in inches: 0.05 in, 0.0005 in).
void check_arc_radii(double start_radius, double end_radius, bool inches);

}  // namespace tk::motion
