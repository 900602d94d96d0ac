/// @file offset_polygons.cpp
/// @brief Round-joined offset of closed polygons (see offset_polygons.hpp).
#include "cad/offset_polygons.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "cad/offset_notches.hpp"
#include "cad/region_union.hpp"

namespace tk::cad {
namespace {

using ClipperLib::cInt;
using ClipperLib::IntPoint;
using ClipperLib::Path;
using ClipperLib::Paths;

constexpr double kDefaultArcTolerance = 0.25;  // Clipper's, in its units
constexpr double kFillWorth = 0.25;            // of the offset: shallower fills save too little

cInt round_half_away(double v) { return static_cast<cInt>(v < 0 ? v - 0.5 : v + 0.5); }

struct Normal {
  double x = 0, y = 0;
};

/// The unit normal to the right of a -> b (outward for a counter-clockwise
/// polygon), as Clipper computes it, and the edge's length on the way.
Normal unit_normal(IntPoint a, IntPoint b, double& length) {
  double dx = double(b.X - a.X), dy = double(b.Y - a.Y);
  length = std::sqrt(dx * dx + dy * dy);
  if (length == 0) return {};
  const double f = 1 / length;
  dx *= f, dy *= f;
  return {dy, -dx};
}

class JoinDrawer {
 public:
  JoinDrawer(double delta, double arc_tolerance, ConcaveCorners concave)
      : delta_(delta), crossing_(concave == ConcaveCorners::crossing) {
    const double magnitude = std::abs(delta);
    const double tolerance = tolerance_ = arc_tolerance <= 0 ? kDefaultArcTolerance
                                          : arc_tolerance > magnitude * kDefaultArcTolerance
                                              ? magnitude * kDefaultArcTolerance
                                              : arc_tolerance;
    double steps = std::numbers::pi / std::acos(1 - tolerance / magnitude);
    steps = std::min(steps, magnitude * std::numbers::pi);  // no more chords than units of length
    sin_ = std::sin(2 * std::numbers::pi / steps), cos_ = std::cos(2 * std::numbers::pi / steps);
    steps_per_radian_ = steps / (2 * std::numbers::pi);
    if (delta < 0) sin_ = -sin_;
  }

  Path offset(const Path& source) const {
    const std::size_t n = source.size();
    std::vector<Normal> normals(n);
    std::vector<double> lengths(n);
    for (std::size_t j = 0; j < n; ++j) {
      const IntPoint a = source[j], b = source[(j + 1) % n];
      normals[j] = unit_normal(a, b, lengths[j]);
    }
    Path out;
    out.reserve(2 * n);
    // As in Clipper, a vertex passed straight on leaves the edge before it
    // the one its successor turns from.
    for (std::size_t j = 0, k = n - 1; j < n; ++j)
      if (corner(source[j], normals[k], normals[j], std::min(lengths[k], lengths[j]), out)) k = j;
    return out;
  }

  /// The chords' largest distance from their arcs (Clipper units).
  double tolerance() const { return tolerance_; }

 private:
  IntPoint along(IntPoint p, Normal n) const {
    return {round_half_away(double(p.X) + n.x * delta_), round_half_away(double(p.Y) + n.y * delta_)};
  }

  /// The offset's points at vertex p between the edge with normal `before`
  /// and the one with normal `after`, the shorter of the two `shorter` long;
  /// false where it goes straight on (one point, on the edge before).
  bool corner(IntPoint p, Normal before, Normal after, double shorter, Path& out) const {
    double sin_turn = before.x * after.y - after.x * before.y;
    const double cos_turn = before.x * after.x + before.y * after.y;
    if (std::abs(sin_turn * delta_) < 1) {
      if (cos_turn > 0) {  // straight on, within a unit
        out.push_back(along(p, before));
        return false;
      }
    } else {
      sin_turn = std::clamp(sin_turn, -1.0, 1.0);
    }
    if (sin_turn * delta_ < 0) {  // concave
      // Where the two offset edges cross, each cut short by |delta| tan(turn / 2).
      const double cut = std::abs(delta_ * sin_turn) / (1 + cos_turn);
      if (crossing_ && cut <= shorter / 2) {
        const double scale = delta_ / (1 + cos_turn);
        out.push_back({round_half_away(double(p.X) + (before.x + after.x) * scale),
                       round_half_away(double(p.Y) + (before.y + after.y) * scale)});
        return true;
      }
      out.push_back(along(p, before));
      out.push_back(p);
      out.push_back(along(p, after));
      return true;
    }
    const double turn = std::atan2(sin_turn, cos_turn);
    const int steps = std::max(static_cast<int>(round_half_away(steps_per_radian_ * std::abs(turn))), 1);
    double x = before.x, y = before.y;
    for (int i = 0; i < steps; ++i) {
      out.push_back(along(p, {x, y}));
      const double x0 = x;
      x = x * cos_ - sin_ * y;
      y = x0 * sin_ + y * cos_;
    }
    out.push_back(along(p, after));
    return true;
  }

  double delta_;
  bool crossing_;
  double tolerance_ = 0;
  double sin_ = 0, cos_ = 1, steps_per_radian_ = 0;
};

}  // namespace

void offset_polygons(const Paths& paths, double delta, double arc_tolerance, ClipperLib::PolyTree& out,
                     ConcaveCorners concave, Notches notches) {
  out.Clear();
  Paths sources;
  for (const Path& path : paths)  // Clipper offsets a closed path of three distinct vertices or more
    if (Path clean = without_repeats(path); clean.size() >= 3) sources.push_back(std::move(clean));
  // The path with the lowest point (largest y, then smallest x; the first
  // of equals) is an outer boundary: its orientation says which way is out.
  const Path* lowest = nullptr;
  IntPoint bottom;
  for (const Path& path : sources)
    for (const IntPoint& p : path)
      if (!lowest || p.Y > bottom.Y || (p.Y == bottom.Y && p.X < bottom.X)) lowest = &path, bottom = p;
  if (lowest && !ClipperLib::Orientation(*lowest))
    for (Path& path : sources) ClipperLib::ReversePath(path);
  Paths offsets;
  if (delta > -1e-20 && delta < 1e-20) {
    offsets = sources;
  } else {
    const JoinDrawer drawer(delta, arc_tolerance, concave);
    const Paths* drawn = &sources;
    Paths filled_paths;
    if (notches == Notches::filled) {
      std::size_t filled = 0;
      for (const Path& path : sources)
        filled_paths.push_back(fill_notches(path, delta, drawer.tolerance(), kFillWorth * std::abs(delta), filled));
      // A path reaching into another's notch would now cross it: then none is filled.
      if (filled > 0 && simple_and_disjoint(filled_paths)) drawn = &filled_paths;
    }
    for (const Path& path : *drawn) offsets.push_back(drawer.offset(path));
  }
  ClipperLib::Clipper clipper;
  clipper.AddPaths(offsets, ClipperLib::ptSubject, true);
  if (delta > 0) {
    clipper.Execute(ClipperLib::ctUnion, out, ClipperLib::pftPositive, ClipperLib::pftPositive);
    return;
  }
  // Shrinking: the union of a frame round everything with the reversed
  // offsets, filled where negative; the frame is then dropped.
  const ClipperLib::IntRect r = clipper.GetBounds();
  clipper.AddPath({{r.left - 10, r.bottom + 10},
                   {r.right + 10, r.bottom + 10},
                   {r.right + 10, r.top - 10},
                   {r.left - 10, r.top - 10}},
                  ClipperLib::ptSubject, true);
  clipper.ReverseSolution(true);
  clipper.Execute(ClipperLib::ctUnion, out, ClipperLib::pftNegative, ClipperLib::pftNegative);
  if (out.ChildCount() == 1 && out.Childs[0]->ChildCount() > 0) {
    // The frame's children, in order, take its place (each keeps its index among them).
    ClipperLib::PolyNode* frame = out.Childs[0];
    out.Childs = frame->Childs;
    for (ClipperLib::PolyNode* child : out.Childs) child->Parent = &out;
    frame->Childs.clear();
  } else {
    out.Clear();
  }
}

}  // namespace tk::cad
