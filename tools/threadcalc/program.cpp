/// @file program.cpp
/// @brief threadcalc --gcode: the threading program of one thread member.
#include <fmt/format.h>

#include <iostream>

#include "cli/option_checks.hpp"
#include "modes.hpp"
#include "threads/thread_gcode.hpp"

namespace threadcalc {

void write_program(const std::vector<std::string>& designations, Options o, const ProgramOptions& p,
                   const tk::cli::ToolApp& tool) {
  if (designations.size() != 1) throw tk::UsageError("--gcode writes the program of one DESIGNATION");
  if (!(p.length > 0)) throw tk::UsageError("--gcode needs the thread's --length");
  const tk::Location where{"argument 1", 0};
  const ThreadDesignation d = tk::with_location(where, [&] { return parse_designation(designations[0]); });
  if (o.choice == MemberChoice::from_class) {
    if (d.external && d.internal) throw tk::UsageError("a fit has two members: choose one with --kind");
    o.choice = d.internal ? MemberChoice::internal : MemberChoice::external;
  }
  if (o.choice == MemberChoice::both) throw tk::UsageError("--gcode writes one member: --kind external or internal");
  const ThreadResult result =
      tk::with_location(where, [&] { return evaluate(d, members_of(d, o.choice).front(), o.turning); });
  warn_all(result, where, tool);
  ProgramSettings settings;
  settings.title = member_designation(result);
  settings.pitch_mm = result.profile.pitch;
  settings.length_mm = p.length;
  settings.rpm = p.rpm > 0 ? p.rpm : spindle_speed(p.cutting_speed, result.profile.major, p.max_rpm);
  if (settings.rpm < kMinRpm)
    throw tk::UsageError(fmt::format(
        "--vc {:g} m/min gives {:.3g} rpm at the {:g} mm diameter, below {:g} rpm: give a higher --vc or --rpm",
        p.cutting_speed, settings.rpm, result.profile.major, kMinRpm));
  settings.clearance_mm = p.clearance;
  settings.run_in_mm = p.run_in;
  settings.acceleration_mm_s2 = p.acceleration;
  // The default run-in is the Z axis's way up to P·S: a slow axis at a fast
  // spindle would start the program metres ahead of the face.
  if (p.run_in == 0)
    tk::cli::require_run_size(synchronisation_distance(settings), kMaxRunInMm,
                              "mm of run-in (the Z axis's way up to P times S; give --run-in, or lower the speed)",
                              "--accel with the spindle speed and the pitch");
  validate(settings);
  settings.left_hand = result.designation.left_hand;
  const ProgramStyle style = p.style == "g76" ? ProgramStyle::g76 : ProgramStyle::passes;
  std::cout << thread_program(style, result.plan, settings) << std::flush;
  if (!std::cout) throw tk::Error("cannot write the program to standard output");
}

}  // namespace threadcalc
