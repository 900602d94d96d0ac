#include "threads/thread_gcode.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "io/error.hpp"

namespace tk::threads {
namespace {

/// A coordinate to 0.1 µm without trailing zeros, as controls read them.
std::string number(double value) {
  if (std::abs(value) < 5e-5) value = 0;
  std::string text = fmt::format("{:.4f}", value);
  while (text.back() == '0') text.pop_back();
  if (text.back() == '.') text.pop_back();
  return text;
}

double round_up_to_tenth_micron(double value) { return std::ceil(value * 1e4 - 1e-6) / 1e4; }

struct Geometry {
  double drive_x;    ///< the drive line's diameter
  double z_start;
  double z_end;
  double direction;  ///< −1 cutting towards the chuck, +1 away from it (left hand)
};

Geometry geometry(const TurningPlan& plan, const ProgramSettings& s) {
  const double run_in = s.run_in_mm > 0 ? s.run_in_mm : 3 * s.pitch_mm;
  const double clearance = 2 * s.clearance_mm;
  Geometry g;
  g.drive_x = plan.external ? plan.blank_diameter + clearance : plan.blank_diameter - clearance;
  // Right hand: from ahead of the face towards the chuck. Left hand (same
  // spindle direction and insert): from the thread's inner end out past the
  // face, which needs a groove to start in.
  g.direction = s.left_hand ? 1 : -1;
  g.z_start = s.left_hand ? -s.length_mm : run_in;
  g.z_end = s.left_hand ? run_in : -s.length_mm;
  return g;
}

std::string header(const TurningPlan& plan, const ProgramSettings& s, const char* style) {
  std::string out;
  out += fmt::format("(threadcalc: {} {}, {} program)\n", s.title, plan.external ? "external" : "internal", style);
  out += fmt::format("(ap {} mm from the peak diameter {}; pitch diameter aimed at {}; {} passes, {} infeed)\n",
                     number(plan.ap), number(plan.peak_diameter), number(plan.target_pitch_diameter), plan.passes,
                     plan.infeed == Infeed::flank ? fmt::format("{}-degree flank", number(plan.infeed_angle_deg))
                                                  : std::string("radial"));
  out += fmt::format("({} before threading: {}; chamfer {} x 45 degrees)\n", plan.external ? "turn" : "bore",
                     number(plan.blank_diameter), number(plan.chamfer));
  out += "G18 G21 G90 G94 G7 (XZ plane, mm, absolute, X as a diameter)\n";
  out += fmt::format("S{} M3\n", number(std::round(s.rpm)));
  return out;
}

/// Diameter at a radial depth below (external) or above (internal) the peak.
double pass_diameter(const TurningPlan& plan, double depth) {
  return plan.peak_diameter + (plan.external ? -2 : 2) * depth;
}

}  // namespace

void validate(const ProgramSettings& s, const TurningPlan& plan) {
  require(std::isfinite(s.pitch_mm) && s.pitch_mm > 0, "the program needs a positive pitch");
  require(std::isfinite(s.length_mm) && s.length_mm > 0 && s.length_mm <= 10000,
          fmt::format("thread length {} mm is outside (0, 10000]", s.length_mm));
  require(std::isfinite(s.rpm) && s.rpm >= 1 && s.rpm <= 100000, fmt::format("spindle speed {} rpm is outside 1-100000", s.rpm));
  require(std::isfinite(s.clearance_mm) && s.clearance_mm > 0 && s.clearance_mm <= 100,
          fmt::format("clearance {} mm is outside (0, 100]", s.clearance_mm));
  require(std::isfinite(s.run_in_mm) && s.run_in_mm >= 0 && s.run_in_mm <= 1000,
          fmt::format("run-in {} mm is outside [0, 1000]", s.run_in_mm));
  if (!plan.external)
    require(plan.blank_diameter - 2 * s.clearance_mm > 0,
            fmt::format("a clearance of {} mm puts the drive line inside a {} mm bore at or below the axis",
                        s.clearance_mm, number(plan.blank_diameter)));
}

std::string thread_program(ProgramStyle style, const TurningPlan& plan, const ProgramSettings& s) {
  validate(s, plan);
  const Geometry g = geometry(plan, s);
  const double tan_angle = std::tan(plan.infeed_angle_deg * std::numbers::pi / 180);
  std::string out = header(plan, s, style == ProgramStyle::g76 ? "G76" : "G33 passes");
  out += fmt::format("G0 X{} Z{}\n", number(g.drive_x), number(g.z_start));
  if (style == ProgramStyle::g76) {
    const double k = 2 * plan.ap;  // G7: I, J and K are diameters
    const double j = round_up_to_tenth_micron(k / std::sqrt(static_cast<double>(plan.passes)));
    out += fmt::format("G76 P{} Z{} I{} J{} K{} R2 Q{} H{} E0 L0\n", number(s.pitch_mm), number(g.z_end),
                       number(plan.peak_diameter - g.drive_x), number(j), number(k), number(plan.infeed_angle_deg),
                       plan.spring_passes);
  } else {
    const auto cut = [&](double depth, const std::string& note) {
      // Flank infeed: the start moves along the cut by depth·tan(angle), so
      // the trailing flank stays on the last cut and only the leading edge cuts.
      const double z = g.z_start + g.direction * depth * tan_angle;
      out += fmt::format("G0 Z{}\n", number(z));
      out += fmt::format("G0 X{} ({})\n", number(pass_diameter(plan, depth)), note);
      out += fmt::format("G33 Z{} K{}\n", number(g.z_end + g.direction * depth * tan_angle), number(s.pitch_mm));
      out += fmt::format("G0 X{}\n", number(g.drive_x));
    };
    for (std::size_t i = 0; i < plan.depths.size(); ++i)
      cut(plan.depths[i], fmt::format("pass {}, depth {}", i + 1, number(plan.depths[i])));
    for (int i = 0; i < plan.spring_passes; ++i) cut(plan.ap, fmt::format("spring pass {}", i + 1));
  }
  // Back along the drive line, clear of the thread (inside the bore when internal).
  out += fmt::format("G0 Z{}\n", number(g.z_start));
  out += "M5\nM30\n";
  return out;
}

}  // namespace tk::threads
