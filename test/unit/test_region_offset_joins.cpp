/// @file test_region_offset_joins.cpp
/// @brief Clipper's round joins drawn coarser on large parts
/// (OffsetOptions::coarse_joins_from), against the offset with the joins at
/// the offset tolerance: on gears and random stars the exact recovery
/// returns the same lines and arcs (a loop may start at another element),
/// the same loops left as polygons, the same uncut stretches; on random
/// spikes, where the coarse polygon may pass over pieces of a few um that
/// cut in by nanometres, every piece at the tool radius within 1 um.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "cad/loops.hpp"
#include "cad/region_distance.hpp"
#include "cad/region_offset.hpp"
#include "cad/segment_geometry.hpp"
#include "region_parts.hpp"
#include "test_volume.hpp"

namespace {

using namespace tk::cad;

bool near(Point a, Point b) { return std::abs(a.x - b.x) <= 1e-9 && std::abs(a.y - b.y) <= 1e-9; }

/// The same elements in the same order round the loop, from wherever each starts.
::testing::AssertionResult same_loop(const Loop& a, const Loop& b) {
  const std::size_t n = a.segments.size();
  if (b.segments.size() != n) return ::testing::AssertionFailure() << n << " elements against " << b.segments.size();
  for (std::size_t shift = 0; shift < n; ++shift) {
    bool all = true;
    for (std::size_t i = 0; i < n && all; ++i) {
      const Segment& s = a.segments[i];
      const Segment& t = b.segments[(i + shift) % n];
      all = near(s.start, t.start) && near(s.end, t.end) && std::abs(s.bulge - t.bulge) <= 1e-9;
    }
    if (all) return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure() << "no rotation of the " << n << " elements matches";
}

RegionOffset offset_with_joins(const std::vector<Loop>& loops, const RegionIndex& index, double radius,
                               MachiningSide side, bool coarse) {
  OffsetOptions options;
  options.tool_radius = radius;
  options.side = side;
  options.coarse_joins_from = coarse ? 0 : std::numeric_limits<std::size_t>::max();
  return offset_region(loops, index, options);
}

void expect_same_offset(const std::vector<Segment>& segments, double radius, MachiningSide side,
                        const std::string& what) {
  const LoopSet set = build_loops(segments, 1e-6);
  const RegionIndex index(set.loops);
  const RegionOffset fine = offset_with_joins(set.loops, index, radius, side, false);
  const RegionOffset coarse = offset_with_joins(set.loops, index, radius, side, true);
  ASSERT_EQ(fine.loops.size(), coarse.loops.size()) << what;
  EXPECT_EQ(fine.polygon_loops, coarse.polygon_loops) << what;
  for (std::size_t i = 0; i < fine.loops.size(); ++i) {
    EXPECT_TRUE(same_loop(fine.loops[i], coarse.loops[i])) << what << ", loop " << i;
    EXPECT_EQ(fine.loops[i].depth, coarse.loops[i].depth) << what;
  }
  ASSERT_EQ(fine.uncut.size(), coarse.uncut.size()) << what;
  for (std::size_t i = 0; i < fine.uncut.size(); ++i) {
    EXPECT_TRUE(near(fine.uncut[i].from, coarse.uncut[i].from)) << what;
    EXPECT_TRUE(near(fine.uncut[i].to, coarse.uncut[i].to)) << what;
    EXPECT_NEAR(fine.uncut[i].depth, coarse.uncut[i].depth, 1e-9) << what;
  }
}

using parts::gear;

TEST(RegionOffsetJoins, CoarseJoinsRecoverTheSameGear) {
  const int spikes = test_volume(48, 16);
  for (const double radius : {0.5, 2.0})
    for (const MachiningSide side : {MachiningSide::outside, MachiningSide::inside})
      for (const double bulge : {0.0, 0.1}) {
        const std::string what = "R " + std::to_string(radius) +
                                 (side == MachiningSide::inside ? " inside" : " outside") + ", bulge " +
                                 std::to_string(bulge);
        expect_same_offset(gear(spikes, side == MachiningSide::inside ? 3 : 5, 1.5, bulge), radius, side, what);
      }
}

TEST(RegionOffsetJoins, CoarseJoinsRecoverTheSameRandomParts) {
  std::mt19937_64 random(24);
  std::uniform_real_distribution<double> unit(0, 1);
  const int trials = test_volume(12, 4);
  for (int trial = 0; trial < trials; ++trial) {
    // A random star with arcs, and a random circle inside it (a hole).
    const std::vector<Segment> part = parts::random_star_with_hole(random, 5 + trial % 20);
    const double radius = 0.3 + 3 * unit(random);
    for (const MachiningSide side : {MachiningSide::outside, MachiningSide::inside})
      expect_same_offset(part, radius, side, "trial " + std::to_string(trial));
  }
}

/// Spikes of random heights (up to 6 mm) 0.4 mm apart round a ring, with
/// the roots a little uneven: valleys where a tool reaches down a flank by
/// a few um only, shorter than the coarse joins' chords.
std::vector<Segment> random_spikes(std::mt19937_64& random, int vertices) {
  std::uniform_real_distribution<double> spike(0, 6), root(0, 0.3);
  const double ring = vertices * 0.4 / (2 * std::numbers::pi);
  std::vector<Point> points;
  for (int i = 0; i < vertices; ++i) {
    const double a = 2 * std::numbers::pi * i / vertices, r = ring + (i % 2 ? spike(random) : root(random));
    points.push_back({r * std::cos(a), r * std::sin(a)});
  }
  std::vector<Segment> out;
  for (std::size_t i = 0; i < points.size(); ++i) out.push_back({points[i], points[(i + 1) % points.size()]});
  return out;
}

// Here the coarse joins' polygon may leave out a piece a few um long that
// the finer one keeps, so the elements need not be the same; but every
// piece must lie at the tool radius within the recovery's own check (ten
// offset tolerances, 1 um), measured by brute force over every element
// (not the index the recovery checks itself with), and the uncut
// stretches' depths must match the fine joins'. Before
// the recovery checked its joints and put such pieces back, the boundary
// fell up to 30 um inside the tool's reach on parts like these.
TEST(RegionOffsetJoins, CoarseJoinsKeepTheToolRadiusOnRandomSpikes) {
  std::mt19937_64 random(2027);
  const int parts = test_volume(6, 2);
  for (int part = 0; part < parts; ++part) {
    const std::vector<Segment> spikes = random_spikes(random, 600);
    const LoopSet set = build_loops(spikes, 1e-6);
    const RegionIndex index(set.loops);
    for (const double radius : {0.7, 1.5, 3.0})
      for (const MachiningSide side : {MachiningSide::outside, MachiningSide::inside}) {
        const std::string what = "part " + std::to_string(part) + ", R " + std::to_string(radius) +
                                 (side == MachiningSide::inside ? " inside" : " outside");
        const RegionOffset fine = offset_with_joins(set.loops, index, radius, side, false);
        const RegionOffset coarse = offset_with_joins(set.loops, index, radius, side, true);
        ASSERT_EQ(fine.loops.size(), coarse.loops.size()) << what;
        EXPECT_EQ(coarse.polygon_loops, 0u) << what;
        double worst = 0;
        for (const Loop& loop : coarse.loops)
          for (const Segment& s : loop.segments)
            for (int k = 0; k <= 10; ++k)
              worst = std::max(
                  worst, std::abs(std::abs(brute_force_query(set.loops, point_at(s, k / 10.0)).distance) - radius));
        EXPECT_LE(worst, 10 * OffsetOptions{}.tolerance) << what << ": a piece off the tool radius";
        ASSERT_EQ(fine.uncut.size(), coarse.uncut.size()) << what;
        for (std::size_t i = 0; i < fine.uncut.size(); ++i)
          EXPECT_NEAR(fine.uncut[i].depth, coarse.uncut[i].depth, 10 * OffsetOptions{}.tolerance) << what;
      }
  }
}

}  // namespace
