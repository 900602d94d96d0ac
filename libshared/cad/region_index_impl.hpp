/// @file region_index_impl.hpp
/// @brief The inside of RegionIndex (see region_distance.cpp for the
/// design), shared by its query side (region_distance.cpp) and its build
/// side (region_index_build.cpp). Private to those two files.
#pragma once

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <mutex>
#include <vector>

#include "cad/region_distance.hpp"
#include "cad/segment_geometry.hpp"

namespace tk::cad {
namespace region_index {

inline constexpr double kInf = std::numeric_limits<double>::infinity();
// Tuned on bench_region_query's gear; see the file comment.
constexpr double kCoarseCellsPerElement = 1;
constexpr double kLeafCovers = 1;      // elements touching a leaf, about
constexpr double kLeafCandidates = 6;  // elements that may be nearest in a leaf, about
// Splits of a cell for that, at most. Four (and a leaf's list pruned at its
// own square, not again at its quarters): bench_region_query's queries
// 15 % fewer instructions than with two and one quartering (the random
// rate 3.5 against 3.1 million a second, the path's 9.3 against 7.3), its
// whole grid built in about 1.4 times the time (the 10k parts of
// bench_region_build's about the same); eight saved 10 % more
// instructions for 1.6 times again and no faster random queries.
constexpr double kMaxListSplit = 4;
constexpr std::size_t kMaxCandidates = 64;               // elements listed per leaf, at most
constexpr std::size_t kBlockCells = 8;                   // side of the blocks first asked of the tree, in cells
constexpr std::size_t kWideWindow = 4 * kMaxCandidates;  // a longer window is asked again less the dominated
// A cell whose window, less the elements dominated over it, is still
// longer than this keeps no lists (nor when the tree's search for them
// visits more nodes than kUndominatedVisits): its queries use the tree.
constexpr std::size_t kUndominatedWindow = kMaxCandidates;
constexpr std::size_t kUndominatedVisits = 200;
// A leaf's list longer than this is pruned again by dominance at the leaf
// (shorter ones are cheaper scanned by a query than pruned).
constexpr std::size_t kLeafDominance = 16;

/// An element prepared for queries. Arcs live in their chord frame as in
/// segment_geometry.cpp: local u along the chord from its midpoint, v
/// across it, mirrored so the arc bulges toward -v; the centre is at
/// (0, centre offset), the ends at (+-half chord, 0).
struct alignas(64) Kernel {  // one cache line
  double x = 0, y = 0;       ///< line: start; arc: chord midpoint
  double dx = 0, dy = 0;     ///< line: end - start; arc: unit chord direction
  double k0 = 0;             ///< line: 1 / |end - start|^2; arc: half chord
  double k1 = 0, k2 = 0;     ///< arc: centre offset, radius
  double side = 0;           ///< 0 line, +1 counter-clockwise arc, -1 clockwise
};

inline Kernel make_kernel(const Segment& s) {
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

[[gnu::always_inline]] inline double distance2(const Kernel& k, Point p) {
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
inline Point nearest_on(const Kernel& k, const Point* ends, Point p) {
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
inline float float_below(double d) {
  float f = static_cast<float>(d);
  if (static_cast<double>(f) > d) f = std::nextafter(f, -std::numeric_limits<float>::infinity());
  return f;
}
inline float float_above(double d) { return -float_below(-d); }

/// The square of the largest distance from p to a point of b.
inline double box_far2(const Box& b, Point p) {
  const double dx = std::max(p.x - b.min_x, b.max_x - p.x), dy = std::max(p.y - b.min_y, b.max_y - p.y);
  return dx * dx + dy * dy;
}

inline double box_distance2(const Box& b, Point p) {
  const double dx = std::max({b.min_x - p.x, 0.0, p.x - b.max_x});
  const double dy = std::max({b.min_y - p.y, 0.0, p.y - b.max_y});
  return dx * dx + dy * dy;
}

/// The tie rule of every nearest-element search: the smaller squared
/// distance, and of two equal ones the lower element index (as brute force,
/// which scans in index order), so that the element named never depends on
/// how the index happens to be built.
inline bool nearer(double d2, std::uint32_t e, double best2, std::uint32_t best) {
  return d2 < best2 || (d2 == best2 && e < best);
}

/// Whether an element no nearer than `lower` (a lower bound on its
/// distance, less the rounding margin) can neither beat the best nor tie
/// with it; strictly, so that an equally near one is still examined for
/// the tie rule.
inline bool cannot_win(double lower, double best2) { return lower > 0 && lower * lower > best2; }

struct Square {  // a leaf's or a block's, as a box that is all its points
  double x0, y0, x1, y1;
};

/// Whether an element (or every element within a box) is farther from each
/// point of a square than q is, by more than a margin: then, q being a
/// point of another element, it is nearest to none of them, and a list
/// for the square can leave it out.
///
/// The corners settle it. For any set E (a segment, an arc, a box),
/// G(p) = (|p - q| + m)^2 - d(p, E)^2 is the largest over the points x of
/// E of (|p - q| + m)^2 - |p - x|^2, each of which is convex in p
/// (|p - q|^2 - |p - x|^2 is linear, 2m|p - q| convex): so G is convex,
/// and below zero over the square as soon as it is at the four corners.
class Dominance {
 public:
  Dominance(const Square& s, Point q, double margin) : corner_{{s.x0, s.y0}, {s.x1, s.y0}, {s.x0, s.y1}, {s.x1, s.y1}} {
    for (int i = 0; i < 4; ++i) {
      const double dx = corner_[i].x - q.x, dy = corner_[i].y - q.y, beyond = std::sqrt(dx * dx + dy * dy) + margin;
      beyond2_[i] = beyond * beyond;
    }
  }
  bool dominated(const Kernel& k) const {
    for (int i = 0; i < 4; ++i)
      if (!(distance2(k, corner_[i]) > beyond2_[i])) return false;
    return true;
  }
  bool dominated(const Box& b) const {
    for (int i = 0; i < 4; ++i)
      if (!(box_distance2(b, corner_[i]) > beyond2_[i])) return false;
    return true;
  }

 private:
  Point corner_[4];
  double beyond2_[4];  // (|corner - q| + margin)^2, which the squared distance must pass
};

inline Box merge(const Box& a, const Box& b) {
  return {std::min(a.min_x, b.min_x), std::min(a.min_y, b.min_y), std::max(a.max_x, b.max_x),
          std::max(a.max_y, b.max_y)};
}

}  // namespace region_index

using namespace region_index;

struct RegionIndex::Impl {
  struct Node {  // of the box tree; its left child is the next node
    Box box;
    // count > 0: a leaf over order[first, first + count); count == 0: an
    // inner node over `first` elements
    std::uint32_t first = 0, count = 0, right = 0;
  };
  struct Coarse {  // a grid cell, split into split x split leaves numbered from first_leaf
    std::uint32_t first_leaf, split;
  };
  struct Candidate {
    float key = INFINITY;  // the element's distance from the leaf centre, rounded down
    std::uint32_t element = 0;
  };
  static constexpr std::size_t kHead = 4;
  struct alignas(64) Leaf {        // one cache line; leaves[i + 1].candidates / .covers end leaf i's lists
    std::uint32_t candidates = 0;  // the list after the head
    std::uint32_t covers : 31 = 0, inside : 1 = 0;  // inside: whether ref is
    float complete = 0;     // every element that can win and is nearer the centre than this is listed
    float nearest = 0;      // the centre's distance to the boundary, rounded up
    Point ref;              // a point of the leaf clear of the boundary
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
  /// The box tree again, two of its levels to a node, for the nearest-
  /// element search: half the steps, four boxes at a time (tree_nearest
  /// took 1.5 to 2 times as long over the binary nodes).
  static constexpr std::uint32_t kLeafChild = 1u << 31, kNoChild = UINT32_MAX;
  struct alignas(64) Wide {
    // Child k's elements lie in the rectangle lo_u <= u.x <= hi_u, lo_v <= v.x <= hi_v,
    // u = (ux, uy) a unit vector, v = (-uy, ux). Along the chord of a finely
    // divided curve it is far thinner than the axis-aligned box, whose corner
    // reaches toward a point R off the curve: offsetting a 100k-element wavy
    // ring, the tree's searches visited 18 nodes each over boxes, 9.4 over
    // rectangles. (The fields a node of boxes alone reads come first, in
    // three cache lines.)
    double lo_u[4], hi_u[4], lo_v[4], hi_v[4];
    std::uint32_t child[4];           // a Wide node, or kLeafChild | the leaf's first in `order`, or kNoChild
    std::uint32_t count[4];           // a leaf's elements
    bool oriented;                    // whether any child's u is not (1, 0) (else the rectangles are boxes)
    alignas(16) double ux[4], uy[4];  // (aligned for SSE2 loads)
  };
  std::vector<Wide> wide;
  struct Frame {  // one child's rectangle as in Wide; while building, the chord it runs along
    double ux = 1, uy = 0, lo_u = kInf, hi_u = -kInf, lo_v = kInf, hi_v = -kInf;
    Point a, b;
  };
  /// The rectangle about `points` along the chord of `chord_ends` (two far
  /// apart of them), or `box` unless the rectangle is much the smaller.
  /// A leaf's from its elements, an inner node's from its children's chords and corners.
  Frame frame(const Point* chord_ends, std::size_t end_count, const Point* points, std::size_t point_count,
              const Box& box) const;
  // kernels[order[i]] at i: a leaf's elements side by side, for tree_nearest.
  // (Not for tree_within: the grid's build reads `kernels` for the same
  // elements just after, and the second array cost its whole grid some 9 %.)
  std::vector<Kernel> ordered_kernels;

  /// The grid's cells, kBlockCells a side to a tile, each tile built whole
  /// by the first query that lands in it: a check along a tool path builds
  /// the tiles it passes and waits for no others.
  struct Tile {
    Coarse coarse[kBlockCells * kBlockCells];  // cell (x0 + i, y0 + j) at j * kBlockCells + i
    std::vector<Leaf> leaves;                  // and one past the last, whose offsets end the last's lists
    std::vector<Candidate> candidates;
    std::vector<Cover> covers;
  };
  /// A piece [t0, t1] of an element whose padded box may touch a cell;
  /// listed cell by cell (cell c's from touch_first[c]), each cell's in element order.
  struct Touch {
    std::uint32_t element;
    double t0, t1;
  };
  // Released (mutable for that) once the last tile is built.
  mutable std::vector<Touch> touches;
  mutable std::vector<std::uint32_t> touch_first;
  std::unique_ptr<std::atomic<Tile*>[]> tiles;  // owned; null until built
  std::unique_ptr<std::once_flag[]> tile_once;  // one builder a tile; others asking meanwhile wait
  mutable std::atomic<std::size_t> tiles_built{0};
  std::size_t tiles_x = 0, tiles_y = 0;
  struct CellWindow {  // while building a tile: the elements that may be nearest in a cell (region_index_cells.cpp)
    std::uint32_t first = 0, count = 0;
    double nearest = 0;  // the cell centre's distance to the boundary
    bool wide = false;   // too many: the cell's leaves keep no list
    // Far from the boundary: the window is what the tree found undominated
    // over the cell, and the cell is split only for its covers.
    bool sparse = false;
  };
  /// One building thread's scratch: a mark per element, distances from a
  /// centre, a cell's leaves' lists, and the tile being built (origin x0,
  /// y0 in cells) with its cells' windows.
  struct Workspace {
    std::vector<std::uint32_t> stamp;
    std::uint32_t mark = 0;
    std::vector<double> near, far2;
    std::vector<std::vector<std::uint32_t>> leaf_lists;
    std::size_t x0 = 0, y0 = 0;
    CellWindow windows[kBlockCells * kBlockCells];
    std::vector<std::uint32_t> window_elements;
    explicit Workspace(std::size_t elements) : stamp(elements, 0), near(elements) {}
    std::size_t local(std::size_t x, std::size_t y) const { return (y - y0) * kBlockCells + (x - x0); }
  };
  /// Workspaces between tile builds (each as large as the boundary).
  mutable std::mutex spare_mutex;
  mutable std::vector<std::unique_ptr<Workspace>> spare;

  /// The grid's layout and the touches come with the first query() (not
  /// with Layout::tree, nor with nearest(), which uses the tiles built).
  bool grid_wanted = false;
  std::once_flag grid_once;
  std::atomic<bool> grid_ready{false};
  void ensure_grid();
  void build_grid();
  void build_touches();
  double ox = 0, oy = 0, size = 1, inv_size = 1;
  double rounding = 0;  // beyond the rounding of any computed distance (as the boxes' padding)
  std::size_t nx = 0, ny = 0;

  Impl() = default;
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;
  ~Impl() {
    for (std::size_t i = 0; tiles && i < tiles_x * tiles_y; ++i) delete tiles[i].load();
  }

  std::uint32_t build_node(std::uint32_t begin, std::uint32_t end);
  /// The Wide node over binary node `node`: its grandchildren (or children that are leaves).
  std::uint32_t build_wide(std::uint32_t node, Frame& whole);
  /// The squared distances from p to node's four rectangles (region_distance.cpp).
  [[gnu::always_inline]] static inline void child_distances(const Wide& node, Point p, double* box2);
  void tree_nearest(Point p, double& best2, std::uint32_t& best) const;
  /// The elements within `radius` of p (and any whose padded box is),
  /// less those `less` finds dominated (whole boxes at once); false (out
  /// unfinished) as soon as there are more than `cap`, or past `visits` of the tree's nodes.
  bool tree_within(Point p, double radius, std::vector<std::uint32_t>& out, std::size_t cap = SIZE_MAX,
                   const Dominance* less = nullptr, std::size_t visits = SIZE_MAX) const;
  bool tree_ray_parity(Point p) const;

  struct Nearest {  // an element nearest to a point, and how near
    double distance;
    std::uint32_t element;
  };
  /// The test over the square round c of half side `half`, by the point
  /// of `nearest` (c's nearest element) nearest to c.
  Dominance dominance(Point c, double half, Nearest nearest) const;

  /// Tile (tx, ty), built now if no thread has built it yet.
  const Tile& tile_at(std::size_t tx, std::size_t ty) const;
  void build_tile(Workspace& w, Tile& t) const;
  /// The windows of block [x0, x0 + span)^2 of cells (in w's tile), from the tree.
  void ask_block(Workspace& w, std::size_t x0, std::size_t y0, std::size_t span) const;
  void split_block(Workspace& w, std::size_t x0, std::size_t y0, std::size_t span, std::vector<std::uint32_t>& list,
                   Nearest nearest) const;
  /// Appends to `out` the elements of `in` that may be nearest to a point of
  /// the square round c of half side `half`; returns the nearest of them to c.
  Nearest prune(Workspace& w, Point c, double half, const std::uint32_t* in, std::size_t count,
                std::vector<std::uint32_t>& out) const;
  /// Drops from `list` the elements dominance(c, half, nearest) finds dominated.
  void drop_dominated(std::vector<std::uint32_t>& list, Point c, double half, Nearest nearest) const;
  /// Cell (x, y)'s window: `list`, c's nearest distance `nearest`.
  void store_window(Workspace& w, std::size_t x, std::size_t y, const std::vector<std::uint32_t>& list, double nearest,
                    bool sparse) const;
  /// The tile's leaves and which elements may touch each.
  void build_covers(Workspace& w, Tile& t) const;
  void build_lists(Workspace& w, Tile& t) const;
  void build_leaves(Workspace& w, const Tile& t, std::size_t x, std::size_t y, std::uint32_t x0, std::uint32_t y0,
                    std::uint32_t span, const std::vector<std::uint32_t>& list) const;
  /// Leaf (lx, ly) of cell (x, y), from its list (sorted here, in place).
  void build_leaf(Workspace& w, Tile& t, std::size_t x, std::size_t y, std::uint32_t lx, std::uint32_t ly,
                  std::vector<std::uint32_t>& listed) const;
  /// Reference points of the tile's leaves (their lists complete).
  void build_refs(Workspace& w, Tile& t) const;
  /// Each leaf's inside flag: the ray test at the tile's first leaf, then
  /// from leaf to leaf by the crossings of the segments joining their
  /// reference points (as a query does from the reference point).
  void build_inside(Workspace& w, Tile& t) const;
  bool chain_parity(Workspace& w, Point from, Point to, const std::vector<std::uint32_t>& elements) const;

  double leaf_nearest(const Tile& t, std::size_t leaf, Point centre, Point p, std::uint32_t& best) const;
  /// The tile and leaf p falls in and its centre; false outside the grid
  /// (or without one), or in a tile not built unless `build`.
  bool locate(Point p, bool build, const Tile*& tile, std::size_t& leaf, Point& leaf_centre) const;
  /// Centre of leaf (x, y) of cell (ix, iy), the same point for building and querying.
  Point centre(std::size_t ix, std::size_t iy, std::uint32_t split, std::uint32_t x, std::uint32_t y) const {
    // split is a power of two up to 32: times its inverse is the same as over it, to the bit.
    static constexpr double kInverse[6] = {1, 0.5, 0.25, 0.125, 0.0625, 0.03125};
    const double inverse = kInverse[std::countr_zero(split)];
    return {ox + (double(std::int64_t(ix)) + (x + 0.5) * inverse) * size,
            oy + (double(std::int64_t(iy)) + (y + 0.5) * inverse) * size};
  }
  RegionQuery answer(Point p, double best2, std::uint32_t best, bool inside) const {
    const double d = std::sqrt(best2);
    return {inside ? -d : d, nearest_on(kernels[best], &ends[2 * best], p), best};
  }
};

}  // namespace tk::cad
