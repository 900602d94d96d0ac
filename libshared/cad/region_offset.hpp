/// @file region_offset.hpp
/// @brief The prohibited region for a round tool of radius R: the drawn
/// part grown by R (machining outside), or the drawn pocket shrunk by R
/// (machining inside, the region is everything but the shrunk pocket).
///
/// Clipper (libpolyclipping) computes the offset of the flattened loops,
/// which settles the topology: notches and pockets narrower than the tool
/// close, loops that vanish go. The geometry then comes back exact: every
/// stretch of Clipper's polygon lies at distance R from one feature of the
/// drawing (the inside of a line or arc, or a corner), so it is replaced by
/// that feature's offset (a parallel line, a concentric arc, or an arc of
/// radius R about the corner), and neighbouring pieces meet where their
/// exact curves cross. A loop whose recovery fails the checks stays as
/// Clipper's polygon (counted in `polygon_loops`).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "cad/loops.hpp"
#include "cad/region_distance.hpp"

namespace tk::cad {

enum class MachiningSide { outside, inside };

/// CPU seconds of each stage of offset_region (for the benchmark).
struct OffsetStageTimes {
  double even_odd_union = 0, clipper_offset = 0, exact_recovery = 0, contour_index = 0, uncut = 0;
};

struct OffsetOptions {
  double tool_radius = 0;  ///< mm, >= 0
  MachiningSide side = MachiningSide::outside;
  double tolerance = 1e-4;        ///< mm: flattening for Clipper, and the checks of the exact recovery
  double uncut_report_mm = 1e-3;  ///< material left thicker than this is reported
  /// The polygon stage's vertices (offset_vertices_estimate) beyond which
  /// the offset is refused before it starts (a usage error: dxf2region(1)).
  double max_vertices = 3e5;                // its time grows with them: a drawing estimated at 124,000 took 7 s
  OffsetStageTimes* stage_times = nullptr;  ///< filled when given
  /// The polygon stage's input vertices from which Clipper draws its round
  /// joins coarser (chords within tool_radius / 100 instead of
  /// `tolerance`, again within tool_radius / 1000 should a loop then fail
  /// the exact recovery, which turns them into true arcs either way: on a
  /// large part Clipper's sweep over the joins' vertices dominates), and
  /// draws concave corners as the crossing of their offset edges, not
  /// Clipper's spikes (offset_polygons.hpp: a 100,000-vertex ring's sweep
  /// held thousands of spikes). Below it the polygons stay Clipper's own.
  /// The exact recovery returns the same lines and arcs either way; a loop
  /// may start at another element, and a point the recovery keeps from
  /// the polygon (where two exact curves do not cross) moves by rounding.
  std::size_t coarse_joins_from = 5000;
  /// The contour's index with its grid (RegionIndex::Layout::grid: fast
  /// queries, for guard_query's barrier points over many positions) or
  /// the box tree alone (enough for the uncut search, whose queries follow
  /// the drawing, each hinted by the last). Either answers the same.
  bool contour_grid = false;
};

/// The vertices the offset's polygon stage implies: chords within
/// `tolerance` along each arc at its radius plus the tool's, a full turn at
/// the tool's radius per loop (the corners), and one per element; none for
/// a tool radius of 0 (the drawing is the region).
double offset_vertices_estimate(const std::vector<Loop>& loops, double tool_radius, double tolerance);

/// A stretch of the drawing the tool cannot reach: material stays there
/// (a concave corner, a slot narrower than the tool, a pocket it does not
/// fit in).
struct UncutSpan {
  Point from, to;
  double depth = 0;          ///< mm of material left, at the worst point
  std::uint32_t entity = 0;  ///< the drawing entity
  std::size_t source_line = 0;
};

struct RegionOffset {
  /// The prohibited region's boundary, each loop with the region on its
  /// left (so a tool travelling a loop backwards has the material on its
  /// right: climb milling with a clockwise spindle).
  std::vector<Loop> loops;
  std::vector<UncutSpan> uncut;
  std::size_t polygon_loops = 0;  ///< loops left as Clipper's polygon
  /// An index over `loops` (for guard_query's barrier points), built for
  /// the uncut search (with a grid or not: OffsetOptions::contour_grid);
  /// null when the tool radius is 0 or there is no loop.
  std::unique_ptr<RegionIndex> contour;
};

/// `drawn` are the drawing's loops (from build_loops, material on the
/// left); `index` is a RegionIndex over the same loops. Throws Error for a
/// drawing too large for Clipper's integers, or with an element more than
/// a kilometre across (the Location's line is the element's DXF line).
RegionOffset offset_region(const std::vector<Loop>& drawn, const RegionIndex& index, const OffsetOptions& options);

/// The tool's side of the prohibited region: the signed distance (positive
/// where the tool centre may be) and the barrier point, for one query.
struct GuardAnswer {
  double distance = 0;      ///< to the prohibited region's boundary; negative inside it
  Point clamped;            ///< the point itself when allowed, else the nearest allowed point
  std::size_t element = 0;  ///< nearest element of the drawing (RegionIndex::elements())
};

/// Exact wherever the tool is allowed and in the band of width R around
/// the drawing; deeper inside the part the distance is -(depth + R), the
/// depth being the distance to the drawing's boundary. The barrier point
/// is the nearest point of `contour` (an index over RegionOffset::loops,
/// the region's exact boundary) when given; otherwise the nearest drawing
/// point pushed R out, again from where it lands while that is within R
/// of another wall (up to 8 times: a slot narrower than the tool has no
/// allowed point, and the push can end inside).
GuardAnswer guard_query(const RegionIndex& index, Point p, double tool_radius, MachiningSide side,
                        const RegionIndex* contour = nullptr);

}  // namespace tk::cad
