/// @file test_clipper_sweep.cpp
/// @brief Clipper's sweep turned a quarter for a part long in x (a comb):
/// chosen only where a horizontal line crosses many times more edges than
/// a vertical one, and undone exactly: the comb's offset is the offset of
/// the same comb standing upright, turned back by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "cad/clipper_sweep.hpp"
#include "cad/loops.hpp"
#include "cad/region_distance.hpp"
#include "cad/region_offset.hpp"

namespace {

using namespace tk::cad;

/// Teeth 10 mm tall, 1 mm wide, 1 mm apart on a 5 mm bar; upright: turned
/// a quarter (x, y) -> (-y, x), so that its teeth point along -x.
std::vector<Point> comb_corners(int teeth, bool upright) {
  std::vector<Point> v;
  for (int k = 0; k < teeth; ++k) {
    const double x = 2.0 * k;
    v.insert(v.end(), {{x, 0}, {x, 10}, {x + 1, 10}, {x + 1, 0}});
  }
  v.insert(v.end(), {{2.0 * teeth, -5}, {0, -5}});
  if (upright)
    for (Point& p : v) p = {-p.y, p.x};
  std::reverse(v.begin(), v.end());  // counter-clockwise
  return v;
}

ClipperLib::Paths clipper_paths(const std::vector<Point>& corners) {
  ClipperLib::Path path;
  for (const Point& p : corners) path.push_back({ClipperLib::cInt(p.x * 1e6), ClipperLib::cInt(p.y * 1e6)});
  return {path};
}

Loop loop_of(const std::vector<Point>& corners) {
  Loop loop;
  for (std::size_t i = 0; i < corners.size(); ++i)
    loop.segments.push_back({corners[i], corners[(i + 1) % corners.size()]});
  return loop;
}

/// A loop's elements as text, each turned back by (x, y) -> (y, -x) when `turn_back`, in a canonical order.
std::vector<std::string> elements_of(const Loop& loop, bool turn_back) {
  std::vector<std::string> out;
  for (Segment s : loop.segments) {
    if (turn_back) s.start = {s.start.y, 0.0 - s.start.x}, s.end = {s.end.y, 0.0 - s.end.x};  // no -0
    char text[200];
    std::snprintf(text, sizeof text, "%.9f %.9f %.9f %.9f %.12f", s.start.x, s.start.y, s.end.x, s.end.y, s.bulge);
    out.push_back(text);
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST(ClipperSweep, TurnsOnlyWhereAHorizontalLineCrossesManyTimesMore) {
  EXPECT_TRUE(sweep_across(clipper_paths(comb_corners(1000, false))));  // 2000 edges across y = 5, 4 across x = 0.5
  EXPECT_FALSE(sweep_across(clipper_paths(comb_corners(1000, true))));  // already the short way
  EXPECT_FALSE(sweep_across(clipper_paths(comb_corners(200, false))));  // too small to matter
}

TEST(ClipperSweep, ACombLongInXOffsetsAsTheSameCombUpright) {
  for (const MachiningSide side : {MachiningSide::outside, MachiningSide::inside}) {
    const std::vector<Loop> lying{loop_of(comb_corners(1000, false))}, upright{loop_of(comb_corners(1000, true))};
    OffsetOptions options;
    options.tool_radius = side == MachiningSide::outside ? 1 : 0.25;
    options.side = side;
    const RegionOffset a = offset_region(lying, RegionIndex(lying), options);
    const RegionOffset b = offset_region(upright, RegionIndex(upright), options);
    ASSERT_EQ(a.loops.size(), b.loops.size());
    ASSERT_EQ(a.polygon_loops, b.polygon_loops);
    std::vector<std::vector<std::string>> got, want;
    for (const Loop& l : a.loops) got.push_back(elements_of(l, false));
    for (const Loop& l : b.loops) want.push_back(elements_of(l, true));
    std::sort(got.begin(), got.end()), std::sort(want.begin(), want.end());
    EXPECT_EQ(got, want);
    EXPECT_EQ(a.uncut.size(), b.uncut.size());
  }
}

}  // namespace
