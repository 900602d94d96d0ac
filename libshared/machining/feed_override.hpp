/// @file feed_override.hpp
/// @brief The fuzzy adaptive feed-rate override of Stryczek & Orawczak ("A
/// fuzzy control strategy in the turning process"), as reconstructed from
/// the description: once per interpolation (IPO) cycle the spindle
/// load M_a is compared with the operator's set value M_z, a Sugeno-style
/// fuzzy rule base gives a factor W_k, and the feed override becomes
/// O_n = W_k * O_a. The "modified" law of the paper averages the load over
/// d cycles, applies only a fraction k of the correction and holds the
/// override inside a dead band of +-p * M_z.
///
/// The per-sample step is inline and allocation-free: the moving average
/// keeps a ring buffer and a running sum, so a sample costs O(1) whatever d is.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace tk::machining {

enum class OverrideVariant { original, modified };

/// "original" or "modified"; throws tk::UsageError otherwise.
OverrideVariant parse_override_variant(const std::string& name);
const char* variant_name(OverrideVariant variant);

/// Largest override the law may command, in percent (formula (4)).
inline constexpr double kMaxOverridePct = 200;

struct FeedOverrideParams {
  OverrideVariant variant = OverrideVariant::original;
  double mz_pct = 60;               ///< M_z, the load to keep, % of rated (0, 100]
  double gain_k = 0.1;              ///< k of formula (6), (0, 1]
  double dead_band_p = 0.1;         ///< p of formula (7), [0, 1): relative to M_z
  std::size_t average_d = 25;       ///< d of formula (5), IPO cycles, >= 1
  double initial_override_pct = 100;  ///< O_a before the first sample, (0, 200]
  /// The floor of the override. Without one, a long overload (W_k = 0.5 every
  /// cycle) would halve the override towards 0 and it could then take many
  /// cycles (or, at exactly 0, forever) to recover.
  double min_override_pct = 1;
};

/// Throws tk::UsageError naming the option (--mz, --k, --p, --d,
/// --initial-override, --min-override) of the first parameter out of range.
void validate(const FeedOverrideParams& params);

/// Formulas (2)-(3): the rule base's factor for the load ratio r = M_a / M_z
/// (r >= 0). Three triangular terms LOW, OK, HIGH with singleton consequents
/// 2 (speed up), 1 (hold) and 0.5 (slow down), weighted average. With these
/// terms the weights always sum to 1 for r >= 0, so W_k is piecewise linear:
/// 2 - r below M_z, 1.5 - r/2 from M_z to 2 M_z, 0.5 above.
inline double fuzzy_factor(double r) {
  const double low = std::max(0.0, 1 - r);
  const double ok = std::max(0.0, 1 - std::abs(r - 1));
  const double high = std::min(1.0, std::max(0.0, r - 1));
  return (2 * low + 1 * ok + 0.5 * high) / (low + ok + high);
}

/// What one IPO cycle decided.
struct OverrideStep {
  double load_used;     ///< M_a (original) or the moving average M_avg (modified), %
  double factor;        ///< the factor applied: W_k (original), W_k' (modified)
  double override_pct;  ///< O_n, the new override, %
};

/// The controller with its state: the override O_a and, for the modified
/// law, the ring buffer of the last d loads. Call step() once per IPO cycle
/// with the measured load (finite, 0-100 %: the caller checks).
class FeedOverride {
 public:
  explicit FeedOverride(const FeedOverrideParams& params);

  OverrideStep step(double load_pct) {
    double used = load_pct;
    if (modified_) used = average(load_pct);
    double factor = fuzzy_factor(used / mz_);
    if (modified_) {
      factor = 1 + gain_k_ * (factor - 1);                   // (6)
      if (std::abs(used - mz_) <= dead_band_) factor = 1;  // (7)
    }
    override_ = std::clamp(factor * override_, min_override_, kMaxOverridePct);  // (4)
    return {used, factor, override_};
  }

  double override_pct() const { return override_; }
  const FeedOverrideParams& params() const { return params_; }

 private:
  /// (5): the mean of the last d loads (of all loads so far while fewer
  /// than d have come). The running sum is recomputed from the buffer each
  /// time the ring wraps, so rounding errors cannot accumulate over a long
  /// run: O(d) work every d samples.
  double average(double load) {
    sum_ += load - ring_[next_];
    ring_[next_] = load;
    if (filled_ < ring_.size()) ++filled_;
    if (++next_ == ring_.size()) {
      next_ = 0;
      resum();
    }
    return sum_ / static_cast<double>(filled_);
  }
  void resum();

  FeedOverrideParams params_;
  bool modified_;
  double mz_, gain_k_, dead_band_, min_override_;
  double override_;
  std::vector<double> ring_;
  std::size_t next_ = 0, filled_ = 0;
  double sum_ = 0;
};

}  // namespace tk::machining
