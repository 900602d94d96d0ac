/// @file subtune_report.hpp
/// @brief subtune's records from the library's results: a sub-tuning step,
/// a chart's step, and a simulated batch's summary and per-part trace.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/record.hpp"
#include "io/record_writer.hpp"
#include "quality/adjustment_policy.hpp"
#include "quality/lathe_sim.hpp"
#include "quality/subtuning.hpp"

namespace tk::quality {

/// The fields a sub-tuning step adds, in output order.
const std::vector<std::string>& subtune_step_fields();
/// The step as cells in subtune_step_fields() order (df empty before a test).
void subtune_step_cells(const SubTuneStep& step, std::vector<io::Cell>& row);

/// The fields a chart's step adds, in output order.
const std::vector<std::string>& chart_step_fields();
/// `parts_since_adjustment` counts this part; `offset` is the corrections' sum so far.
void add_chart_step(Record& record, const PolicyStep& step, std::uint64_t parts_since_adjustment, double offset);

/// One simulated part under `policy` (--trace).
const std::vector<std::string>& trace_fields();
Record trace_record(std::string_view policy, const PartRecord& part);

/// The run lengths of a charted policy: in control, after a shift, under a drift.
struct PolicyRunLengths {
  RunLengthEstimate in_control, shifted, drifting;
};

/// One policy's batch: as given (`run`), stable (its corrections are false
/// alarms), and its run lengths (null fields for the policy 'none').
const std::vector<std::string>& batch_summary_fields();
Record batch_summary(std::string_view policy, const LatheOutcome& run, const LatheOutcome& stable,
                     const std::optional<PolicyRunLengths>& run_lengths, double sigma_mm);

}  // namespace tk::quality
