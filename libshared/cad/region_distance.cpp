/// @file region_distance.cpp
/// @brief Signed distance to a region bounded by lines and arcs.
///
/// The index is a uniform grid over the boundary's box (enlarged by a
/// quarter on each side) about two cells per element. Each cell keeps
///  - the elements nearest its centre, sorted by that distance, down to
///    the window every point of the cell needs (nearest distance from the
///    centre plus a cell diagonal) or to a cap; a query scans them until
///    the triangle inequality rules out the rest, and falls back to a box
///    tree only when a capped list runs out;
///  - a reference point away from the boundary, whether it is inside
///    (by the same ray test as brute force), and the elements overlapping
///    the cell: the query's inside flag is the reference point's flipped
///    once per crossing of the short segment from it to the query point.
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
constexpr double kCellsPerElement = 2;
constexpr std::size_t kMaxCandidates = 48;

/// An element prepared for queries. Arcs live in their chord frame as in
/// segment_geometry.cpp: local u along the chord from its midpoint, v
/// across it, mirrored so the arc bulges toward -v; the centre is at
/// (0, centre offset), the ends at (+-half chord, 0).
struct Kernel {
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
  const double chord = std::hypot(dx, dy), b = std::abs(s.bulge);
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

Point nearest_on(const Kernel& k, const Segment& s, Point p) {
  if (k.side == 0) {
    const double t = std::clamp(((p.x - k.x) * k.dx + (p.y - k.y) * k.dy) * k.k0, 0.0, 1.0);
    return t <= 0 ? s.start : t >= 1 ? s.end : Point{k.x + t * k.dx, k.y + t * k.dy};
  }
  double u, v;
  to_local(k, p, u, v);
  const double wv = v - k.k1, rho = std::sqrt(u * u + wv * wv);
  if (!in_sweep(k, u, v) || rho == 0) return u > 0 ? s.end : s.start;
  const double excess = (u * u + v * v - 2 * v * k.k1 - k.k0 * k.k0) / (rho + k.k2);
  const double nu = u - excess * u / rho, nv = (v - excess * wv / rho) * k.side;
  return {k.x + nu * k.dx - nv * k.dy, k.y + nu * k.dy + nv * k.dx};
}

inline bool in_circle(const Kernel& k, Point p) {
  double u, v;
  to_local(k, p, u, v);
  return u * u + v * v - 2 * v * k.k1 - k.k0 * k.k0 < 0;
}

/// p in the region between an arc and its chord; `left` is left_of(start, end, p).
inline bool in_lens(const Kernel& k, bool left, Point p) { return (k.side > 0 ? !left : left) && in_circle(k, p); }

/// Crossing parity of the ray from p toward +x (the rules of crosses_ray()).
inline bool ray_parity(const Kernel& k, const Segment& s, Point p) {
  const Point a = s.start, b = s.end;
  const bool straddles = (a.y > p.y) != (b.y > p.y);
  if (k.side == 0) return straddles && left_of(a, b, p) == (b.y > a.y);
  const bool left = left_of(a, b, p);
  return (straddles && left == (b.y > a.y)) != in_lens(k, left, p);
}

/// Crossing parity of the segment from c to p: the element's ends are
/// sided by left_of(c, p, end), c and p by left_of(start, end, .) as in
/// the ray test (c_left and c_lens precomputed). An arc crosses as often
/// as its chord, plus once for each of c and p inside its lens.
inline bool segment_parity(const Kernel& k, const Segment& s, Point c, Point p, bool c_left, bool c_lens) {
  const bool chord_straddles = left_of(c, p, s.start) != left_of(c, p, s.end);
  if (k.side == 0) return chord_straddles && c_left != left_of(s.start, s.end, p);
  const bool p_left = left_of(s.start, s.end, p);
  return ((chord_straddles && c_left != p_left) != c_lens) != in_lens(k, p_left, p);
}

double box_distance2(const Box& b, Point p) {
  const double dx = std::max({b.min_x - p.x, 0.0, p.x - b.max_x});
  const double dy = std::max({b.min_y - p.y, 0.0, p.y - b.max_y});
  return dx * dx + dy * dy;
}

Box merge(const Box& a, const Box& b) {
  return {std::min(a.min_x, b.min_x), std::min(a.min_y, b.min_y), std::max(a.max_x, b.max_x),
          std::max(a.max_y, b.max_y)};
}

/// The largest float not above d: a key that never overstates a distance.
float float_below(double d) {
  float f = static_cast<float>(d);
  if (static_cast<double>(f) > d) f = std::nextafter(f, -std::numeric_limits<float>::infinity());
  return f;
}

}  // namespace

struct RegionIndex::Impl {
  struct Node {  // of the box tree; its left child is the next node
    Box box;
    std::uint32_t first = 0, count = 0, right = 0;  // count > 0: leaf over order[first, first + count)
  };
  struct Cell {  // cells[i + 1].candidates / .covers end cell i's lists
    std::uint32_t candidates = 0, covers = 0;
    float complete = 0;  // every element nearer the centre than this is listed
    std::uint32_t inside = 0;
    Point ref;
  };
  struct Candidate {
    float key;  // distance from the cell centre, rounded down
    std::uint32_t element;
  };
  static constexpr std::uint32_t kRefLeft = 1u << 31, kRefLens = 1u << 30, kElementBits = kRefLens - 1;

  std::vector<Segment> segments;
  std::vector<std::size_t> loop_of;
  std::vector<Kernel> kernels;
  std::vector<Box> boxes;
  std::vector<Node> nodes;
  std::vector<std::uint32_t> order;
  std::vector<Cell> cells;
  std::vector<Candidate> candidates;
  std::vector<std::uint32_t> covers;  // element | kRefLeft | kRefLens
  double ox = 0, oy = 0, size = 1, inv_size = 1;
  std::size_t nx = 0, ny = 0;

  std::uint32_t build_node(std::uint32_t begin, std::uint32_t end);
  void tree_nearest(Point p, double& best2, std::uint32_t& best) const;
  void tree_within(Point p, double radius, std::vector<std::pair<double, std::uint32_t>>& out) const;
  bool tree_ray_parity(Point p) const;
  void build_grid();
  double cell_nearest(std::size_t ix, std::size_t iy, Point p, std::uint32_t& best) const;
  Point centre(std::size_t ix, std::size_t iy) const {
    return {ox + (double(ix) + 0.5) * size, oy + (double(iy) + 0.5) * size};
  }
  RegionQuery answer(Point p, double best2, std::uint32_t best, bool inside) const {
    if (segments.empty()) return {kInf, p, 0};
    const double d = std::sqrt(best2);
    return {inside ? -d : d, nearest_on(kernels[best], segments[best], p), best};
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
    const Node& node = nodes[stack[--top]];
    if (box_distance2(node.box, p) >= best2) continue;
    if (node.count > 0) {
      for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
        const double d2 = distance2(kernels[order[i]], p);
        if (d2 < best2) best2 = d2, best = order[i];
      }
      continue;
    }
    const std::uint32_t left = static_cast<std::uint32_t>(&node - nodes.data()) + 1, right = node.right;
    const bool left_first = box_distance2(nodes[left].box, p) <= box_distance2(nodes[right].box, p);
    stack[top++] = left_first ? right : left;  // the nearer child is popped first
    stack[top++] = left_first ? left : right;
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
      odd ^= ray_parity(kernels[order[i]], segments[order[i]], p);
  }
  return odd;
}

double RegionIndex::Impl::cell_nearest(std::size_t ix, std::size_t iy, Point p, std::uint32_t& best) const {
  const std::size_t index = iy * nx + ix;
  const Point c = centre(ix, iy);
  const double from_centre = std::sqrt((p.x - c.x) * (p.x - c.x) + (p.y - c.y) * (p.y - c.y));
  double best2 = kInf;
  const Candidate* it = candidates.data() + cells[index].candidates;
  const Candidate* const end = candidates.data() + cells[index + 1].candidates;
  for (; it != end; ++it) {
    // |p - e| >= |c - e| - |p - c|: nothing further down the list can win.
    const double lower = double(it->key) - from_centre;
    if (lower > 0 && lower * lower >= best2) return best2;
    const double d2 = distance2(kernels[it->element], p);
    if (d2 < best2) best2 = d2, best = it->element;
  }
  const double lower = double(cells[index].complete) - from_centre;
  if (!(lower > 0 && lower * lower >= best2)) tree_nearest(p, best2, best);
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
  const double wanted = std::clamp(kCellsPerElement * double(segments.size()), 1.0, double(1 << 22));
  size = std::sqrt(width * height / wanted);
  nx = static_cast<std::size_t>(std::clamp(std::ceil(width / size), 1.0, double(1 << 13)));
  ny = static_cast<std::size_t>(std::clamp(std::ceil(height / size), 1.0, double(1 << 13)));
  size = std::max(width / double(nx), height / double(ny));
  inv_size = 1 / size;
  cells.assign(nx * ny + 1, Cell{});
  const auto column = [&](double x) { return std::size_t(std::clamp(std::floor((x - ox) * inv_size), 0.0, double(nx - 1))); };
  const auto row = [&](double y) { return std::size_t(std::clamp(std::floor((y - oy) * inv_size), 0.0, double(ny - 1))); };

  // Cover lists: elements cut into pieces of half a cell, each piece's box
  // (padded) marking the cells it may touch. Emitted in element order, so a
  // stable sort by cell leaves each cell's elements ascending.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> touches;
  const double pad = 1e-6 * size;
  for (std::uint32_t e = 0; e < segments.size(); ++e) {
    const double pieces = std::clamp(std::ceil(segment_length(segments[e]) / (size / 2)), 1.0, double(1 << 20));
    for (double i = 0; i < pieces; ++i) {
      const Box b = pieces == 1 ? boxes[e] : bounding_box(sub_segment(segments[e], i / pieces, (i + 1) / pieces));
      for (std::size_t y = row(b.min_y - pad); y <= row(b.max_y + pad); ++y)
        for (std::size_t x = column(b.min_x - pad); x <= column(b.max_x + pad); ++x)
          touches.emplace_back(static_cast<std::uint32_t>(y * nx + x), e);
    }
  }
  std::stable_sort(touches.begin(), touches.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  touches.erase(std::unique(touches.begin(), touches.end()), touches.end());
  for (const auto& [cell, e] : touches) ++cells[cell + 1].covers, covers.push_back(e);
  for (std::size_t i = 0; i < nx * ny; ++i) cells[i + 1].covers += cells[i].covers;

  // Candidate lists, from the tree: the nearest distance d from the centre,
  // then every element within d + a diagonal (what any point of the cell
  // may need), capped.
  const double diagonal = size * std::sqrt(2.0);
  std::vector<std::pair<double, std::uint32_t>> found;
  for (std::size_t iy = 0; iy < ny; ++iy) {
    double previous = kInf;
    for (std::size_t ix = 0; ix < nx; ++ix) {
      const Point c = centre(ix, iy);
      const double bound = previous + size;  // the previous centre's nearest is this close
      double best2 = bound < kInf ? bound * bound * (1 + 1e-9) : kInf;
      std::uint32_t best = 0;
      tree_nearest(c, best2, best);
      previous = std::sqrt(best2);
      const double window = (previous + diagonal) * (1 + 1e-12);
      found.clear();
      tree_within(c, window, found);
      std::sort(found.begin(), found.end());
      const std::size_t index = iy * nx + ix;
      cells[index].complete = float_below(found.size() > kMaxCandidates ? found[kMaxCandidates].first : window);
      found.resize(std::min(found.size(), kMaxCandidates));
      for (const auto& [d, e] : found) candidates.push_back({float_below(d), e});
      cells[index + 1].candidates = static_cast<std::uint32_t>(candidates.size());
    }
  }

  // Reference points: the first of a few scattered points of the cell that
  // keeps clear of the boundary; its inside flag from the ray test over the
  // cover lists of the cells to its right (no other element can cross).
  std::vector<std::size_t> stamp(segments.size(), SIZE_MAX);
  for (std::size_t iy = 0; iy < ny; ++iy)
    for (std::size_t ix = 0; ix < nx; ++ix) {
      const std::size_t index = iy * nx + ix;
      Cell& cell = cells[index];
      double clearest = -1;
      for (int k = 0; k < 8 && clearest < 1e-4 * size; ++k) {
        const double fx = 0.1 + 0.8 * std::fmod(0.5137 + 0.6180339887 * k, 1.0);
        const double fy = 0.1 + 0.8 * std::fmod(0.5291 + 0.7548776662 * k, 1.0);
        const Point q{ox + (double(ix) + fx) * size, oy + (double(iy) + fy) * size};
        std::uint32_t ignored = 0;
        const double clearance = std::sqrt(cell_nearest(ix, iy, q, ignored));
        if (clearance > clearest) clearest = clearance, cell.ref = q;
      }
      for (std::uint32_t m = cell.covers; m < cells[index + 1].covers; ++m) {
        const std::uint32_t e = covers[m];
        const bool left = left_of(segments[e].start, segments[e].end, cell.ref);
        covers[m] |= (left ? kRefLeft : 0) | (kernels[e].side != 0 && in_lens(kernels[e], left, cell.ref) ? kRefLens : 0);
      }
      bool odd = false;
      for (std::size_t right = index; right < (iy + 1) * nx; ++right)
        for (std::uint32_t m = cells[right].covers; m < cells[right + 1].covers; ++m) {
          const std::uint32_t e = covers[m] & kElementBits;
          if (stamp[e] == index) continue;
          stamp[e] = index;
          odd ^= ray_parity(kernels[e], segments[e], cell.ref);
        }
      cell.inside = odd;
    }
}

RegionIndex::RegionIndex(const std::vector<Loop>& loops) : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  for (std::size_t l = 0; l < loops.size(); ++l)
    for (const Segment& s : loops[l].segments) m.segments.push_back(s), m.loop_of.push_back(l);
  if (m.segments.size() >= Impl::kElementBits) throw Error("region boundary too large to index");
  if (m.segments.empty()) return;
  for (const Segment& s : m.segments) m.kernels.push_back(make_kernel(s)), m.boxes.push_back(bounding_box(s));
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
  const double best2 = m.cell_nearest(ix, iy, p, best);
  const std::size_t index = iy * m.nx + ix;
  const Impl::Cell& cell = m.cells[index];
  bool inside = cell.inside;
  for (std::uint32_t i = cell.covers; i < m.cells[index + 1].covers; ++i) {
    const std::uint32_t packed = m.covers[i], e = packed & Impl::kElementBits;
    inside ^= segment_parity(m.kernels[e], m.segments[e], cell.ref, p, packed & Impl::kRefLeft, packed & Impl::kRefLens);
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
      inside ^= ray_parity(k, s, p);
      ++index;
    }
  if (!nearest) return {kInf, p, 0};
  const double d = std::sqrt(best2);
  return {inside ? -d : d, nearest_on(make_kernel(*nearest), *nearest, p), best};
}

}  // namespace tk::cad
