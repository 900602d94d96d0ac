/// @file test_region_offset.cpp
/// @brief The tool-radius offset against closed forms (Steiner's formula
/// for convex parts: area A + P R + pi R^2, perimeter P + 2 pi R; exact
/// corner arcs), the barrier of guard_query, and the G-code contour.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <sstream>

#include "cad/invasion_check.hpp"
#include "cad/loops.hpp"
#include "cad/region_distance.hpp"
#include "cad/region_offset.hpp"
#include "cad/segment_geometry.hpp"
#include "cad/toolpath.hpp"
#include "io/error.hpp"

namespace {

using tk::cad::Loop;
using tk::cad::MachiningSide;
using tk::cad::Point;
using tk::cad::Segment;

std::vector<Segment> polygon_segments(const std::vector<Point>& points) {
  std::vector<Segment> out;
  for (std::size_t i = 0; i < points.size(); ++i) out.push_back({points[i], points[(i + 1) % points.size()]});
  return out;
}

/// Two half circles.
std::vector<Segment> circle(Point c, double r) {
  return {{{c.x + r, c.y}, {c.x - r, c.y}, 1}, {{c.x - r, c.y}, {c.x + r, c.y}, 1}};
}

struct Offset {
  std::vector<Loop> drawn;
  tk::cad::RegionIndex index;
  tk::cad::RegionOffset result;
};

Offset offset(const std::vector<Segment>& segments, double radius, MachiningSide side = MachiningSide::outside) {
  tk::cad::LoopSet set = tk::cad::build_loops(segments, 1e-6);
  tk::cad::RegionIndex index(set.loops);
  tk::cad::OffsetOptions options;
  options.tool_radius = radius;
  options.side = side;
  tk::cad::RegionOffset result = tk::cad::offset_region(set.loops, index, options);
  return {std::move(set.loops), std::move(index), std::move(result)};
}

double length(const Loop& loop) {
  double sum = 0;
  for (const Segment& s : loop.segments) sum += tk::cad::segment_length(s);
  return sum;
}

/// Every piece of every loop lies at distance R from the drawing.
void expect_at_tool_radius(const Offset& o, double radius) {
  for (const Loop& loop : o.result.loops)
    for (const Segment& s : loop.segments)
      for (double t : {0.0, 0.1, 0.37, 0.5, 0.81, 1.0})
        EXPECT_NEAR(std::abs(o.index.query(tk::cad::point_at(s, t)).distance), radius, 1e-7);
}

TEST(RegionOffset, SquareGrowsByLinesAndCornerArcs) {
  const Offset o = offset(polygon_segments({{0, 0}, {10, 0}, {10, 10}, {0, 10}}), 1);
  ASSERT_EQ(o.result.loops.size(), 1u);
  EXPECT_EQ(o.result.polygon_loops, 0u);
  const Loop& loop = o.result.loops[0];
  ASSERT_EQ(loop.segments.size(), 8u);
  int arcs = 0;
  for (const Segment& s : loop.segments) {
    if (!tk::cad::is_arc(s)) continue;
    ++arcs;
    const tk::cad::ArcShape arc = tk::cad::arc_shape(s);
    EXPECT_NEAR(arc.radius, 1, 1e-9);
    EXPECT_NEAR(std::abs(arc.sweep), std::numbers::pi / 2, 1e-9);
    // Centred on a corner of the square.
    EXPECT_NEAR(std::fmod(arc.centre.x + 1e-12, 10), 0, 1e-9);
    EXPECT_NEAR(std::fmod(arc.centre.y + 1e-12, 10), 0, 1e-9);
  }
  EXPECT_EQ(arcs, 4);
  EXPECT_NEAR(loop.area, 100 + 40 * 1 + std::numbers::pi, 1e-9);  // Steiner
  EXPECT_NEAR(length(loop), 40 + 2 * std::numbers::pi, 1e-9);
  EXPECT_TRUE(o.result.uncut.empty());
  expect_at_tool_radius(o, 1);
}

TEST(RegionOffset, PocketShrinksWithSharpCornersAndTheRegionIsOutside) {
  const Offset o = offset(polygon_segments({{0, 0}, {10, 0}, {10, 10}, {0, 10}}), 1, MachiningSide::inside);
  ASSERT_EQ(o.result.loops.size(), 1u);
  const Loop& loop = o.result.loops[0];
  ASSERT_EQ(loop.segments.size(), 4u);
  for (const Segment& s : loop.segments) {
    EXPECT_FALSE(tk::cad::is_arc(s));
    EXPECT_TRUE(std::abs(s.start.x - 1) < 1e-9 || std::abs(s.start.x - 9) < 1e-9);
    EXPECT_TRUE(std::abs(s.start.y - 1) < 1e-9 || std::abs(s.start.y - 9) < 1e-9);
  }
  // The prohibited region (everything but the 8 x 8 square) is on the left: clockwise.
  EXPECT_NEAR(loop.area, -64, 1e-9);
  // The tool leaves the four corners: material within R (sqrt 2 - 1) of them.
  ASSERT_EQ(o.result.uncut.size(), 4u);
  for (const tk::cad::UncutSpan& span : o.result.uncut) EXPECT_NEAR(span.depth, std::sqrt(2.0) - 1, 0.01);
}

TEST(RegionOffset, DiscGrowsToAConcentricCircle) {
  const Offset o = offset(circle({3, -2}, 5), 2);
  ASSERT_EQ(o.result.loops.size(), 1u);
  for (const Segment& s : o.result.loops[0].segments) {
    ASSERT_TRUE(tk::cad::is_arc(s));
    const tk::cad::ArcShape arc = tk::cad::arc_shape(s);
    EXPECT_NEAR(arc.radius, 7, 1e-9);
    EXPECT_NEAR(arc.centre.x, 3, 1e-9);
    EXPECT_NEAR(arc.centre.y, -2, 1e-9);
  }
  EXPECT_NEAR(o.result.loops[0].area, std::numbers::pi * 49, 1e-7);
}

TEST(RegionOffset, HoleShrinksAndVanishesWhenTheToolIsWider) {
  std::vector<Segment> plate = polygon_segments({{0, 0}, {40, 0}, {40, 40}, {0, 40}});
  for (const Segment& s : circle({20, 20}, 5)) plate.push_back(s);
  const Offset grown = offset(plate, 2);
  ASSERT_EQ(grown.result.loops.size(), 2u);
  EXPECT_TRUE(grown.result.loops[1].is_hole());
  EXPECT_NEAR(grown.result.loops[1].area, -std::numbers::pi * 9, 1e-7);
  expect_at_tool_radius(grown, 2);
  // A 12 mm tool does not fit the 10 mm bore: the hole goes, all of it uncut.
  const Offset wide = offset(plate, 6);
  ASSERT_EQ(wide.result.loops.size(), 1u);
  EXPECT_FALSE(wide.result.uncut.empty());
  double deepest = 0;
  for (const tk::cad::UncutSpan& span : wide.result.uncut) deepest = std::max(deepest, span.depth);
  // The bore's wall is 15 mm (on the axes) to 16.5 mm (diagonally) beyond the tool's reach from the outside.
  EXPECT_NEAR(deepest, 40 - 20 - 5 / std::sqrt(2.0), 0.05);
}

TEST(RegionOffset, NarrowSlotClosesAndIsReportedUncut) {
  // 60 x 40 with a slot 3 wide and 15 deep from the top: a 4 mm tool does not enter.
  const Offset o =
      offset(polygon_segments({{0, 0}, {60, 0}, {60, 40}, {31.5, 40}, {31.5, 25}, {28.5, 25}, {28.5, 40}, {0, 40}}), 2);
  ASSERT_EQ(o.result.loops.size(), 1u);
  // Steiner for the block, less the dent over the slot's mouth that neither
  // corner arc reaches: twice the integral of 2 - sqrt(4 - u^2), u in 0..1.5.
  const double dent = 2 * (3 - (0.75 * std::sqrt(1.75) + 2 * std::asin(0.75)));
  EXPECT_NEAR(o.result.loops[0].area, 2400 + 2 * 200 + 4 * std::numbers::pi - dent, 1e-6);
  ASSERT_FALSE(o.result.uncut.empty());
  for (const tk::cad::UncutSpan& span : o.result.uncut) {
    EXPECT_GE(std::min(span.from.x, span.to.x), 28.5 - 1e-9);
    EXPECT_LE(std::max(span.from.x, span.to.x), 31.5 + 1e-9);
    EXPECT_GE(std::min(span.from.y, span.to.y), 25 - 1e-9);
  }
  expect_at_tool_radius(o, 2);
}

TEST(RegionOffset, RandomStarsRecoverExactly) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> unit(0, 1);
  for (int trial = 0; trial < 20; ++trial) {
    const int n = 5 + trial;
    std::vector<Point> points;
    for (int i = 0; i < n; ++i) {
      const double angle = 2 * std::numbers::pi * i / n, r = 20 + 15 * unit(random);
      points.push_back({r * std::cos(angle), r * std::sin(angle)});
    }
    std::vector<Segment> star = polygon_segments(points);
    for (Segment& s : star) s.bulge = unit(random) < 0.3 ? 0.4 * (unit(random) - 0.5) : 0;
    const double radius = 0.5 + 3 * unit(random);
    const Offset o = offset(star, radius);
    ASSERT_FALSE(o.result.loops.empty()) << trial;
    EXPECT_EQ(o.result.polygon_loops, 0u) << trial;
    expect_at_tool_radius(o, radius);
  }
}

TEST(GuardQuery, BarrierIsTheNearestAllowedPoint) {
  tk::cad::LoopSet set = tk::cad::build_loops(polygon_segments({{0, 0}, {10, 0}, {10, 10}, {0, 10}}), 1e-6);
  const tk::cad::RegionIndex index(set.loops);
  // Outside machining, R = 2.
  auto a = tk::cad::guard_query(index, {5, -5}, 2, MachiningSide::outside);
  EXPECT_NEAR(a.distance, 3, 1e-12);
  EXPECT_NEAR(a.clamped.y, -5, 1e-12);
  a = tk::cad::guard_query(index, {5, -1}, 2, MachiningSide::outside);  // in the band
  EXPECT_NEAR(a.distance, -1, 1e-12);
  EXPECT_NEAR(a.clamped.x, 5, 1e-12);
  EXPECT_NEAR(a.clamped.y, -2, 1e-12);
  a = tk::cad::guard_query(index, {5, 3}, 2, MachiningSide::outside);  // in the part
  EXPECT_NEAR(a.distance, -5, 1e-12);
  EXPECT_NEAR(a.clamped.y, -2, 1e-12);
  a = tk::cad::guard_query(index, {5, 0}, 2, MachiningSide::outside);  // on the drawing
  EXPECT_NEAR(a.distance, -2, 1e-12);
  EXPECT_NEAR(a.clamped.y, -2, 1e-12);
  a = tk::cad::guard_query(index, {12, 12}, 2, MachiningSide::outside);  // off a corner
  EXPECT_NEAR(a.distance, std::sqrt(8.0) - 2, 1e-12);
  a = tk::cad::guard_query(index, {11, 11}, 2, MachiningSide::outside);
  EXPECT_NEAR(std::hypot(a.clamped.x - 10, a.clamped.y - 10), 2, 1e-12);
  // Inside machining: the pocket's middle is allowed, near its wall not.
  a = tk::cad::guard_query(index, {5, 5}, 2, MachiningSide::inside);
  EXPECT_NEAR(a.distance, 3, 1e-12);
  a = tk::cad::guard_query(index, {5, 1}, 2, MachiningSide::inside);
  EXPECT_NEAR(a.distance, -1, 1e-12);
  EXPECT_NEAR(a.clamped.y, 2, 1e-12);
  a = tk::cad::guard_query(index, {5, -1}, 2, MachiningSide::inside);  // out of the pocket
  EXPECT_NEAR(a.distance, -3, 1e-12);
  EXPECT_NEAR(a.clamped.y, 2, 1e-12);
}

TEST(GuardQuery, InASlotNarrowerThanTheToolTheBarrierIsTheContour) {
  const Offset o =
      offset(polygon_segments({{0, 0}, {60, 0}, {60, 40}, {31.5, 40}, {31.5, 25}, {28.5, 25}, {28.5, 40}, {0, 40}}), 2);
  ASSERT_TRUE(o.result.contour);
  // Over the slot's mouth the region's boundary is the two corner arcs (radius 2 about (28.5, 40) and
  // (31.5, 40)), which meet at the dent (30, 40 + sqrt(4 - 1.5^2)). From deep in the slot, and from
  // beside the left corner's arc below the dent, the nearest allowed point is the dent.
  const Point dent{30, 40 + std::sqrt(1.75)};
  for (Point p : {Point{30, 30}, Point{29, 39}}) {
    const auto a = tk::cad::guard_query(o.index, p, 2, MachiningSide::outside, o.result.contour.get());
    EXPECT_LT(a.distance, 0);
    EXPECT_NEAR(a.clamped.x, dent.x, 1e-9);
    EXPECT_NEAR(a.clamped.y, dent.y, 1e-9);
  }
  // Just inside the right corner's arc above the dent: pushed out along the radius from (31.5, 40).
  const Point p{30.2, 41.5};
  const double r = std::hypot(p.x - 31.5, p.y - 40);
  const auto a = tk::cad::guard_query(o.index, p, 2, MachiningSide::outside, o.result.contour.get());
  EXPECT_NEAR(a.distance, r - 2, 1e-12);
  EXPECT_NEAR(a.clamped.x, 31.5 + 2 * (p.x - 31.5) / r, 1e-9);
  EXPECT_NEAR(a.clamped.y, 40 + 2 * (p.y - 40) / r, 1e-9);
}

TEST(InvasionGuard, LatencyAwareStopFromTheApproachSpeed) {
  tk::cad::LoopSet set = tk::cad::build_loops(polygon_segments({{0, 0}, {10, 0}, {10, 10}, {0, 10}}), 1e-6);
  const tk::cad::RegionIndex index(set.loops);
  tk::cad::InvasionGuard guard(index, {1, MachiningSide::outside, 0.1, 0.0});
  // Straight at the bottom edge at 20 mm/s: 2 mm covered during the latency.
  auto c = guard.check({5, -10}, 0.0);
  EXPECT_EQ(*c.approach_mm_s, 0);
  EXPECT_FALSE(*c.stop);
  c = guard.check({5, -6}, 0.2);  // distance 5
  EXPECT_NEAR(*c.approach_mm_s, 20, 1e-9);
  EXPECT_FALSE(*c.stop);              // 5 - 2 > 0
  c = guard.check({5, -2.5}, 0.375);  // distance 1.5 < 2 covered in 0.1 s
  EXPECT_TRUE(*c.stop);
  EXPECT_THROW(guard.check({5, -2}, 0.3), tk::Error);
  EXPECT_EQ(guard.summary().positions, 4u);
  EXPECT_EQ(guard.summary().invasions, 0u);
  // 1 mm in 1e-320 s: no speed to extrapolate from, an error rather than "no stop".
  tk::cad::InvasionGuard fresh(index, {1, MachiningSide::outside, 0.1, 0.0});
  fresh.check({5, -10}, 0.0);
  EXPECT_THROW(fresh.check({5, -9}, 1e-320), tk::Error);
}

TEST(InvasionGuard, LatencyAwareStopSeesTheWallItIsNotNearestTo) {
  // A pocket 10 x 10 for a tool of radius 1: the centre stays in [1, 9] x [1, 9]. The tool runs at
  // 20 mm/s along (1, 0.2) toward the top right: the top wall is nearest (1 mm, falling at 3.9 mm/s)
  // while the right wall, 1.5 mm away, falls at 19.6 mm/s and is reached within the 0.1 s latency.
  // The distance's own rate (1 - 3.9 x 0.1 > 0) would not stop; the move to where the stop takes
  // effect, (7.5, 8) + 0.1 x 20 x (0.98, 0.196), crosses x = 9.
  tk::cad::LoopSet set = tk::cad::build_loops(polygon_segments({{0, 0}, {10, 0}, {10, 10}, {0, 10}}), 1e-6);
  const tk::cad::RegionIndex index(set.loops);
  tk::cad::InvasionGuard guard(index, {1, MachiningSide::inside, 0.1, 0.0});
  const double ux = 1 / std::hypot(1, 0.2), uy = 0.2 / std::hypot(1, 0.2);
  auto c = guard.check({7.5 - 20 * 0.05 * ux, 8 - 20 * 0.05 * uy}, 0.0);
  EXPECT_FALSE(*c.stop);
  c = guard.check({7.5, 8}, 0.05);
  EXPECT_NEAR(c.answer.distance, 1, 1e-12);
  EXPECT_NEAR(*c.approach_mm_s, 20 * uy, 1e-9);
  EXPECT_TRUE(*c.stop);
}

TEST(Toolpath, ClimbContourOfASquareIsClockwiseWithCornerArcs) {
  const Offset o = offset(polygon_segments({{0, 0}, {10, 0}, {10, 10}, {0, 10}}), 1);
  tk::cad::ToolpathOptions options;
  const std::string gcode = tk::cad::toolpath_gcode(o.result.loops, options);
  std::istringstream lines(gcode);
  std::string line;
  int g1 = 0, g2 = 0, g3 = 0;
  while (std::getline(lines, line)) {
    g1 += line.rfind("G1 X", 0) == 0;
    g2 += line.rfind("G2 ", 0) == 0;
    g3 += line.rfind("G3 ", 0) == 0;
    if (line.rfind("G2 ", 0) == 0) {
      // I, J point from the start to a corner of the square, 1 mm away.
      double x, y, i, j;
      ASSERT_EQ(std::sscanf(line.c_str(), "G2 X%lf Y%lf I%lf J%lf", &x, &y, &i, &j), 4) << line;
      EXPECT_NEAR(std::hypot(i, j), 1, 1e-6);
    }
  }
  EXPECT_EQ(g1, 4);
  EXPECT_EQ(g2, 4);  // climb: clockwise round the outside
  EXPECT_EQ(g3, 0);
  EXPECT_NE(gcode.find("G1 Z-1.000000 F100.000000"), std::string::npos);
  EXPECT_EQ(gcode.substr(gcode.size() - 3), "M2\n");
  options.climb = false;
  const std::string conventional = tk::cad::toolpath_gcode(o.result.loops, options);
  EXPECT_EQ(conventional.find("G2 "), std::string::npos);
  EXPECT_NE(conventional.find("G3 "), std::string::npos);
  options.safe_z = -5;
  EXPECT_THROW(tk::cad::toolpath_gcode(o.result.loops, options), tk::Error);
}

}  // namespace
