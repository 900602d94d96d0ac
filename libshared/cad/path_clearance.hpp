/// @file path_clearance.hpp
/// @brief How close a straight move comes to the prohibited region, from
/// the region's signed distance alone. The distance changes no faster than
/// the point moves (it is 1-Lipschitz), so stepping along the move by the
/// distance left above a level (sphere tracing) never steps over a point
/// below that level; a convex corner clipped in passing is found as well
/// as the end of the move.
#pragma once

#include <functional>
#include <optional>

#include "cad/drawing.hpp"

namespace tk::cad {

/// Signed distance to the prohibited region's boundary: positive outside
/// (where the tool may be), negative inside.
using SignedDistance = std::function<double(Point)>;

/// The first point of the move from `from` to `to` whose distance is below
/// `level`, as the fraction of the move (0 at `from`), or nothing. Steps
/// are at least 0.1 um: a dip below the level shallower than that can be
/// missed. A move it cannot resolve (a step lost in rounding, or more than
/// 10^6 steps: 100 mm within 0.1 um of the level) gives the point reached,
/// as if it were below.
std::optional<double> first_below(const SignedDistance& distance, Point from, Point to, double level);

/// How deep the move goes into the region: 0 when it never enters, else
/// the largest depth sampled every 0.01 mm from where it enters to `to`.
double deepest_on_move(const SignedDistance& distance, Point from, Point to);

}  // namespace tk::cad
