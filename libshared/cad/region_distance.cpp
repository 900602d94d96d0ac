/// @file region_distance.cpp
/// @brief Signed distance to a region bounded by lines and arcs.
///
/// The index is a two-level grid over the boundary's box, enlarged by a
/// quarter on each side: about one cell per element, each cell split into
/// leaves until about one element touches a leaf and few may be nearest to
/// its points. Each leaf keeps
///  - the elements that may be nearest to one of its points: those within
///    the centre's nearest distance plus a leaf diagonal, pruned by the
///    same test on quarters of the leaf, three times over, which leaves
///    little more than the elements whose Voronoi regions meet the leaf.
///    They are sorted by distance from the centre, the first four kept in
///    the leaf's own cache line, and a query stops once the triangle
///    inequality rules out the rest. Lists are capped (at the
///    centre of a circle of many arcs every arc may win); a query that
///    runs off a capped list finishes in a box tree over the elements,
///    as do queries outside the grid;
///  - a reference point clear of the boundary, whether it is inside (by
///    the same ray test as brute force), and the elements that may touch
///    the leaf: the query's inside flag is the reference point's, flipped
///    once per crossing of the short segment from there to the query point.
/// The crossing tests share their conventions and their left_of() calls
/// with the ray test, so the two agree exactly wherever the query point is
/// not on the boundary itself; the nearest element's normal is never used.
#include "cad/region_distance.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "cad/segment_geometry.hpp"
#include "io/error.hpp"

namespace tk::cad {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Tuned on bench_region_query's gear; see the file comment.
constexpr double kCoarseCellsPerElement = 1;
constexpr double kLeafCovers = 1;           // elements touching a leaf, about
constexpr double kLeafCandidates = 6;       // elements that may be nearest in a leaf, about
constexpr double kMaxListSplit = 2;         // splits of a cell for that, at most
constexpr std::size_t kMaxCandidates = 64;  // elements listed per leaf, at most
constexpr int kRefineDepth = 3;             // quarterings of a leaf while pruning its list
constexpr std::size_t kRefineLimit = 1024;  // longer lists are not pruned
constexpr std::size_t kWideWindow = 4 * kMaxCandidates;  // longer windows are not refined at all

/// An element prepared for queries. Arcs live in their chord frame as in
/// segment_geometry.cpp: local u along the chord from its midpoint, v
/// across it, mirrored so the arc bulges toward -v; the centre is at
/// (0, centre offset), the ends at (+-half chord, 0).
struct alignas(64) Kernel {  // one cache line
  double x = 0, y = 0;    ///< line: start; arc: chord midpoint
  double dx = 0, dy = 0;  ///< line: end - start; arc: unit chord direction
  double k0 = 0;          ///< line: 1 / |end - start|^2; arc: half chord
  double k1 = 0, k2 = 0;  ///< arc: centre offset, radius
  double side = 0;        ///< 0 line, +1 counter-clockwise arc, -1 clockwise
};

Kernel make_kernel(const Segment& s) {
  Kernel k;
  const double dx = s.end.x - s.start.x, dy = s.end.y - s.start.y;
  if (!is_arc(s)) {
    const double length2 = dx * dx + dy * dy;
    k.x = s.start.x, k.y = s.start.y, k.dx = dx, k.dy = dy, k.k0 = length2 > 0 ? 1 / length2 : 0;
    return k;
  }
  const double chord = std::sqrt(dx * dx + dy * dy), b = std::abs(s.bulge);
  k.x = (s.start.x + s.end.x) / 2, k.y = (s.start.y + s.end.y) / 2;
  k.dx = chord > 0 ? dx / chord : 1, k.dy = chord > 0 ? dy / chord : 0;
  k.k0 = chord / 2;
  k.k1 = chord * (1 - b * b) / (4 * b);
  k.k2 = chord * (1 + b * b) / (4 * b);
  k.side = s.bulge > 0 ? 1 : -1;
  return k;
}

inline void to_local(const Kernel& k, Point p, double& u, double& v) {
  const double px = p.x - k.x, py = p.y - k.y;
  u = px * k.dx + py * k.dy;
  v = k.side * (py * k.dx - px * k.dy);
}

/// Is the direction from the arc's centre to local (u, v) within its sweep?
inline bool in_sweep(const Kernel& k, double u, double v) { return k.k1 * (k.k0 - std::abs(u)) - v * k.k0 >= 0; }

inline double distance2(const Kernel& k, Point p) {
  if (k.side == 0) {
    const double px = p.x - k.x, py = p.y - k.y;
    const double t = std::clamp((px * k.dx + py * k.dy) * k.k0, 0.0, 1.0);
    const double ex = px - t * k.dx, ey = py - t * k.dy;
    return ex * ex + ey * ey;
  }
  double u, v;
  to_local(k, p, u, v);
  if (in_sweep(k, u, v)) {
    // rho - r as (rho^2 - r^2) / (rho + r): no cancellation for huge radii.
    const double wv = v - k.k1;
    const double excess = (u * u + v * v - 2 * v * k.k1 - k.k0 * k.k0) / (std::sqrt(u * u + wv * wv) + k.k2);
    return excess * excess;
  }
  const double e = std::abs(u) - k.k0;
  return e * e + v * v;
}

/// The nearest point of the element whose ends are ends[0], ends[1] (those exactly).
Point nearest_on(const Kernel& k, const Point* ends, Point p) {
  if (k.side == 0) {
    const double t = std::clamp(((p.x - k.x) * k.dx + (p.y - k.y) * k.dy) * k.k0, 0.0, 1.0);
    return t <= 0 ? ends[0] : t >= 1 ? ends[1] : Point{k.x + t * k.dx, k.y + t * k.dy};
  }
  double u, v;
  to_local(k, p, u, v);
  const double wv = v - k.k1, rho = std::sqrt(u * u + wv * wv);
  // At (or within rounding of) the centre the direction is noise and every
  // point of the arc is as near: take an end.
  if (!in_sweep(k, u, v) || rho <= 1e-9 * k.k2) return ends[u > 0 ? 1 : 0];
  const double excess = (u * u + v * v - 2 * v * k.k1 - k.k0 * k.k0) / (rho + k.k2);
  const double nu = u - excess * u / rho, nv = v - excess * wv / rho;
  if (!in_sweep(k, nu, nv)) return ends[u > 0 ? 1 : 0];  // rounding at the sweep's edge
  return {k.x + nu * k.dx - nv * k.side * k.dy, k.y + nu * k.dy + nv * k.side * k.dx};
}

inline bool in_circle(const Kernel& k, Point p) {
  double u, v;
  to_local(k, p, u, v);
  return u * u + v * v - 2 * v * k.k1 - k.k0 * k.k0 < 0;
}

/// p in the region between an arc and its chord; `left` is left_of(start, end, p).
inline bool in_lens(const Kernel& k, bool left, Point p) { return (k.side > 0 ? !left : left) && in_circle(k, p); }

/// Crossing parity of the ray from p toward +x of the element from a to b
/// (the rules of crosses_ray()).
inline bool ray_parity(const Kernel& k, Point a, Point b, Point p) {
  const bool straddles = (a.y > p.y) != (b.y > p.y);
  if (k.side == 0) return straddles && left_of(a, b, p) == (b.y > a.y);
  const bool left = left_of(a, b, p);
  return (straddles && left == (b.y > a.y)) != in_lens(k, left, p);
}

/// Crossing parity of the segment from c to p: the element's ends are
/// sided by left_of(c, p, end), c and p by left_of(start, end, .) as in
/// the ray test (c_left and c_lens precomputed). An arc crosses as often
/// as its chord, plus once for each of c and p inside its lens.
/// `arc` and `ccw` describe the element, so that a line needs no kernel.
inline bool segment_parity(const Kernel& k, Point a, Point b, bool arc, bool ccw, Point c, Point p, bool c_left,
                           bool c_lens) {
  const bool p_left = left_of(a, b, p);
  const bool chord = c_left != p_left && left_of(c, p, a) != left_of(c, p, b);
  if (!arc) return chord;
  const bool p_lens = (ccw ? !p_left : p_left) && in_circle(k, p);
  return (chord != c_lens) != p_lens;
}

/// The largest float not above d, and the smallest not below.
float float_below(double d) {
  float f = static_cast<float>(d);
  if (static_cast<double>(f) > d) f = std::nextafter(f, -std::numeric_limits<float>::infinity());
  return f;
}
float float_above(double d) { return -float_below(-d); }

double box_distance2(const Box& b, Point p) {
  const double dx = std::max({b.min_x - p.x, 0.0, p.x - b.max_x});
  const double dy = std::max({b.min_y - p.y, 0.0, p.y - b.max_y});
  return dx * dx + dy * dy;
}

Box merge(const Box& a, const Box& b) {
  return {std::min(a.min_x, b.min_x), std::min(a.min_y, b.min_y), std::max(a.max_x, b.max_x),
          std::max(a.max_y, b.max_y)};
}

}  // namespace

struct RegionIndex::Impl {
  struct Node {  // of the box tree; its left child is the next node
    Box box;
    std::uint32_t first = 0, count = 0, right = 0;  // count > 0: leaf over order[first, first + count)
  };
  struct Coarse {  // a grid cell, split into split x split leaves numbered from first_leaf
    std::uint32_t first_leaf, split;
  };
  struct Candidate {
    float key = INFINITY;  // the element's distance from the leaf centre, rounded down
    std::uint32_t element = 0;
  };
  static constexpr std::size_t kHead = 4;
  struct alignas(64) Leaf {  // one cache line; leaves[i + 1].candidates / .covers end leaf i's lists
    std::uint32_t candidates = 0;  // the list after the head
    std::uint32_t covers : 31 = 0, inside : 1 = 0;  // inside: whether ref is
    float complete = 0;  // every element that can win and is nearer the centre than this is listed
    float nearest = 0;   // the centre's distance to the boundary, rounded up
    Point ref;           // a point of the leaf clear of the boundary
    Candidate head[kHead];  // the list's first entries (key infinity: none), at hand with the rest
  };
  struct Cover {  // an element that may touch a leaf, with its ends at hand
    Point start, end;
    std::uint32_t packed;  // element | kRefLeft | kRefLens | kArc | kCcw
  };
  // left_of / in_lens at the leaf's reference point, and the kind of element
  static constexpr std::uint32_t kRefLeft = 1u << 31, kRefLens = 1u << 30, kArc = 1u << 29, kCcw = 1u << 28;
  static constexpr std::uint32_t kElementBits = kCcw - 1;

  std::vector<Segment> segments;
  std::vector<std::size_t> loop_of;
  std::vector<Kernel> kernels;
  std::vector<Point> ends;  // start and end of each element, compact
  std::vector<Box> boxes;
  std::vector<Node> nodes;
  std::vector<std::uint32_t> order;
  std::vector<Coarse> coarse;
  std::vector<Leaf> leaves;
  std::vector<Candidate> candidates;
  std::vector<Cover> covers;
  double ox = 0, oy = 0, size = 1, inv_size = 1;
  std::size_t nx = 0, ny = 0;

  std::uint32_t build_node(std::uint32_t begin, std::uint32_t end);
  void tree_nearest(Point p, double& best2, std::uint32_t& best) const;
  void tree_within(Point p, double radius, std::vector<std::pair<double, std::uint32_t>>& out) const;
  bool tree_ray_parity(Point p) const;
  void build_grid();
  void build_covers();
  void build_leaf(std::size_t cell, std::uint32_t x, std::uint32_t y);
  std::vector<std::uint32_t> winners(Point c, double half, int depth, double& nearest);
  void refine(Point q, double half, std::size_t begin, std::size_t end, int depth, std::vector<std::uint32_t>& out);

  // Scratch while building: a mark per element, distances from a centre,
  // and refine()'s lists, each square's after its parent's.
  std::vector<std::uint32_t> stamp;
  std::uint32_t mark = 0;
  std::vector<double> near, far2;
  std::vector<std::uint32_t> scratch;
  double leaf_nearest(std::size_t leaf, Point centre, Point p, std::uint32_t& best) const;
  /// Centre of leaf (x, y) of cell (ix, iy), the same point for building and querying.
  Point centre(std::size_t ix, std::size_t iy, std::uint32_t split, std::uint32_t x, std::uint32_t y) const {
    return {ox + (double(ix) + (x + 0.5) / split) * size, oy + (double(iy) + (y + 0.5) / split) * size};
  }
  RegionQuery answer(Point p, double best2, std::uint32_t best, bool inside) const {
    const double d = std::sqrt(best2);
    return {inside ? -d : d, nearest_on(kernels[best], &ends[2 * best], p), best};
  }
};

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
  nodes[index].right = right;
  return index;
}

void RegionIndex::Impl::tree_nearest(Point p, double& best2, std::uint32_t& best) const {
  std::uint32_t stack[128];
  std::size_t top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const std::uint32_t index = stack[--top];
    const Node& node = nodes[index];
    if (box_distance2(node.box, p) >= best2) continue;
    if (node.count > 0) {
      for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
        const double d2 = distance2(kernels[order[i]], p);
        if (d2 < best2) best2 = d2, best = order[i];
      }
      continue;
    }
    const bool left_first = box_distance2(nodes[index + 1].box, p) <= box_distance2(nodes[node.right].box, p);
    stack[top++] = left_first ? node.right : index + 1;  // the nearer child is popped first
    stack[top++] = left_first ? index + 1 : node.right;
  }
}

void RegionIndex::Impl::tree_within(Point p, double radius, std::vector<std::pair<double, std::uint32_t>>& out) const {
  const double r2 = radius * radius;
  std::uint32_t stack[128];
  std::size_t top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const std::uint32_t index = stack[--top];
    const Node& node = nodes[index];
    if (box_distance2(node.box, p) > r2) continue;
    if (node.count == 0) {
      stack[top++] = node.right;
      stack[top++] = index + 1;
      continue;
    }
    for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
      const double d2 = distance2(kernels[order[i]], p);
      if (d2 <= r2) out.emplace_back(std::sqrt(d2), order[i]);
    }
  }
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

double RegionIndex::Impl::leaf_nearest(std::size_t leaf, Point centre, Point p, std::uint32_t& best) const {
  const Leaf& l = leaves[leaf];
  const double from_centre = std::sqrt((p.x - centre.x) * (p.x - centre.x) + (p.y - centre.y) * (p.y - centre.y));
  // Start from a bound the nearest element beats: |p - e| <= |c - e| + |p - c|.
  const double bound = (double(l.nearest) + from_centre) * (1 + 1e-12);
  double best2 = bound * bound + std::numeric_limits<double>::min();
  best = UINT32_MAX;
  // |p - e| >= |c - e| - |p - c|: nothing further down the list can win.
  const auto beaten = [&](const Candidate& c) {
    const double lower = double(c.key) - from_centre;
    return lower > 0 && lower * lower >= best2;
  };
  const auto try_element = [&](std::uint32_t e) {
    const double d2 = distance2(kernels[e], p);
    if (d2 < best2) best2 = d2, best = e;
  };
  bool done = false;
  for (std::size_t i = 0; i < kHead && !(done = beaten(l.head[i])); ++i) try_element(l.head[i].element);
  const Candidate* it = candidates.data() + l.candidates;
  const Candidate* const end = candidates.data() + leaves[leaf + 1].candidates;
  for (; !done && it != end && !(done = beaten(*it)); ++it) try_element(it->element);
  const double lower = double(l.complete) - from_centre;
  if (!done && !(lower > 0 && lower * lower >= best2)) tree_nearest(p, best2, best);
  if (best == UINT32_MAX) best2 = kInf, tree_nearest(p, best2, best);  // not reached; rounding guard
  return best2;
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
  nx = static_cast<std::size_t>(std::clamp(std::ceil(width / size), 1.0, double(1 << 12)));
  ny = static_cast<std::size_t>(std::clamp(std::ceil(height / size), 1.0, double(1 << 12)));
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
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;  // (leaf, element)
  std::uint32_t leaf_count = 0;
  for (std::size_t t = 0, cell = 0; cell < nx * ny; ++cell) {
    const std::size_t begin = t;
    std::size_t distinct = 0;
    for (; t < touches.size() && touches[t].cell == cell; ++t)
      distinct += t == begin || touches[t].element != touches[t - 1].element;
    // Enough leaves for about kLeafCovers elements touching each, and, up to
    // a point, about kLeafCandidates that may be nearest (roughly as many
    // as Voronoi regions cross the leaf, so in proportion to its width).
    double nearest = 0;
    const Point middle{ox + (double(cell % nx) + 0.5) * size, oy + (double(cell / nx) + 0.5) * size};
    const double may_win = double(winners(middle, size / 2, 1, nearest).size());
    const double wanted =
        std::max(std::sqrt(double(distinct) / kLeafCovers), std::min(may_win / kLeafCandidates, kMaxListSplit));
    const auto split = static_cast<std::uint32_t>(std::clamp(std::ceil(wanted), 1.0, 32.0));
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
void RegionIndex::Impl::refine(Point q, double half, std::size_t begin, std::size_t end, int depth,
                               std::vector<std::uint32_t>& out) {
  double nearest2 = kInf;
  far2.resize(std::max(far2.size(), end));
  for (std::size_t i = begin; i < end; ++i) nearest2 = std::min(nearest2, far2[i] = distance2(kernels[scratch[i]], q));
  const double reach = (std::sqrt(nearest2) + 2 * std::sqrt(2.0) * half) * (1 + 1e-9);
  const std::size_t first = scratch.size();
  for (std::size_t i = begin; i < end; ++i)
    if (far2[i] <= reach * reach) scratch.push_back(scratch[i]);
  const std::size_t last = scratch.size();
  // Stop at one element, at the depth limit, or where quartering stopped
  // pruning (all nearly equidistant, as round the centre of a fine circle).
  const bool stuck = depth > 0 && last - first == end - begin;
  if (last - first <= 1 || depth == kRefineDepth || stuck || last - first > kRefineLimit) {
    for (std::size_t i = first; i < last; ++i)
      if (stamp[scratch[i]] != mark) stamp[scratch[i]] = mark, out.push_back(scratch[i]);
  } else {
    for (double dy : {-0.5, 0.5})
      for (double dx : {-0.5, 0.5}) refine({q.x + dx * half, q.y + dy * half}, half / 2, first, last, depth + 1, out);
  }
  scratch.resize(first);
}

/// The elements that may be nearest to a point of the square round c of
/// half side `half` (refined `depth` times), sorted by their distance from
/// c (left in near[]); `nearest` gets c's distance to the boundary.
std::vector<std::uint32_t> RegionIndex::Impl::winners(Point c, double half, int depth, double& nearest) {
  double best2 = kInf;
  std::uint32_t best = 0;
  tree_nearest(c, best2, best);
  nearest = std::sqrt(best2);
  std::vector<std::pair<double, std::uint32_t>> found;
  tree_within(c, (nearest + 2 * std::sqrt(2.0) * half) * (1 + 1e-9), found);
  std::vector<std::uint32_t> listed;
  for (const auto& [d, e] : found) near[e] = d;
  if (found.size() > kWideWindow) {
    // Many elements nearly equidistant (deep inside a finely divided
    // outline): refining would cost more than it saves. The nearest
    // kMaxCandidates + 1 by distance from c keep the leaf's promise (every
    // element nearer than the last listed is listed); queries beyond fall
    // back to the tree.
    std::nth_element(found.begin(), found.begin() + kMaxCandidates, found.end());
    for (std::size_t i = 0; i <= kMaxCandidates; ++i) listed.push_back(found[i].second);
  } else {
    scratch.clear();
    for (const auto& entry : found) scratch.push_back(entry.second);
    ++mark;
    refine(c, half, 0, scratch.size(), kRefineDepth - depth, listed);
  }
  std::sort(listed.begin(), listed.end(),
            [&](std::uint32_t a, std::uint32_t b) { return std::pair{near[a], a} < std::pair{near[b], b}; });
  return listed;
}

/// A leaf's candidates, capped; then its reference point: the first of a
/// few scattered points that keeps clear of the boundary, with its inside
/// flag from the ray test.
void RegionIndex::Impl::build_leaf(std::size_t cell, std::uint32_t x, std::uint32_t y) {
  const std::size_t leaf = coarse[cell].first_leaf + y * coarse[cell].split + x;
  const double leaf_size = size / coarse[cell].split;
  const Point c = centre(cell % nx, cell / nx, coarse[cell].split, x, y);
  double nearest = 0;
  std::vector<std::uint32_t> listed = winners(c, leaf_size / 2, kRefineDepth, nearest);
  leaves[leaf].nearest = float_above(nearest);
  leaves[leaf].complete = listed.size() > kMaxCandidates ? float_below(near[listed[kMaxCandidates]]) : INFINITY;
  listed.resize(std::min(listed.size(), kMaxCandidates));
  for (std::size_t i = 0; i < listed.size(); ++i) {
    const Candidate entry{float_below(near[listed[i]]), listed[i]};
    if (i < kHead) leaves[leaf].head[i] = entry;
    else candidates.push_back(entry);
  }
  leaves[leaf + 1].candidates = static_cast<std::uint32_t>(candidates.size());

  double clearest = -1;
  Point& ref = leaves[leaf].ref;
  std::uint32_t ignored = 0;
  for (int k = 0; k < 8 && clearest < 1e-4 * leaf_size; ++k) {
    const double fx = 0.8 * std::fmod(0.5137 + 0.6180339887 * k, 1.0) - 0.4;
    const double fy = 0.8 * std::fmod(0.5291 + 0.7548776662 * k, 1.0) - 0.4;
    const Point q{c.x + fx * leaf_size, c.y + fy * leaf_size};
    const double clearance = std::sqrt(leaf_nearest(leaf, c, q, ignored));
    if (clearance > clearest) clearest = clearance, ref = q;
  }
  for (std::uint32_t m = leaves[leaf].covers; m < leaves[leaf + 1].covers; ++m) {
    const std::uint32_t e = covers[m].packed;
    const bool left = left_of(covers[m].start, covers[m].end, ref), arc = kernels[e].side != 0;
    covers[m].packed |= (left ? kRefLeft : 0) | (arc && in_lens(kernels[e], left, ref) ? kRefLens : 0) |
                        (arc ? kArc : 0) | (kernels[e].side > 0 ? kCcw : 0);
  }
  leaves[leaf].inside = tree_ray_parity(ref);
}

RegionIndex::RegionIndex(const std::vector<Loop>& loops) : impl_(std::make_unique<Impl>()) {
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
  for (Box& b : m.boxes) b = {b.min_x - pad, b.min_y - pad, b.max_x + pad, b.max_y + pad};
  m.order.resize(m.segments.size());
  for (std::uint32_t i = 0; i < m.order.size(); ++i) m.order[i] = i;
  m.nodes.reserve(m.segments.size());
  m.build_node(0, static_cast<std::uint32_t>(m.order.size()));
  m.build_grid();
  if (m.nx == 0) return;
  m.stamp.assign(m.segments.size(), 0);
  m.near.resize(m.segments.size());
  m.build_covers();
  for (std::size_t cell = 0; cell < m.coarse.size(); ++cell)
    for (std::uint32_t y = 0; y < m.coarse[cell].split; ++y)
      for (std::uint32_t x = 0; x < m.coarse[cell].split; ++x) m.build_leaf(cell, x, y);
  m.stamp = {}, m.near = {}, m.far2 = {}, m.scratch = {};
}

RegionIndex::~RegionIndex() = default;
RegionIndex::RegionIndex(RegionIndex&&) noexcept = default;
RegionIndex& RegionIndex::operator=(RegionIndex&&) noexcept = default;

const std::vector<Segment>& RegionIndex::elements() const { return impl_->segments; }
std::size_t RegionIndex::loop_of(std::size_t element) const { return impl_->loop_of.at(element); }

RegionQuery RegionIndex::query(Point p) const {
  const Impl& m = *impl_;
  if (m.segments.empty()) return {kInf, p, 0};
  const double fx = (p.x - m.ox) * m.inv_size, fy = (p.y - m.oy) * m.inv_size;
  std::uint32_t best = 0;
  if (!(fx >= 0 && fy >= 0 && fx < double(m.nx) && fy < double(m.ny))) {
    double best2 = kInf;
    m.tree_nearest(p, best2, best);
    return m.answer(p, best2, best, m.tree_ray_parity(p));
  }
  const auto ix = static_cast<std::size_t>(fx), iy = static_cast<std::size_t>(fy);
  const std::size_t cell = iy * m.nx + ix;
  const std::uint32_t split = m.coarse[cell].split;
  std::uint32_t sx = 0, sy = 0;
  if (split > 1) {
    sx = std::min(split - 1, static_cast<std::uint32_t>((fx - double(ix)) * split));
    sy = std::min(split - 1, static_cast<std::uint32_t>((fy - double(iy)) * split));
  }
  const std::size_t leaf = m.coarse[cell].first_leaf + sy * split + sx;
  const double best2 = m.leaf_nearest(leaf, m.centre(ix, iy, split, sx, sy), p, best);
  const Impl::Leaf& l = m.leaves[leaf];
  bool inside = l.inside;
  for (std::uint32_t i = l.covers; i < m.leaves[leaf + 1].covers; ++i) {
    const Impl::Cover& c = m.covers[i];
    inside ^= segment_parity(m.kernels[c.packed & Impl::kElementBits], c.start, c.end, c.packed & Impl::kArc,
                             c.packed & Impl::kCcw, l.ref, p, c.packed & Impl::kRefLeft, c.packed & Impl::kRefLens);
  }
  return m.answer(p, best2, best, inside);
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
