/// @file main.cpp
/// @brief gcode-pulse: G-code to timed step pulses (the nearest neighbour
/// to the programmed path, Panayotov & Goranov's direct single-impulse
/// calculation, Bresenham or DDA), or a summary of them.
#include <fmt/format.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>

#include "cli/number_option.hpp"
#include "cli/option_checks.hpp"
#include "cli/tool_app.hpp"
#include "io/error.hpp"
#include "modes.hpp"
#include "motion/machine_settings.hpp"
#include "motion/tool_table.hpp"

namespace {

/// "X,Y,Z" as three numbers in `range`; a usage error naming the option otherwise.
std::array<double, 3> parse_axes(const std::string& text, const char* option, tk::motion::SettingRange range) {
  const std::vector<double> values = tk::cli::parse_numbers(text, option, 3);
  for (const double value : values) tk::cli::require_range(value, range.low, range.high, option);
  return {values[0], values[1], values[2]};
}

/// --window "X0,Y0,X1,Y1" in mm, within the interpreter's coordinate range;
/// a usage error otherwise.
tk::motion::SvgWindow parse_window(const std::string& text) {
  const double limit = tk::motion::InterpreterOptions{}.max_coordinate_mm;
  const auto refuse = [limit] {
    return tk::UsageError(
        fmt::format("--window needs X0,Y0,X1,Y1 in mm from {0:g} to {1:g} with X0 < X1 and Y0 < Y1", -limit, limit));
  };
  std::vector<double> v;
  try {
    v = tk::cli::parse_numbers(text, "--window", 4);
  } catch (const tk::Error&) {
    throw refuse();
  }
  const tk::motion::SvgWindow w{v[0], v[1], v[2], v[3]};
  if (!(w.x0 < w.x1) || !(w.y0 < w.y1)) throw refuse();
  for (const double corner : {w.x0, w.y0, w.x1, w.y1})
    if (!(std::abs(corner) <= limit)) throw refuse();
  return w;
}

}  // namespace

int main(int argc, char** argv) {
  tk::cli::ToolApp tool("gcode-pulse",
                        "Turn G-code (RS274/NGC as LinuxCNC and grbl run it) into timed step pulses, one event "
                        "per lattice move (t, dx, dy, dz), or a summary of them.",
                        "See gcode-pulse(1).");
  std::string steps = "200,200,400", method = "nearest", svg_path, window_text, machine_file, axis_max_feed, axis_accel,
              start, verify_path, tool_table;
  bool summary_only = false, lenient = false, binary = false, canon = false;
  double accel = 500, rapid = 5000, max_feed = 0, junction_deviation = 0.01;
  std::size_t lookahead = 256;
  std::uint64_t max_pulses = static_cast<std::uint64_t>(tk::motion::PulseOptions::kDefaultMaxPulses);
  using tk::cli::range_check, tk::cli::count_check, tk::cli::ZeroAllowed;
  const auto in = [](tk::motion::SettingRange r) { return range_check(r.low, r.high); };
  CLI::App& app = tool.app();
  app.add_option("--steps-per-mm", steps, "steps per mm of X, Y and Z")->capture_default_str()->type_name("X,Y,Z");
  app.add_option("--method", method,
                 "nearest (the neighbour nearest the programmed path), direct (Panayotov & Goranov's: the "
                 "neighbour nearest where the line from the current point to the end leaves the box of one "
                 "step, the line drawn again after every step), bresenham or dda")
      ->check(CLI::IsMember(
          std::vector<std::string>(tk::motion::kStepMethodNames.begin(), tk::motion::kStepMethodNames.end())))
      ->capture_default_str()
      ->type_name("NAME");
  app.add_flag("--summary", summary_only, "write one summary record instead of the pulses");
  app.add_flag("--binary", binary, "write the pulses in the compact binary form (see gcode-pulse(1))");
  app.add_option("--verify-binary", verify_path,
                 "check that FILE is a complete --binary stream and write one record of what it holds")
      ->type_name("FILE");
  app.add_flag("--canon", canon,
               "read LinuxCNC's canonical commands (rs274 -g PROGRAM | gcode-pulse --canon) instead of G-code: "
               "whatever LinuxCNC interprets");
  app.add_option("--tool-table", tool_table,
                 "LinuxCNC tool table (T1 P1 Z12.5 ...; offsets in mm) whose offsets G43 applies; without one, "
                 "G43 of a tool other than 0 is refused")
      ->type_name("FILE");
  app.add_flag("--lenient", lenient,
               "skip words that change motion but cannot be honoured (G41, canned cycles...) with a warning");
  app.add_option("--svg", svg_path, "draw the ideal and the stepped path in the XY plane (needs --window)")
      ->type_name("FILE");
  app.add_option("--window", window_text, "the part of the XY plane to draw, mm")->type_name("X0,Y0,X1,Y1");
  app.add_option("--machine", machine_file, "machine description (JSON, keys as these options; options given here win)")
      ->type_name("FILE");
  app.add_option("--accel", accel, "acceleration along the path, mm/s^2")
      ->check(in(tk::motion::kAccelRange))
      ->capture_default_str()
      ->type_name("A");
  app.add_option("--axis-accel", axis_accel, "acceleration limit of each axis, mm/s^2 (default: none)")
      ->type_name("X,Y,Z");
  app.add_option("--rapid", rapid, "G0 speed, mm/min")
      ->check(in(tk::motion::kFeedRange))
      ->capture_default_str()
      ->type_name("F");
  app.add_option("--max-feed", max_feed, "cap on programmed feeds, mm/min (default: --rapid)")
      ->check(in(tk::motion::kFeedRange))
      ->type_name("F");
  app.add_option("--axis-max-feed", axis_max_feed, "speed limit of each axis, G0 included, mm/min (default: none)")
      ->type_name("X,Y,Z");
  app.add_option("--junction-deviation", junction_deviation, "corner rounding allowed for junction speeds, mm")
      ->check(in(tk::motion::kJunctionDeviationRange))
      ->capture_default_str()
      ->type_name("MM");
  app.add_option("--lookahead", lookahead, "blocks planned together")
      ->check(count_check(static_cast<std::uint64_t>(tk::motion::kLookaheadRange.low),
                          static_cast<std::uint64_t>(tk::motion::kLookaheadRange.high)))
      ->capture_default_str()
      ->type_name("N");
  app.add_option("--start", start, "where the machine stands when the program starts, mm (default: 0,0,0)")
      ->type_name("X,Y,Z");
  app.add_option("--max-pulses", max_pulses,
                 "refuse (exit 1, at its line) the block that takes the step pulses the program implies past N")
      ->check(count_check(1, 1000000000000))
      ->capture_default_str()
      ->type_name("N");
  tool.add_input_files("G-code files, run one after another; standard input when none or '-'");

  return tool.run(argc, argv, [&] {
    if (!verify_path.empty()) {
      gcode_pulse::verify_binary(verify_path, tool);
      return;
    }
    // The machine file first, then whatever the command line gives.
    tk::motion::MachineSettings settings;
    if (!machine_file.empty()) settings = tk::motion::read_machine_file(machine_file);
    tk::motion::MachineSettings given;
    auto on_command_line = [&](const char* name) { return app.get_option(name)->count() > 0; };
    if (on_command_line("--steps-per-mm"))
      given.steps_per_mm = parse_axes(steps, "--steps-per-mm", tk::motion::kStepsPerMmRange);
    if (on_command_line("--axis-max-feed"))
      given.axis_max_feed = parse_axes(axis_max_feed, "--axis-max-feed", tk::motion::kFeedRange);
    if (on_command_line("--axis-accel"))
      given.axis_accel = parse_axes(axis_accel, "--axis-accel", tk::motion::kAccelRange);
    if (on_command_line("--start")) given.start = parse_axes(start, "--start", tk::motion::start_range());
    if (on_command_line("--accel")) given.accel = accel;
    if (on_command_line("--rapid")) given.rapid = rapid;
    if (on_command_line("--max-feed")) given.max_feed = max_feed;
    if (on_command_line("--junction-deviation")) given.junction_deviation = junction_deviation;
    if (on_command_line("--lookahead")) given.lookahead = lookahead;
    settings.override_with(given);
    tk::motion::PulseOptions options;
    settings.apply_to(options);
    options.method = tk::motion::step_method_named(method);
    options.interpreter.lenient = lenient;
    options.canon = canon;
    if (!tool_table.empty()) {
      if (canon) throw tk::UsageError("--tool-table is for G-code: rs274 applies its own table (rs274 -t FILE)");
      options.interpreter.tool_table = tk::motion::read_tool_table(tool_table);
      options.interpreter.has_tool_table = true;
    }
    options.max_pulses = static_cast<double>(max_pulses);

    if (binary && summary_only) throw tk::UsageError("--binary and --summary exclude each other");
    if (binary && tool.common().csv) throw tk::UsageError("--binary and --csv exclude each other");
    if (binary && isatty(STDOUT_FILENO))
      throw tk::UsageError("--binary will not write to a terminal: redirect standard output");
    if (svg_path.empty() != window_text.empty()) throw tk::UsageError("--svg and --window go together");
    gcode_pulse::RunOutput output;
    output.summary_only = summary_only;
    output.binary = binary;
    output.method_name = method;
    output.svg_path = svg_path;
    if (!svg_path.empty()) output.svg = std::make_unique<tk::motion::PathSvg>(parse_window(window_text));
    gcode_pulse::run_programs(options, output, tool);
  });
}
