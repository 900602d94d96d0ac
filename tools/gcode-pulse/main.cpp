/// @file main.cpp
/// @brief gcode-pulse: G-code to timed step pulses (direct single-impulse
/// calculation, Bresenham or DDA), or a summary of them.
#include <unistd.h>

#include <cmath>
#include <cstdlib>

#include "cli/tool_app.hpp"
#include "io/error.hpp"
#include "io/record_writer.hpp"
#include "motion/pulse_binary.hpp"
#include "motion/pulse_run.hpp"

namespace {

/// "X,Y,Z": three positive finite numbers.
std::array<double, 3> parse_steps_per_mm(const std::string& text) {
  std::array<double, 3> values{};
  std::size_t at = 0;
  for (int axis = 0; axis < 3; ++axis) {
    const std::size_t comma = axis < 2 ? text.find(',', at) : text.size();
    if (comma == std::string::npos) throw tk::UsageError("--steps-per-mm needs three numbers X,Y,Z");
    const std::string part = text.substr(at, comma - at);
    char* end = nullptr;
    values[axis] = std::strtod(part.c_str(), &end);
    if (part.empty() || *end != '\0' || !std::isfinite(values[axis]) || values[axis] <= 0)
      throw tk::UsageError("--steps-per-mm: '" + part + "' is not a positive number");
    at = comma + 1;
  }
  return values;
}

void positive(double value, const char* option) {
  if (!(value > 0) || !std::isfinite(value)) throw tk::UsageError(std::string(option) + " must be a positive number");
}

}  // namespace

int main(int argc, char** argv) {
  tk::cli::ToolApp tool("gcode-pulse",
                        "Turn G-code (RS274/NGC as LinuxCNC and grbl run it) into timed step pulses, one event "
                        "per lattice move (t, dx, dy, dz), or a summary of them.",
                        "See gcode-pulse(1).");
  std::string steps = "200,200,400", method = "direct", svg_path, window_text;
  bool summary_only = false, lenient = false, binary = false;
  tk::motion::MachineLimits limits;
  double rapid_mm_min = 5000, max_feed_mm_min = 0;
  CLI::App& app = tool.app();
  app.add_option("--steps-per-mm", steps, "steps per mm of X, Y and Z")->capture_default_str()->type_name("X,Y,Z");
  app.add_option("--method", method, "direct (the seed's nearest-neighbour calculation), bresenham or dda")
      ->check(CLI::IsMember({"direct", "bresenham", "dda"}))
      ->capture_default_str()
      ->type_name("NAME");
  app.add_flag("--summary", summary_only, "write one summary record instead of the pulses");
  app.add_flag("--binary", binary, "write the pulses in the compact binary form (see gcode-pulse(1))");
  app.add_flag("--lenient", lenient, "skip words that change motion but cannot be honoured (G41, canned cycles...) with a warning");
  app.add_option("--svg", svg_path, "draw the ideal and the stepped path in the XY plane (needs --window)")
      ->type_name("FILE");
  app.add_option("--window", window_text, "the part of the XY plane to draw, mm")->type_name("X0,Y0,X1,Y1");
  app.add_option("--accel", limits.acceleration, "acceleration, mm/s^2")->capture_default_str()->type_name("A");
  app.add_option("--rapid", rapid_mm_min, "G0 speed, mm/min")->capture_default_str()->type_name("F");
  app.add_option("--max-feed", max_feed_mm_min, "cap on programmed feeds, mm/min (default: --rapid)")->type_name("F");
  app.add_option("--junction-deviation", limits.junction_deviation, "corner rounding allowed for junction speeds, mm")
      ->capture_default_str()
      ->type_name("MM");
  app.add_option("--lookahead", limits.lookahead, "blocks planned together")->capture_default_str()->type_name("N");
  tool.add_input_files("G-code files, run one after another; standard input when none or '-'");

  return tool.run(argc, argv, [&] {
    tk::motion::PulseOptions options;
    options.steps_per_mm = parse_steps_per_mm(steps);
    options.method = method == "bresenham" ? tk::motion::StepMethod::bresenham
                     : method == "dda"     ? tk::motion::StepMethod::dda
                                           : tk::motion::StepMethod::direct;
    positive(limits.acceleration, "--accel");
    positive(rapid_mm_min, "--rapid");
    if (max_feed_mm_min != 0) positive(max_feed_mm_min, "--max-feed");
    if (!(limits.junction_deviation >= 0) || !std::isfinite(limits.junction_deviation))
      throw tk::UsageError("--junction-deviation must not be negative");
    if (limits.lookahead == 0) throw tk::UsageError("--lookahead must be at least 1");
    limits.rapid_speed = rapid_mm_min / 60;
    limits.max_speed = (max_feed_mm_min > 0 ? max_feed_mm_min : rapid_mm_min) / 60;
    options.limits = limits;
    options.interpreter.lenient = lenient;

    if (binary && summary_only) throw tk::UsageError("--binary and --summary exclude each other");
    if (binary && tool.common().csv) throw tk::UsageError("--binary and --csv exclude each other");
    if (binary && isatty(STDOUT_FILENO)) throw tk::UsageError("--binary will not write to a terminal: redirect standard output");
    tk::io::RecordWriter writer(tool.output_format());
    std::unique_ptr<tk::motion::PulseBinaryWriter> binary_writer;
    tk::motion::PulseRun::PulseSink on_pulses;
    if (binary) {
      binary_writer = std::make_unique<tk::motion::PulseBinaryWriter>(stdout, options.steps_per_mm);
      on_pulses = [&](std::span<const tk::motion::Pulse> pulses) { binary_writer->write(pulses); };
    } else if (!summary_only) {
      writer.declare_fields({"t", "dx", "dy", "dz"});
      on_pulses = [&](std::span<const tk::motion::Pulse> pulses) {
        for (const tk::motion::Pulse& pulse : pulses) {
          const double row[4] = {pulse.t, static_cast<double>(pulse.delta[0]), static_cast<double>(pulse.delta[1]),
                                 static_cast<double>(pulse.delta[2])};
          writer.write_numbers(row, 0b1110);
        }
      };
    }
    tk::motion::PulseRun run(options, on_pulses, [&](const std::string& message) { tool.warn(message); });
    if (svg_path.empty() != window_text.empty()) throw tk::UsageError("--svg and --window go together");
    std::unique_ptr<tk::motion::PathSvg> svg;
    if (!svg_path.empty()) {
      svg = std::make_unique<tk::motion::PathSvg>(tk::motion::parse_svg_window(window_text));
      run.draw(svg.get());
    }
    std::vector<std::string> inputs = tool.common().inputs;
    if (inputs.empty()) inputs.push_back("-");
    try {
      for (const std::string& path : inputs) run.run_file(path);
      run.finish();
    } catch (const tk::Error&) {
      if (binary_writer) binary_writer->flush();  // the pulses before the error stay written
      throw;
    }
    if (svg) {
      svg->write(svg_path);
      if (svg->truncated()) tool.warn(svg_path + ": more than 500,000 points in the window: the drawing stops there");
    }
    if (summary_only) {
      const tk::motion::PulseSummary s = run.summary();
      tk::Record record;
      record["method"] = method;
      static const char* const kAxes[3] = {"x", "y", "z"};
      for (int axis = 0; axis < 3; ++axis) record[std::string("pulses_") + kAxes[axis]] = s.pulses[axis];
      for (int axis = 0; axis < 3; ++axis) record[std::string("final_") + kAxes[axis]] = s.final_mm[axis];
      record["duration_s"] = s.duration_s;
      record["dwell_s"] = s.dwell_s;
      record["path_mm"] = s.path_mm;
      record["max_deviation_mm"] = s.max_deviation_mm;
      record["rms_deviation_mm"] = s.rms_deviation_mm();
      for (int axis = 0; axis < 3; ++axis) record[std::string("peak_rate_") + kAxes[axis]] = s.peak_rate[axis];
      record["coincident_steps"] = s.coincident_steps;
      record["events"] = s.events;
      record["blocks"] = s.blocks;
      record["motions"] = s.motions;
      record["feed_capped_blocks"] = s.feed_capped;
      tk::Record unused = tk::Record::object();
      for (const auto& [word, count] : s.unused_words) unused[word] = count;
      record["unused_words"] = tool.output_format() == tk::io::OutputFormat::csv ? tk::Record(unused.dump()) : unused;
      writer.write(record);
    }
    if (binary_writer) binary_writer->flush();
    writer.flush();
  });
}
