/// @file turning_report.hpp
/// @brief A simulated turning pass under the feed override as records: one
/// per constant-allowance segment, and the pass's summary beside the run at
/// 100 %.
#pragma once

#include <string>

#include "io/record.hpp"
#include "machining/turning_sim.hpp"

namespace tk::machining {

/// {"record": "segment"}, the segment's extent and its load and override figures.
Record segment_record(const SegmentStats& s);

/// {"record": "summary"}: the pass under the law of `variant` holding `mz_pct`
/// against the `baseline` pass at 100 % override.
Record summary_record(const std::string& variant, double mz_pct, const RunStats& run, const RunStats& baseline,
                      const TurningParams& process);

}  // namespace tk::machining
