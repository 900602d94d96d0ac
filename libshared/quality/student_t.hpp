/// @file student_t.hpp
/// @brief Critical values of Student's t for a test repeated at every part:
/// Boost.Math's quantile once per degree of freedom, then a table lookup, so
/// a stream filter pays O(1) per part.
#pragma once

#include <cstddef>
#include <vector>

namespace tk::quality {

enum class Sidedness { one, two };

/// t quantile with upper-tail probability `tail` (0 < tail < 0.5) and `df` > 0
/// degrees of freedom, from Boost.Math.
double student_t_upper_quantile(double tail, double df);

/// The critical value t_{α,k}: exceeded by |T| with probability α (two-sided)
/// or by T with probability α (one-sided).
class StudentCriticalValues {
 public:
  StudentCriticalValues(double alpha, Sidedness sidedness);

  /// t critical at `df` ≥ 1 degrees of freedom. Values up to kTableLimit are
  /// Boost's quantile, computed on first use and kept; beyond it the
  /// Cornish-Fisher series in 1/df (Abramowitz & Stegun 26.7.5), whose
  /// error there is below 1e-15.
  double at(std::size_t df) const {
    if (df < table_.size() && table_[df] > 0) return table_[df];
    return compute(df);
  }

  static constexpr std::size_t kTableLimit = 1 << 14;

 private:
  double compute(std::size_t df) const;

  double tail_;             ///< upper-tail probability: α or α/2
  double normal_quantile_;  ///< z at the same tail, for the series
  double series_[4];        ///< its coefficients of 1/ν .. 1/ν⁴, which depend on z only
  mutable std::vector<double> table_;
};

}  // namespace tk::quality
