/// @file main.cpp
/// @brief threadcalc: ISO metric threads from their designation to limits of
/// size (ISO 68-1, ISO 261, ISO 965-1), thread-turning data for a
/// full-profile insert, and the threading program (Karker, Andó & Sudhan Raj).
#include <fmt/format.h>

#include <cmath>
#include <iostream>

#include "cli/option_checks.hpp"
#include "cli/tool_app.hpp"
#include "io/error.hpp"
#include "io/record_reader.hpp"
#include "io/record_writer.hpp"
#include "threads/designation_input.hpp"
#include "threads/thread_gcode.hpp"
#include "threads/thread_report.hpp"

namespace {

using namespace tk::threads;

struct Options {
  MemberChoice choice = MemberChoice::from_class;
  TurningSettings turning;
  int decimals = 4;
  std::string field = "designation";
};

/// Parses and evaluates one designation; errors get `where`.
std::vector<ThreadResult> evaluate_text(const std::string& text, const Options& o, const tk::Location& where) {
  return tk::with_location(where, [&] {
    const ThreadDesignation designation = parse_designation(text);
    std::vector<ThreadResult> results;
    for (const ThreadMember& member : members_of(designation, o.choice))
      results.push_back(evaluate(designation, member, o.turning));
    return results;
  });
}

void warn_all(const ThreadResult& result, const tk::Location& where, const tk::cli::ToolApp& tool) {
  for (const std::string& warning : result.warnings) tool.warn(tk::Error(warning, where).located_message());
}

void write_records(const std::vector<std::string>& designations, const std::vector<std::string>& inputs,
                   const Options& o, const tk::cli::ToolApp& tool) {
  tk::io::RecordWriter writer(tool.output_format());
  std::vector<std::string> fields = report_fields();
  // Designations from arguments make a record of their own; from records,
  // the designation's column stays where the input has it.
  if (!designations.empty()) fields.insert(fields.begin(), o.field);
  writer.declare_fields(fields);
  const auto emit = [&](const tk::Record& input, const std::string& text, const tk::Location& where) {
    for (const ThreadResult& result : evaluate_text(text, o, where)) {
      tk::Record record = input;
      add_fields(record, result, o.decimals);
      tk::with_location(where, [&] { writer.write(record); });
      warn_all(result, where, tool);
    }
  };
  if (!designations.empty()) {
    for (std::size_t i = 0; i < designations.size(); ++i)
      emit(tk::Record{{o.field, designations[i]}}, designations[i], {fmt::format("argument {}", i + 1), 0});
    writer.flush();
    return;
  }
  tk::io::RecordReader reader(inputs, designation_lines_probe(o.field));
  tk::Record record;
  while (reader.next(record)) {
    const tk::Location where = reader.where();
    const auto it = record.find(o.field);
    if (it == record.end() || !it->is_string() || it->get<std::string>().empty())
      throw tk::Error(fmt::format("no '{}' field with a designation", o.field), where);
    emit(record, it->get<std::string>(), where);
  }
  writer.flush();
}

/// The program's ranges (threadcalc(1), PROGRAMS), as validate() checks them.
constexpr double kMaxLengthMm = 10000, kMinRpm = 1, kMaxRpm = 100000, kMaxRunInMm = 1000;

struct ProgramOptions {
  std::string style;
  double length = 0;
  double rpm = 0;
  double cutting_speed = 100;
  double max_rpm = 3000;
  double clearance = 1;
  double run_in = 0;
  double acceleration = 500;
};

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

}  // namespace

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
