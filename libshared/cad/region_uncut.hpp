/// @file region_uncut.hpp
/// @brief The stretches of a drawing a round tool cannot reach: material
/// left where the tool's contour stays farther than its radius.
#pragma once

#include <vector>

#include "cad/loops.hpp"
#include "cad/region_distance.hpp"
#include "cad/region_offset.hpp"

namespace tk::cad {

/// Points of the drawing farther than R (+ the report threshold) from the
/// tool's contour (`contour`, an index over it; null: no contour, all is
/// uncut): material the tool cannot reach. Sampled every R / 8 along each
/// element; the deepest point of a span is then refined by a
/// golden-section search between its neighbouring samples.
std::vector<UncutSpan> find_uncut(const std::vector<Loop>& drawn, const RegionIndex* contour, double radius,
                                  const OffsetOptions& options);

}  // namespace tk::cad
