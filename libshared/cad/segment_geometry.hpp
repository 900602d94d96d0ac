/// @file segment_geometry.hpp
/// @brief Geometry of one Segment (a line, or a circular arc given by its
/// bulge): its circle, length, points along it, the nearest point to a
/// query, bounding box, and flattening into chords.
#pragma once

#include <cmath>
#include <vector>

#include "cad/drawing.hpp"

namespace tk::cad {

/// The circle of an arc segment. `sweep` is signed: positive counter-clockwise.
struct ArcShape {
  Point centre;
  double radius = 0;
  double start_angle = 0;  ///< of the start point, radians
  double sweep = 0;        ///< 4 atan(bulge)
};

struct Box {
  double min_x = 0, min_y = 0, max_x = 0, max_y = 0;
};

/// A bulge this small (|bulge| <= 1e-12) is a line. Inline, as is
/// point_at's line case: the uncut search asks them millions of times.
inline bool is_arc(const Segment& segment) { return std::abs(segment.bulge) > 1e-12; }
/// Only for is_arc(segment).
ArcShape arc_shape(const Segment& segment);
/// The bulge of an arc from its centre and signed sweep (helper for readers).
double bulge_of_sweep(double sweep);
double segment_length(const Segment& segment);
/// point_at() of an arc, for 0 < t < 1.
Point arc_point_at(const Segment& segment, double t);
/// Point at fraction t in [0, 1] of the length.
inline Point point_at(const Segment& segment, double t) {
  if (t <= 0) return segment.start;
  if (t >= 1) return segment.end;
  if (is_arc(segment)) return arc_point_at(segment, t);
  return {segment.start.x + t * (segment.end.x - segment.start.x),
          segment.start.y + t * (segment.end.y - segment.start.y)};
}
/// Unit direction of travel at fraction t.
Point tangent_at(const Segment& segment, double t);
/// Nearest point of the segment to p; *t_out gets its fraction of the length.
Point nearest_point(const Segment& segment, Point p, double* t_out = nullptr);
Box bounding_box(const Segment& segment);
/// Appends the points after segment.start up to and including segment.end,
/// so that no chord strays more than `tolerance` from the arc (a line adds
/// just its end).
void flatten(const Segment& segment, double tolerance, std::vector<Point>& out);

/// The part of the segment between fractions t0 <= t1 of its length (the
/// same circle for an arc); t0 = 0 and t1 = 1 keep the exact ends.
Segment sub_segment(const Segment& segment, double t0, double t1);
/// Signed area between the chord and the arc, positive when the arc turns
/// counter-clockwise (0 for a line): what a loop's shoelace over chords misses.
double arc_area(const Segment& segment);

/// The distance between two points.
inline double distance(Point a, Point b) { return std::hypot(a.x - b.x, a.y - b.y); }
/// Twice the signed area of the triangle a, b, p: > 0 when p is left of a -> b.
double orient(Point a, Point b, Point p);
/// Whether p is left of the line a -> b, a point on the line counting as
/// moved by (+e, +e^2) for an infinitesimal e: the answer for b -> a is the
/// opposite one, and every inside/outside decision in cad/ goes through
/// this one out-of-line function, so two decisions about the same points
/// always agree.
bool left_of(Point a, Point b, Point p);
/// Whether the segment crosses the ray from p toward +x an odd number of
/// times, p counting as moved by (+e, +e^2) as in left_of(), so that over a
/// closed loop the parities add up to the loop's crossing number (the
/// even-odd inside test).
bool crosses_ray(const Segment& segment, Point p);

}  // namespace tk::cad
