/// @file region_union.hpp
/// @brief The even-odd union the offset starts from, skipped where it
/// would change nothing. Clipper's union of n vertices sweeps every active
/// edge at each local minimum and merge (about 10 s on a 100,000-element
/// gear); but loops that are simple, pairwise disjoint and already
/// oriented by their nesting (outer boundaries counter-clockwise, holes
/// clockwise) are their own even-odd union. A Shamos-Hoey sweep on
/// Clipper's integers proves that in O(n log n); only the clean-up Clipper
/// would do (repeated and collinear vertices dropped) is left to do.
#pragma once

#include <polyclipping/clipper.hpp>

#include <vector>

namespace tk::cad {

/// > 0 when c lies left of the line a -> b (the turn a -> b -> c is
/// counter-clockwise), < 0 right of it, 0 on it; exact on Clipper's integers.
int orient_exact(const ClipperLib::IntPoint& a, const ClipperLib::IntPoint& b, const ClipperLib::IntPoint& c);

/// Whether no two edges of the closed `paths` meet, but consecutive edges
/// of one path at their shared vertex (without doubling back over each
/// other). Exact on Clipper's integers; paths of fewer than 3 distinct
/// vertices are not simple. O(n log n) in the edges.
bool simple_and_disjoint(const ClipperLib::Paths& paths);

/// The path without consecutive repeats, nor a last vertex equal to the
/// first: the vertices Clipper keeps of a closed path it is given.
ClipperLib::Path without_repeats(const ClipperLib::Path& path);

/// The path without repeated vertices (consecutive, or the last equal to
/// the first) and without vertices on the line through their neighbours,
/// as Clipper's output would leave it (repeated until none is left).
ClipperLib::Path without_collinear(const ClipperLib::Path& path);

/// Replaces `paths` by their even-odd union: by Clipper, unless the paths
/// are simple and disjoint and each one's orientation is already the one
/// its nesting gives (`outer[i]`: counter-clockwise, positive area), in
/// which case each path only loses its repeated and collinear vertices,
/// starts after its lowest vertex and the paths come highest first: the
/// same polygons Clipper gives, in its order, and from starts from which
/// Clipper's offset draws the same polygons (the start Clipper's union
/// picks is not always that one; test_region_union checks the offsets
/// agree, polygon by polygon). Returns whether Clipper's union was skipped.
bool even_odd_union(ClipperLib::Paths& paths, const std::vector<bool>& outer);

}  // namespace tk::cad
