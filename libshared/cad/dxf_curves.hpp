/// @file dxf_curves.hpp
/// @brief Flattening of the DXF curves that are not circular arcs (internal
/// to the DXF reader): elliptic arcs and NURBS curves become points joined
/// by chords that stray at most a tolerance from the curve.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "cad/drawing.hpp"

namespace tk::cad::dxf {

/// Replaces `out` with the points of the elliptic arc
/// centre + cos(t) major + sin(t) minor for t from `start` to start + span,
/// first and last included, evenly spaced in t. The spacing keeps the
/// sagitta of every chord within `tolerance` (the arc of a circle of the
/// larger semi-axis bounds it), with at most `max_points` points; a full
/// ellipse (span 2 pi) ends exactly on its first point. No points when both
/// axes are zero.
void flatten_ellipse(Point centre, Point major, Point minor, double start, double span, double tolerance,
                     std::size_t max_points, std::vector<Point>& out);

enum class SplineResult { ok, invalid, too_large };

/// Limits on what a SPLINE may ask for.
inline constexpr int kMaxSplineDegree = 10;

/// Replaces `out` with points along the NURBS curve of `degree` over
/// `control` points (weights all 1 when `weights` is empty; an open uniform
/// knot vector when `knots` is empty, as ezdxf does), from the start of its
/// domain to its end, evaluated by de Boor's algorithm. Each knot span is
/// halved recursively until the points at 1/4, 1/2 and 3/4 of a piece lie
/// within `tolerance` of its chord; no more than `max_points` points are
/// made (pieces that would need more stay single chords).
///
/// invalid: degree outside 1..kMaxSplineDegree, fewer than degree + 1
/// control points, a knot count other than control + degree + 1,
/// decreasing or non-finite knots, an empty domain, or weights that are not
/// one positive number per control point. too_large: more control points
/// than `max_points`.
SplineResult flatten_spline(int degree, std::span<const double> knots, std::span<const double> weights,
                            std::span<const Point> control, double tolerance, std::size_t max_points,
                            std::vector<Point>& out);

}  // namespace tk::cad::dxf
