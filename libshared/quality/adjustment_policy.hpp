/// @file adjustment_policy.hpp
/// @brief What decides, part by part, whether to correct the set-up: the
/// paper's sub-tuning and the SPC charts users compare it with (Shewhart X
/// chart of individuals, EWMA, tabular CUSUM), behind one interface so the
/// simulation and the ARL runs treat them alike.
#pragma once

#include <limits>
#include <memory>
#include <string>
#include <string_view>

#include "quality/subtuning.hpp"

namespace tk::quality {

enum class PolicyKind { none, subtune, shewhart, ewma, cusum };
std::string_view policy_name(PolicyKind kind);
/// Error for a name that is not a policy.
PolicyKind parse_policy(std::string_view name);

/// The charts' settings. They watch the size's deviation from `target` in
/// units of `sigma`, the in-control standard deviation of one measurement.
struct ChartSettings {
  double target = 0, sigma = 1;
  double shewhart_l = 3;                 ///< limits at ± L σ
  double ewma_lambda = 0.2, ewma_l = 3;  ///< qcc's defaults; asymptotic limits ± L σ √(λ/(2 − λ))
  double cusum_k = 0.5, cusum_h = 5;     ///< reference value and decision interval, in σ
};

struct PolicyStep {
  bool alarm = false;
  double correction = 0;  ///< mm to add to the set-up (0 without an alarm)
  /// The policy's estimate of the current size level before any correction
  /// (sub-tuning: the run's line at this part; EWMA: target + z); NaN when it has none.
  double level = std::numeric_limits<double>::quiet_NaN();
  /// What the policy compares with its limit, before any restart: t and
  /// t_crit (sub-tuning); x − target and L σ (Shewhart); z and L σ_z
  /// (EWMA); C+, or −C− when that is larger, and H (CUSUM). NaN when none.
  double statistic = std::numeric_limits<double>::quiet_NaN();
  double limit = std::numeric_limits<double>::quiet_NaN();
};

class AdjustmentPolicy {
 public:
  virtual ~AdjustmentPolicy() = default;
  virtual PolicyKind kind() const = 0;
  /// Takes one measured size; after an alarm the policy starts afresh, as
  /// after any adjustment of the set-up.
  virtual PolicyStep observe(double size) = 0;
  /// Forgets everything (a new, independent run of parts).
  virtual void reset() = 0;
};

/// A fresh policy. The charts' correction moves the mean back to the target
/// by their estimate of the shift: the point itself (Shewhart), the EWMA, or
/// the CUSUM's μ̂ = target ± (K + C/N) (Montgomery §9.1).
std::unique_ptr<AdjustmentPolicy> make_policy(PolicyKind kind, const SubTuneSettings& subtune,
                                              const ChartSettings& charts);

}  // namespace tk::quality
