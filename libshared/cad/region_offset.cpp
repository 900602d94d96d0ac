/// @file region_offset.cpp
/// @brief Tool-radius offset: Clipper for the topology, exact lines and arcs
/// recovered from the drawing's features, and the stretches left uncut.
#include "cad/region_offset.hpp"

#include <fmt/format.h>
#include <polyclipping/clipper.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include <ctime>

#include "cad/clipper_sweep.hpp"
#include "cad/offset_polygons.hpp"
#include "cad/region_uncut.hpp"
#include "cad/region_union.hpp"
#include "cad/segment_geometry.hpp"
#include "cli/option_checks.hpp"
#include "io/error.hpp"

namespace tk::cad {
namespace {

constexpr double kClipperUnitMm = 1e-6;  // 1 nm integers: ±4.6e12 mm fit Clipper's 62-bit range
constexpr double kLargestCoordinateMm = 1e9;
// Of the tool radius, on large parts (join_tolerance): first try, and after a failed recovery.
constexpr double kCoarseJoinSagitta = 1e-2, kFineJoinSagitta = 1e-3;
constexpr double kLargestPartMm = 1e6;  // a kilometre: beyond it, the units are wrong, not the machine big

Point operator+(Point a, Point b) { return {a.x + b.x, a.y + b.y}; }
Point operator-(Point a, Point b) { return {a.x - b.x, a.y - b.y}; }
Point operator*(double s, Point a) { return {s * a.x, s * a.y}; }
double dot(Point a, Point b) { return a.x * b.x + a.y * b.y; }
double cross(Point a, Point b) { return a.x * b.y - a.y * b.x; }
double norm(Point a) { return std::hypot(a.x, a.y); }
Point unit(Point a) {
  const double n = norm(a);
  return n > 0 ? (1 / n) * a : Point{};
}

/// The exact curve a stretch of the offset follows: a line (through
/// `origin` along unit `direction`) or a circle.
struct Primitive {
  bool circle = false;
  Point origin, direction;  // line
  Point centre;             // circle
  double radius = 0;

  Point project(Point p) const {
    if (!circle) return origin + dot(p - origin, direction) * direction;
    const Point d = p - centre;
    const double n = norm(d);
    return n > 0 ? centre + (radius / n) * d : centre + Point{radius, 0};
  }
};

/// What a point of the offset is nearest to: an element's inside, or a
/// corner of the drawing (identified by the element that starts there).
struct Feature {
  std::size_t element = 0;
  bool corner = false;
  bool operator==(const Feature&) const = default;
};

/// The drawing's elements with the successor of each within its loop.
class DrawingFeatures {
 public:
  DrawingFeatures(const std::vector<Loop>& drawn, const RegionIndex& index) : index_(index) {
    for (const Loop& loop : drawn) {
      const std::size_t first = next_.size();
      for (std::size_t i = 0; i < loop.segments.size(); ++i)
        next_.push_back(i + 1 < loop.segments.size() ? next_.size() + 1 : first);
    }
  }

  /// The feature nearest to p; the offset curve through p at distance R.
  Feature classify(Point p) const {
    // Points come along the polygon: the last answer is a near element, a
    // bound for the tree's search (the index's grid is built only for
    // signed-distance queries; the answer is the same either way).
    const RegionQuery q = index_.nearest(p, hint_);
    hint_ = q.element;
    const Segment& s = index_.elements()[q.element];
    double t = 0;
    nearest_point(s, p, &t);
    if (t <= 0) return {q.element, true};
    if (t >= 1) return {next_[q.element], true};
    return {q.element, false};
  }

  Primitive primitive(const Feature& f, Point near, double radius) const {
    const Segment& s = index_.elements()[f.element];
    Primitive prim;
    if (f.corner) {
      prim.circle = true;
      prim.centre = s.start;
      prim.radius = radius;
    } else if (!is_arc(s)) {
      prim.direction = unit(s.end - s.start);
      const Point left{-prim.direction.y, prim.direction.x};
      const double side = cross(prim.direction, near - s.start) >= 0 ? 1 : -1;
      prim.origin = s.start + (side * radius) * left;
    } else {
      const ArcShape arc = arc_shape(s);
      prim.circle = true;
      prim.centre = arc.centre;
      prim.radius = norm(near - arc.centre) >= arc.radius ? arc.radius + radius : std::max(arc.radius - radius, 0.0);
    }
    return prim;
  }

 private:
  const RegionIndex& index_;
  std::vector<std::size_t> next_;
  mutable std::size_t hint_ = SIZE_MAX;
};

/// Where two exact curves cross, nearest to `near`; nullopt when they do
/// not (tangent within rounding, or parallel).
std::optional<Point> crossing_near(const Primitive& a, const Primitive& b, Point near) {
  std::vector<Point> found;
  auto line_circle = [&](const Primitive& line, const Primitive& circle) {
    const Point foot = line.origin + dot(circle.centre - line.origin, line.direction) * line.direction;
    const double h2 = circle.radius * circle.radius - dot(foot - circle.centre, foot - circle.centre);
    if (h2 < -1e-9 * circle.radius * circle.radius) return;
    const double h = std::sqrt(std::max(h2, 0.0));
    found.push_back(foot + h * line.direction);
    found.push_back(foot - h * line.direction);
  };
  if (!a.circle && !b.circle) {
    const double denominator = cross(a.direction, b.direction);
    if (std::abs(denominator) < 1e-12) return std::nullopt;
    found.push_back(a.origin + (cross(b.origin - a.origin, b.direction) / denominator) * a.direction);
  } else if (!a.circle) {
    line_circle(a, b);
  } else if (!b.circle) {
    line_circle(b, a);
  } else {
    const Point d = b.centre - a.centre;
    const double distance = norm(d);
    if (distance < 1e-12) return std::nullopt;
    const double along = (distance * distance + a.radius * a.radius - b.radius * b.radius) / (2 * distance);
    const double h2 = a.radius * a.radius - along * along;
    if (h2 < -1e-9 * a.radius * a.radius) return std::nullopt;
    const double h = std::sqrt(std::max(h2, 0.0));
    const Point u = (1 / distance) * d, base = a.centre + along * u, across{-u.y, u.x};
    found.push_back(base + h * across);
    found.push_back(base - h * across);
  }
  if (found.empty()) return std::nullopt;
  return *std::min_element(found.begin(), found.end(),
                           [&](Point p, Point q) { return norm(p - near) < norm(q - near); });
}

/// The piece of `prim` from `from` to `to`, turning the way the polygon
/// stretch `path` (from, ..., to) turns about the centre.
Segment piece(const Primitive& prim, Point from, Point to, const std::vector<Point>& path) {
  Segment s{from, to};
  if (!prim.circle) return s;
  double turning = 0;
  for (std::size_t i = 1; i < path.size(); ++i) turning += cross(path[i - 1] - prim.centre, path[i] - prim.centre);
  const double a0 = std::atan2(from.y - prim.centre.y, from.x - prim.centre.x);
  const double a1 = std::atan2(to.y - prim.centre.y, to.x - prim.centre.x);
  double sweep = a1 - a0;
  const double two_pi = 2 * std::numbers::pi;
  if (turning >= 0) {
    while (sweep <= 0) sweep += two_pi;
  } else {
    while (sweep >= 0) sweep -= two_pi;
  }
  s.bulge = std::tan(sweep / 4);
  return s;
}

ClipperLib::Path to_clipper(const Loop& loop, double tolerance) {
  const std::vector<Point> points = flatten_loop(loop, tolerance);
  ClipperLib::Path path;
  path.reserve(points.size());
  for (const Point& p : points) {
    if (!(std::abs(p.x) <= kLargestCoordinateMm && std::abs(p.y) <= kLargestCoordinateMm))
      throw Error("coordinates beyond ±1e9 mm: too large to offset");
    path.push_back({static_cast<ClipperLib::cInt>(std::llround(p.x / kClipperUnitMm)),
                    static_cast<ClipperLib::cInt>(std::llround(p.y / kClipperUnitMm))});
  }
  return path;
}

std::vector<Point> from_clipper(const ClipperLib::Path& path) {
  std::vector<Point> points;
  points.reserve(path.size());
  for (const ClipperLib::IntPoint& p : path)
    points.push_back({static_cast<double>(p.X) * kClipperUnitMm, static_cast<double>(p.Y) * kClipperUnitMm});
  return points;
}

Loop polygon_loop(const std::vector<Point>& polygon) {
  Loop loop;
  for (std::size_t i = 0; i < polygon.size(); ++i)
    loop.segments.push_back({polygon[i], polygon[(i + 1) % polygon.size()]});
  return loop;
}

/// Clipper's polygon as exact lines and arcs, or nullopt when the pieces do
/// not check out (each piece's start and middle at distance R from the
/// drawing, and the length close to the polygon's). A feature whose piece
/// the polygon's chords pass over is put back where the joint of its
/// neighbours falls inside its band.
std::optional<Loop> recover_exact(const std::vector<Point>& polygon, const DrawingFeatures& features,
                                  const RegionIndex& index, double radius, double tolerance) {
  const std::size_t n = polygon.size();
  if (n < 3) return std::nullopt;
  // Edge i runs from polygon[i] to polygon[i + 1]; its middle names its feature.
  std::vector<Feature> edge_feature(n);
  for (std::size_t i = 0; i < n; ++i) edge_feature[i] = features.classify(0.5 * (polygon[i] + polygon[(i + 1) % n]));
  // Start at a change of feature so no run wraps around.
  std::size_t start = 0;
  while (start < n && edge_feature[start] == edge_feature[(start + n - 1) % n]) ++start;
  Loop loop;
  if (start == n) {  // one feature all round: a circle about a corner or concentric with an arc
    const Primitive prim = features.primitive(edge_feature[0], polygon[0], radius);
    if (!prim.circle) return std::nullopt;
    double turning = 0;
    for (std::size_t i = 0; i < n; ++i) turning += cross(polygon[i] - prim.centre, polygon[(i + 1) % n] - prim.centre);
    const Point a = prim.project(polygon[0]), b = prim.centre + (prim.centre - a);
    const double half_turn = turning >= 0 ? 1 : -1;  // bulge of a half circle
    loop.segments.push_back({a, b, half_turn});
    loop.segments.push_back({b, a, half_turn});
  } else {
    struct Run {
      Feature feature;
      std::size_t first_edge, edges;
      Primitive prim;
    };
    std::vector<Run> runs;
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t e = (start + k) % n;
      if (runs.empty() || !(runs.back().feature == edge_feature[e])) runs.push_back({edge_feature[e], e, 0, {}});
      ++runs.back().edges;
    }
    for (Run& run : runs) {
      const std::size_t middle_edge = (run.first_edge + run.edges / 2) % n;
      run.prim = features.primitive(run.feature, 0.5 * (polygon[middle_edge] + polygon[(middle_edge + 1) % n]), radius);
    }
    // Run r starts at the vertex where edge run.first_edge starts.
    const auto joint = [&](const Primitive& before, const Primitive& after, Point vertex) {
      const Point on_before = before.project(vertex), on_after = after.project(vertex);
      std::optional<Point> crossing;
      if (norm(on_before - on_after) > 1e-9) crossing = crossing_near(before, after, vertex);
      return crossing && norm(*crossing - vertex) < 1e3 * tolerance + 0.1 * radius ? *crossing
                                                                                   : 0.5 * (on_before + on_after);
    };
    // A feature whose piece is shorter than the polygon's chords (a few um
    // of a flank, in the valley between two tips' arcs) can fall between two
    // edges' middles: then the pieces either side of it meet nearer than R
    // to it. It goes in between them, met where the curves cross. A joint
    // still off the tool radius by more than the checks allow fails the recovery.
    const double allowed = std::max(10 * tolerance, 1e-9 * radius);
    std::size_t hint = SIZE_MAX;
    const auto off_by = [&](Point at) {
      const RegionQuery q = index.nearest(at, hint);
      hint = q.element;
      return q.distance - radius;
    };
    std::vector<Run> kept{runs.front()};
    std::vector<Point> joints{Point{}};  // joints[k] starts kept[k]; the first is settled last
    // The joint from kept.back() into `next`, after the features missed
    // between them; should putting one back not check out (a joint off the
    // radius, a piece against the polygon's way round), the joint is left
    // as it was, if that passes the checks.
    const auto join = [&](const Run& next) -> std::optional<Point> {
      const std::size_t v = next.first_edge;
      const Point vertex = polygon[v], way = polygon[(v + 1) % n] - polygon[(v + n - 1) % n];
      const Point first = joint(kept.back().prim, next.prim, vertex);
      const double first_off = off_by(first);
      const std::size_t kept_before = kept.size();
      const auto as_it_was = [&]() -> std::optional<Point> {
        kept.resize(kept_before), joints.resize(kept_before);
        if (std::abs(first_off) > allowed) return std::nullopt;
        return first;
      };
      Point at = first;
      double off = first_off;
      for (int put_back = 0;; ++put_back) {
        const double scale = std::max({radius, kept.back().prim.radius, next.prim.radius});
        if (std::abs(off) <= 1e-9 * scale + 1e-12 * (std::abs(at.x) + std::abs(at.y))) return at;
        const Feature missed = features.classify(at);
        if (off > 0 || missed == kept.back().feature || missed == next.feature || put_back == 4) {
          if (std::abs(off) > allowed) return as_it_was();
          return at;
        }
        const Run added{missed, next.first_edge, 0, features.primitive(missed, at, radius)};
        const Point into = joint(kept.back().prim, added.prim, at), out_of = joint(added.prim, next.prim, at);
        if (dot(out_of - into, way) < 0 || std::abs(off_by(into)) > allowed) return as_it_was();
        kept.push_back(added);
        joints.push_back(into);
        at = out_of;
        off = off_by(at);
      }
    };
    for (std::size_t r = 1; r < runs.size(); ++r) {
      const std::optional<Point> at = join(runs[r]);
      if (!at) return std::nullopt;
      kept.push_back(runs[r]);
      joints.push_back(*at);
    }
    const std::optional<Point> first = join(runs.front());  // round the loop, into the first run
    if (!first) return std::nullopt;
    joints.front() = *first;
    runs = std::move(kept);
    for (std::size_t r = 0; r < runs.size(); ++r) {
      const Point from = joints[r], to = joints[(r + 1) % runs.size()];
      if (norm(to - from) < 1e-9) continue;
      std::vector<Point> path{from};
      for (std::size_t k = 1; k < runs[r].edges; ++k) path.push_back(polygon[(runs[r].first_edge + k) % n]);
      path.push_back(to);
      loop.segments.push_back(piece(runs[r].prim, from, to, path));
    }
  }
  // The checks: every piece at distance R from the drawing, and about the polygon's length.
  if (loop.segments.size() < 2) return std::nullopt;
  double polygon_length = 0, exact_length = 0;
  for (std::size_t i = 0; i < n; ++i) polygon_length += norm(polygon[(i + 1) % n] - polygon[i]);
  std::size_t hint = SIZE_MAX;  // the last answer, near the next point
  for (std::size_t i = 0; i < loop.segments.size(); ++i) {
    Segment& s = loop.segments[i];
    s.end = loop.segments[(i + 1) % loop.segments.size()].start;  // exactly closed
    exact_length += segment_length(s);
    for (double t : {0.25, 0.5, 0.75}) {  // (the starts were checked above, as the joints)
      const RegionQuery q = index.nearest(point_at(s, t), hint);
      const double d = q.distance;
      hint = q.element;
      if (std::abs(d - radius) > std::max(10 * tolerance, 1e-9 * radius)) return std::nullopt;
    }
  }
  if (std::abs(exact_length - polygon_length) > 0.01 * polygon_length + 100 * tolerance) return std::nullopt;
  return loop;
}

void reverse(Loop& loop) {
  reverse_chain(loop.segments);
  loop.area = -loop.area;
}

/// Adds the CPU seconds since the last call (or construction) to a stage's total.
class StageClock {
 public:
  explicit StageClock(OffsetStageTimes* times) : times_(times), last_(now()) {}
  void add(double OffsetStageTimes::*stage) {
    if (!times_) return;
    const double t = now();
    times_->*stage += t - last_;
    last_ = t;
  }

 private:
  static double now() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) + double(t.tv_nsec) * 1e-9;
  }
  OffsetStageTimes* times_;
  double last_;
};

/// Whether the polygon stage draws a large part's way (OffsetOptions::coarse_joins_from).
bool large_part(const ClipperLib::Paths& paths, const OffsetOptions& options) {
  std::size_t vertices = 0;
  for (const ClipperLib::Path& path : paths) vertices += path.size();
  return vertices >= options.coarse_joins_from;
}

/// Clipper's round joins: chords within `tolerance`, or on a large part
/// within R / 100 (11 chords a half turn), R / 1000 (35) if that leaves a
/// loop to the polygon. Each spike tip of a gear turns half round: at
/// R = 1 mm and the default 0.1 um that is 111 vertices, and Clipper's
/// sweep visits every active edge at each of them.
double join_tolerance(bool large, double sagitta, const OffsetOptions& options) {
  return large ? std::max(options.tolerance, options.tool_radius * sagitta) : options.tolerance;
}

/// Walks Clipper's tree into `result.loops`, outer boundaries before their
/// holes, depth from nesting, each loop exact where recover_exact() can.
void recover_loops(const ClipperLib::PolyTree& tree, const DrawingFeatures& features, const RegionIndex& index,
                   const OffsetOptions& options, RegionOffset& result) {
  std::vector<std::pair<const ClipperLib::PolyNode*, int>> pending;
  for (const ClipperLib::PolyNode* child : tree.Childs) pending.push_back({child, -1});
  for (std::size_t i = 0; i < pending.size(); ++i) {
    const auto [node, parent] = pending[i];
    const std::vector<Point> polygon = from_clipper(node->Contour);
    if (polygon.size() < 3) continue;
    std::optional<Loop> exact = recover_exact(polygon, features, index, options.tool_radius, options.tolerance);
    if (!exact) ++result.polygon_loops;
    Loop loop = exact ? std::move(*exact) : polygon_loop(polygon);
    loop.parent = parent;
    loop.depth = parent < 0 ? 0 : result.loops[parent].depth + 1;
    loop.area = signed_area(loop.segments);
    if ((loop.area < 0) != loop.is_hole()) reverse(loop);
    const int self = static_cast<int>(result.loops.size());
    result.loops.push_back(std::move(loop));
    for (const ClipperLib::PolyNode* child : node->Childs) pending.push_back({child, self});
  }
}

}  // namespace

double offset_vertices_estimate(const std::vector<Loop>& loops, double tool_radius, double tolerance) {
  // Chords of sagitta `tolerance` on a turn of θ at radius R: about
  // θ / (2 acos(1 - tol/R)) ~ θ/2 sqrt(R / (2 tol)).
  const auto chords = [tolerance](double turn, double radius) {
    return turn / 2 * std::sqrt(radius / (2 * tolerance));
  };
  double vertices = 0;
  if (tool_radius == 0) return vertices;  // the loops are the region: nothing is flattened
  for (const Loop& loop : loops) {
    vertices += chords(2 * std::numbers::pi, tool_radius);  // the corners' arcs turn once round in all
    for (const Segment& s : loop.segments) {
      vertices += 1;
      if (s.bulge == 0) continue;
      const double turn = 4 * std::atan(std::abs(s.bulge));  // the arc's angle
      const double radius = std::hypot(s.end.x - s.start.x, s.end.y - s.start.y) / (2 * std::sin(turn / 2));
      vertices += chords(turn, radius + tool_radius);
    }
  }
  return vertices;
}

RegionOffset offset_region(const std::vector<Loop>& drawn, const RegionIndex& index, const OffsetOptions& options) {
  if (!(options.tool_radius >= 0 && std::isfinite(options.tool_radius)))
    throw Error("the tool radius must be a finite number >= 0");
  RegionOffset result;
  const bool inside = options.side == MachiningSide::inside;
  // The offset's work grows with the part's size over the tolerance: refuse absurd sizes (an arc of
  // bulge 1e7 between two near points is a circle hundreds of kilometres across).
  for (const Loop& loop : drawn)
    for (const Segment& s : loop.segments) {
      const Box b = bounding_box(s);
      if (!(b.max_x - b.min_x <= kLargestPartMm && b.max_y - b.min_y <= kLargestPartMm))
        throw Error(fmt::format("an element spans more than 1 km ({:g} mm): too large to machine; are the units right?",
                                std::max(b.max_x - b.min_x, b.max_y - b.min_y)),
                    {"", s.source_line});
    }
  cli::require_run_size(offset_vertices_estimate(drawn, options.tool_radius, options.tolerance), options.max_vertices,
                        "offset polygon vertices", "--tool-radius, --offset-tol and the drawing's arcs");
  StageClock clock(options.stage_times);
  if (options.tool_radius == 0 || drawn.empty()) {
    result.loops = drawn;
  } else {
    ClipperLib::Paths paths;
    for (const Loop& loop : drawn) paths.push_back(to_clipper(loop, options.tolerance));
    const bool turned = sweep_across(paths);  // a part long in x: Clipper sweeps it the short way
    if (turned) quarter_turn(paths);
    // The region is the loops' even-odd interior (as RegionIndex sees it),
    // also where a drawing's loops cross themselves or each other; Clipper
    // offsets by orientation, so hand it the even-odd union first.
    // (A union, not SimplifyPolygons: its strictly-simple pass is quadratic on spiky outlines.)
    // Simple disjoint loops, oriented by their nesting, are their own union (region_union.hpp).
    std::vector<bool> outer;
    for (const Loop& loop : drawn) outer.push_back(!loop.is_hole());
    even_odd_union(paths, outer);
    clock.add(&OffsetStageTimes::even_odd_union);
    const bool large = large_part(paths, options);
    const DrawingFeatures features(drawn, index);
    // A large part's joins are drawn coarse first, and the notches the tool
    // cannot enter filled (offset_notches.hpp); should any loop fail the
    // exact recovery, the polygon stage runs again with the finer joins and
    // nothing filled, so that a loop left as a polygon is as close as before.
    for (const double sagitta : {kCoarseJoinSagitta, kFineJoinSagitta}) {
      result.loops.clear();
      result.polygon_loops = 0;
      ClipperLib::PolyTree tree;
      offset_polygons(paths, (inside ? -options.tool_radius : options.tool_radius) / kClipperUnitMm,
                      join_tolerance(large, sagitta, options) / kClipperUnitMm, tree,
                      large ? ConcaveCorners::crossing : ConcaveCorners::spikes,
                      large && sagitta == kCoarseJoinSagitta ? Notches::filled : Notches::kept);
      if (turned) quarter_turn_back(tree);
      clock.add(&OffsetStageTimes::clipper_offset);
      recover_loops(tree, features, index, options, result);
      clock.add(&OffsetStageTimes::exact_recovery);
      if (result.polygon_loops == 0 || !large) break;  // (a small part's first run is its only way)
    }
  }
  // One index over the contour serves the uncut search here and the barrier points of guard_query.
  // The uncut search's queries follow the drawing, each hinted by the last
  // answer: the tree alone serves them faster than a grid pays for itself
  // (10,000-element gear: 1.5 + 251 ms against 234 + 172 ms).
  if (options.tool_radius > 0 && !result.loops.empty())
    result.contour = std::make_unique<RegionIndex>(
        result.loops, options.contour_grid ? RegionIndex::Layout::grid : RegionIndex::Layout::tree);
  clock.add(&OffsetStageTimes::contour_index);
  result.uncut = find_uncut(drawn, result.contour.get(), options.tool_radius, options);
  clock.add(&OffsetStageTimes::uncut);
  // Inside machining: the region is everything but the shrunk pocket, so the loops turn round
  // (the index does not care: its inside is even-odd and its distances have no direction).
  if (inside)
    for (Loop& loop : result.loops) reverse(loop);
  return result;
}

namespace {

/// The nearest point of the drawing's boundary pushed R toward the tool's side.
Point push_out(const RegionIndex& index, const RegionQuery& q, Point p, double tool_radius, double toward_allowed) {
  const double clearance = toward_allowed * q.distance;
  Point away = p - q.nearest;
  if (norm(away) > 1e-12) {
    away = (clearance >= 0 ? 1.0 : -1.0) * unit(away);
  } else {  // on the boundary: the normal toward the tool's side (the material is on the left)
    double t = 0;
    const Segment& s = index.elements()[q.element];
    nearest_point(s, p, &t);
    const Point tangent = tangent_at(s, t);
    away = toward_allowed * Point{tangent.y, -tangent.x};
  }
  return q.nearest + tool_radius * away;
}

}  // namespace

GuardAnswer guard_query(const RegionIndex& index, Point p, double tool_radius, MachiningSide side,
                        const RegionIndex* contour) {
  const double toward_allowed = side == MachiningSide::outside ? 1 : -1;
  RegionQuery q = index.query(p);
  GuardAnswer answer{toward_allowed * q.distance - tool_radius, p, q.element};
  if (answer.distance >= 0) return answer;
  if (contour && !contour->elements().empty()) {
    answer.clamped = contour->query(p).nearest;
    return answer;
  }
  // Pushed out from one wall, a point can land within R of another (a slot
  // a little wider than the tool): push again from there, a few times.
  Point at = p;
  for (int round = 0; round < 8; ++round) {
    at = push_out(index, q, at, tool_radius, toward_allowed);
    q = index.query(at);
    if (toward_allowed * q.distance - tool_radius >= -1e-9 * std::max(1.0, tool_radius)) break;
  }
  answer.clamped = at;
  return answer;
}

}  // namespace tk::cad
