/// @file region_uncut.hpp
/// @brief The stretches of a drawing a round tool cannot reach: material
/// left where the tool's contour stays farther than its radius.
#pragma once

#include <cstddef>
#include <vector>

#include "cad/loops.hpp"
#include "cad/region_distance.hpp"
#include "cad/region_offset.hpp"

namespace tk::cad {

/// How many exact gaps the uncut search computed, by stage: by a search
/// of the contour's index, or, where one element is known to be nearest
/// throughout (a slot's floor), as that element's distance. For tests and
/// measurements.
struct UncutQueryCounts {
  std::size_t samples = 0;   ///< points sampled along the drawing
  std::size_t sampling = 0;  ///< exact answers to tell uncut samples from cut ones
  std::size_t deepest = 0;   ///< more, to find each span's deepest sample
  std::size_t refining = 0;  ///< the golden-section search's
};

/// Points of the drawing farther than R (+ the report threshold) from the
/// tool's contour (`contour`, an index over it; null: no contour, all is
/// uncut): material the tool cannot reach. Sampled every R / 8 along each
/// element; the deepest point of a span is then refined by a
/// golden-section search between its neighbouring samples. The answer is
/// that of every sample's exact distance, though most samples are settled
/// by bounds (the distance is 1-Lipschitz along the drawing). `counts`,
/// when given, receives the number of exact distances asked.
std::vector<UncutSpan> find_uncut(const std::vector<Loop>& drawn, const RegionIndex* contour, double radius,
                                  const OffsetOptions& options, UncutQueryCounts* counts = nullptr);

}  // namespace tk::cad
