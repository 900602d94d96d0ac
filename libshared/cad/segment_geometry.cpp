/// @file segment_geometry.cpp
/// @brief Lines and bulge arcs: shape, length, points, nearest point, box,
/// flattening, crossing parity. Arcs are worked in the frame of their chord
/// (see ArcFrame) rather than around their centre, so that an almost
/// straight arc, whose centre may lie 1e12 chords away, keeps full precision.
#include "cad/segment_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tk::cad {

namespace {

/// An arc in the frame of its chord, mirrored so that it always bulges
/// toward -across: a point q has local coordinates u = (q - mid).along,
/// v = (q - mid).across; the centre is (0, centre_offset), the arc's middle
/// (0, -sagitta) and its ends (-half_chord, 0), (half_chord, 0).
struct ArcFrame {
  Point mid, along, across;
  double half_chord = 0, centre_offset = 0, radius = 0, sagitta = 0;
  double half_sweep = 0;  ///< |sweep| / 2
};

ArcFrame arc_frame(const Segment& segment) {
  ArcFrame f;
  const double dx = segment.end.x - segment.start.x, dy = segment.end.y - segment.start.y;
  const double chord = std::hypot(dx, dy);
  const double b = std::abs(segment.bulge), side = segment.bulge > 0 ? 1.0 : -1.0;
  f.mid = {(segment.start.x + segment.end.x) / 2, (segment.start.y + segment.end.y) / 2};
  f.along = chord > 0 ? Point{dx / chord, dy / chord} : Point{1, 0};
  // A counter-clockwise arc bulges to the right of its chord; mirroring a
  // clockwise one makes every arc bulge toward -across.
  f.across = {-f.along.y * side, f.along.x * side};
  f.half_chord = chord / 2;
  f.centre_offset = chord * (1 - b * b) / (4 * b);
  f.radius = chord * (1 + b * b) / (4 * b);
  f.sagitta = b * chord / 2;
  f.half_sweep = 2 * std::atan(b);
  return f;
}

Point global(const ArcFrame& f, double u, double v) {
  return {f.mid.x + u * f.along.x + v * f.across.x, f.mid.y + u * f.along.y + v * f.across.y};
}

/// Local point of the arc at angle psi from its middle (-half_sweep at the
/// start): (r sin psi, r (1 - cos psi) - sagitta), without the cancellation
/// of centre_offset - r cos psi when the radius is huge.
Point local_at(const ArcFrame& f, double psi) {
  const double half = std::sin(psi / 2);
  return {f.radius * std::sin(psi), 2 * f.radius * half * half - f.sagitta};
}

}  // namespace

ArcShape arc_shape(const Segment& segment) {
  const ArcFrame f = arc_frame(segment);
  ArcShape shape;
  shape.centre = global(f, 0, f.centre_offset);
  shape.radius = f.radius;
  shape.start_angle = std::atan2(segment.start.y - shape.centre.y, segment.start.x - shape.centre.x);
  shape.sweep = 4 * std::atan(segment.bulge);
  return shape;
}

double bulge_of_sweep(double sweep) { return std::tan(sweep / 4); }

double segment_length(const Segment& segment) {
  const double chord = std::hypot(segment.end.x - segment.start.x, segment.end.y - segment.start.y);
  if (!is_arc(segment)) return chord;
  const double b = std::abs(segment.bulge);
  return chord * (1 + b * b) * std::atan(b) / b;  // radius * |sweep|
}

Point arc_point_at(const Segment& segment, double t) {
  const ArcFrame f = arc_frame(segment);
  const Point q = local_at(f, (2 * t - 1) * f.half_sweep);
  return global(f, q.x, q.y);
}

Point tangent_at(const Segment& segment, double t) {
  if (!is_arc(segment)) {
    const double dx = segment.end.x - segment.start.x, dy = segment.end.y - segment.start.y;
    const double length = std::hypot(dx, dy);
    return length > 0 ? Point{dx / length, dy / length} : Point{1, 0};
  }
  const ArcFrame f = arc_frame(segment);
  const double psi = (2 * std::clamp(t, 0.0, 1.0) - 1) * f.half_sweep;
  const double c = std::cos(psi), s = std::sin(psi);
  return {c * f.along.x + s * f.across.x, c * f.along.y + s * f.across.y};
}

Point nearest_point(const Segment& segment, Point p, double* t_out) {
  double t = 0;
  Point nearest = segment.start;
  if (!is_arc(segment)) {
    const double dx = segment.end.x - segment.start.x, dy = segment.end.y - segment.start.y;
    const double length2 = dx * dx + dy * dy;
    t = length2 > 0 ? ((p.x - segment.start.x) * dx + (p.y - segment.start.y) * dy) / length2 : 0;
    t = std::clamp(t, 0.0, 1.0);
    nearest = t >= 1 ? segment.end : Point{segment.start.x + t * dx, segment.start.y + t * dy};
  } else {
    const ArcFrame f = arc_frame(segment);
    const double px = p.x - f.mid.x, py = p.y - f.mid.y;
    const double u = px * f.along.x + py * f.along.y, v = px * f.across.x + py * f.across.y;
    const double h = f.centre_offset, hc = f.half_chord;
    // Is the direction from the centre to p within the arc's sweep? (sine
    // of the angle between it and the direction to the nearer end)
    const double wv = v - h, rho = std::sqrt(u * u + wv * wv);
    if (h * (hc - std::abs(u)) - v * hc >= 0 && rho > 0) {
      // rho - r as (rho^2 - r^2) / (rho + r), with h^2 - r^2 = -hc^2 exactly.
      const double excess = (u * u + v * v - 2 * v * h - hc * hc) / (rho + f.radius);
      nearest = global(f, u - excess * u / rho, v - excess * wv / rho);
      const double psi = std::atan2(u, -wv);
      t = std::clamp((psi + f.half_sweep) / (2 * f.half_sweep), 0.0, 1.0);
    } else if (u > 0) {
      nearest = segment.end;
      t = 1;
    }
  }
  if (t_out) *t_out = t;
  return nearest;
}

Box bounding_box(const Segment& segment) {
  Box box{std::min(segment.start.x, segment.end.x), std::min(segment.start.y, segment.end.y),
          std::max(segment.start.x, segment.end.x), std::max(segment.start.y, segment.end.y)};
  if (!is_arc(segment)) return box;
  const ArcFrame f = arc_frame(segment);
  // The circle's extreme point in each axis direction, when the arc reaches it.
  const Point directions[4] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
  for (const Point& e : directions) {
    const double du = e.x * f.along.x + e.y * f.along.y, dv = e.x * f.across.x + e.y * f.across.y;
    if (std::atan2(std::abs(du), -dv) >= f.half_sweep) continue;
    // centre_offset + r dv, written so a huge radius does not cancel.
    const double v = dv < 0 ? f.radius * (du * du / (1 - dv)) - f.sagitta : f.centre_offset + f.radius * dv;
    const Point q = global(f, f.radius * du, v);
    box.min_x = std::min(box.min_x, q.x);
    box.min_y = std::min(box.min_y, q.y);
    box.max_x = std::max(box.max_x, q.x);
    box.max_y = std::max(box.max_y, q.y);
  }
  return box;
}

void flatten(const Segment& segment, double tolerance, std::vector<Point>& out) {
  constexpr long kMaxChords = 100000;
  if (!is_arc(segment)) {
    out.push_back(segment.end);
    return;
  }
  const ArcFrame f = arc_frame(segment);
  // A chord spanning angle a strays r (1 - cos(a/2)) from the arc; solve for
  // a with acos(1 - x) = 2 asin(sqrt(x/2)), exact also for tiny x.
  const double x = tolerance > 0 ? tolerance / f.radius : 0;
  const double max_angle = x >= 2 ? 2 * std::numbers::pi : 4 * std::asin(std::sqrt(x / 2));
  const double wanted = max_angle > 0 ? std::ceil(2 * f.half_sweep / max_angle) : double(kMaxChords);
  const long chords = std::clamp(static_cast<long>(std::min(wanted, double(kMaxChords))), 1L, kMaxChords);
  for (long i = 1; i < chords; ++i) {
    const Point q = local_at(f, (2.0 * double(i) / double(chords) - 1) * f.half_sweep);
    out.push_back(global(f, q.x, q.y));
  }
  out.push_back(segment.end);
}

Segment sub_segment(const Segment& segment, double t0, double t1) {
  Segment part = segment;
  part.start = point_at(segment, t0);
  part.end = point_at(segment, t1);
  if (is_arc(segment)) part.bulge = std::tan(std::atan(segment.bulge) * (t1 - t0));
  return part;
}

double arc_area(const Segment& segment) {
  if (!is_arc(segment)) return 0;
  const ArcFrame f = arc_frame(segment);
  const double sweep = 2 * f.half_sweep;
  // (r^2 / 2)(sweep - sin sweep); the series avoids cancellation for flat arcs.
  const double s2 = sweep * sweep;
  const double shape = sweep < 1e-2 ? sweep * s2 / 6 * (1 - s2 / 20 * (1 - s2 / 42)) : sweep - std::sin(sweep);
  const double area = f.radius * f.radius / 2 * shape;
  return segment.bulge > 0 ? area : -area;
}

double orient(Point a, Point b, Point p) { return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x); }

bool left_of(Point a, Point b, Point p) {
  const double o = orient(a, b, p);
  if (o != 0) return o > 0;
  // orient(a, b, p + (e, e^2)) = -(b.y - a.y) e + (b.x - a.x) e^2
  return b.y != a.y ? b.y < a.y : b.x > a.x;
}

bool crosses_ray(const Segment& segment, Point p) {
  const Point a = segment.start, b = segment.end;
  // An end exactly at p.y is below p moved up by e^2.
  const bool straddles = (a.y > p.y) != (b.y > p.y);
  if (!is_arc(segment)) return straddles && left_of(a, b, p) == (b.y > a.y);
  // The arc crosses as often as its chord, plus once more when p lies in
  // the region between chord and arc (a convex set the ray leaves once).
  const bool left = left_of(a, b, p);
  const bool chord = straddles && left == (b.y > a.y);
  const bool apex_side = segment.bulge > 0 ? !left : left;
  if (!apex_side) return chord;
  const ArcFrame f = arc_frame(segment);
  const double px = p.x - f.mid.x, py = p.y - f.mid.y;
  const double u = px * f.along.x + py * f.along.y, v = px * f.across.x + py * f.across.y;
  const bool in_circle = u * u + v * v - 2 * v * f.centre_offset - f.half_chord * f.half_chord < 0;
  return chord != in_circle;
}

}  // namespace tk::cad
