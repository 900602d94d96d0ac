#include "machining/turning_report.hpp"

namespace tk::machining {

Record segment_record(const SegmentStats& s) {
  return {{"record", "segment"},
          {"segment", s.index},
          {"z_from", s.segment.z_from_mm},
          {"z_to", s.segment.z_to_mm},
          {"depth", s.segment.depth_mm},
          {"start_s", s.start_s},
          {"duration_s", s.duration_s},
          {"load_at_100_pct", s.load_at_100_pct},
          {"mean_load_pct", s.mean_load_pct},
          {"max_load_pct", s.max_load_pct},
          {"mean_override_pct", s.mean_override_pct},
          {"settled_override_pct", s.settled_override_pct},
          {"oscillation_pct", s.oscillation_pct},
          {"override_sd_pct", s.override_sd_pct}};
}

Record summary_record(const std::string& variant, double mz_pct, const RunStats& run, const RunStats& baseline,
                      const TurningParams& process) {
  return {{"record", "summary"},
          {"variant", variant},
          {"mz", mz_pct},
          {"machining_time_s", run.time_s},
          {"baseline_time_s", baseline.time_s},
          {"time_ratio", run.time_s / baseline.time_s},
          {"time_above_mz_s", run.time_above_mz_s},
          {"baseline_time_above_mz_s", baseline.time_above_mz_s},
          {"override_oscillation_pct", run.oscillation_pct},
          {"override_sd_pct", run.override_sd_pct},
          {"oscillation_segment", run.oscillation_segment},
          {"mean_override_pct", run.mean_override_pct},
          {"mean_load_pct", run.mean_load_pct},
          {"max_load_pct", run.max_load_pct},
          {"baseline_max_load_pct", baseline.max_load_pct},
          {"cycles", run.cycles},
          {"length_mm", process.profile.back().z_to_mm - process.profile.front().z_from_mm},
          {"spindle_rpm", spindle_speed_rev_s(process) * 60}};
}

}  // namespace tk::machining
