/// @file test_region_uncut.cpp
/// @brief The uncut search skips the contour's search for samples its last
/// answer's element already puts within reach (region_uncut.cpp): the
/// stretches it reports are those brute force over the contour finds at
/// the same samples (every R / 8 along each element), joined over corners
/// the same way, none missed and none made up.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <random>
#include <string>
#include <vector>

#include "cad/loops.hpp"
#include "cad/region_distance.hpp"
#include "cad/region_offset.hpp"
#include "cad/segment_geometry.hpp"
#include "region_parts.hpp"
#include "test_volume.hpp"

namespace region_uncut_test {  // named: the unity build joins the tests' anonymous namespaces

using namespace tk::cad;

struct Stretch {
  Point from, to;
  double deepest = 0;  // the deepest sample's gap
};

bool same_point(Point a, Point b) { return std::hypot(a.x - b.x, a.y - b.y) < 1e-9; }

/// The stretches by brute force: each sample's gap to the contour's nearest
/// element, over every element; runs above the threshold, joined where one
/// ends at the point the next starts (within a loop, and round its start).
std::vector<Stretch> brute_force_stretches(const std::vector<Loop>& drawn, const std::vector<Loop>& contour,
                                           double radius, const OffsetOptions& options) {
  std::vector<Stretch> all;
  const double step = std::max(radius / 8, 10 * options.tolerance);
  for (const Loop& loop : drawn) {
    std::vector<Stretch> runs;
    for (const Segment& s : loop.segments) {
      const std::size_t samples = std::min<std::size_t>(10000, 1 + static_cast<std::size_t>(segment_length(s) / step));
      bool open = false;
      for (std::size_t i = 0; i <= samples; ++i) {
        const Point p = point_at(s, static_cast<double>(i) / samples);
        // No contour (the tool fits nowhere): all is uncut, R + 1 deep by find_uncut's convention.
        const double gap = contour.empty() ? radius + 1 : std::abs(brute_force_query(contour, p).distance) - radius;
        if (gap <= options.uncut_report_mm) {
          open = false;
          continue;
        }
        if (!open) runs.push_back({p, p, gap});
        open = true;
        runs.back().to = p;
        runs.back().deepest = std::max(runs.back().deepest, gap);
      }
    }
    std::vector<Stretch> joined;
    for (const Stretch& run : runs)
      if (!joined.empty() && same_point(joined.back().to, run.from)) {
        joined.back().to = run.to;
        joined.back().deepest = std::max(joined.back().deepest, run.deepest);
      } else {
        joined.push_back(run);
      }
    if (joined.size() > 1 && same_point(joined.back().to, joined.front().from)) {
      joined.front().from = joined.back().from;
      joined.front().deepest = std::max(joined.front().deepest, joined.back().deepest);
      joined.pop_back();
    }
    all.insert(all.end(), joined.begin(), joined.end());
  }
  return all;
}

void expect_brute_force_stretches(const std::vector<Segment>& segments, double radius, MachiningSide side,
                                  const std::string& what) {
  const LoopSet set = build_loops(segments, 1e-6);
  const OffsetOptions options{.tool_radius = radius, .side = side};
  const RegionOffset offset = offset_region(set.loops, RegionIndex(set.loops), options);
  const std::vector<Stretch> expected = brute_force_stretches(set.loops, offset.loops, radius, options);
  ASSERT_EQ(offset.uncut.size(), expected.size()) << what;
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_TRUE(same_point(offset.uncut[i].from, expected[i].from)) << what << ", span " << i;
    EXPECT_TRUE(same_point(offset.uncut[i].to, expected[i].to)) << what << ", span " << i;
    EXPECT_GE(offset.uncut[i].depth, expected[i].deepest - 1e-9) << what << ", span " << i;
  }
}

std::string label(double radius, MachiningSide side) {
  return "R " + std::to_string(radius) + (side == MachiningSide::inside ? " inside" : " outside");
}

TEST(RegionUncut, GearsAsBruteForceFindsThem) {
  for (const double bulge : {0.0, -0.15})
    for (const double radius : {0.3, 1.0})
      for (const MachiningSide side : {MachiningSide::outside, MachiningSide::inside})
        expect_brute_force_stretches(
            parts::gear(test_volume(40, 12), side == MachiningSide::inside ? 3 : 5, 0.5, bulge), radius, side,
            label(radius, side) + ", bulge " + std::to_string(bulge));
}

TEST(RegionUncut, RandomPartsAsBruteForceFindsThem) {
  std::mt19937_64 random(424);
  for (int star = 0; star < test_volume(8, 3); ++star) {
    const std::vector<Segment> part = parts::random_star_with_hole(random, 6 + 3 * star);
    for (const double radius : {0.7, 2.5, 6.0})
      for (const MachiningSide side : {MachiningSide::outside, MachiningSide::inside})
        expect_brute_force_stretches(part, radius, side, "star " + std::to_string(star) + ", " + label(radius, side));
  }
}

}  // namespace region_uncut_test
