/// @file modes.hpp
/// @brief fuzzyfeed's modes, one file each (the filter over load records,
/// --simulate); main.cpp wires the options to them.
#pragma once

#include <string>
#include <vector>

#include "cli/tool_app.hpp"
#include "io/record_writer.hpp"
#include "machining/feed_override.hpp"
#include "machining/turning_sim.hpp"

namespace fuzzyfeed {

using namespace tk::machining;

/// The stream mode: each record gets the law's answer to its load.
void filter_records(const std::vector<std::string>& inputs, const FeedOverrideParams& law_params,
                    tk::io::OutputFormat format);

/// --simulate's options beside the law's and the process's.
struct SimulateSettings {
  std::string variant = "original", profile_path, trace_path, svg_path;
  double power_kw = 9;
  bool segments = false;
};

/// --simulate: a turning pass under the law (`law`, already validated), its
/// summary record (after --segments' records), --trace and --svg.
void simulate(const SimulateSettings& settings, const FeedOverrideParams& law, TurningParams process,
              tk::cli::ToolApp& tool);

}  // namespace fuzzyfeed
