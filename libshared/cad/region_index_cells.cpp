/// @file region_index_cells.cpp
/// @brief Each grid cell's window: the elements that may be nearest to one
/// of its points, found top down so that the build grows as n log n.
///
/// An element that is nearest to a point p of a square of half side h
/// around c lies within d(c) + 2 sqrt(2) h of c (|e - c| <= |e - p| + |p - c|
/// <= d(p) + sqrt(2) h <= d(c) + 2 sqrt(2) h). Applied to a block of cells
/// with the box tree, then to its quarters with the block's list only (the
/// nearest to a quarter's centre is in it), down to the cells, each element
/// is examined a few times per level instead of once per cell; each
/// cell's window then drops the elements dominated over the cell. A block
/// whose window holds more than kWideWindow elements (far from the
/// boundary, or deep inside a finely divided outline, where many are
/// nearly equidistant) is asked again quarter by quarter; a cell that
/// still has that many asks the tree for those not dominated over it, and
/// past kUndominatedWindow of them (or kUndominatedVisits of the tree's
/// nodes) is wide: its leaves keep no list and their queries use the tree.
#include <algorithm>
#include <cmath>

#include "cad/region_index_impl.hpp"

namespace tk::cad {

RegionIndex::Impl::Nearest RegionIndex::Impl::prune(Workspace& w, Point c, double half, const std::uint32_t* in,
                                                    std::size_t count, std::vector<std::uint32_t>& out) const {
  std::vector<double>& far2 = w.far2;
  if (far2.size() < count) far2.resize(count);
  double nearest2 = kInf;
  std::uint32_t nearest_element = 0;
  for (std::size_t i = 0; i < count; ++i) {
    far2[i] = distance2(kernels[in[i]], c);
    if (nearer(far2[i], in[i], nearest2, nearest_element)) nearest2 = far2[i], nearest_element = in[i];
  }
  const double nearest = std::sqrt(nearest2);
  const double reach = (nearest + 2 * std::sqrt(2.0) * half) * (1 + 1e-9);
  for (std::size_t i = 0; i < count; ++i)
    if (far2[i] <= reach * reach) out.push_back(in[i]);
  return {nearest, nearest_element};
}

/// Cells [x0, x0 + span) x [y0, y0 + span) from `list`, their block's window.
void RegionIndex::Impl::split_block(Workspace& w, std::size_t x0, std::size_t y0, std::size_t span,
                                    std::vector<std::uint32_t>& list, Nearest nearest) const {
  if (span == 1) {
    // Less those that cannot win anywhere in the cell: cheap once a cell,
    // and it spares every leaf's list and the leaves themselves.
    if (list.size() > 1) drop_dominated(list, centre(x0, y0, 1, 0, 0), size / 2, nearest);
    store_window(w, x0, y0, list, nearest.distance, false);
    return;
  }
  const std::size_t half_span = span / 2;
  std::vector<std::uint32_t> quarter;
  for (std::size_t dy = 0; dy < 2; ++dy)
    for (std::size_t dx = 0; dx < 2; ++dx) {
      const std::size_t x = x0 + dx * half_span, y = y0 + dy * half_span;
      if (x >= nx || y >= ny) continue;
      quarter.clear();
      const Point c{ox + (double(x) + double(half_span) / 2) * size, oy + (double(y) + double(half_span) / 2) * size};
      split_block(w, x, y, half_span, quarter,
                  prune(w, c, double(half_span) * size / 2, list.data(), list.size(), quarter));
    }
}

/// The block's window from the tree; quartered when too wide.
void RegionIndex::Impl::ask_block(Workspace& w, std::size_t x0, std::size_t y0, std::size_t span) const {
  if (x0 >= nx || y0 >= ny) return;
  const Point c{ox + (double(x0) + double(span) / 2) * size, oy + (double(y0) + double(span) / 2) * size};
  double best2 = kInf;
  std::uint32_t best = 0;
  tree_nearest(c, best2, best);
  const double nearest = std::sqrt(best2);
  const double reach = (nearest + std::sqrt(2.0) * double(span) * size) * (1 + 1e-9);
  std::vector<std::uint32_t> list;
  if (tree_within(c, reach, list, kWideWindow)) {
    split_block(w, x0, y0, span, list, {nearest, best});
    return;
  }
  if (span > 1) {
    const std::size_t half_span = span / 2;
    for (std::size_t dy = 0; dy < 2; ++dy)
      for (std::size_t dx = 0; dx < 2; ++dx) ask_block(w, x0 + dx * half_span, y0 + dy * half_span, half_span);
    return;
  }
  // A cell with too many near enough (far from the boundary, or deep inside
  // a finely divided outline): the tree again, less the elements dominated over the cell.
  list.clear();
  const Dominance less = dominance(c, size / 2, {nearest, best});
  if (tree_within(c, reach, list, kUndominatedWindow, &less, kUndominatedVisits)) {
    store_window(w, x0, y0, list, nearest, true);
  } else {
    CellWindow& window = w.windows[w.local(x0, y0)];
    window.wide = true, window.nearest = nearest;
  }
}

void RegionIndex::Impl::store_window(Workspace& w, std::size_t x, std::size_t y, const std::vector<std::uint32_t>& list,
                                     double nearest, bool sparse) const {
  CellWindow& window = w.windows[w.local(x, y)];
  window.first = static_cast<std::uint32_t>(w.window_elements.size());
  window.count = static_cast<std::uint32_t>(list.size());
  window.nearest = nearest, window.sparse = sparse;
  w.window_elements.insert(w.window_elements.end(), list.begin(), list.end());
}

/// Crossing parity of the segment from `from` to `to` with `elements`
/// (each counted once): the query's test, with `from` as the reference point.
bool RegionIndex::Impl::chain_parity(Workspace& w, Point from, Point to,
                                     const std::vector<std::uint32_t>& elements) const {
  bool odd = false;
  ++w.mark;
  for (const std::uint32_t e : elements) {
    if (w.stamp[e] == w.mark) continue;
    w.stamp[e] = w.mark;
    const Kernel& k = kernels[e];
    const Point a = ends[2 * e], b = ends[2 * e + 1];
    const bool arc = k.side != 0, from_left = left_of(a, b, from);
    odd ^= segment_parity(k, a, b, arc, k.side > 0, from, to, from_left, arc && in_lens(k, from_left, from));
  }
  return odd;
}

void RegionIndex::Impl::build_inside(Workspace& w, Tile& t) const {
  std::vector<std::uint32_t> elements;
  const auto add_cell = [&](std::size_t x, std::size_t y) {
    for (std::size_t k = touch_first[y * nx + x]; k < touch_first[y * nx + x + 1]; ++k)
      elements.push_back(touches[k].element);
  };
  const auto add_leaf = [&](std::size_t leaf) {
    for (std::uint32_t m = t.leaves[leaf].covers; m < t.leaves[leaf + 1].covers; ++m)
      elements.push_back(t.covers[m].packed & kElementBits);
  };
  // Two neighbouring squares of one size make a rectangle: the segment
  // joining points of theirs stays in it, so only their elements can cross it.
  const auto follow = [&](std::size_t from, std::size_t to) {
    t.leaves[to].inside = t.leaves[from].inside != chain_parity(w, t.leaves[from].ref, t.leaves[to].ref, elements);
  };
  const auto first_leaf = [&](std::size_t x, std::size_t y) { return t.coarse[w.local(x, y)].first_leaf; };
  for (std::size_t y = w.y0; y < std::min(ny, w.y0 + kBlockCells); ++y)
    for (std::size_t x = w.x0; x < std::min(nx, w.x0 + kBlockCells); ++x) {
      const std::size_t first = first_leaf(x, y), split = t.coarse[w.local(x, y)].split;
      if (x == w.x0 && y == w.y0) {
        t.leaves[first].inside = tree_ray_parity(t.leaves[first].ref);
      } else {  // from the cell to the left, or, in the tile's first column, the one below
        const std::size_t from_x = x > w.x0 ? x - 1 : x, from_y = x > w.x0 ? y : y - 1;
        elements.clear();
        add_cell(from_x, from_y), add_cell(x, y);
        follow(first_leaf(from_x, from_y), first);
      }
      for (std::size_t j = 0; j < split; ++j)
        for (std::size_t i = j == 0 ? 1 : 0; i < split; ++i) {
          const std::size_t leaf = first + j * split + i, from = i > 0 ? leaf - 1 : leaf - split;
          elements.clear();
          add_leaf(from), add_leaf(leaf);
          follow(from, leaf);
        }
    }
}

}  // namespace tk::cad
