/// @file region_union.cpp
/// @brief The offset's even-odd union, skipped for simple disjoint loops
/// (see region_union.hpp): a Shamos-Hoey sweep with exact integer tests.
#include "cad/region_union.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <set>
#include <utility>
#include <vector>

namespace tk::cad {
namespace {

using ClipperLib::cInt;
using ClipperLib::IntPoint;
__extension__ typedef __int128 WideInt;  // products of coordinate differences (< 2^63 each) fit

int sign_of(WideInt v) { return (v > 0) - (v < 0); }

}  // namespace

int orient_exact(const IntPoint& a, const IntPoint& b, const IntPoint& c) {
  return sign_of(WideInt(b.X - a.X) * WideInt(c.Y - a.Y) - WideInt(b.Y - a.Y) * WideInt(c.X - a.X));
}

namespace {

bool lexicographic_less(const IntPoint& a, const IntPoint& b) { return a.X != b.X ? a.X < b.X : a.Y < b.Y; }

/// One edge of a path; `left` is its lexicographically smaller end.
struct SweepEdge {
  IntPoint left, right;
  IntPoint from, to;  // as the path runs
  std::size_t path = 0, index = 0, path_size = 0;
};

/// c on the closed segment a-b, given that the three are collinear.
bool on_closed_segment(const IntPoint& a, const IntPoint& b, const IntPoint& c) {
  return std::min(a.X, b.X) <= c.X && c.X <= std::max(a.X, b.X) && std::min(a.Y, b.Y) <= c.Y &&
         c.Y <= std::max(a.Y, b.Y);
}

/// Whether two edges meet where a simple set of loops may not: anywhere,
/// unless they follow each other in one path, where they may share their
/// common vertex (and not double back over each other).
bool edges_meet(const SweepEdge& a, const SweepEdge& b) {
  if (a.path == b.path && a.path_size >= 3) {
    const SweepEdge* first = nullptr;
    const SweepEdge* second = nullptr;
    if ((a.index + 1) % a.path_size == b.index) first = &a, second = &b;
    if ((b.index + 1) % b.path_size == a.index) first = &b, second = &a;
    if (first) {  // share first->to == second->from; collinear and turning back is an overlap
      if (orient_exact(first->from, first->to, second->to) != 0) return false;
      const WideInt along = WideInt(first->to.X - first->from.X) * WideInt(second->to.X - second->from.X) +
                            WideInt(first->to.Y - first->from.Y) * WideInt(second->to.Y - second->from.Y);
      return along < 0;
    }
  }
  const int o1 = orient_exact(a.left, a.right, b.left), o2 = orient_exact(a.left, a.right, b.right);
  const int o3 = orient_exact(b.left, b.right, a.left), o4 = orient_exact(b.left, b.right, a.right);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return (o1 == 0 && on_closed_segment(a.left, a.right, b.left)) ||
         (o2 == 0 && on_closed_segment(a.left, a.right, b.right)) ||
         (o3 == 0 && on_closed_segment(b.left, b.right, a.left)) ||
         (o4 == 0 && on_closed_segment(b.left, b.right, a.right));
}

/// The sweep line's order, at the abscissa where the later of the two
/// edges starts: by height there, then by slope, then by position in the
/// input (meaningful among edges that do not meet, which is all the sweep
/// needs until it finds a pair that does).
struct BelowAtSweep {
  const std::vector<SweepEdge>* edges;
  bool operator()(std::size_t i, std::size_t j) const {
    const SweepEdge& a = (*edges)[i];
    const SweepEdge& b = (*edges)[j];
    int height;  // sign of a's height minus b's
    if (a.left.X >= b.left.X)
      height = b.left.X == b.right.X ? sign_of(WideInt(a.left.Y) - WideInt(b.left.Y))
                                     : orient_exact(b.left, b.right, a.left);
    else
      height = a.left.X == a.right.X ? sign_of(WideInt(a.left.Y) - WideInt(b.left.Y))
                                     : -orient_exact(a.left, a.right, b.left);
    if (height != 0) return height < 0;
    const int slope = sign_of(WideInt(a.right.X - a.left.X) * WideInt(b.right.Y - b.left.Y) -
                              WideInt(a.right.Y - a.left.Y) * WideInt(b.right.X - b.left.X));
    if (slope != 0) return slope > 0;  // b turns counter-clockwise from a: steeper, so above
    return i < j;
  }
};

}  // namespace

ClipperLib::Path without_repeats(const ClipperLib::Path& path) {
  ClipperLib::Path distinct;
  distinct.reserve(path.size());
  for (const IntPoint& p : path)
    if (distinct.empty() || !(distinct.back() == p)) distinct.push_back(p);
  while (distinct.size() > 1 && distinct.back() == distinct.front()) distinct.pop_back();
  return distinct;
}

bool simple_and_disjoint(const ClipperLib::Paths& paths) {
  std::vector<SweepEdge> edges;
  for (std::size_t p = 0; p < paths.size(); ++p) {
    const ClipperLib::Path& path = paths[p];
    if (path.size() < 3) return false;
    for (std::size_t i = 0; i < path.size(); ++i) {
      // Transposed, so the sweep line runs along x as Clipper's does: where
      // the caller turned the paths for Clipper (clipper_sweep.hpp), it
      // crosses few edges for this sweep too. Meeting is unchanged by it.
      const IntPoint from{path[i].Y, path[i].X};
      const IntPoint to{path[(i + 1) % path.size()].Y, path[(i + 1) % path.size()].X};
      if (from == to) return false;  // a repeated vertex: not a polygon's edge
      const bool forward = lexicographic_less(from, to);
      edges.push_back({forward ? from : to, forward ? to : from, from, to, p, i, path.size()});
    }
  }
  // Events: an edge enters at its left end, leaves at its right end; at one
  // abscissa all entries come before the leavings (so edges touching there are compared).
  struct SweepEvent {
    cInt x;
    bool leaves;
    std::size_t edge;
  };
  std::vector<SweepEvent> events;
  events.reserve(2 * edges.size());
  for (std::size_t e = 0; e < edges.size(); ++e)
    events.push_back({edges[e].left.X, false, e}), events.push_back({edges[e].right.X, true, e});
  std::sort(events.begin(), events.end(), [&](const SweepEvent& a, const SweepEvent& b) {
    if (a.x != b.x) return a.x < b.x;
    if (a.leaves != b.leaves) return !a.leaves;
    return lexicographic_less(edges[a.edge].left, edges[b.edge].left);
  });
  using Sweep = std::set<std::size_t, BelowAtSweep>;
  Sweep sweep(BelowAtSweep{&edges});
  std::vector<Sweep::iterator> where(edges.size());
  for (const SweepEvent& event : events) {
    const std::size_t e = event.edge;
    if (!event.leaves) {
      const auto above = sweep.lower_bound(e);
      if (above != sweep.end() && edges_meet(edges[*above], edges[e])) return false;
      if (above != sweep.begin() && edges_meet(edges[*std::prev(above)], edges[e])) return false;
      where[e] = sweep.insert(above, e);
    } else {
      const auto at = where[e];
      const auto above = std::next(at);
      if (at != sweep.begin() && above != sweep.end() && edges_meet(edges[*std::prev(at)], edges[*above])) return false;
      sweep.erase(at);
    }
  }
  return true;
}

namespace {

// without_collinear() on a path already without repeats.
ClipperLib::Path corners_of(const ClipperLib::Path& distinct) {
  // Clipper drops a vertex whose neighbours are collinear with it, again
  // until none is; on a path that does not double back, one pass against
  // the original neighbours drops the same (the inner vertices of each straight run).
  ClipperLib::Path corners;
  const std::size_t n = distinct.size();
  for (std::size_t i = 0; i < n; ++i)
    if (n < 3 || orient_exact(distinct[(i + n - 1) % n], distinct[i], distinct[(i + 1) % n]) != 0)
      corners.push_back(distinct[i]);
  return corners;
}

}  // namespace

ClipperLib::Path without_collinear(const ClipperLib::Path& path) { return corners_of(without_repeats(path)); }

bool even_odd_union(ClipperLib::Paths& paths, const std::vector<bool>& outer) {
  ClipperLib::Paths distinct;
  distinct.reserve(paths.size());
  for (const ClipperLib::Path& path : paths) distinct.push_back(without_repeats(path));
  bool skip = outer.size() == paths.size() && simple_and_disjoint(distinct);
  ClipperLib::Paths cleaned;
  if (skip) {
    cleaned.reserve(paths.size());
    for (std::size_t i = 0; i < distinct.size() && skip; ++i) {
      cleaned.push_back(corners_of(distinct[i]));
      // Rounding to integers can flip a sliver; then Clipper decides.
      skip = cleaned.back().size() >= 3 && ClipperLib::Orientation(cleaned.back()) == outer[i] &&
             ClipperLib::Area(cleaned.back()) != 0;
    }
  }
  if (skip) {
    // As Clipper's union hands them on (what the offset's own sweep
    // breaks ties by): each path from the vertex after its lowest, the
    // paths by their highest vertex, highest first.
    for (ClipperLib::Path& path : cleaned) {
      const auto lowest = std::min_element(path.begin(), path.end(), [](const IntPoint& a, const IntPoint& b) {
        return a.Y != b.Y ? a.Y < b.Y : a.X < b.X;
      });
      std::rotate(path.begin(), std::next(lowest) == path.end() ? path.begin() : std::next(lowest), path.end());
    }
    std::vector<std::pair<cInt, std::size_t>> by_top;
    for (std::size_t i = 0; i < cleaned.size(); ++i) {
      cInt top = cleaned[i][0].Y;
      for (const IntPoint& p : cleaned[i]) top = std::max(top, p.Y);
      by_top.push_back({-top, i});  // highest first, then in the input's order
    }
    std::sort(by_top.begin(), by_top.end());
    paths.clear();
    for (const auto& [minus_top, i] : by_top) paths.push_back(std::move(cleaned[i]));
    return true;
  }
  ClipperLib::Clipper even_odd;
  even_odd.AddPaths(paths, ClipperLib::ptSubject, true);
  even_odd.Execute(ClipperLib::ctUnion, paths, ClipperLib::pftEvenOdd, ClipperLib::pftEvenOdd);
  return false;
}

}  // namespace tk::cad
