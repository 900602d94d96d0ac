/// @file region_index_build.cpp
/// @brief Building RegionIndex: the box tree, the two-level grid, each
/// leaf's candidate list (pruned by quartering) and reference point.
#include <algorithm>
#include <cmath>
#include <future>
#include <thread>

#include "cad/region_index_impl.hpp"
#include "cad/segment_geometry.hpp"
#include "io/error.hpp"

namespace tk::cad {

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
}

/// Leaves and their cover lists (which elements may touch each leaf).
/// Elements are cut into pieces of half a cell, each piece's padded box
/// marking the cells it may touch; a cell then splits into leaves (see
/// below), and the pieces in it are cut again to find theirs.
void RegionIndex::Impl::build_covers() {
  struct Touch {
    std::uint32_t cell, element;
    double t0, t1;
  };
  const double pad = 1e-6 * size;
  const auto span = [&](double lo, double hi, double origin, double step, std::size_t n) {
    const auto at = [&](double x) { return std::clamp(std::floor((x - origin) / step), 0.0, double(n - 1)); };
    return std::pair{std::size_t(at(lo - pad)), std::size_t(at(hi + pad))};
  };
  std::vector<Touch> touches;
  for (std::uint32_t e = 0; e < segments.size(); ++e) {
    const double pieces = std::clamp(std::ceil(segment_length(segments[e]) / (size / 2)), 1.0, double(1 << 20));
    for (double i = 0; i < pieces; ++i) {
      const double t0 = i / pieces, t1 = (i + 1) / pieces;
      const Box b = pieces == 1 ? boxes[e] : bounding_box(sub_segment(segments[e], t0, t1));
      const auto [x0, x1] = span(b.min_x, b.max_x, ox, size, nx);
      const auto [y0, y1] = span(b.min_y, b.max_y, oy, size, ny);
      for (std::size_t y = y0; y <= y1; ++y)
        for (std::size_t x = x0; x <= x1; ++x) touches.push_back({std::uint32_t(y * nx + x), e, t0, t1});
    }
  }
  std::stable_sort(touches.begin(), touches.end(), [](const Touch& a, const Touch& b) { return a.cell < b.cell; });

  coarse.assign(nx * ny, Coarse{0, 1});
  cell_touch_first.assign(nx * ny + 1, 0);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;  // (leaf, element)
  std::uint32_t leaf_count = 0;
  for (std::size_t t = 0, cell = 0; cell < nx * ny; ++cell) {
    const std::size_t begin = t;
    std::size_t distinct = 0;
    cell_touch_first[cell] = static_cast<std::uint32_t>(cell_touches.size());
    for (; t < touches.size() && touches[t].cell == cell; ++t)
      if (t == begin || touches[t].element != touches[t - 1].element)
        ++distinct, cell_touches.push_back(touches[t].element);
    // Enough leaves for about kLeafCovers elements touching each, and, up to
    // a point, about kLeafCandidates that may be nearest (roughly as many
    // as Voronoi regions cross the leaf, so in proportion to its width).
    const CellWindow& w = windows[cell];
    const double by_covers = std::sqrt(double(distinct) / kLeafCovers);
    // The cell's window is pruned at the cell's square already, so that is
    // what may win there (refining it again was a costly no-op: a list
    // that keeps over kStuckShare of itself is not quartered).
    const double may_win = double(w.count);
    const double wanted = std::max(by_covers, std::min(may_win / kLeafCandidates, kMaxListSplit));
    // A power of two (the nearer, in ratio), so that leaves' lists come down by quarters.
    const double clamped = std::clamp(std::ceil(wanted), 1.0, 32.0);
    std::uint32_t split = 1;
    while (split * 2 <= clamped) split *= 2;
    if (clamped > std::sqrt(2.0) * split) split *= 2;
    coarse[cell] = {leaf_count, split};
    leaf_count += split * split;
    const double x0 = ox + double(cell % nx) * size, y0 = oy + double(cell / nx) * size, step = size / split;
    for (std::size_t k = begin; k < t; ++k) {
      const Touch& touch = touches[k];
      if (split == 1) {
        pairs.emplace_back(coarse[cell].first_leaf, touch.element);
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
        for (std::size_t y = sy0; y <= sy1; ++y)
          for (std::size_t x = sx0; x <= sx1; ++x)
            pairs.emplace_back(coarse[cell].first_leaf + std::uint32_t(y * split + x), touch.element);
      }
    }
  }
  cell_touch_first[nx * ny] = static_cast<std::uint32_t>(cell_touches.size());
  std::stable_sort(pairs.begin(), pairs.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  leaves.assign(leaf_count + 1, Leaf{});
  for (const auto& [leaf, e] : pairs) ++leaves[leaf + 1].covers, covers.push_back({ends[2 * e], ends[2 * e + 1], e});
  for (std::size_t i = 0; i < leaf_count; ++i) leaves[i + 1].covers += leaves[i].covers;
}

/// Adds to `out` (once, by mark) the elements of `window` that may be the
/// nearest to some point of the square round q of half side `half`: those
/// within the nearest distance from q plus a diagonal. A square with more
/// than one is quartered, down to kRefineDepth, so the list comes close to
/// the elements whose Voronoi regions meet the square.
void RegionIndex::Impl::refine(Workspace& w, Point q, double half, std::size_t begin, std::size_t end, int depth,
                               std::vector<std::uint32_t>& out, bool pruned) const {
  std::vector<std::uint32_t>& scratch = w.scratch;
  std::vector<double>& far2 = w.far2;
  // A list pruned by this very test already (the leaf's, from its cell's
  // by quarters) is taken as it is: the test would keep all of it.
  std::size_t first = begin, last = end;
  if (!pruned) {
    double nearest2 = kInf;
    if (far2.size() < end) far2.resize(end);
    for (std::size_t i = begin; i < end; ++i)
      nearest2 = std::min(nearest2, far2[i] = distance2(kernels[scratch[i]], q));
    const double reach = (std::sqrt(nearest2) + 2 * std::sqrt(2.0) * half) * (1 + 1e-9);
    first = scratch.size();
    for (std::size_t i = begin; i < end; ++i)
      if (far2[i] <= reach * reach) scratch.push_back(scratch[i]);
    last = scratch.size();
  }
  // Stop at one element, at the depth limit, or where quartering prunes
  // little (many nearly equidistant, as round the centre of a fine circle):
  // each level costs four times the last.
  const bool stuck = !pruned && depth > 0 && double(last - first) > kStuckShare * double(end - begin);
  if (last - first <= 1 || depth == kRefineDepth || stuck || last - first > kRefineLimit) {
    for (std::size_t i = first; i < last; ++i)
      if (w.stamp[scratch[i]] != w.mark) w.stamp[scratch[i]] = w.mark, out.push_back(scratch[i]);
  } else {
    for (double dy : {-0.5, 0.5})
      for (double dx : {-0.5, 0.5})
        refine(w, {q.x + dx * half, q.y + dy * half}, half / 2, first, last, depth + 1, out);
  }
  if (!pruned) scratch.resize(first);
}

/// A leaf's candidates, capped; then its reference point: the first of a
/// few scattered points that keeps clear of the boundary (its inside flag
/// comes later, from build_inside).
/// The lists of the leaves of a cell's block [x0, x0 + span)^2 (in
/// leaves) into leaf_lists, each quarter's pruned from the block's.
void RegionIndex::Impl::build_leaves(Workspace& w, std::size_t cell, std::uint32_t x0, std::uint32_t y0,
                                     std::uint32_t span, const std::vector<std::uint32_t>& list) {
  if (span == 1) {
    w.leaf_lists[y0 * coarse[cell].split + x0] = list;
    return;
  }
  const std::uint32_t half_span = span / 2;
  const double step = size / coarse[cell].split;
  std::vector<std::uint32_t> quarter;
  for (std::uint32_t dy = 0; dy < 2; ++dy)
    for (std::uint32_t dx = 0; dx < 2; ++dx) {
      const std::uint32_t x = x0 + dx * half_span, y = y0 + dy * half_span;
      const Point c{ox + double(cell % nx) * size + (x + half_span / 2.0) * step,
                    oy + double(cell / nx) * size + (y + half_span / 2.0) * step};
      quarter.clear();
      if (!windows[cell].wide) prune(w, c, half_span * step / 2 * (1 + 1e-9), list.data(), list.size(), quarter);
      build_leaves(w, cell, x, y, half_span, quarter);
    }
}

void RegionIndex::Impl::build_leaf(Workspace& w, std::size_t cell, std::uint32_t x, std::uint32_t y,
                                   const std::vector<std::uint32_t>& list) {
  const std::size_t leaf = coarse[cell].first_leaf + y * coarse[cell].split + x;
  const double leaf_size = size / coarse[cell].split;
  const Point c = centre(cell % nx, cell / nx, coarse[cell].split, x, y);
  const CellWindow& window = windows[cell];
  const Point middle = centre(cell % nx, cell / nx, 1, 0, 0);
  // A wide cell's leaves: no list, and a bound on the centre's distance for a start.
  const double from_middle = std::hypot(c.x - middle.x, c.y - middle.y);
  const std::vector<std::uint32_t> listed = leaf_window(w, cell, c, leaf_size / 2, list.data(), list.size());
  const std::vector<double>& near = w.near;
  const double nearest = listed.empty() ? (window.nearest + from_middle) * (1 + 1e-12) : near[listed[0]];
  leaves[leaf].nearest = float_above(nearest);
  leaves[leaf].complete = window.wide                      ? 0
                          : listed.size() > kMaxCandidates ? float_below(near[listed[kMaxCandidates]])
                                                           : INFINITY;
  for (std::size_t i = 0; i < std::min(listed.size(), kMaxCandidates); ++i) {
    const Candidate entry{float_below(near[listed[i]]), listed[i]};
    if (i < kHead) leaves[leaf].head[i] = entry;
    else w.candidates.push_back(entry);
  }
  leaves[leaf + 1].candidates = static_cast<std::uint32_t>(w.candidates.size());  // relative: see build_lists
}

void RegionIndex::Impl::build_lists(Workspace& w, std::size_t cell_begin, std::size_t cell_end) {
  std::vector<std::uint32_t> list;
  for (std::size_t cell = cell_begin; cell < cell_end; ++cell) {
    const CellWindow& window = windows[cell];
    list.assign(window_elements.begin() + window.first, window_elements.begin() + window.first + window.count);
    const std::uint32_t split = coarse[cell].split;
    w.leaf_lists.resize(std::size_t(split) * split);
    build_leaves(w, cell, 0, 0, split, list);
    for (std::uint32_t y = 0; y < split; ++y)  // in order: each leaf's lists end the last's
      for (std::uint32_t x = 0; x < split; ++x) build_leaf(w, cell, x, y, w.leaf_lists[y * split + x]);
  }
}

/// Each leaf's reference point: the first of a few scattered points that
/// keeps clear of the boundary (its inside flag comes later, from
/// build_inside), and its covers' sides of it.
void RegionIndex::Impl::build_refs(std::size_t cell_begin, std::size_t cell_end) {
  for (std::size_t cell = cell_begin; cell < cell_end; ++cell) {
    const std::uint32_t split = coarse[cell].split;
    const double leaf_size = size / split;
    const CellWindow& window = windows[cell];
    const Point middle = centre(cell % nx, cell / nx, 1, 0, 0);
    for (std::uint32_t y = 0; y < split; ++y)
      for (std::uint32_t x = 0; x < split; ++x) {
        const std::size_t leaf = coarse[cell].first_leaf + y * split + x;
        const Point c = centre(cell % nx, cell / nx, split, x, y);
        double clearest = -1;
        Point& ref = leaves[leaf].ref;
        std::uint32_t ignored = 0;
        for (int k = 0; k < 8 && clearest < 1e-4 * leaf_size; ++k) {
          const double fx = 0.8 * std::fmod(0.5137 + 0.6180339887 * k, 1.0) - 0.4;
          const double fy = 0.8 * std::fmod(0.5291 + 0.7548776662 * k, 1.0) - 0.4;
          const Point q{c.x + fx * leaf_size, c.y + fy * leaf_size};
          // Far from the boundary a lower bound settles it without a search.
          const double at_least = (window.nearest - std::hypot(q.x - middle.x, q.y - middle.y)) * (1 - 1e-9);
          const double clearance =
              at_least >= 1e-4 * leaf_size ? at_least : std::sqrt(leaf_nearest(leaf, c, q, ignored));
          if (clearance > clearest) clearest = clearance, ref = q;
        }
        for (std::uint32_t m = leaves[leaf].covers; m < leaves[leaf + 1].covers; ++m) {
          const std::uint32_t e = covers[m].packed;
          const bool left = left_of(covers[m].start, covers[m].end, ref), arc = kernels[e].side != 0;
          covers[m].packed |= (left ? kRefLeft : 0) | (arc && in_lens(kernels[e], left, ref) ? kRefLens : 0) |
                              (arc ? kArc : 0) | (kernels[e].side > 0 ? kCcw : 0);
        }
      }
  }
}

namespace {

constexpr std::size_t kThreadedFrom = 2000;  // elements: below, a second thread costs more than it saves

/// work(0) and, with two parts, work(1) on a second thread at the same
/// time; each work(part) picks its own share of cells.
template <class Work>
void in_parts(std::size_t parts, Work&& work) {
  if (parts == 1) return work(0);
  auto second = std::async(std::launch::async, [&] { work(1); });
  work(0);
  second.get();
}

}  // namespace

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
  m.grid_wanted = layout == Layout::grid;  // built by the first query() (Impl::ensure_grid)
}

void RegionIndex::Impl::ensure_grid() {
  if (!grid_wanted) return;
  std::call_once(grid_once, [this] {
    build_grid_lists();
    grid_ready.store(true, std::memory_order_release);
  });
}

void RegionIndex::Impl::build_grid_lists() {
  Impl& m = *this;
  m.build_grid();
  if (m.nx == 0) return;
  // Two threads where there is enough work (the machine has two cores):
  // each part builds its windows and lists into its own workspace, joined
  // in order, so the index is the same whatever the parts.
  const std::size_t parts = m.segments.size() >= kThreadedFrom && std::thread::hardware_concurrency() > 1 ? 2 : 1;
  std::vector<Impl::Workspace> work;
  for (std::size_t i = 0; i < parts; ++i) work.emplace_back(m.segments.size());
  const auto halves = [&](std::size_t count, std::size_t part) {
    return std::pair{count * part / parts, count * (part + 1) / parts};
  };
  m.windows.assign(m.nx * m.ny, Impl::CellWindow{});
  const std::size_t block_rows = (m.ny + kBlockCells - 1) / kBlockCells;
  in_parts(parts, [&](std::size_t part) {
    const auto [begin, end] = halves(block_rows, part);
    m.build_windows(work[part], begin, end);
  });
  for (std::size_t part = 0; part < parts; ++part) {  // the windows' offsets made absolute
    const auto base = static_cast<std::uint32_t>(m.window_elements.size());
    const auto [begin, end] = halves(block_rows, part);
    for (std::size_t cell = begin * kBlockCells * m.nx; cell < std::min(m.ny, end * kBlockCells) * m.nx; ++cell)
      m.windows[cell].first += base;
    m.window_elements.insert(m.window_elements.end(), work[part].window_elements.begin(),
                             work[part].window_elements.end());
    work[part].window_elements = {};
  }
  m.build_covers();
  // The lists, split where half the leaves are.
  std::vector<std::size_t> cell_bounds{0};
  if (parts == 2) {
    const std::size_t leaf_count = m.leaves.size() - 1;
    std::size_t cell = 0;
    while (cell < m.coarse.size() && m.coarse[cell].first_leaf < leaf_count / 2) ++cell;
    cell_bounds.push_back(cell);
  }
  cell_bounds.push_back(m.coarse.size());
  in_parts(parts, [&](std::size_t part) { m.build_lists(work[part], cell_bounds[part], cell_bounds[part + 1]); });
  for (std::size_t part = 0; part < parts; ++part) {  // each part's list ends made absolute
    const auto base = static_cast<std::uint32_t>(m.candidates.size());
    const auto first_leaf_of = [&](std::size_t cell) {
      return cell < m.coarse.size() ? std::size_t(m.coarse[cell].first_leaf) : m.leaves.size() - 1;
    };
    const std::size_t first_leaf = first_leaf_of(cell_bounds[part]), end_leaf = first_leaf_of(cell_bounds[part + 1]);
    for (std::size_t leaf = first_leaf; leaf < end_leaf; ++leaf) m.leaves[leaf + 1].candidates += base;
    m.candidates.insert(m.candidates.end(), work[part].candidates.begin(), work[part].candidates.end());
    work[part].candidates = {};
  }
  in_parts(parts, [&](std::size_t part) { m.build_refs(cell_bounds[part], cell_bounds[part + 1]); });
  for (const Impl::Leaf& leaf : m.leaves) m.leaf_cover_first.push_back(leaf.covers);
  in_parts(parts, [&](std::size_t part) {
    const auto [begin, end] = halves(m.ny, part);
    m.build_inside(work[part], begin, end);
  });
  m.windows = {}, m.window_elements = {}, m.cell_touches = {}, m.cell_touch_first = {}, m.leaf_cover_first = {};
}

}  // namespace tk::cad
