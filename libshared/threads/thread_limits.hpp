/// @file thread_limits.hpp
/// @brief The basic profile of ISO 68-1 and the limits of size of ISO 965-1
/// for one member (external or internal) of an ISO metric thread.
#pragma once

#include <string>
#include <vector>

#include "threads/designation.hpp"

namespace tk::threads {

/// ISO 68-1's basic profile, mm. H is the fundamental triangle's height.
struct BasicProfile {
  double major = 0;           ///< d = D
  double pitch = 0;           ///< P
  double height = 0;          ///< H = √3/2 · P
  double pitch_diameter = 0;  ///< d2 = D2 = d − 3H/4
  double minor = 0;           ///< d1 = D1 = d − 5H/4
  double root_minor = 0;      ///< d3 = d1 − H/6, the external thread's minor at a root radius of H/6
  double external_depth = 0;  ///< h3 = (d − d3)/2 = 17H/24
  double internal_depth = 0;  ///< H1 = (D − D1)/2 = 5H/8
  double root_radius = 0;     ///< H/6, the external root's radius that gives d3
  double crest_flat = 0;      ///< P/8, the basic flat at the major diameter
  double root_flat = 0;       ///< P/4, the basic flat at the minor diameter
};

BasicProfile basic_profile(double major_mm, double pitch_mm);

/// A value of the tolerance tables that came from a formula, not a table.
struct ComputedNote {
  std::string value;   ///< "Td2", "es"...
  std::string source;  ///< the formula's name
};

/// Limits of size of an external thread (bolt), mm. The fundamental
/// deviation es is zero or negative; tolerances are positive widths.
struct ExternalLimits {
  ToleranceClass tolerance;
  double es = 0, Td = 0, Td2 = 0;
  double d_max = 0, d_min = 0, d2_max = 0, d2_min = 0, d3_max = 0;
  double root_radius_min = 0;  ///< 0.125 P (ISO 965-1's minimum root radius)
  std::vector<ComputedNote> computed;
  double d_mid() const { return (d_max + d_min) / 2; }
  double d2_mid() const { return (d2_max + d2_min) / 2; }
};

/// Limits of size of an internal thread (nut), mm. EI is zero or positive.
/// D max is not limited by ISO 965-1 (the root is not toleranced).
struct InternalLimits {
  ToleranceClass tolerance;
  double EI = 0, TD1 = 0, TD2 = 0;
  double D_min = 0, D1_min = 0, D1_max = 0, D2_min = 0, D2_max = 0;
  std::vector<ComputedNote> computed;
  double D1_mid() const { return (D1_max + D1_min) / 2; }
  double D2_mid() const { return (D2_max + D2_min) / 2; }
};

/// Throws tk::Error naming the problem when the class has no value in
/// ISO 965-1 for this size (a grade the diameter does not have, such as 3
/// or 5 for d; a position the standard does not define at this pitch, such
/// as e below P 0.5) or when the zones come out inconsistent (d2 min not
/// above d3 max, d min not above d2 max).
ExternalLimits external_limits(const BasicProfile& profile, const ToleranceClass& tolerance);
/// As external_limits; checks D2 min above D1 max.
InternalLimits internal_limits(const BasicProfile& profile, const ToleranceClass& tolerance);

/// ISO 965-1's medium tolerance quality, the class for general use: for
/// the normal length of engagement 6g and 6H, for the short one 5g6g and
/// 5H, for the long one 7g6g and 7H (the first choices of its table of
/// recommended classes); 6h and 5H for diameters up to 1.4 mm.
ToleranceClass default_external_class(double major_mm, Engagement engagement = Engagement::normal_n);
ToleranceClass default_internal_class(double major_mm, Engagement engagement = Engagement::normal_n);

}  // namespace tk::threads
