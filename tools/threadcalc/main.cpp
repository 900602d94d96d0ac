/// @file main.cpp
/// @brief threadcalc: ISO metric threads from their designation to limits of
/// size (ISO 68-1, ISO 261, ISO 965-1), thread-turning data for a
/// full-profile insert, and the threading program (Karker, Andó & Sudhan Raj).
/// Each mode is a file of its own (modes.hpp); this one wires the options.
#include "cli/option_checks.hpp"
#include "cli/tool_app.hpp"
#include "io/error.hpp"
#include "modes.hpp"

using namespace threadcalc;

int main(int argc, char** argv) {
  tk::cli::ToolApp tool("threadcalc",
                        "ISO metric threads (ISO 68-1, ISO 261, ISO 965-1): limits of size, the middle of each "
                        "tolerance zone, thread-turning data for a full-profile insert, and the threading program "
                        "(LinuxCNC G76 or plain G33 passes). Designations come as arguments or as records with a "
                        "'designation' field (JSON Lines, CSV, or one per line).",
                        "See threadcalc(1).");
  using tk::cli::range_check;
  std::vector<std::string> designations, inputs;
  Options o;
  ProgramOptions program;
  std::string kind = "auto", infeed = "radial";
  CLI::App& app = tool.app();
  app.add_option("designations", designations, "thread designations (M30x2-6g, M10, M10x1.5-6H/6g, M20x2-LH...)");
  app.add_option("-i,--input", inputs, "read records from FILE ('-' standard input) instead of arguments; repeatable")
      ->type_name("FILE")
      ->allow_extra_args(false);
  app.add_option("--field", o.field, "the field that holds the designation")->capture_default_str();
  app.add_option("--kind", kind, "auto: as the class says, both for a fit or no class; or external, internal, both")
      ->check(CLI::IsMember({"auto", "external", "internal", "both"}))
      ->capture_default_str();
  app.add_option("--decimals", o.decimals, "round millimetres to this many places (3, a micrometre, or more)")
      ->check(tk::cli::count_check(3, 9))
      ->capture_default_str();
  const std::string turning_group = "Thread turning (full-profile insert)";
  CLI::Option* flank_angle =
      app.add_option("--flank-angle", o.turning.flank_angle_deg, "flank infeed's angle from the radial, degrees")
          ->check(range_check(0, 30))
          ->capture_default_str();
  std::vector<CLI::Option*> turning_options{
      app.add_option("--passes", o.turning.passes, "passes (default: the pitch's lower end in Widia's table)")
          ->check(tk::cli::count_check(2, 100)),
      app.add_option("--min-last-pass", o.turning.min_last_pass_mm,
                     "the default passes keep the last one at least this deep, mm")
          ->check(range_check(0, 1))
          ->capture_default_str(),
      app.add_option("--spring-passes", o.turning.spring_passes, "passes repeated at full depth")
          ->check(tk::cli::count_check(0, 10))
          ->capture_default_str(),
      app.add_option("--infeed", infeed, "radial, or flank (modified flank infeed)")
          ->check(CLI::IsMember({"radial", "flank"}))
          ->capture_default_str(),
      flank_angle,
      app.add_option("--stock", o.turning.topping_stock_mm,
                     "diametral stock the insert tops off the crest, mm (default 0.15, 0.15 P below P 1)")
          ->check(range_check(0, 5)),
      app.add_option("--chamfer-margin", o.turning.chamfer_margin_mm,
                     "the chamfer's reach below the root, mm (default 0.25, P/2 below P 0.5)")
          ->check(range_check(0, 10)),
      app.add_option("--run-out", o.turning.run_out_mm,
                     "axial length of the pull-out at the thread's end, for retract_angle, mm (default 1.25 P)")
          ->check(range_check(0, 100))};
  for (CLI::Option* option : turning_options) option->group(turning_group);
  const std::string program_group = "Threading program";
  std::vector<CLI::Option*> program_options{
      app.add_option("--length", program.length, "thread length from the face (Z0) towards -Z, mm")
          ->check(range_check(0.1, kMaxLengthMm)),
      app.add_option("--rpm", program.rpm, "spindle speed (default: from --vc at the nominal diameter)")
          ->check(range_check(kMinRpm, kMaxRpm)),
      app.add_option("--vc", program.cutting_speed, "cutting speed, m/min")
          ->check(range_check(1, 5000))
          ->capture_default_str(),
      app.add_option("--max-rpm", program.max_rpm, "the highest spindle speed --vc may give")
          ->check(range_check(kMinRpm, kMaxRpm))
          ->capture_default_str(),
      app.add_option("--clearance", program.clearance,
                     "radial gap of the drive line from the blank (inside: at most a tenth of the bore), mm")
          ->check(range_check(0.01, 100))
          ->capture_default_str(),
      app.add_option("--accel", program.acceleration, "the Z axis's acceleration, mm/s^2 (sets the default run-in)")
          ->check(range_check(1, 1e6))
          ->capture_default_str(),
      app.add_option("--run-in", program.run_in,
                     "start this far ahead of the face (left hand: beyond the thread's end), mm (default: 3 P, or what "
                     "--accel needs)")
          ->check(range_check(0, kMaxRunInMm))};
  CLI::Option* gcode =
      app.add_option("--gcode", program.style, "write the threading program instead of records: g76 or passes")
          ->check(CLI::IsMember({"g76", "passes"}));
  program_options.push_back(gcode);
  for (CLI::Option* option : program_options) option->group(program_group);

  return tool.run(argc, argv, [&] {
    o.choice = kind == "external"   ? MemberChoice::external
               : kind == "internal" ? MemberChoice::internal
               : kind == "both"     ? MemberChoice::both
                                    : MemberChoice::from_class;
    o.turning.infeed = infeed == "flank" ? Infeed::flank : Infeed::radial;
    if (o.turning.infeed != Infeed::flank && flank_angle->count() > 0)
      throw tk::UsageError("--flank-angle goes with --infeed flank");
    if (!designations.empty() && !inputs.empty()) throw tk::UsageError("give designations or --input, not both");
    if (gcode->count() > 0) {
      write_program(designations, o, program, tool);
      return;
    }
    for (CLI::Option* option : program_options)
      if (option->count() > 0) throw tk::UsageError(option->get_name() + " goes with --gcode");
    write_records(designations, inputs, o, tool);
  });
}
