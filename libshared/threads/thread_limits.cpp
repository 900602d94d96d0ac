#include "threads/thread_limits.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <optional>

#include "io/error.hpp"
#include "threads/iso965_tables.hpp"

namespace tk::threads {
namespace {

constexpr double micrometre = 1e-3;

double take(const std::optional<Micrometres>& value, const char* name, std::vector<ComputedNote>& computed) {
  if (value->computed) computed.push_back({name, value->source});
  return value->value * micrometre;
}

/// `grades` lists the grades the diameter has; a grade among them that still
/// has no value lacks one at this pitch (below the tables' first pitch).
[[noreturn]] void no_value(const BasicProfile& p, std::string_view what, const ToleranceZone& zone,
                           std::initializer_list<int> grades, std::string_view allowed) {
  if (std::find(grades.begin(), grades.end(), zone.grade) != grades.end())
    throw Error(fmt::format("M{}x{}: ISO 965-1 has no {} for {}{} at pitch {} mm", p.major, p.pitch, what, zone.grade,
                            zone.position, p.pitch));
  throw Error(fmt::format("M{}x{}: ISO 965-1 has no {} for {}{} ({})", p.major, p.pitch, what, zone.grade,
                          zone.position, allowed));
}

/// The fundamental deviation, checked to exist at this pitch.
std::optional<Micrometres> deviation(const BasicProfile& p, const ToleranceZone& zone) {
  std::optional<Micrometres> value = fundamental_deviation(zone.position, p.pitch);
  if (!value)
    throw Error(fmt::format("M{}x{}: ISO 965-1 defines no position '{}' at pitch {} mm", p.major, p.pitch,
                            zone.position, p.pitch));
  return value;
}

}  // namespace

BasicProfile basic_profile(double major_mm, double pitch_mm) {
  BasicProfile p;
  p.major = major_mm;
  p.pitch = pitch_mm;
  p.height = std::sqrt(3.0) / 2 * pitch_mm;
  p.pitch_diameter = major_mm - 0.75 * p.height;
  p.minor = major_mm - 1.25 * p.height;
  p.root_radius = p.height / 6;
  p.root_minor = p.minor - p.height / 6;
  p.external_depth = 17.0 / 24 * p.height;
  p.internal_depth = 5.0 / 8 * p.height;
  p.crest_flat = pitch_mm / 8;
  p.root_flat = pitch_mm / 4;
  require(p.root_minor > 0, fmt::format("M{}x{}: the pitch is too large for the diameter (d3 = {:.4f} mm)", major_mm,
                                        pitch_mm, p.root_minor));
  return p;
}

ExternalLimits external_limits(const BasicProfile& p, const ToleranceClass& tolerance) {
  ExternalLimits l;
  l.tolerance = tolerance;
  l.es = take(deviation(p, tolerance.pitch), "es", l.computed);
  const std::optional<Micrometres> Td = major_diameter_tolerance(tolerance.crest.grade, p.pitch);
  if (!Td) no_value(p, "major diameter tolerance Td", tolerance.crest, {4, 6, 8}, "d has grades 4, 6 and 8");
  l.Td = take(Td, "Td", l.computed);
  const std::optional<Micrometres> Td2 = external_pitch_diameter_tolerance(tolerance.pitch.grade, p.major, p.pitch);
  if (!Td2) no_value(p, "pitch diameter tolerance Td2", tolerance.pitch, {3, 4, 5, 6, 7, 8, 9}, "d2 has grades 3 to 9");
  l.Td2 = take(Td2, "Td2", l.computed);
  l.d_max = p.major + l.es;
  l.d_min = l.d_max - l.Td;
  l.d2_max = p.pitch_diameter + l.es;
  l.d2_min = l.d2_max - l.Td2;
  l.d3_max = p.root_minor + l.es;
  l.root_radius_min = 0.125 * p.pitch;
  if (!(l.d2_min > l.d3_max))
    throw Error(fmt::format("M{}x{}-{}: d2 min {:.4f} is not above d3 max {:.4f}", p.major, p.pitch, tolerance.text(),
                            l.d2_min, l.d3_max));
  if (!(l.d_min > l.d2_max))
    throw Error(fmt::format("M{}x{}-{}: d min {:.4f} is not above d2 max {:.4f}", p.major, p.pitch, tolerance.text(),
                            l.d_min, l.d2_max));
  return l;
}

InternalLimits internal_limits(const BasicProfile& p, const ToleranceClass& tolerance) {
  InternalLimits l;
  l.tolerance = tolerance;
  l.EI = take(deviation(p, tolerance.pitch), "EI", l.computed);
  const std::optional<Micrometres> TD1 = minor_diameter_tolerance(tolerance.crest.grade, p.pitch);
  if (!TD1) no_value(p, "minor diameter tolerance TD1", tolerance.crest, {4, 5, 6, 7, 8}, "D1 has grades 4 to 8");
  l.TD1 = take(TD1, "TD1", l.computed);
  const std::optional<Micrometres> TD2 = internal_pitch_diameter_tolerance(tolerance.pitch.grade, p.major, p.pitch);
  if (!TD2) no_value(p, "pitch diameter tolerance TD2", tolerance.pitch, {4, 5, 6, 7, 8}, "D2 has grades 4 to 8");
  l.TD2 = take(TD2, "TD2", l.computed);
  l.D_min = p.major + l.EI;
  l.D2_min = p.pitch_diameter + l.EI;
  l.D2_max = l.D2_min + l.TD2;
  l.D1_min = p.minor + l.EI;
  l.D1_max = l.D1_min + l.TD1;
  if (!(l.D2_min > l.D1_max))
    throw Error(fmt::format("M{}x{}-{}: D2 min {:.4f} is not above D1 max {:.4f}", p.major, p.pitch, tolerance.text(),
                            l.D2_min, l.D1_max));
  return l;
}

ToleranceClass default_external_class(double major_mm, Engagement engagement) {
  if (major_mm <= 1.4) return {{6, 'h'}, {6, 'h'}};
  const int pitch_grade = engagement == Engagement::short_s ? 5 : engagement == Engagement::long_l ? 7 : 6;
  return {{pitch_grade, 'g'}, {6, 'g'}};
}

ToleranceClass default_internal_class(double major_mm, Engagement engagement) {
  if (major_mm <= 1.4) return {{5, 'H'}, {5, 'H'}};
  const int grade = engagement == Engagement::short_s ? 5 : engagement == Engagement::long_l ? 7 : 6;
  return {{grade, 'H'}, {grade, 'H'}};
}

}  // namespace tk::threads
