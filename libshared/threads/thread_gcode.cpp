#include "threads/thread_gcode.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "io/error.hpp"
#include "motion/gcode_writer.hpp"

namespace tk::threads {
namespace {

/// A coordinate to 0.1 µm without trailing zeros, as controls read them.
std::string number(double value) { return motion::gcode_number(value, motion::kTrimmedTenthMicrons); }

/// To the 0.1 µm that number() prints: nearest, and up.
double round_to_tenth_micron(double value) { return std::round(value * 1e4) / 1e4; }
double round_up_to_tenth_micron(double value) { return std::ceil(value * 1e4) / 1e4; }

struct Geometry {
  double drive_x;  ///< the drive line's diameter
  double safe_z;   ///< ahead of the face: where the tool goes in and out
  double z_start;
  double z_end;
  double direction;  ///< −1 cutting towards the chuck, +1 away from it (left hand)
};

/// Radial gap of the drive line from the bore: the option, but at most a
/// tenth of the bore so a small bore keeps room for the boring bar.
double internal_clearance(const TurningPlan& plan, const ProgramSettings& s) {
  return std::min(s.clearance_mm, plan.blank_diameter / 10);
}

Geometry geometry(const TurningPlan& plan, const ProgramSettings& s) {
  // Up to speed before the thread starts: the lead is only right at P·S.
  const double run_in = s.run_in_mm > 0 ? s.run_in_mm : std::max(3 * s.pitch_mm, synchronisation_distance(s));
  Geometry g;
  g.drive_x =
      plan.external ? plan.blank_diameter + 2 * s.clearance_mm : plan.blank_diameter - 2 * internal_clearance(plan, s);
  g.safe_z = run_in;
  // Right hand: from ahead of the face towards the chuck. Left hand (same
  // spindle direction and insert): from run_in beyond the thread's inner
  // end, in a groove, out past the face.
  g.direction = s.left_hand ? 1 : -1;
  g.z_start = s.left_hand ? -s.length_mm - run_in : run_in;
  g.z_end = s.left_hand ? run_in : -s.length_mm;
  return g;
}

void header(motion::GcodeWriter& out, const TurningPlan& plan, const ProgramSettings& s, const char* style) {
  out.comment(fmt::format("threadcalc: {} {}, {} program", s.title, plan.external ? "external" : "internal", style));
  out.comment(fmt::format("ap {} mm from the peak diameter {}; pitch diameter aimed at {}; {} passes, {} infeed",
                          number(plan.ap), number(plan.peak_diameter), number(plan.target_pitch_diameter), plan.passes,
                          plan.infeed == Infeed::flank ? fmt::format("{}-degree flank", number(plan.infeed_angle_deg))
                                                       : std::string("radial")));
  out.comment(fmt::format("{} before threading: {}; chamfer {} x 45 degrees", plan.external ? "turn" : "bore",
                          number(plan.blank_diameter), number(plan.chamfer)));
  out.line("G18 G21 G90 G94 G7", "XZ plane, mm, absolute, X as a diameter");
  out.line(fmt::format("S{} M3", number(std::round(s.rpm))));
}

/// Diameter at a radial depth below (external) or above (internal) the peak.
double pass_diameter(const TurningPlan& plan, double depth) {
  return plan.peak_diameter + (plan.external ? -2 : 2) * depth;
}

}  // namespace

double spindle_speed(double cutting_speed_m_min, double diameter_mm, double max_rpm) {
  return std::min(max_rpm, 1000 * cutting_speed_m_min / (std::numbers::pi * diameter_mm));
}

double synchronisation_distance(const ProgramSettings& s) {
  const double speed = s.pitch_mm * s.rpm / 60;  // mm/s
  return speed * speed / (2 * s.acceleration_mm_s2);
}

void validate(const ProgramSettings& s) {
  // The settings are threadcalc's options: a bad one is a usage error.
  const auto check = [](bool ok, const std::string& message) {
    if (!ok) throw UsageError(message);
  };
  check(std::isfinite(s.pitch_mm) && s.pitch_mm > 0, "the program needs a positive pitch");
  check(std::isfinite(s.length_mm) && s.length_mm > 0 && s.length_mm <= 10000,
        fmt::format("--length: thread length {} mm is outside (0, 10000]", s.length_mm));
  check(std::isfinite(s.rpm) && s.rpm >= 1 && s.rpm <= 100000,
        fmt::format("--rpm: spindle speed {} rpm is outside 1-100000", s.rpm));
  check(std::isfinite(s.clearance_mm) && s.clearance_mm > 0 && s.clearance_mm <= 100,
        fmt::format("--clearance: clearance {} mm is outside (0, 100]", s.clearance_mm));
  check(std::isfinite(s.run_in_mm) && s.run_in_mm >= 0 && s.run_in_mm <= 1000,
        fmt::format("--run-in: run-in {} mm is outside [0, 1000]", s.run_in_mm));
  check(std::isfinite(s.acceleration_mm_s2) && s.acceleration_mm_s2 > 0 && s.acceleration_mm_s2 <= 1e6,
        fmt::format("--accel: acceleration {} mm/s^2 is outside (0, 1e6]", s.acceleration_mm_s2));
}

std::string thread_program(ProgramStyle style, const TurningPlan& plan, const ProgramSettings& s) {
  validate(s);
  const Geometry g = geometry(plan, s);
  const double tan_angle = std::tan(plan.infeed_angle_deg * std::numbers::pi / 180);
  motion::GcodeWriter out(motion::kTrimmedTenthMicrons);
  header(out, plan, s, style == ProgramStyle::g76 ? "G76" : "G33 passes");
  if (style == ProgramStyle::g76)
    out.comment("G76 cuts at ap*sqrt[i/n]: the plan's count and final depth, not its light first pass");
  if (s.left_hand)
    out.comment(fmt::format("left hand: starts {} mm beyond the thread's inner end, in a groove at least that wide",
                            number(g.safe_z + plan.ap * tan_angle)));
  out.comment(
      fmt::format("the Z axis takes {} mm to reach P*S and as much to stop: the thread's end needs that undercut",
                  number(synchronisation_distance(s))));
  // To the safe Z first, then onto the drive line, then along it: never a
  // diagonal rapid through the face or into the bore.
  out.line(fmt::format("G0 Z{}", number(g.safe_z)));
  out.line(fmt::format("G0 X{}", number(g.drive_x)));
  if (style == ProgramStyle::g76) {
    if (g.z_start != g.safe_z) out.line(fmt::format("G0 Z{}", number(g.z_start)));
    // G7: I, J and K are diameters. J from K as printed, so J·√n reaches it.
    const double k = round_to_tenth_micron(2 * plan.ap);
    const double j = round_up_to_tenth_micron(k / std::sqrt(static_cast<double>(plan.passes)));
    out.line(fmt::format("G76 P{} Z{} I{} J{} K{} R2 Q{} H{} E0 L0", number(s.pitch_mm), number(g.z_end),
                         number(plan.peak_diameter - g.drive_x), number(j), number(k), number(plan.infeed_angle_deg),
                         plan.spring_passes));
  } else {
    const auto cut = [&](double depth, const std::string& note) {
      // Flank infeed: the pass moves along Z by depth·tan(angle), so the
      // trailing flank stays on the last cut and only the leading edge cuts;
      // the full-depth pass ends exactly at the thread's end, as G76's does.
      const double shift = g.direction * (depth - plan.ap) * tan_angle;
      out.line(fmt::format("G0 Z{}", number(g.z_start + shift)));
      out.line(fmt::format("G0 X{}", number(pass_diameter(plan, depth))), note);
      out.line(fmt::format("G33 Z{} K{}", number(g.z_end + shift), number(s.pitch_mm)));
      out.line(fmt::format("G0 X{}", number(g.drive_x)));
    };
    for (std::size_t i = 0; i < plan.depths.size(); ++i)
      cut(plan.depths[i], fmt::format("pass {}, depth {}", i + 1, number(plan.depths[i])));
    for (int i = 0; i < plan.spring_passes; ++i) cut(plan.ap, fmt::format("spring pass {}", i + 1));
  }
  // Back along the drive line to the safe Z, out of the bore when internal.
  out.line(fmt::format("G0 Z{}", number(g.safe_z)));
  out.line("M5");
  out.line("M30");
  return out.text();
}

}  // namespace tk::threads
