/// @file region_index_dominance.cpp
/// @brief The lists' pruning by dominance (the Dominance test, in
/// region_index_impl.hpp): from a cell's or a leaf's list, and from the
/// tree for a cell too near too many elements for a list by distance alone.
#include <algorithm>
#include <cmath>

#include "cad/region_index_impl.hpp"

namespace tk::cad {

bool RegionIndex::Impl::tree_undominated(Point c, double reach, const Dominance& test, std::vector<std::uint32_t>& out,
                                         std::size_t cap) const {
  const double reach2 = reach * reach;
  std::uint32_t stack[128];
  std::size_t top = 0, budget = kUndominatedVisits;
  stack[top++] = 0;
  while (top > 0) {
    if (--budget == 0) return false;
    const std::uint32_t index = stack[--top];
    const Node& node = nodes[index];
    if (box_distance2(node.box, c) > reach2 || test.dominated(node.box)) continue;
    if (node.count == 0) {
      stack[top++] = node.right;
      stack[top++] = index + 1;
      continue;
    }
    for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
      const std::uint32_t e = order[i];
      if (distance2(kernels[e], c) <= reach2 && !test.dominated(kernels[e])) out.push_back(e);
    }
    if (out.size() > cap) return false;
  }
  return true;
}

Dominance RegionIndex::Impl::dominance(Point c, double half, Nearest nearest) const {
  const std::uint32_t f = nearest.element;
  const Point q = nearest_on(kernels[f], &ends[2 * f], c);
  // Beyond the rounding of the distances compared (about nearest.distance from the square).
  const double margin = 4 * rounding + 1e-12 * (nearest.distance + half);
  return Dominance({c.x - half, c.y - half, c.x + half, c.y + half}, q, margin);
}

void RegionIndex::Impl::drop_dominated(std::vector<std::uint32_t>& list, std::size_t from, Point c, double half,
                                       Nearest nearest) const {
  const Dominance test = dominance(c, half, nearest);
  const auto kept = std::remove_if(list.begin() + std::ptrdiff_t(from), list.end(),
                                   [&](std::uint32_t e) { return e != nearest.element && test.dominated(kernels[e]); });
  list.erase(kept, list.end());
}

}  // namespace tk::cad
