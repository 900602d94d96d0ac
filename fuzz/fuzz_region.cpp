/// @file fuzz_region.cpp
/// @brief libFuzzer target: dxf2region's geometry after the reader. The
/// first byte chooses the tool radius (0, 0.5, 2 or 7 mm), the side and
/// the join tolerance; the rest is read as a DXF file (ASCII or binary)
/// and, when it gives at most 300 segments within ±10,000 units, goes
/// through build_loops, RegionIndex (against brute force), offset_region,
/// guard_query and toolpath_gcode, as `dxf2region` chains them. Seeds in
/// fuzz/seeds/fuzz_region/ (an option byte, then a DXF), dictionary
/// fuzz/dicts/dxf.dict.
///
/// tk::Error is the expected rejection; any other exception, crash,
/// sanitizer report or hang is a bug.
///
/// Oracles (switch off by name with TK_FUZZ_SKIP=a,b while a finding is open):
///   closed     every loop's segments meet end to start, the last the first
///   index      RegionIndex::query equals brute_force_query at probe points
///              (distance to 1e-9 relative; inside/outside where |d| > 1e-6)
///   offset     the middle of every exactly recovered offset piece lies at
///              the tool radius from the drawing, within 10 x the offset
///              tolerance (what recover_exact promises)
///   barrier    a position clamped to the offset contour (when there is
///              one: a pocket narrower than the tool has none) is no
///              deeper in the region than that
///   (offset and barrier only for drawings without T-junctions or doubled
///   edges: loops that touch or overlap bound hairs of no area, which the
///   distance keeps the tool off and Clipper's union drops)
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "cad/dxf_reader.hpp"
#include "cad/loops.hpp"
#include "cad/region_distance.hpp"
#include "cad/region_offset.hpp"
#include "cad/segment_geometry.hpp"
#include "cad/toolpath.hpp"
#include "fuzz_common.hpp"
#include "io/error.hpp"

namespace {

using namespace tk::cad;
using tk::fuzz::invariant_failed;
using tk::fuzz::oracle_enabled;

constexpr std::size_t kMaxSegments = 300;
constexpr double kMaxCoordinate = 1e4;
constexpr double kOffsetTolerance = 1e-2;  // coarse: a fine contour of a huge arc makes a slow index
// The contour is exact up to what Clipper's polygon (within the offset
// tolerance) can tell apart; recover_exact accepts pieces within 10 x that.
constexpr double kContourTolerance = 10 * kOffsetTolerance;

bool small_and_bounded(const Drawing& d) {
  if (d.segments.size() > kMaxSegments) return false;
  for (const Segment& s : d.segments) {
    const Box b = bounding_box(s);  // an arc's, not just its ends
    for (double v : {b.min_x, b.min_y, b.max_x, b.max_y})
      if (!(std::abs(v) <= kMaxCoordinate)) return false;
  }
  return true;
}

void check_closed(const std::vector<Loop>& loops, const char* what) {
  if (!oracle_enabled("closed")) return;
  for (std::size_t l = 0; l < loops.size(); ++l) {
    const auto& s = loops[l].segments;
    for (std::size_t i = 0; i < s.size(); ++i) {
      const Point a = s[i].end, b = s[(i + 1) % s.size()].start;
      if (a.x != b.x || a.y != b.y) invariant_failed("closed", std::string(what) + " loop " + std::to_string(l));
    }
  }
}

/// Probe points: segment ends and middles, pushed a little off, and a few fixed points.
std::vector<Point> probes(const std::vector<Loop>& loops) {
  std::vector<Point> out{{0, 0}, {1, 1}, {-3, 7}};
  for (const Loop& loop : loops)
    for (const Segment& s : loop.segments) {
      const Point m = point_at(s, 0.5);
      out.push_back(s.start);
      out.push_back(m);
      out.push_back({m.x + 0.37, m.y - 0.21});
      if (out.size() > 200) return out;
    }
  return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const double radii[4] = {0, 0.5, 2, 7};
  const double radius = radii[data[0] & 3];
  const MachiningSide side = data[0] & 4 ? MachiningSide::inside : MachiningSide::outside;
  const double join = data[0] & 8 ? 0.1 : 1e-3;
  const std::string_view bytes(reinterpret_cast<const char*>(data + 1), size - 1);
  try {
    DxfReadOptions options;
    options.chord_tolerance = 0.05;
    options.max_segments = kMaxSegments + 1;
    const Drawing drawing = read_dxf(bytes, "fuzz.dxf", options);
    if (!small_and_bounded(drawing)) return 0;
    const LoopSet set = build_loops(drawing.segments, join);
    check_closed(set.loops, "drawn");
    const RegionIndex index(set.loops);
    OffsetOptions offset_options;
    offset_options.tool_radius = radius;
    offset_options.side = side;
    offset_options.tolerance = kOffsetTolerance;
    const RegionOffset region = set.loops.empty() ? RegionOffset{} : offset_region(set.loops, index, offset_options);
    check_closed(region.loops, "offset");
    const RegionIndex* contour =
        region.contour.get();  // null for a zero radius: the barrier is then the drawing itself
    // Loops that touch or overlap themselves or each other (a vertex on an
    // edge, an edge drawn twice) bound hairs of no area: the distance keeps
    // the tool off them, Clipper's union drops them. The oracles on the
    // contour hold for drawings without.
    const bool clean = set.t_junctions.empty() && doubled_edges(set.loops).empty();
    for (const Point& p : probes(set.loops)) {
      const RegionQuery fast = index.query(p), slow = brute_force_query(set.loops, p);
      const double scale = std::max(1.0, std::abs(slow.distance));
      if (oracle_enabled("index") && (std::abs(std::abs(fast.distance) - std::abs(slow.distance)) > 1e-9 * scale ||
                                      (std::abs(slow.distance) > 1e-6 * scale && fast.inside() != slow.inside())))
        invariant_failed("index", "at (" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")");
      if (set.loops.empty()) continue;
      (void)guard_query(index, p, radius, side);  // the push-out barrier: may end inside in a narrow slot
      const GuardAnswer guard = guard_query(index, p, radius, side, contour);
      const double after = guard_query(index, guard.clamped, radius, side).distance;
      if (oracle_enabled("barrier") && clean && !region.loops.empty() && after < -kContourTolerance)
        invariant_failed("barrier", "(" + std::to_string(p.x) + ", " + std::to_string(p.y) + ") clamped to (" +
                                        std::to_string(guard.clamped.x) + ", " + std::to_string(guard.clamped.y) +
                                        "), " + std::to_string(after) + " deep");
    }
    if (set.loops.empty()) return 0;
    if (oracle_enabled("offset") && clean && radius > 0 && region.polygon_loops == 0)
      for (const Loop& loop : region.loops)
        for (const Segment& s : loop.segments) {
          const double d = std::abs(index.query(point_at(s, 0.5)).distance);
          if (std::abs(d - radius) > kContourTolerance) invariant_failed("offset", std::to_string(d));
        }
    ToolpathOptions toolpath;
    (void)toolpath_gcode(region.loops, toolpath);
  } catch (const tk::Error&) {
    // the expected rejection
  }
  return 0;
}
