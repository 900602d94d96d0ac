/// @file region_index_dominance.cpp
/// @brief The lists' pruning by dominance (the Dominance test, in
/// region_index_impl.hpp) for a cell's or a leaf's list; tree_within()
/// applies the same test to the tree's boxes.
#include <algorithm>
#include <cmath>

#include "cad/region_index_impl.hpp"

namespace tk::cad {

Dominance RegionIndex::Impl::dominance(Point c, double half, Nearest nearest) const {
  const std::uint32_t f = nearest.element;
  const Point q = nearest_on(kernels[f], &ends[2 * f], c);
  // Beyond the rounding of the distances compared (about nearest.distance from the square).
  const double margin = 4 * rounding + 1e-12 * (nearest.distance + half);
  return Dominance({c.x - half, c.y - half, c.x + half, c.y + half}, q, margin);
}

void RegionIndex::Impl::drop_dominated(std::vector<std::uint32_t>& list, Point c, double half, Nearest nearest) const {
  const Dominance test = dominance(c, half, nearest);
  const auto kept = std::remove_if(list.begin(), list.end(), [&](std::uint32_t e) {
    return e != nearest.element && test.dominated(kernels[e]);  // (the nearest is never dominated; spared its test)
  });
  list.erase(kept, list.end());
}

}  // namespace tk::cad
