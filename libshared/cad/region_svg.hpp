/// @file region_svg.hpp
/// @brief The region as an SVG drawing: the part, the prohibited region and
/// its contour, what the chaining and the offset found, a legend naming
/// each layer drawn and a scale bar.
#pragma once

#include <string>
#include <vector>

#include "cad/loops.hpp"
#include "cad/region_offset.hpp"

namespace tk::cad {

struct SvgLayers {
  const std::vector<Loop>* drawn = nullptr;    ///< thin black
  const std::vector<Segment>* open = nullptr;  ///< grey, dashed
  const std::vector<Loop>* region = nullptr;   ///< filled, the prohibited region
  const std::vector<LooseEnd>* loose_ends = nullptr;
  const std::vector<UncutSpan>* uncut = nullptr;
  std::string title;
};

/// Writes the drawing to `path` (Error when it cannot), y up, 1 mm a unit;
/// the legend (layers with something in them) and the scale bar stand below it.
void write_region_svg(const std::string& path, const SvgLayers& layers);

}  // namespace tk::cad
