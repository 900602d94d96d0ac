/// @file dxf_entities.cpp
/// @brief Entity by entity, the ENTITIES section of a DXF file becomes
/// segments: what each group code means per entity type, OCS handling
/// (extrusion (0,0,1) as is, (0,0,-1) mirrored in x, anything else
/// skipped), arcs split at most in halves so bulges stay within 1, and the
/// bookkeeping of read and skipped entities.
#include "cad/dxf_entities.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "cad/dxf_curves.hpp"

namespace tk::cad::dxf {

namespace {

constexpr double kPi = std::numbers::pi;
/// Vertices, knots, weights or points kept for one SPLINE at most.
constexpr std::size_t kMaxSplineInput = kMaxCurvePoints + kMaxSplineDegree + 1;

/// math.isclose with its default relative tolerance, as ezdxf uses it.
bool is_close(double a, double b, double absolute) {
  return std::abs(a - b) <= std::max(1e-9 * std::max(std::abs(a), std::abs(b)), absolute);
}

/// Python's float %, whose result takes the sign of the (positive) divisor.
double modulo(double a, double m) {
  const double r = std::fmod(a, m);
  return r < 0 ? r + m : r;
}

/// The counter-clockwise span from `start` to `end` in [0, full], with
/// ezdxf's rules (arc_angle_span_deg/_rad): equal inputs span nothing,
/// inputs equal modulo a turn span a full turn, an end of exactly one turn
/// is kept as it is.
double angle_span(double start, double end, double full, double absolute) {
  if (is_close(start, end, absolute)) return 0;
  start = modulo(start, full);
  if (is_close(start, modulo(end, full), absolute)) return full;
  if (!is_close(end, full, absolute)) end = modulo(end, full);
  if (end < start) end += full;
  return std::min(end - start, full);
}

/// A point of a circle at an angle in degrees, exact at multiples of 90.
Point on_circle(Point centre, double radius, double degrees) {
  const double d = modulo(degrees, 360);
  double c = 0, s = 0;
  if (d == 0) {
    c = 1;
  } else if (d == 90) {
    s = 1;
  } else if (d == 180) {
    c = -1;
  } else if (d == 270) {
    s = -1;
  } else {
    c = std::cos(d * (kPi / 180));
    s = std::sin(d * (kPi / 180));
  }
  return {centre.x + radius * c, centre.y + radius * s};
}

constexpr const char* kReadNames[] = {"", "LINE", "ARC", "CIRCLE", "LWPOLYLINE", "POLYLINE", "ELLIPSE", "SPLINE"};

}  // namespace

EntityBuilder::EntityBuilder(Drawing& drawing, const TagReader& tags, const DxfReadOptions& options)
    : drawing_(drawing), tags_(tags), options_(options) {}

EntityBuilder::Plane EntityBuilder::plane_of(const double extrusion[3]) {
  const double length = std::hypot(extrusion[0], extrusion[1], extrusion[2]);
  if (!(length > 0) || !std::isfinite(length)) return Plane::other;
  if (std::abs(extrusion[0]) <= 1e-12 * length && std::abs(extrusion[1]) <= 1e-12 * length)
    return extrusion[2] > 0 ? Plane::xy : Plane::mirrored;
  return Plane::other;
}

void EntityBuilder::start(const Tag& tag) {
  if (started_) end_entity();
  started_ = true;
  Entity& e = entity_;
  e.type = tag.text;
  const std::string_view type = tag.text;
  const bool child_type = type == "VERTEX" || type == "SEQEND" || type == "ATTRIB";
  if (child_type && (polyline_.open || insert_open_)) {
    e.kind = type == "SEQEND" ? Kind::seqend : Kind::child;
  } else {
    close_parent();
    if (next_index_ > std::numeric_limits<std::uint32_t>::max())
      tags_.fail_at(tags_.start_of(tag), "more than 2^32 entities");
    e.index = static_cast<std::uint32_t>(next_index_++);
    e.kind = type == "LINE"         ? Kind::line
             : type == "ARC"        ? Kind::arc
             : type == "LWPOLYLINE" ? Kind::lwpolyline
             : type == "CIRCLE"     ? Kind::circle
             : type == "POLYLINE"   ? Kind::polyline
             : type == "ELLIPSE"    ? Kind::ellipse
             : type == "SPLINE"     ? Kind::spline
             : type == "INSERT"     ? Kind::insert
                                    : Kind::other;
  }
  e.layer = "0";  // the default layer when group code 8 is missing
  e.start = tags_.start_of(tag);
  e.p10 = e.p11 = Point{};
  e.v40 = e.v41 = e.v42 = e.v50 = e.v51 = 0;
  if (e.kind == Kind::ellipse) {  // a full ellipse with axis ratio 1 unless told otherwise
    e.v40 = 1;
    e.v42 = 2 * kPi;
  }
  e.extrusion[0] = e.extrusion[1] = 0;
  e.extrusion[2] = 1;
  e.flags = e.degree = 0;
  e.paper = e.in_app_group = e.too_large = false;
  e.vertices.clear();
  e.knots.clear();
  e.weights.clear();
  e.control.clear();
  e.fit.clear();
}

void EntityBuilder::add(const Tag& tag) {
  Entity& e = entity_;
  if (e.in_app_group) {  // "102 {NAME" ... "102 }": application data, any codes
    if (tag.code == 102 && tag.text == "}") e.in_app_group = false;
    return;
  }
  switch (tag.code) {
    case 8: e.layer = tag.text; return;
    case 67: e.paper = tags_.integer(tag) != 0; return;
    case 102: e.in_app_group = !tag.text.empty() && tag.text[0] == '{'; return;
    case 210:
    case 220:
    case 230:
      if (e.kind != Kind::other && e.kind != Kind::insert && e.kind != Kind::line)
        e.extrusion[(tag.code - 210) / 10] = tags_.real(tag);
      return;
    default: break;
  }
  const int code = tag.code;
  switch (e.kind) {
    case Kind::line:
      if (code == 10) add_point(tag, e.p10.x);
      else if (code == 20) add_point(tag, e.p10.y);
      else if (code == 11) add_point(tag, e.p11.x);
      else if (code == 21) add_point(tag, e.p11.y);
      return;
    case Kind::arc:
    case Kind::circle:
      if (code == 10) add_point(tag, e.p10.x);
      else if (code == 20) add_point(tag, e.p10.y);
      else if (code == 40) e.v40 = tags_.real(tag);
      else if (code == 50) e.v50 = tags_.real(tag);
      else if (code == 51) e.v51 = tags_.real(tag);
      return;
    case Kind::lwpolyline:
      // Each 10 starts a vertex; 20 and 42 belong to the last one. Group
      // code 90 (the vertex count) is not trusted for anything.
      if (code == 10) e.vertices.push_back({tags_.real(tag), 0, 0});
      else if (code == 20 && !e.vertices.empty()) e.vertices.back().y = tags_.real(tag);
      else if (code == 42 && !e.vertices.empty()) e.vertices.back().bulge = tags_.real(tag);
      else if (code == 70) e.flags = tags_.integer(tag);
      return;
    case Kind::polyline:
      if (code == 70) e.flags = tags_.integer(tag);
      return;
    case Kind::child:  // VERTEX (and ATTRIB, which is not used)
      if (code == 10) add_point(tag, e.p10.x);
      else if (code == 20) add_point(tag, e.p10.y);
      else if (code == 42) e.v42 = tags_.real(tag);
      else if (code == 70) e.flags = tags_.integer(tag);
      return;
    case Kind::ellipse:
      if (code == 10) add_point(tag, e.p10.x);
      else if (code == 20) add_point(tag, e.p10.y);
      else if (code == 11) add_point(tag, e.p11.x);
      else if (code == 21) add_point(tag, e.p11.y);
      else if (code == 40) e.v40 = tags_.real(tag);
      else if (code == 41) e.v41 = tags_.real(tag);
      else if (code == 42) e.v42 = tags_.real(tag);
      return;
    case Kind::spline: {
      const auto room = [&e](std::size_t size) {
        if (size < kMaxSplineInput) return true;
        e.too_large = true;
        return false;
      };
      if (code == 10) {
        if (room(e.control.size())) e.control.push_back({tags_.real(tag), 0});
      } else if (code == 20 && !e.control.empty()) {
        e.control.back().y = tags_.real(tag);
      } else if (code == 11) {
        if (room(e.fit.size())) e.fit.push_back({tags_.real(tag), 0});
      } else if (code == 21 && !e.fit.empty()) {
        e.fit.back().y = tags_.real(tag);
      } else if (code == 40) {
        if (room(e.knots.size())) e.knots.push_back(tags_.real(tag));
      } else if (code == 41) {
        if (room(e.weights.size())) e.weights.push_back(tags_.real(tag));
      } else if (code == 70) {
        e.flags = tags_.integer(tag);
      } else if (code == 71) {
        e.degree = tags_.integer(tag);
      }
      return;
    }
    default: return;
  }
}

void EntityBuilder::finish() {
  if (started_) end_entity();
  started_ = false;
  close_parent();
  for (std::size_t kind = 1; kind < std::size(kReadNames); ++kind)
    if (read_counts_[kind]) drawing_.entities_read[kReadNames[kind]] += read_counts_[kind];
  std::fill(std::begin(read_counts_), std::end(read_counts_), 0);
}

void EntityBuilder::close_parent() {
  if (polyline_.open) end_polyline();
  insert_open_ = false;
}

bool EntityBuilder::skipped(std::string_view type, bool paper, Plane plane) {
  if (!paper && plane != Plane::other) return false;
  name_.assign(type);
  name_ += paper ? " (paper space)" : " (not in XY plane)";
  ++drawing_.entities_skipped[name_];
  return true;
}

void EntityBuilder::count_read(Kind kind, std::string_view layer, std::uint32_t index, std::size_t start) {
  ++read_counts_[static_cast<std::size_t>(kind)];
  if (!have_last_layer_ || layer != last_layer_) {
    name_.assign(layer);
    const auto [it, inserted] = layer_index_.try_emplace(name_, static_cast<std::uint32_t>(drawing_.layers.size()));
    if (inserted) drawing_.layers.push_back(name_);
    last_layer_ = layer;
    last_layer_index_ = it->second;
    have_last_layer_ = true;
  }
  out_layer_ = last_layer_index_;
  out_index_ = index;
  out_start_ = start;
}

void EntityBuilder::end_entity() {
  Entity& e = entity_;
  const Plane plane = plane_of(e.extrusion);
  const bool mirror = plane == Plane::mirrored;
  switch (e.kind) {
    case Kind::other:
    case Kind::insert:
      name_.assign(e.type);
      if (e.paper) name_ += " (paper space)";
      ++drawing_.entities_skipped[name_];
      insert_open_ = e.kind == Kind::insert;  // its ATTRIBs and SEQEND belong to it
      return;
    case Kind::child:
      // Spline frame control points (flag 16) are not on the curve.
      if (polyline_.open && e.type == "VERTEX" && !(e.flags & 16))
        polyline_.vertices.push_back({e.p10.x, e.p10.y, e.v42});
      return;
    case Kind::seqend: close_parent(); return;
    case Kind::polyline:
      polyline_.open = true;
      polyline_.layer = e.layer;
      polyline_.start = e.start;
      polyline_.index = e.index;
      polyline_.flags = e.flags;
      std::copy(std::begin(e.extrusion), std::end(e.extrusion), std::begin(polyline_.extrusion));
      polyline_.paper = e.paper;
      polyline_.vertices.clear();
      return;
    case Kind::line:
      if (skipped(e.type, e.paper, Plane::xy)) return;  // LINE is in world coordinates
      count_read(e.kind, e.layer, e.index, e.start);
      segment(e.p10, e.p11, 0, false);
      return;
    case Kind::arc:
    case Kind::circle: {
      if (skipped(e.type, e.paper, plane)) return;
      count_read(e.kind, e.layer, e.index, e.start);
      const double span = e.kind == Kind::circle ? 360 : angle_span(e.v50, e.v51, 360, 1e-13);
      if (span > 0 && e.v40 > 0) emit_arc(e.p10, e.v40, e.kind == Kind::circle ? 0 : e.v50, span, mirror);
      return;
    }
    case Kind::lwpolyline:
      if (skipped(e.type, e.paper, plane)) return;
      count_read(e.kind, e.layer, e.index, e.start);
      emit_vertices(e.vertices, (e.flags & 1) != 0, mirror);
      return;
    case Kind::ellipse: {
      if (skipped(e.type, e.paper, plane)) return;
      count_read(e.kind, e.layer, e.index, e.start);
      // Centre and major axis are in world coordinates; the parameter runs
      // counter-clockwise about the extrusion, so (0,0,-1) turns it around.
      const double s = mirror ? -1 : 1;
      const Point minor{-s * e.v40 * e.p11.y, s * e.v40 * e.p11.x};
      const double span = angle_span(e.v41, e.v42, 2 * kPi, 1e-15);
      if (span == 0) return;
      flatten_ellipse(e.p10, e.p11, minor, e.v41, span, options_.chord_tolerance, curve_limit(), points_);
      emit_chords(points_);
      return;
    }
    case Kind::spline: end_spline(plane); return;
  }
}

void EntityBuilder::end_spline(Plane plane) {
  Entity& e = entity_;
  if (skipped(e.type, e.paper, plane)) return;  // control points are in world coordinates
  const auto skip = [&](const char* reason) {
    name_.assign(e.type);
    name_ += reason;
    ++drawing_.entities_skipped[name_];
  };
  if (e.too_large) return skip(" (too large)");
  if (e.control.empty()) {
    // Only fit points: joined by straight chords (AutoCAD would fit a cubic
    // through them; the chords are exact at the fit points).
    if (e.fit.empty()) return skip(" (invalid)");
    count_read(e.kind, e.layer, e.index, e.start);
    emit_chords(e.fit);
    return;
  }
  const int degree = static_cast<int>(std::clamp<std::int64_t>(e.degree, -1, kMaxSplineDegree + 1));
  // Every knot span gives a chord at least; beyond the segments left, the
  // chords themselves will say so (unless they have no length).
  const std::size_t limit = std::max(curve_limit(), std::min(e.control.size() + 1, kMaxCurvePoints));
  const SplineResult result =
      flatten_spline(degree, e.knots, e.weights, e.control, options_.chord_tolerance, limit, points_);
  if (result == SplineResult::invalid) return skip(" (invalid)");
  if (result == SplineResult::too_large) return skip(" (too large)");
  count_read(e.kind, e.layer, e.index, e.start);
  emit_chords(points_);
}

void EntityBuilder::end_polyline() {
  Polyline& p = polyline_;
  p.open = false;
  const char* reason = p.paper                                 ? " (paper space)"
                       : (p.flags & 64)                        ? " (polyface mesh)"
                       : (p.flags & 16)                        ? " (polygon mesh)"
                       : (p.flags & 8)                         ? " (3D)"
                       : plane_of(p.extrusion) == Plane::other ? " (not in XY plane)"
                                                               : nullptr;
  if (reason) {
    name_ = "POLYLINE";
    name_ += reason;
    ++drawing_.entities_skipped[name_];
    return;
  }
  count_read(Kind::polyline, p.layer, p.index, p.start);
  emit_vertices(p.vertices, (p.flags & 1) != 0, plane_of(p.extrusion) == Plane::mirrored);
}

std::size_t EntityBuilder::curve_limit() const {
  const std::size_t used = drawing_.segments.size();
  const std::size_t left = used < options_.max_segments ? options_.max_segments - used : 0;
  return std::min(kMaxCurvePoints, left + 2);  // one point more than chords, and one more to overflow
}

void EntityBuilder::too_many_segments(std::size_t start) const {
  tags_.fail_at(start, "more than " + std::to_string(options_.max_segments) + " segments");
}

void EntityBuilder::emit_arc(Point centre, double radius, double start_degrees, double span_degrees, bool mirror) {
  // Halves above 180 degrees keep every bulge within 1, where it is well
  // conditioned (a bulge near a full turn grows without bound).
  const int pieces = span_degrees > 180 ? 2 : 1;
  const double piece = span_degrees / pieces;
  const double bulge = piece == 180 ? 1.0 : std::tan(piece * (kPi / 720));
  const auto placed = [mirror](Point p) { return mirror ? Point{-p.x, p.y} : p; };
  const Point first = on_circle(centre, radius, start_degrees);
  Point from = first;
  for (int i = 1; i <= pieces; ++i) {
    const Point to = i < pieces            ? on_circle(centre, radius, start_degrees + piece)
                     : span_degrees == 360 ? first
                                           : on_circle(centre, radius, start_degrees + span_degrees);
    segment(placed(from), placed(to), mirror ? -bulge : bulge, false);
    from = to;
  }
}

void EntityBuilder::emit_vertices(const std::vector<Vertex>& vertices, bool closed, bool mirror) {
  const auto placed = [mirror](const Vertex& v) { return mirror ? Point{-v.x, v.y} : Point{v.x, v.y}; };
  const auto bulge = [mirror](const Vertex& v) { return mirror && v.bulge != 0 ? -v.bulge : v.bulge; };
  const std::size_t n = vertices.size();
  for (std::size_t i = 0; i + 1 < n; ++i)
    segment(placed(vertices[i]), placed(vertices[i + 1]), bulge(vertices[i]), false);
  if (closed && n > 1) segment(placed(vertices[n - 1]), placed(vertices[0]), bulge(vertices[n - 1]), false);
}

void EntityBuilder::emit_chords(const std::vector<Point>& points) {
  for (std::size_t i = 1; i < points.size(); ++i) segment(points[i - 1], points[i], 0, true);
}

void EntityBuilder::segment(Point a, Point b, double bulge, bool flattened) {
  if (!std::isfinite(a.x) || !std::isfinite(a.y) || !std::isfinite(b.x) || !std::isfinite(b.y) || !std::isfinite(bulge))
    tags_.fail_at(out_start_, "coordinates out of range");
  if (a.x == b.x && a.y == b.y) return;  // zero length: nothing to cut
  if (drawing_.segments.size() >= options_.max_segments) too_many_segments(out_start_);
  drawing_.segments.push_back(Segment{a, b, bulge, out_layer_, out_index_, tags_.source_line(out_start_), flattened});
}

}  // namespace tk::cad::dxf
