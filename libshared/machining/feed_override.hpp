/// @file feed_override.hpp
/// @brief The adaptive feed override of Stryczek & Orawczak, "A fuzzy
/// control strategy in the turning process" (seed 001), as the paper prints
/// it. Once per interpolation (IPO) cycle the spindle load M_a (% of rated
/// torque) and the operator's set value M_z give a correction coefficient
/// W_k, and W_k is aggregated with the override in force O_a into the new
/// override O_n:
///
///   below M_z  (1) W_k = exp((-5/M_z^2) M_a^2)
///              (3) O_n = 200 (O_a/200 + W_k - W_k O_a/200)   fuzzy disjunction
///   above M_z  (2) W_k = exp(-10/(1 - M_z/100) (M_a/100 - M_z/100)^2)
///              (4) O_n = W_k O_a                              fuzzy conjunction
///
/// The modified law replaces (1), (2) and (4) and keeps (3):
///
///   below M_z  (5) W_k = k exp((-5/M_z^2) M_a^2)
///   above M_z  (6) W_k = p exp(-10/(1 - M_z/100) (M_a/100 - M_z/100)^2) + (1 - p)
///              (7) O_n = W_k (O_a - d) + d
///
/// with the paper's k = p = 0.1 and d = 25 (an override in %).
///
/// Where the paper is silent: at M_a = M_z exactly the conjunction branch
/// applies, where (2) and (6) give W_k = 1 and (4) and (7) give O_n = O_a
/// (the load is on target: the override holds; (1) would give e^-5 there).
/// The laws keep O_n in the paper's (0, 200] without clamping: (3) is a
/// probabilistic sum of O_a/200 and W_k in [0, 1], (4) and (7) are convex
/// combinations. O_n is only held at or below 200 against rounding, and
/// kept at or above an optional floor (none by default).
#pragma once

#include <algorithm>
#include <cmath>
#include <string>

namespace tk::machining {

enum class OverrideVariant { original, modified };

/// "original" or "modified"; throws tk::UsageError otherwise.
OverrideVariant parse_override_variant(const std::string& name);
const char* variant_name(OverrideVariant variant);

/// The largest override, % ("the value set O_n = (0, 200%]").
inline constexpr double kMaxOverridePct = 200;

struct FeedOverrideParams {
  OverrideVariant variant = OverrideVariant::original;
  double mz_pct = 60;                 ///< M_z, % of rated torque, (0, 100]
  double k = 0.1;                     ///< (5): the disjunction's weight, (0, 1]
  double p = 0.1;                     ///< (6): the conjunction's weight, [0, 1]
  double d_pct = 25;                  ///< (7): the override an overload pulls towards, % in [0, 100]
  double initial_override_pct = 100;  ///< O_a before the first cycle, (0, 200]
  double min_override_pct = 0;        ///< an optional floor of O_n, % in [0, 200); 0: none
};

/// Throws tk::UsageError naming the option (--mz, --k, --p, --d,
/// --initial-override, --min-override) of the first parameter out of range.
void validate(const FeedOverrideParams& params);

/// W_k for the load M_a (%, finite and >= 0): (1)/(2), or (5)/(6) for the
/// modified law; 1 at M_a = M_z.
inline double correction_coefficient(const FeedOverrideParams& law, double ma) {
  const double mz = law.mz_pct;
  const bool modified = law.variant == OverrideVariant::modified;
  if (ma < mz) {
    // (1), (-5/M_z^2)(M_a^2) written -5 (M_a/M_z)^2: no 0 * inf for a tiny M_z.
    const double ratio = ma / mz;
    const double wk = std::exp(-5 * (ratio * ratio));
    return modified ? law.k * wk : wk;  // (5)
  }
  if (ma == mz) return 1;  // (2) and (6) at M_a = M_z; also where 1 - M_z/100 = 0
  const double excess = ma / 100 - mz / 100;
  const double wk = std::exp(-10 / (1 - mz / 100) * (excess * excess));  // (2)
  return modified ? law.p * wk + (1 - law.p) : wk;                       // (6)
}

/// O_n from W_k and O_a: (3) below M_z, (4) or (7) from M_z on.
inline double aggregate_override(const FeedOverrideParams& law, bool below_mz, double wk, double oa) {
  double on;
  if (below_mz)
    on = oa + wk * (200 - oa);  // (3), 200 (O_a/200 + W_k - W_k O_a/200) multiplied out: never below O_a in rounding
  else if (law.variant == OverrideVariant::original) on = wk * oa;  // (4)
  else on = wk * (oa - law.d_pct) + law.d_pct;                      // (7)
  return std::clamp(on, law.min_override_pct, kMaxOverridePct);
}

/// What one IPO cycle decided.
struct OverrideStep {
  double wk;            ///< W_k
  double override_pct;  ///< O_n, the override written for the next cycle, %
};

/// The law with its one piece of state, the override in force. Call step()
/// once per IPO cycle with the measured load (finite, 0-100 %: the caller
/// checks).
class FeedOverride {
 public:
  explicit FeedOverride(const FeedOverrideParams& params);

  OverrideStep step(double load_pct) {
    const double wk = correction_coefficient(params_, load_pct);
    override_ = aggregate_override(params_, load_pct < params_.mz_pct, wk, override_);
    return {wk, override_};
  }

  double override_pct() const { return override_; }
  const FeedOverrideParams& params() const { return params_; }

 private:
  FeedOverrideParams params_;
  double override_;
};

}  // namespace tk::machining
