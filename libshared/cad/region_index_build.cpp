/// @file region_index_build.cpp
/// @brief Building RegionIndex: the box tree, the two-level grid tile by
/// tile, each leaf's candidate list (pruned by quartering) and reference point.
#include <algorithm>
#include <cmath>

#include "cad/region_index_impl.hpp"
#include "cad/segment_geometry.hpp"
#include "io/error.hpp"

namespace tk::cad {
namespace {

// A child's rectangle is taken along its chord where that is this much smaller
// than its box: a stretch of a curve or a slanted line. (Elsewhere the box
// serves as well, and a node of boxes alone is searched without projections.)
constexpr double kOrientedArea = 0.2;

/// The first and last of n cells of side `step` from `origin` that [lo, hi] meets (clamped to the row).
std::pair<std::size_t, std::size_t> cells_spanned(double lo, double hi, double origin, double step, std::size_t n) {
  const auto at = [&](double x) {
    return std::size_t(std::clamp(std::floor((x - origin) / step), 0.0, double(n - 1)));
  };
  return {at(lo), at(hi)};
}

}  // namespace

std::uint32_t RegionIndex::Impl::build_node(std::uint32_t begin, std::uint32_t end) {
  const auto index = static_cast<std::uint32_t>(nodes.size());
  nodes.emplace_back();
  Box box = boxes[order[begin]], centres{kInf, kInf, -kInf, -kInf};
  for (std::uint32_t i = begin; i < end; ++i) {
    const Box& b = boxes[order[i]];
    box = merge(box, b);
    const Point c{(b.min_x + b.max_x) / 2, (b.min_y + b.max_y) / 2};
    centres = merge(centres, {c.x, c.y, c.x, c.y});
  }
  nodes[index].box = box;
  if (end - begin <= 4) {
    nodes[index].first = begin, nodes[index].count = end - begin;
    return index;
  }
  // Median split of the box centres along the longer side.
  const bool by_x = centres.max_x - centres.min_x >= centres.max_y - centres.min_y;
  const std::uint32_t mid = begin + (end - begin) / 2;
  std::nth_element(order.begin() + begin, order.begin() + mid, order.begin() + end,
                   [&](std::uint32_t a, std::uint32_t b) {
                     const Box &p = boxes[a], &q = boxes[b];
                     return by_x ? p.min_x + p.max_x < q.min_x + q.max_x : p.min_y + p.max_y < q.min_y + q.max_y;
                   });
  build_node(begin, mid);
  const std::uint32_t right = build_node(mid, end);
  nodes[index].right = right, nodes[index].first = end - begin;
  return index;
}

std::uint32_t RegionIndex::Impl::build_wide(std::uint32_t node, Frame& whole) {
  std::uint32_t below[4];
  std::size_t n = 0;
  const auto take = [&](std::uint32_t b) {
    if (nodes[b].count > 0) {
      below[n++] = b;
    } else {
      below[n++] = b + 1, below[n++] = nodes[b].right;
    }
  };
  if (nodes[node].count > 0) {  // a leaf root
    below[n++] = node;
  } else {
    take(node + 1), take(nodes[node].right);
  }
  const auto index = static_cast<std::uint32_t>(wide.size());
  wide.emplace_back();
  // The whole node's rectangle comes from its children's: their chords' ends and their corners.
  Point chord_ends[8], corners[16];
  std::size_t chord_count = 0, corner_count = 0;
  for (std::size_t k = 0; k < 4; ++k) {
    Frame f;
    std::uint32_t child = kNoChild, count = 0;
    if (k < n) {
      const Node& b = nodes[below[k]];
      count = b.count;
      if (b.count > 0) {
        child = kLeafChild | b.first;
        Point leaf_ends[8], points[16];
        std::size_t point_count = 0;
        for (std::uint32_t i = 0; i < b.count; ++i) {
          const std::uint32_t e = order[b.first + i];
          leaf_ends[2 * i] = ends[2 * e], leaf_ends[2 * i + 1] = ends[2 * e + 1];
          if (kernels[e].side == 0) {  // a line lies between its ends
            points[point_count++] = ends[2 * e], points[point_count++] = ends[2 * e + 1];
          } else {  // an arc within its box
            const Box& c = boxes[e];
            for (const Point q :
                 {Point{c.min_x, c.min_y}, Point{c.max_x, c.min_y}, Point{c.min_x, c.max_y}, Point{c.max_x, c.max_y}})
              points[point_count++] = q;
          }
        }
        f = frame(leaf_ends, 2 * b.count, points, point_count, b.box);
      } else {
        child = build_wide(below[k], f);
      }
      chord_ends[chord_count++] = f.a, chord_ends[chord_count++] = f.b;
      for (const double u : {f.lo_u, f.hi_u})
        for (const double v : {f.lo_v, f.hi_v}) corners[corner_count++] = {u * f.ux - v * f.uy, u * f.uy + v * f.ux};
    }
    Wide& w = wide[index];  // after the recursion, which may have moved it
    w.ux[k] = f.ux, w.uy[k] = f.uy, w.lo_u[k] = f.lo_u, w.hi_u[k] = f.hi_u, w.lo_v[k] = f.lo_v, w.hi_v[k] = f.hi_v;
    w.child[k] = child, w.count[k] = count;
    // u = (1, 0) exactly: a nearly level chord's ux rounds to 1 while its uy is not 0.
    w.oriented = (k > 0 && w.oriented) || f.ux != 1 || f.uy != 0;
  }
  whole = frame(chord_ends, chord_count, corners, corner_count, nodes[node].box);
  return index;
}

RegionIndex::Impl::Frame RegionIndex::Impl::frame(const Point* chord_ends, std::size_t end_count, const Point* points,
                                                  std::size_t point_count, const Box& box) const {
  Frame f{1, 0, box.min_x, box.max_x, box.min_y, box.max_y, chord_ends[0], chord_ends[0]};
  // The chord: the end farthest from the first, and the one farthest from that.
  double widest = 0;
  const auto farthest = [&](Point from, Point& to) {
    widest = 0;
    for (std::size_t i = 0; i < end_count; ++i) {
      const double dx = chord_ends[i].x - from.x, dy = chord_ends[i].y - from.y;
      if (dx * dx + dy * dy > widest) widest = dx * dx + dy * dy, to = chord_ends[i];
    }
  };
  farthest(chord_ends[0], f.a);
  farthest(f.a, f.b);
  if (!(widest > 0)) return f;
  const double chord = std::sqrt(widest);
  Frame along{(f.b.x - f.a.x) / chord, (f.b.y - f.a.y) / chord, kInf, -kInf, kInf, -kInf, f.a, f.b};
  for (std::size_t i = 0; i < point_count; ++i) {
    const Point q = points[i];
    const double u = along.ux * q.x + along.uy * q.y, v = along.ux * q.y - along.uy * q.x;
    along.lo_u = std::min(along.lo_u, u), along.hi_u = std::max(along.hi_u, u);
    along.lo_v = std::min(along.lo_v, v), along.hi_v = std::max(along.hi_v, v);
  }
  // Padded as the boxes are, beyond the projections' (and the corners') rounding.
  const double pad = 2 * rounding;
  along.lo_u -= pad, along.hi_u += pad, along.lo_v -= pad, along.hi_v += pad;
  const double area = (along.hi_u - along.lo_u) * (along.hi_v - along.lo_v);
  return area < kOrientedArea * (box.max_x - box.min_x) * (box.max_y - box.min_y) ? along : f;
}

void RegionIndex::Impl::build_grid() {
  Box all = boxes.front();
  for (const Box& b : boxes) all = merge(all, b);
  const double w = all.max_x - all.min_x, h = all.max_y - all.min_y, extent = std::max(w, h);
  if (!(extent > 0) || !std::isfinite(extent)) return;  // no grid: every query uses the tree
  const double mx = w / 4 + 1e-6 * extent, my = h / 4 + 1e-6 * extent;
  ox = all.min_x - mx, oy = all.min_y - my;
  const double width = w + 2 * mx, height = h + 2 * my;
  const double wanted = std::clamp(kCoarseCellsPerElement * double(segments.size()), 1.0, double(1 << 22));
  size = std::sqrt(width * height / wanted);
  // No cap per side beyond the total's: a long thin part (a comb of
  // 100,000 teeth) capped at 4,096 cells a side got cells of hundreds of
  // elements, whose lists cost their square to refine.
  nx = static_cast<std::size_t>(std::clamp(std::ceil(width / size), 1.0, double(1 << 22)));
  ny = static_cast<std::size_t>(std::clamp(std::ceil(height / size), 1.0, double(1 << 22)));
  size = std::max(width / double(nx), height / double(ny));
  inv_size = 1 / size;
  tiles_x = (nx + kBlockCells - 1) / kBlockCells, tiles_y = (ny + kBlockCells - 1) / kBlockCells;
  tiles = std::make_unique<std::atomic<Tile*>[]>(tiles_x * tiles_y);
  tile_once = std::make_unique<std::once_flag[]>(tiles_x * tiles_y);
  for (std::size_t i = 0; i < tiles_x * tiles_y; ++i) tiles[i].store(nullptr, std::memory_order_relaxed);
  build_touches();
}

/// Which cells each element may touch: elements are cut into pieces of
/// half a cell, each piece's padded box marking cells. A tile's cells then
/// split into leaves (build_covers), and the pieces in them are cut again.
void RegionIndex::Impl::build_touches() {
  const double pad = 1e-6 * size;
  const auto span = [&](double lo, double hi, double origin, std::size_t n) {
    return cells_spanned(lo - pad, hi + pad, origin, size, n);
  };
  struct Mark {
    std::uint32_t cell;
    Touch touch;
  };
  std::vector<Mark> marks;
  for (std::uint32_t e = 0; e < segments.size(); ++e) {
    const double pieces = std::clamp(std::ceil(segment_length(segments[e]) / (size / 2)), 1.0, double(1 << 20));
    for (double i = 0; i < pieces; ++i) {
      const double t0 = i / pieces, t1 = (i + 1) / pieces;
      const Box b = pieces == 1 ? boxes[e] : bounding_box(sub_segment(segments[e], t0, t1));
      const auto [x0, x1] = span(b.min_x, b.max_x, ox, nx);
      const auto [y0, y1] = span(b.min_y, b.max_y, oy, ny);
      for (std::size_t y = y0; y <= y1; ++y)
        for (std::size_t x = x0; x <= x1; ++x) marks.push_back({std::uint32_t(y * nx + x), {e, t0, t1}});
    }
  }
  // By cell, keeping the element order within each (a counting sort).
  touch_first.assign(nx * ny + 1, 0);
  for (const Mark& m : marks) ++touch_first[m.cell + 1];
  for (std::size_t c = 0; c < nx * ny; ++c) touch_first[c + 1] += touch_first[c];
  touches.resize(marks.size());
  std::vector<std::uint32_t> next(touch_first.begin(), touch_first.end() - 1);
  for (const Mark& m : marks) touches[next[m.cell]++] = m.touch;
}

/// The tile's leaves and their cover lists (which elements may touch each
/// leaf): each cell splits into leaves (see below), and its touches are
/// cut again to find theirs.
void RegionIndex::Impl::build_covers(Workspace& w, Tile& t) const {
  const double pad = 1e-6 * size;
  const auto span = [&](double lo, double hi, double origin, double step, std::size_t n) {
    return cells_spanned(lo - pad, hi + pad, origin, step, n);
  };
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;  // (leaf, element)
  std::uint32_t leaf_count = 0;
  for (std::size_t y = w.y0; y < std::min(ny, w.y0 + kBlockCells); ++y)
    for (std::size_t x = w.x0; x < std::min(nx, w.x0 + kBlockCells); ++x) {
      const std::size_t cell = y * nx + x, begin = touch_first[cell], end = touch_first[cell + 1];
      std::size_t distinct = 0;
      for (std::size_t k = begin; k < end; ++k) distinct += k == begin || touches[k].element != touches[k - 1].element;
      // Enough leaves for about kLeafCovers elements touching each, and, up to
      // a point, about kLeafCandidates that may be nearest (roughly as many
      // as Voronoi regions cross the leaf, so in proportion to its width).
      const CellWindow& window = w.windows[w.local(x, y)];
      const double by_covers = std::sqrt(double(distinct) / kLeafCovers);
      // The cell's window is pruned at the cell's square already, so that is
      // what may win there.
      const double may_win = double(window.count);
      const double wanted =
          window.sparse ? by_covers : std::max(by_covers, std::min(may_win / kLeafCandidates, kMaxListSplit));
      // A power of two (the nearer, in ratio), so that leaves' lists come down by quarters.
      const double clamped = std::clamp(std::ceil(wanted), 1.0, 32.0);
      std::uint32_t split = 1;
      while (split * 2 <= clamped) split *= 2;
      if (clamped > std::sqrt(2.0) * split) split *= 2;
      Coarse& coarse = t.coarse[w.local(x, y)];
      coarse = {leaf_count, split};
      leaf_count += split * split;
      const double x0 = ox + double(x) * size, y0 = oy + double(y) * size, step = size / split;
      for (std::size_t k = begin; k < end; ++k) {
        const Touch& touch = touches[k];
        if (split == 1) {
          pairs.emplace_back(coarse.first_leaf, touch.element);
          continue;
        }
        for (std::uint32_t j = 0; j < split; ++j) {
          const double step_t = (touch.t1 - touch.t0) / split;
          const double t0 = touch.t0 + step_t * j, t1 = touch.t0 + step_t * (j + 1);
          const Box b = bounding_box(sub_segment(segments[touch.element], t0, t1));
          if (b.max_x + pad < x0 || b.min_x - pad > x0 + size || b.max_y + pad < y0 || b.min_y - pad > y0 + size)
            continue;
          const auto [sx0, sx1] = span(b.min_x, b.max_x, x0, step, split);
          const auto [sy0, sy1] = span(b.min_y, b.max_y, y0, step, split);
          for (std::size_t sy = sy0; sy <= sy1; ++sy)
            for (std::size_t sx = sx0; sx <= sx1; ++sx)
              pairs.emplace_back(coarse.first_leaf + std::uint32_t(sy * split + sx), touch.element);
        }
      }
    }
  std::stable_sort(pairs.begin(), pairs.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  t.leaves.assign(leaf_count + 1, Leaf{});
  for (const auto& [leaf, e] : pairs)
    ++t.leaves[leaf + 1].covers, t.covers.push_back({ends[2 * e], ends[2 * e + 1], e});
  for (std::size_t i = 0; i < leaf_count; ++i) t.leaves[i + 1].covers += t.leaves[i].covers;
}

/// The lists of the leaves of block [x0, x0 + span)^2 (in leaves) of cell
/// (x, y) into leaf_lists, each quarter's pruned from the block's.
void RegionIndex::Impl::build_leaves(Workspace& w, const Tile& t, std::size_t x, std::size_t y, std::uint32_t x0,
                                     std::uint32_t y0, std::uint32_t span,
                                     const std::vector<std::uint32_t>& list) const {
  const std::uint32_t split = t.coarse[w.local(x, y)].split;
  if (span == 1) {
    w.leaf_lists[y0 * split + x0] = list;
    return;
  }
  const std::uint32_t half_span = span / 2;
  const double step = size / split;
  std::vector<std::uint32_t> quarter;
  for (std::uint32_t dy = 0; dy < 2; ++dy)
    for (std::uint32_t dx = 0; dx < 2; ++dx) {
      const std::uint32_t lx = x0 + dx * half_span, ly = y0 + dy * half_span;
      const Point c{ox + double(x) * size + (lx + half_span / 2.0) * step,
                    oy + double(y) * size + (ly + half_span / 2.0) * step};
      quarter.clear();  // (a wide cell's list is empty: so are its quarters')
      prune(w, c, half_span * step / 2 * (1 + 1e-9), list.data(), list.size(), quarter);
      build_leaves(w, t, x, y, lx, ly, half_span, quarter);
    }
}

/// Leaf (lx, ly) of cell (x, y): its candidates, capped, after the last leaf's.
void RegionIndex::Impl::build_leaf(Workspace& w, Tile& t, std::size_t x, std::size_t y, std::uint32_t lx,
                                   std::uint32_t ly, std::vector<std::uint32_t>& listed) const {
  const Coarse& coarse = t.coarse[w.local(x, y)];
  Leaf& leaf = t.leaves[coarse.first_leaf + ly * coarse.split + lx];
  const Point c = centre(x, y, coarse.split, lx, ly);
  const CellWindow& window = w.windows[w.local(x, y)];
  const Point middle = centre(x, y, 1, 0, 0);
  // A wide cell's leaves: no list, and a bound on the centre's distance for a start.
  const double from_middle = std::hypot(c.x - middle.x, c.y - middle.y);
  // The list (its cell's window pruned at the leaf's square; empty in a
  // wide cell), sorted by distance from the centre.
  std::vector<double>& near = w.near;
  for (const std::uint32_t e : listed) near[e] = std::sqrt(distance2(kernels[e], c));
  std::sort(listed.begin(), listed.end(), [&](std::uint32_t a, std::uint32_t b) {
    return std::pair{near[a], a} < std::pair{near[b], b};
  });
  // (A leaf that is its whole cell has its cell's window, pruned so already.)
  if (listed.size() > kLeafDominance && coarse.split > 1)
    drop_dominated(listed, c, size / coarse.split / 2, {near[listed[0]], listed[0]});
  const double nearest = listed.empty() ? (window.nearest + from_middle) * (1 + 1e-12) : near[listed[0]];
  leaf.nearest = float_above(nearest);
  leaf.complete = window.wide                      ? 0
                  : listed.size() > kMaxCandidates ? float_below(near[listed[kMaxCandidates]])
                                                   : INFINITY;
  for (std::size_t i = 0; i < std::min(listed.size(), kMaxCandidates); ++i) {
    const Candidate entry{float_below(near[listed[i]]), listed[i]};
    if (i < kHead) leaf.head[i] = entry;
    else t.candidates.push_back(entry);
  }
  (&leaf)[1].candidates = static_cast<std::uint32_t>(t.candidates.size());
}

void RegionIndex::Impl::build_lists(Workspace& w, Tile& t) const {
  std::vector<std::uint32_t> list;
  for (std::size_t y = w.y0; y < std::min(ny, w.y0 + kBlockCells); ++y)
    for (std::size_t x = w.x0; x < std::min(nx, w.x0 + kBlockCells); ++x) {
      const CellWindow& window = w.windows[w.local(x, y)];
      list.assign(w.window_elements.begin() + window.first, w.window_elements.begin() + window.first + window.count);
      const std::uint32_t split = t.coarse[w.local(x, y)].split;
      w.leaf_lists.resize(std::size_t(split) * split);
      build_leaves(w, t, x, y, 0, 0, split, list);
      for (std::uint32_t ly = 0; ly < split; ++ly)  // in order: each leaf's lists end the last's
        for (std::uint32_t lx = 0; lx < split; ++lx) build_leaf(w, t, x, y, lx, ly, w.leaf_lists[ly * split + lx]);
    }
}

/// Each leaf's reference point: the first of a few scattered points that
/// keeps clear of the boundary (its inside flag comes later, from
/// build_inside), and its covers' sides of it.
void RegionIndex::Impl::build_refs(Workspace& w, Tile& t) const {
  for (std::size_t y = w.y0; y < std::min(ny, w.y0 + kBlockCells); ++y)
    for (std::size_t x = w.x0; x < std::min(nx, w.x0 + kBlockCells); ++x) {
      const Coarse& coarse = t.coarse[w.local(x, y)];
      const std::uint32_t split = coarse.split;
      const double leaf_size = size / split;
      const CellWindow& window = w.windows[w.local(x, y)];
      const Point middle = centre(x, y, 1, 0, 0);
      for (std::uint32_t ly = 0; ly < split; ++ly)
        for (std::uint32_t lx = 0; lx < split; ++lx) {
          const std::size_t leaf = coarse.first_leaf + ly * split + lx;
          const Point c = centre(x, y, split, lx, ly);
          double clearest = -1;
          Point& ref = t.leaves[leaf].ref;
          std::uint32_t ignored = 0;
          for (int k = 0; k < 8 && clearest < 1e-4 * leaf_size; ++k) {
            const double fx = 0.8 * std::fmod(0.5137 + 0.6180339887 * k, 1.0) - 0.4;
            const double fy = 0.8 * std::fmod(0.5291 + 0.7548776662 * k, 1.0) - 0.4;
            const Point q{c.x + fx * leaf_size, c.y + fy * leaf_size};
            // Far from the boundary a lower bound settles it without a search.
            const double at_least = (window.nearest - std::hypot(q.x - middle.x, q.y - middle.y)) * (1 - 1e-9);
            const double clearance =
                at_least >= 1e-4 * leaf_size ? at_least : std::sqrt(leaf_nearest(t, leaf, c, q, ignored));
            if (clearance > clearest) clearest = clearance, ref = q;
          }
          for (std::uint32_t m = t.leaves[leaf].covers; m < t.leaves[leaf + 1].covers; ++m) {
            const std::uint32_t e = t.covers[m].packed;
            const bool left = left_of(t.covers[m].start, t.covers[m].end, ref), arc = kernels[e].side != 0;
            t.covers[m].packed |= (left ? kRefLeft : 0) | (arc && in_lens(kernels[e], left, ref) ? kRefLens : 0) |
                                  (arc ? kArc : 0) | (kernels[e].side > 0 ? kCcw : 0);
          }
        }
    }
}

RegionIndex::RegionIndex(const std::vector<Loop>& loops, Layout layout) : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  for (std::size_t l = 0; l < loops.size(); ++l)
    for (const Segment& s : loops[l].segments) m.segments.push_back(s), m.loop_of.push_back(l);
  if (m.segments.size() >= Impl::kElementBits) throw Error("region boundary too large to index");
  if (m.segments.empty()) return;
  for (const Segment& s : m.segments) {
    m.kernels.push_back(make_kernel(s));
    m.boxes.push_back(bounding_box(s));
    m.ends.push_back(s.start), m.ends.push_back(s.end);
  }
  // Pad the boxes a little beyond rounding, so pruning by box never drops
  // an element that a direct computation would count.
  double scale = 0;
  for (const Box& b : m.boxes)
    scale = std::max({scale, std::abs(b.min_x), std::abs(b.min_y), std::abs(b.max_x), std::abs(b.max_y)});
  const double pad = 1e-12 * scale;
  m.rounding = pad;
  for (Box& b : m.boxes) b = {b.min_x - pad, b.min_y - pad, b.max_x + pad, b.max_y + pad};
  m.order.resize(m.segments.size());
  for (std::uint32_t i = 0; i < m.order.size(); ++i) m.order[i] = i;
  m.nodes.reserve(m.segments.size());
  m.build_node(0, static_cast<std::uint32_t>(m.order.size()));
  m.wide.reserve(m.nodes.size() / 3 + 1);
  Impl::Frame whole;
  m.build_wide(0, whole);
  m.ordered_kernels.reserve(m.order.size());
  for (const std::uint32_t e : m.order) m.ordered_kernels.push_back(m.kernels[e]);
  m.grid_wanted = layout == Layout::grid;  // laid out by the first query() (Impl::ensure_grid)
}

void RegionIndex::Impl::ensure_grid() {
  if (!grid_wanted) return;
  std::call_once(grid_once, [this] {
    build_grid();
    grid_ready.store(true, std::memory_order_release);
  });
}

const RegionIndex::Impl::Tile& RegionIndex::Impl::tile_at(std::size_t tx, std::size_t ty) const {
  std::atomic<Tile*>& slot = tiles[ty * tiles_x + tx];
  if (const Tile* built = slot.load(std::memory_order_acquire)) return *built;
  std::call_once(tile_once[ty * tiles_x + tx], [&] {
    std::unique_ptr<Workspace> w;
    {
      const std::lock_guard lock(spare_mutex);
      if (!spare.empty()) w = std::move(spare.back()), spare.pop_back();
    }
    if (!w) w = std::make_unique<Workspace>(segments.size());
    auto tile = std::make_unique<Tile>();
    w->x0 = tx * kBlockCells, w->y0 = ty * kBlockCells;
    build_tile(*w, *tile);
    slot.store(tile.release(), std::memory_order_release);
    const std::lock_guard lock(spare_mutex);
    spare.push_back(std::move(w));
    // The last tile built: no builder is left to need the touches or a workspace.
    if (tiles_built.fetch_add(1) + 1 == tiles_x * tiles_y) touches = {}, touch_first = {}, spare.clear();
  });
  return *slot.load(std::memory_order_acquire);
}

void RegionIndex::prepare() const {
  impl_->ensure_grid();
  const Impl& m = *impl_;
  for (std::size_t ty = 0; ty < m.tiles_y; ++ty)
    for (std::size_t tx = 0; tx < m.tiles_x; ++tx) m.tile_at(tx, ty);
}

void RegionIndex::Impl::build_tile(Workspace& w, Tile& t) const {
  w.window_elements.clear();
  for (CellWindow& window : w.windows) window = {};
  ask_block(w, w.x0, w.y0, kBlockCells);
  build_covers(w, t);
  build_lists(w, t);
  build_refs(w, t);
  build_inside(w, t);
}

}  // namespace tk::cad
