/// @file offset_polygons.hpp
/// @brief Clipper's offset of closed polygons with round joins
/// (ClipperOffset with jtRound and etClosedPolygon, Clipper 6.4.2), drawn
/// here so that one kind of join can be lighter.
///
/// Clipper draws every concave corner as the end of one offset edge, the
/// corner itself, and the start of the next: a spike of the tool's radius
/// back to the drawing, which the closing union removes. On a finely
/// divided curve (a 100,000-vertex ring) every second vertex is such a
/// corner; a horizontal line crosses thousands of spikes, Clipper's sweep
/// keeps them all in its edge list, and its offset took 4.4 s. Clipper2
/// leaves the corner point out where the turn is nearly flat, but the two
/// offset edges then cross, and the union (Clipper 6's) walks its whole
/// output polygon at each such crossing (GetBottomPt): 6.3 s. So here a
/// concave corner is drawn as the point where the two offset edges cross
/// (exactly the offset's corner there), wherever that cuts each edge by at
/// most half its length (|delta| tan(turn / 2)), so that no edge is cut
/// away from both ends; sharper corners of short edges keep Clipper's
/// spike. Every other point is Clipper 6.4.2's, computed the same way.
#pragma once

#include <polyclipping/clipper.hpp>

namespace tk::cad {

/// The union of `paths` (closed polygons) grown by `delta` (Clipper units;
/// negative shrinks) with round joins of chords within `arc_tolerance`
/// (Clipper units), into `out` as ClipperOffset::Execute(PolyTree&) would
/// give it. The paths' orientation is taken from the lowest one (an outer
/// boundary), as ClipperOffset does.
enum class ConcaveCorners {
  crossing,  ///< where the offset edges cross, where that is safe (above)
  spikes     ///< always Clipper 6.4.2's spike: its own polygons, point for point
};
enum class Notches {
  kept,   ///< every path as it is
  filled  ///< the notches the tool cannot enter filled first (offset_notches.hpp): the same region
};
void offset_polygons(const ClipperLib::Paths& paths, double delta, double arc_tolerance, ClipperLib::PolyTree& out,
                     ConcaveCorners concave = ConcaveCorners::crossing, Notches notches = Notches::kept);

}  // namespace tk::cad
