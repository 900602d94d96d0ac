/// @file sample_grid.hpp
/// @brief The sample points of fuzzylite's discrete Centroid for one output
/// range, kept with a scratch row so that a centroid costs no allocation and
/// touches only the samples under the fired terms.
#pragma once

#include <span>
#include <vector>

#include "fuzzy/centroid.hpp"

namespace tk::fuzzy {

class SampleGrid {
 public:
  SampleGrid(double min, double max, int resolution);

  /// As discrete_centroid(); the same sample points and the same sums, in
  /// another order of addition (the last bits may differ from fuzzylite's).
  CentroidResult centroid(std::span<const ImpliedTerm> terms, Implication implication);

  int resolution() const { return static_cast<int>(x_.size()); }

 private:
  double min_, dx_;
  std::vector<double> x_;  ///< x_i = min + (i + 0.5) dx, as fuzzylite computes it
  std::vector<double> y_;  ///< the aggregate at x_i, scratch
};

}  // namespace tk::fuzzy
