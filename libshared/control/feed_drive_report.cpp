#include "control/feed_drive_report.hpp"

namespace tk::control {

const std::vector<std::string> kSummaryFields{"controller",
                                              "Lambda",
                                              "alpha",
                                              "beta",
                                              "rms_error_mm",
                                              "max_error_mm",
                                              "rms_velocity_error_mm_s",
                                              "rms_s",
                                              "chattering",
                                              "hf_share",
                                              "effort_rms_n",
                                              "max_force_n",
                                              "saturated_share",
                                              "measured_s",
                                              "plant_steps",
                                              "diverged",
                                              "diverged_at_s"};

Record summary_record(const FeedDriveConfig& c, const FeedDriveSummary& s) {
  Record r{{"controller", controller_name(c.gains.kind)}};
  if (c.gains.kind == ControllerKind::smc) r["Lambda"] = c.gains.switching;
  if (c.gains.kind == ControllerKind::sta) r["alpha"] = c.gains.alpha, r["beta"] = c.gains.beta;
  // A diverged run has no tracking error to rank it by (the figures before
  // the divergence, or none at all when it came before --settle, would say
  // 0.0 and top a sweep sorted by error): null, and `diverged` says why.
  const auto tracking = [&s](double figure) { return s.diverged ? Record() : Record(figure); };
  r["rms_error_mm"] = tracking(s.rms_error_mm), r["max_error_mm"] = tracking(s.max_error_mm);
  r["rms_velocity_error_mm_s"] = tracking(s.rms_velocity_error_mm_s), r["rms_s"] = tracking(s.rms_s);
  r["chattering"] = s.chattering_n_s, r["hf_share"] = s.hf_share;
  r["effort_rms_n"] = s.effort_rms_n, r["max_force_n"] = s.max_force_n, r["saturated_share"] = s.saturated_share;
  r["measured_s"] = s.measured_s, r["plant_steps"] = s.plant_steps, r["diverged"] = s.diverged;
  if (s.diverged) r["diverged_at_s"] = s.diverged_at_s;
  return r;
}
}  // namespace tk::control
