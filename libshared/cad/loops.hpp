/// @file loops.hpp
/// @brief Chains a drawing's segments into closed loops: ends within the
/// join tolerance meet; loose ends and T-junctions (an end that touches
/// another segment's interior) are reported with their coordinates; loops
/// nest into outer boundaries and holes and are oriented with the region
/// (the material) on their left: outer boundaries counter-clockwise, holes
/// clockwise.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "cad/drawing.hpp"

namespace tk::cad {

struct Loop {
  std::vector<Segment> segments;  ///< end of each = start of the next, last end = first start, exactly
  int depth = 0;                  ///< 0 outer boundary, 1 hole, 2 island in a hole, ...
  int parent = -1;                ///< index of the enclosing loop, -1 for none
  double area = 0;                ///< signed, after orientation: > 0 outer (even depth), < 0 hole
  bool is_hole() const { return depth % 2 == 1; }
};

/// An end of a segment that meets no other end within the tolerance.
struct LooseEnd {
  Point at;
  std::uint32_t entity = 0;
  std::size_t source_line = 0;
};

/// An end of one segment lying on the interior of another.
struct TJunction {
  Point at;
  std::uint32_t entity = 0;  ///< the entity whose end it is
  std::size_t source_line = 0;
  std::uint32_t touched_entity = 0;  ///< the entity whose interior it touches
  std::size_t touched_source_line = 0;
};

struct LoopSet {
  std::vector<Loop> loops;             ///< outer boundaries before their holes
  std::vector<Segment> open_segments;  ///< segments of chains that did not close
  std::vector<LooseEnd> loose_ends;
  std::vector<TJunction> t_junctions;
};

/// Segments shorter than the tolerance are dropped; zero-area loops are
/// reported as open. Deterministic for a given input order.
LoopSet build_loops(const std::vector<Segment>& segments, double join_tolerance);

/// Signed area enclosed by a closed chain of segments, arcs included
/// exactly: > 0 when it runs counter-clockwise.
double signed_area(const std::vector<Segment>& loop);

/// The same path travelled the other way: order reversed, ends swapped, bulges negated.
void reverse_chain(std::vector<Segment>& chain);

/// The loop as a closed polyline (first point repeated at the end), every
/// chord within `tolerance` of its curve.
std::vector<Point> flatten_loop(const Loop& loop, double tolerance);

/// Midpoints of the loops' edges drawn twice (the same ends, either way
/// round, the same curve): two loops sharing an edge, or a loop doubling
/// back on itself. Even-odd, such an edge bounds nothing, yet the distance
/// keeps the tool off it, so the offset there is not to be trusted.
std::vector<Point> doubled_edges(const std::vector<Loop>& loops);

}  // namespace tk::cad
