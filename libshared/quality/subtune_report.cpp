#include "quality/subtune_report.hpp"

#include <cmath>

namespace tk::quality {

const std::vector<std::string>& subtune_step_fields() {
  static const std::vector<std::string> fields{"run",    "n",  "a",        "b",          "s",     "t",
                                               "t_crit", "df", "decision", "correction", "offset"};
  return fields;
}

void subtune_step_cells(const SubTuneStep& step, std::vector<io::Cell>& row) {
  using io::Cell;
  row.assign({Cell::integer(static_cast<long long>(step.run)), Cell::integer(static_cast<long long>(step.n)),
              Cell::real(step.a), Cell::real(step.b), Cell::real(step.s), Cell::real(step.t), Cell::real(step.t_crit),
              step.df > 0 ? Cell::integer(static_cast<long long>(step.df)) : Cell::real(NAN),
              Cell::text(decision_name(step.decision)), Cell::real(step.correction), Cell::real(step.offset)});
}

const std::vector<std::string>& chart_step_fields() {
  static const std::vector<std::string> fields{"n", "statistic", "limit", "level", "decision", "correction", "offset"};
  return fields;
}

void add_chart_step(Record& record, const PolicyStep& step, std::uint64_t parts_since_adjustment, double offset) {
  record["n"] = parts_since_adjustment;
  record["statistic"] = step.statistic, record["limit"] = step.limit;
  record["level"] = step.level;
  record["decision"] = step.alarm ? "adjust" : "none";
  record["correction"] = step.correction, record["offset"] = offset;
}

const std::vector<std::string>& trace_fields() {
  static const std::vector<std::string> fields{"policy",   "part",  "allowance",  "size",
                                               "measured", "alarm", "correction", "offset"};
  return fields;
}

Record trace_record(std::string_view policy, const PartRecord& p) {
  return {
      {"policy", std::string(policy)}, {"part", p.part},   {"allowance", p.allowance_mm},   {"size", p.size_mm},
      {"measured", p.measured_mm},     {"alarm", p.alarm}, {"correction", p.correction_mm}, {"offset", p.offset_mm}};
}

const std::vector<std::string>& batch_summary_fields() {
  static const std::vector<std::string> fields{"policy",
                                               "parts",
                                               "in_tolerance_share",
                                               "mean_abs_deviation_mm",
                                               "rms_deviation_mm",
                                               "max_abs_deviation_mm",
                                               "corrections",
                                               "false_alarms",
                                               "arl0",
                                               "arl0_se",
                                               "arl_shift",
                                               "arl_shift_se",
                                               "arl_drift",
                                               "arl_drift_se",
                                               "sigma_mm"};
  return fields;
}

Record batch_summary(std::string_view policy, const LatheOutcome& run, const LatheOutcome& stable,
                     const std::optional<PolicyRunLengths>& run_lengths, double sigma_mm) {
  Record r{{"policy", std::string(policy)},
           {"parts", run.parts},
           {"in_tolerance_share", static_cast<double>(run.in_tolerance) / static_cast<double>(run.parts)},
           {"mean_abs_deviation_mm", run.mean_abs_deviation_mm},
           {"rms_deviation_mm", run.rms_deviation_mm},
           {"max_abs_deviation_mm", run.max_abs_deviation_mm},
           {"corrections", run.corrections},
           {"false_alarms", stable.corrections}};
  if (run_lengths) {
    r["arl0"] = run_lengths->in_control.mean, r["arl0_se"] = run_lengths->in_control.standard_error;
    r["arl_shift"] = run_lengths->shifted.mean, r["arl_shift_se"] = run_lengths->shifted.standard_error;
    r["arl_drift"] = run_lengths->drifting.mean, r["arl_drift_se"] = run_lengths->drifting.standard_error;
  } else {
    for (const char* f : {"arl0", "arl0_se", "arl_shift", "arl_shift_se", "arl_drift", "arl_drift_se"}) r[f] = nullptr;
  }
  r["sigma_mm"] = sigma_mm;
  return r;
}

}  // namespace tk::quality
