/// @file modes.hpp
/// @brief gcode-pulse's modes, one file each; main.cpp wires the options to them.
#pragma once

#include <memory>
#include <string>

#include "cli/tool_app.hpp"
#include "motion/path_svg.hpp"
#include "motion/pulse_run.hpp"

namespace gcode_pulse {

/// --verify-binary FILE: one record of what the stream holds.
void verify_binary(const std::string& path, tk::cli::ToolApp& tool);

/// What the run writes besides the pulses' records.
struct RunOutput {
  bool summary_only = false, binary = false;
  std::string method_name;  ///< --method as given, for the summary
  std::string svg_path;
  std::unique_ptr<tk::motion::PathSvg> svg;  ///< with --svg and --window
};

/// The programs (tool.common().inputs, standard input when none) run to
/// pulses (records or --binary) or a --summary record.
void run_programs(const tk::motion::PulseOptions& options, RunOutput& output, tk::cli::ToolApp& tool);

}  // namespace gcode_pulse
