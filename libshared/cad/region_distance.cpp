/// @file region_distance.cpp
/// @brief Signed distance to a region bounded by lines and arcs.
///
/// The index is a two-level grid over the boundary's box, enlarged by a
/// quarter on each side: about one cell per element, each cell split into
/// leaves (a power of two a side) until about one element touches a leaf
/// and few may be nearest to its points (up to 4 x 4 leaves for that). Each
/// leaf keeps
///  - the elements that may be nearest to one of its points: those within
///    the centre's nearest distance plus a leaf diagonal, which is close to
///    the elements whose Voronoi regions meet the leaf once leaves are
///    small (rather than pruning a larger leaf's list again at its
///    quarters, which cost more to build). The lists come top down (see
///    region_index_cells.cpp) so the build grows as about n log n. Each
///    cell's list, and a leaf's longer than 16, then drops the elements
///    dominated over its square: farther from each of its points than the
///    point of the centre's nearest element nearest the centre (the test
///    asks four corners; see Dominance). A cell with too many candidates
///    by distance (far from the boundary) takes its list from the tree
///    less the dominated; one with too many still (deep inside a finely
///    divided outline) keeps none, and its queries use the tree.
///    They are sorted by distance from the centre, the first four kept in
///    the leaf's own cache line, and a query stops once the triangle
///    inequality rules out the rest. Lists are capped; a query that
///    runs off a capped list finishes in a box tree over the elements,
///    as do queries outside the grid;
///  - a reference point clear of the boundary, whether it is inside (by
///    the same ray test as brute force at the first leaf of its tile, then
///    from leaf to leaf by the crossing test below), and the elements that
///    may touch the leaf: the query's inside flag is the reference point's,
///    flipped once per crossing of the short segment from there to the
///    query point.
/// Cells come in tiles of 8 x 8, each built whole by the first query that
/// lands in it (a tile depends on the boundary alone, so the answers do not
/// depend on which tiles are built, nor in what order).
/// The crossing tests share their conventions and their left_of() calls
/// with the ray test, so the two agree exactly wherever the query point is.
#include "cad/region_distance.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "cad/region_index_impl.hpp"
#include "cad/segment_geometry.hpp"

namespace tk::cad {

/// The squared distances from p to a Wide node's four rectangles (less a
/// relative margin for an oriented one's projections, whose rounding grows
/// with p's distance from the part). Two children at a time where SSE2 is
/// there (every x86-64): the same operations, so the same bits.
inline void RegionIndex::Impl::child_distances(const Wide& node, Point p, double* box2) {
#if defined(__SSE2__)
  const __m128d x = _mm_set1_pd(p.x), y = _mm_set1_pd(p.y), zero = _mm_setzero_pd();
  const auto outside = [&](const double* lo, const double* hi, __m128d at) {
    return _mm_max_pd(_mm_max_pd(_mm_sub_pd(_mm_load_pd(lo), at), _mm_sub_pd(at, _mm_load_pd(hi))), zero);
  };
  for (std::size_t k = 0; k < 4; k += 2) {
    __m128d u = x, v = y;
    if (node.oriented) {
      const __m128d ux = _mm_load_pd(node.ux + k), uy = _mm_load_pd(node.uy + k);
      u = _mm_add_pd(_mm_mul_pd(ux, x), _mm_mul_pd(uy, y));
      v = _mm_sub_pd(_mm_mul_pd(ux, y), _mm_mul_pd(uy, x));
    }
    const __m128d du = outside(node.lo_u + k, node.hi_u + k, u), dv = outside(node.lo_v + k, node.hi_v + k, v);
    __m128d d2 = _mm_add_pd(_mm_mul_pd(du, du), _mm_mul_pd(dv, dv));
    if (node.oriented) d2 = _mm_mul_pd(d2, _mm_set1_pd(1 - 1e-12));
    _mm_store_pd(box2 + k, d2);
  }
#else
  for (std::size_t k = 0; k < 4; ++k) {
    double u = p.x, v = p.y;
    if (node.oriented) u = node.ux[k] * p.x + node.uy[k] * p.y, v = node.ux[k] * p.y - node.uy[k] * p.x;
    const double du = std::max(std::max(node.lo_u[k] - u, u - node.hi_u[k]), 0.0);
    const double dv = std::max(std::max(node.lo_v[k] - v, v - node.hi_v[k]), 0.0);
    box2[k] = node.oriented ? (du * du + dv * dv) * (1 - 1e-12) : du * du + dv * dv;
  }
#endif
}

void RegionIndex::Impl::tree_nearest(Point p, double& best2, std::uint32_t& best) const {
  // Each child waits with its box's distance, computed once (when its
  // parent ordered its children). Not std::pair: its constructor zeroed the
  // whole stack on every call (6 % of the uncut search's time in here).
  struct Waiting {
    std::uint32_t child, count;
    double box2;
  };
  Waiting stack[128];  // a Wide level adds three at most; there are under 16
  std::size_t top = 0;
  stack[top++] = {0, 0, 0.0};
  while (top > 0) {
    const Waiting w = stack[--top];
    if (w.box2 > best2) continue;  // not >=: an equally near element may have a lower index
    if (w.child & kLeafChild) {
      const std::uint32_t first = w.child & ~kLeafChild;
      for (std::uint32_t i = first; i < first + w.count; ++i) {
        const double d2 = distance2(ordered_kernels[i], p);
        if (nearer(d2, order[i], best2, best)) best2 = d2, best = order[i];
      }
      continue;
    }
    const Wide& node = wide[w.child];
    alignas(16) double box2[4];
    child_distances(node, p, box2);
    // The children within reach, sorted into the stack in place, the
    // farthest deepest (the nearest is popped first). In place: copied from
    // a small array, the copy was a rep movs, 60 % of this function's time.
    const std::size_t base = top;
    for (std::size_t k = 0; k < 4; ++k) {
      if (node.child[k] == kNoChild || box2[k] > best2) continue;
      std::size_t j = top++;
      for (; j > base && stack[j - 1].box2 < box2[k]; --j) stack[j] = stack[j - 1];
      stack[j] = {node.child[k], node.count[k], box2[k]};
    }
  }
}

bool RegionIndex::Impl::tree_within(Point p, double radius, std::vector<std::uint32_t>& out, std::size_t cap,
                                    const Dominance* less, std::size_t visits) const {
  const double r2 = radius * radius;
  std::uint32_t stack[128];
  std::size_t top = 0;
  stack[top++] = 0;
  while (top > 0) {
    if (visits-- == 0) return false;
    const std::uint32_t index = stack[--top];
    const Node& node = nodes[index];
    if (box_distance2(node.box, p) > r2 || (less && less->dominated(node.box))) continue;
    if (!less && box_far2(node.box, p) <= r2) {
      // Every element of a box within the radius is: past the cap, stop
      // (a wide cell's window fails fast); else take them all without a
      // distance each (a subtree's elements are a run of `order`, starting
      // at its leftmost leaf's).
      const std::uint32_t count = node.count > 0 ? node.count : node.first;
      if (out.size() + count > cap) return false;
      std::uint32_t leftmost = index;
      while (nodes[leftmost].count == 0) ++leftmost;
      const auto run = order.begin() + nodes[leftmost].first;
      out.insert(out.end(), run, run + count);
      continue;
    }
    if (node.count == 0) {
      stack[top++] = node.right;
      stack[top++] = index + 1;
      continue;
    }
    for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
      const std::uint32_t e = order[i];
      if (distance2(kernels[e], p) <= r2 && !(less && less->dominated(kernels[e]))) out.push_back(e);
    }
    if (out.size() > cap) return false;
  }
  return true;
}

bool RegionIndex::Impl::tree_ray_parity(Point p) const {
  bool odd = false;
  std::uint32_t stack[128];
  std::size_t top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const std::uint32_t index = stack[--top];
    const Node& node = nodes[index];
    // The element, its chord and the region between them lie in the box.
    if (node.box.max_x < p.x || node.box.min_y > p.y || node.box.max_y < p.y) continue;
    if (node.count == 0) {
      stack[top++] = node.right;
      stack[top++] = index + 1;
      continue;
    }
    for (std::uint32_t i = node.first; i < node.first + node.count; ++i)
      odd ^= ray_parity(kernels[order[i]], ends[2 * order[i]], ends[2 * order[i] + 1], p);
  }
  return odd;
}

double RegionIndex::Impl::leaf_nearest(const Tile& t, std::size_t leaf, Point centre, Point p,
                                       std::uint32_t& best) const {
  const Leaf& l = t.leaves[leaf];
  const double from_centre = std::sqrt((p.x - centre.x) * (p.x - centre.x) + (p.y - centre.y) * (p.y - centre.y));
  // Start from a bound the nearest element beats: |p - e| <= |c - e| + |p - c|.
  const double bound = (double(l.nearest) + from_centre) * (1 + 1e-12);
  double best2 = bound * bound + std::numeric_limits<double>::min();
  best = UINT32_MAX;
  // |p - e| >= |c - e| - |p - c|: nothing further down the list can win,
  // nor tie (less a rounding margin, so that an element whose computed
  // distance ties with the best is still examined for the tie rule).
  const auto ruled_out = [&](double key) { return cannot_win(key - from_centre - rounding, best2); };
  const auto beaten = [&](const Candidate& c) { return ruled_out(double(c.key)); };
  const auto try_element = [&](std::uint32_t e) {
    const double d2 = distance2(kernels[e], p);
    if (nearer(d2, e, best2, best)) best2 = d2, best = e;
  };
  bool done = false;
  for (std::size_t i = 0; i < kHead && !(done = beaten(l.head[i])); ++i) try_element(l.head[i].element);
  const Candidate* it = t.candidates.data() + l.candidates;
  const Candidate* const end = t.candidates.data() + t.leaves[leaf + 1].candidates;
  for (; !done && it != end && !(done = beaten(*it)); ++it) try_element(it->element);
  // A wide leaf (no list) or one whose list ran out: the tree, searched
  // within the bound (which spares it most of the boundary far off).
  if (best == UINT32_MAX || (!done && !ruled_out(double(l.complete)))) tree_nearest(p, best2, best);
  if (best == UINT32_MAX) best2 = kInf, tree_nearest(p, best2, best);  // not reached; rounding guard
  return best2;
}

RegionIndex::~RegionIndex() = default;
RegionIndex::RegionIndex(RegionIndex&&) noexcept = default;
RegionIndex& RegionIndex::operator=(RegionIndex&&) noexcept = default;

const std::vector<Segment>& RegionIndex::elements() const { return impl_->segments; }
std::size_t RegionIndex::loop_of(std::size_t element) const { return impl_->loop_of.at(element); }

bool RegionIndex::Impl::locate(Point p, bool build, const Tile*& tile, std::size_t& leaf, Point& leaf_centre) const {
  // Signed conversions: the unsigned ones cost a branch each (the grid has under 2^23 cells a side).
  const double fx = (p.x - ox) * inv_size, fy = (p.y - oy) * inv_size;
  if (!(fx >= 0 && fy >= 0 && fx < double(std::int64_t(nx)) && fy < double(std::int64_t(ny)))) return false;
  const auto ix = std::size_t(static_cast<std::int64_t>(fx)), iy = std::size_t(static_cast<std::int64_t>(fy));
  const std::size_t tx = ix / kBlockCells, ty = iy / kBlockCells;
  tile = tiles[ty * tiles_x + tx].load(std::memory_order_acquire);
  if (!tile) {
    if (!build) return false;
    tile = &tile_at(tx, ty);
  }
  const Coarse& coarse = tile->coarse[(iy - ty * kBlockCells) * kBlockCells + (ix - tx * kBlockCells)];
  const std::uint32_t split = coarse.split;
  std::uint32_t sx = 0, sy = 0;
  if (split > 1) {
    sx = std::min(split - 1, std::uint32_t(static_cast<std::int32_t>((fx - double(std::int64_t(ix))) * split)));
    sy = std::min(split - 1, std::uint32_t(static_cast<std::int32_t>((fy - double(std::int64_t(iy))) * split)));
  }
  leaf = coarse.first_leaf + sy * split + sx;
  leaf_centre = centre(ix, iy, split, sx, sy);
  return true;
}

RegionQuery RegionIndex::query(Point p) const {
  const Impl& m = *impl_;
  if (m.segments.empty()) return {kInf, p, 0};
  if (!m.grid_ready.load(std::memory_order_acquire)) impl_->ensure_grid();
  std::uint32_t best = 0;
  const Impl::Tile* tile = nullptr;
  std::size_t leaf = 0;
  Point leaf_centre;
  if (!m.locate(p, true, tile, leaf, leaf_centre)) {
    double best2 = kInf;
    m.tree_nearest(p, best2, best);
    return m.answer(p, best2, best, m.tree_ray_parity(p));
  }
  const double best2 = m.leaf_nearest(*tile, leaf, leaf_centre, p, best);
  const Impl::Leaf& l = tile->leaves[leaf];
  bool inside = l.inside;
  for (std::uint32_t i = l.covers; i < tile->leaves[leaf + 1].covers; ++i) {
    const Impl::Cover& c = tile->covers[i];
    inside ^= segment_parity(m.kernels[c.packed & Impl::kElementBits], c.start, c.end, c.packed & Impl::kArc,
                             c.packed & Impl::kCcw, l.ref, p, c.packed & Impl::kRefLeft, c.packed & Impl::kRefLens);
  }
  return m.answer(p, best2, best, inside);
}

RegionQuery RegionIndex::nearest(Point p, std::size_t hint) const {
  const Impl& m = *impl_;
  if (m.segments.empty()) return {kInf, p, 0};
  std::uint32_t best = 0;
  const Impl::Tile* tile = nullptr;
  std::size_t leaf = 0;
  Point leaf_centre;
  if (m.grid_ready.load(std::memory_order_acquire) && m.locate(p, false, tile, leaf, leaf_centre)) {
    const double best2 = m.leaf_nearest(*tile, leaf, leaf_centre, p, best);  // sets best: not in answer()'s arguments
    return m.answer(p, best2, best, false);
  }
  // The hint's own distance bounds the search from the start; the tie rule
  // still names the lowest of equally near elements.
  double best2 = kInf;
  if (hint < m.segments.size()) best = static_cast<std::uint32_t>(hint), best2 = distance2(m.kernels[best], p);
  m.tree_nearest(p, best2, best);
  return m.answer(p, best2, best, false);
}

double RegionIndex::distance_to(std::size_t element, Point p) const {
  return std::sqrt(distance2(impl_->kernels.at(element), p));
}

RegionIndex::Nearby::Nearby(const RegionIndex& index, Point centre, double spread, double reach)
    : index_(&index), centre_(centre), spread_(spread), reach2_(reach * reach) {
  const Impl& m = *index.impl_;
  if (m.segments.empty() || !(spread >= 0 && reach >= 0 && std::isfinite(spread + reach))) {
    reach2_ = -1;  // every point goes to nearest()
    return;
  }
  // An element nearest to a point within `spread` of the centre, at most
  // `reach` from it, is within reach + spread of the centre.
  const double margin = m.rounding + 1e-12 * (reach + spread);
  std::vector<std::uint32_t> found;
  m.tree_within(centre, reach + spread + margin, found);
  elements_.reserve(found.size());
  for (const std::uint32_t e : found) elements_.push_back({std::sqrt(distance2(m.kernels[e], centre)) - margin, e});
  std::sort(elements_.begin(), elements_.end(),
            [](const Element& a, const Element& b) { return a.from_centre < b.from_centre; });
  // The first is nearest everywhere in the spread when even its farthest
  // (its distance from the centre plus the spread) is nearer than the
  // second's nearest (its distance less the spread) and within reach.
  if (elements_.empty()) return;
  const double farthest = elements_[0].from_centre + 2 * margin + spread;
  if (farthest <= reach && (elements_.size() == 1 || farthest < elements_[1].from_centre - spread))
    sole_ = elements_[0].index;
}

RegionQuery RegionIndex::Nearby::nearest(Point p) const {
  const double dx = p.x - centre_.x, dy = p.y - centre_.y;
  if (!(dx * dx + dy * dy <= spread_ * spread_)) return index_->nearest(p);
  const Impl& m = *index_->impl_;
  double best2 = kInf;
  std::uint32_t best = UINT32_MAX;
  for (const Element& e : elements_) {
    // No nearer than its distance from the centre less p's (the margin is
    // in from_centre): once that rules it out, it rules out every later one.
    if (cannot_win(e.from_centre - spread_, best2)) break;
    const double d2 = distance2(m.kernels[e.index], p);
    if (nearer(d2, e.index, best2, best)) best2 = d2, best = e.index;
  }
  if (!(best2 <= reach2_)) return index_->nearest(p);  // farther than promised: the list may lack its nearest
  return m.answer(p, best2, best, false);
}

RegionQuery brute_force_query(const std::vector<Loop>& loops, Point p) {
  double best2 = kInf;
  const Segment* nearest = nullptr;
  std::size_t best = 0, index = 0;
  bool inside = false;
  for (const Loop& loop : loops)
    for (const Segment& s : loop.segments) {
      const Kernel k = make_kernel(s);
      const double d2 = distance2(k, p);
      if (d2 < best2) best2 = d2, best = index, nearest = &s;
      inside ^= ray_parity(k, s.start, s.end, p);
      ++index;
    }
  if (!nearest) return {kInf, p, 0};
  const double d = std::sqrt(best2);
  const Point ends[2] = {nearest->start, nearest->end};
  return {inside ? -d : d, nearest_on(make_kernel(*nearest), ends, p), best};
}

}  // namespace tk::cad
