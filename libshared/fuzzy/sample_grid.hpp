/// @file sample_grid.hpp
/// @brief The sample points of fuzzylite's discrete Centroid for one output
/// range, with each output term prepared once (its inverse slopes and the
/// samples it can reach), so that a centroid costs no allocation, no
/// division, and touches only the samples under the fired terms.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "fuzzy/centroid.hpp"

namespace tk::fuzzy {

/// An output term ready for sampling.
struct GridTerm {
  double a = 0, d = 0;                ///< the support [a, d]
  double rise = 0, fall = 0;          ///< 1 / (b - a) and 1 / (d - c); +inf for a vertical edge
  std::ptrdiff_t first = 0, end = 0;  ///< the samples [first, end) that can be inside [a, d]
};

class SampleGrid {
 public:
  SampleGrid(double min, double max, int resolution);

  GridTerm prepare(const Trapezoid& term) const;

  /// The centroid of the aggregate of terms[i] at levels[i] (a level of 0:
  /// not fired), as discrete_centroid(): the same samples and sums, added in
  /// another order (the last bits may differ from fuzzylite's).
  CentroidResult centroid(std::span<const GridTerm> terms, std::span<const double> levels, Implication implication);
  CentroidResult centroid(std::span<const ImpliedTerm> terms, Implication implication);

  int resolution() const { return static_cast<int>(x_.size()); }

 private:
  double min_, dx_;
  std::vector<double> x_;  ///< x_i = min + (i + 0.5) dx, as fuzzylite computes it
  std::vector<double> y_;  ///< the aggregate at x_i, scratch
  std::vector<std::pair<std::ptrdiff_t, std::ptrdiff_t>> spans_;  ///< scratch: sample spans to add up
};

}  // namespace tk::fuzzy
