/// @file run_programs.cpp
/// @brief gcode-pulse's run: G-code to pulse records, a --binary stream or
/// a --summary record, and the --svg drawing.
#include "io/error.hpp"
#include "io/record_writer.hpp"
#include "modes.hpp"
#include "motion/pulse_binary.hpp"
#include "motion/pulse_report.hpp"

namespace gcode_pulse {

void run_programs(const tk::motion::PulseOptions& options, RunOutput& output, tk::cli::ToolApp& tool) {
  const bool binary = output.binary, summary_only = output.summary_only;
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
  if (output.svg) run.draw(output.svg.get());
  std::vector<std::string> inputs = tool.common().inputs;
  if (inputs.empty()) inputs.push_back("-");
  try {
    for (const std::string& path : inputs) run.run_file(path);
    run.finish();
  } catch (const tk::Error&) {
    if (binary_writer) binary_writer->flush();  // the pulses before the error stay written
    throw;
  }
  if (output.svg) {
    output.svg->write(output.svg_path);
    if (output.svg->truncated())
      tool.warn(output.svg_path + ": more than 500,000 points in the window: the drawing stops there");
  }
  if (summary_only) {
    tk::Record record = tk::motion::pulse_summary_record(run.summary(), output.method_name);
    if (tool.output_format() == tk::io::OutputFormat::csv)
      record["unused_words"] = tk::Record(record["unused_words"].dump());
    writer.write(record);
  }
  if (binary_writer) binary_writer->finish();
  writer.flush();
}

}  // namespace gcode_pulse
