/// @file test_region_nearby.cpp
/// @brief RegionIndex::Nearby (the elements that can be nearest round one
/// spot, listed once) answers as brute force does, bit for bit: the same
/// element, distance and nearest point, ties to the lower element
/// included; and a point outside its promise (farther from the centre
/// than the spread, or from the boundary than the reach) still gets the
/// right answer. RegionIndex::distance_to, the uncut search's bound,
/// against the segment's own nearest point.
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

#include "cad/loops.hpp"
#include "cad/region_distance.hpp"
#include "cad/segment_geometry.hpp"
#include "region_parts.hpp"
#include "test_volume.hpp"

namespace region_nearby_test {  // named: the unity build joins the tests' anonymous namespaces

using namespace tk::cad;

/// p's answer from `nearby` against brute force's.
void expect_brute_force(const RegionIndex::Nearby& nearby, const std::vector<Loop>& loops, Point p, const char* what) {
  const RegionQuery got = nearby.nearest(p), want = brute_force_query(loops, p);
  ASSERT_EQ(got.element, want.element) << what << " at (" << p.x << ", " << p.y << ")";
  ASSERT_EQ(got.distance, std::abs(want.distance)) << what << " at (" << p.x << ", " << p.y << ")";
  ASSERT_EQ(got.nearest.x, want.nearest.x) << what;
  ASSERT_EQ(got.nearest.y, want.nearest.y) << what;
}

/// A random point between `from` and `to` away from the centre.
Point around(std::mt19937_64& random, Point centre, double from, double to) {
  std::uniform_real_distribution<double> unit(0, 1);
  const double angle = 2 * std::numbers::pi * unit(random), r = from + (to - from) * std::sqrt(unit(random));
  return {centre.x + r * std::cos(angle), centre.y + r * std::sin(angle)};
}

TEST(RegionNearby, AnswersAsBruteForceWithinItsSpreadAndOutside) {
  std::mt19937_64 random(11);
  const LoopSet set = build_loops(parts::random_star_with_hole(random, test_volume(400, 100)), 1e-9);
  const RegionIndex index(set.loops, RegionIndex::Layout::tree);
  std::uniform_real_distribution<double> coordinate(-45, 45), unit(0, 1);
  for (int spot = 0; spot < test_volume(300, 40); ++spot) {
    const Point centre{coordinate(random), coordinate(random)};
    const double spread = 3 * unit(random) * unit(random);
    // The tightest promise: the centre's distance plus the spread.
    const double reach = index.nearest(centre).distance + spread;
    const RegionIndex::Nearby nearby(index, centre, spread, reach);
    expect_brute_force(nearby, set.loops, centre, "centre");
    for (int i = 0; i < 20; ++i) expect_brute_force(nearby, set.loops, around(random, centre, 0, spread), "within");
    for (int i = 0; i < 5; ++i)  // beyond the spread: nearest() itself
      expect_brute_force(nearby, set.loops, around(random, centre, 1.01 * spread + 0.01, 10 + 5 * spread),
                         "beyond the spread");
    // A reach promised too short: whatever the list lacks, the answer is right.
    const RegionIndex::Nearby short_reach(index, centre, spread, 0.25 * reach);
    for (int i = 0; i < 10; ++i)
      expect_brute_force(short_reach, set.loops, around(random, centre, 0, spread), "reach too short");
  }
}

TEST(RegionNearby, ASoleElementIsNearestThroughoutBySearchOfAll) {
  // sole(), where it names an element, must be nearer than every other at
  // each point of the spread (brute force over all the elements, not the
  // list), and its distance there the answer's; it must name one often
  // enough on small spreads that the check means something.
  std::mt19937_64 random(23);
  const LoopSet set = build_loops(parts::random_star_with_hole(random, test_volume(200, 60)), 1e-9);
  const RegionIndex index(set.loops, RegionIndex::Layout::tree);
  std::vector<Segment> all;
  for (const Loop& loop : set.loops) all.insert(all.end(), loop.segments.begin(), loop.segments.end());
  std::uniform_real_distribution<double> coordinate(-45, 45), unit(0, 1);
  int named = 0, spots = test_volume(400, 80);
  for (int spot = 0; spot < spots; ++spot) {
    const Point centre{coordinate(random), coordinate(random)};
    const double spread = 0.5 * unit(random) * unit(random);
    const double reach = index.nearest(centre).distance + spread + unit(random);
    const RegionIndex::Nearby nearby(index, centre, spread, reach);
    const std::size_t sole = nearby.sole();
    // Promised a reach short of the boundary, the list may lack the
    // nearest: no element can be named sole.
    EXPECT_EQ(RegionIndex::Nearby(index, centre, spread, 0.5 * index.nearest(centre).distance).sole(), SIZE_MAX);
    if (sole == SIZE_MAX) continue;
    ++named;
    for (int i = 0; i < 20; ++i) {
      const Point p = around(random, centre, 0, spread);
      const double own = distance(nearest_point(all[sole], p), p);
      for (std::size_t e = 0; e < all.size(); ++e) {
        if (e != sole) {
          ASSERT_LT(own, distance(nearest_point(all[e], p), p)) << "element " << e << " as near";
        }
      }
      const RegionQuery q = nearby.nearest(p);
      ASSERT_EQ(q.element, sole);
      ASSERT_EQ(q.distance, index.distance_to(sole, p));
    }
  }
  EXPECT_GT(named, spots / 10) << "sole() named an element at " << named << " of " << spots << " spots";
  // Two elements equally near the centre: neither is sole.
  const std::vector<Segment> sides{
      {{0, 0}, {10, 0}, 0}, {{10, 0}, {10, 10}, 0}, {{10, 10}, {0, 10}, 0}, {{0, 10}, {0, 0}, 0}};
  const LoopSet square = build_loops(sides, 1e-9);
  const RegionIndex square_index(square.loops, RegionIndex::Layout::tree);
  EXPECT_EQ(RegionIndex::Nearby(square_index, {5, 5}, 0.1, 10).sole(), SIZE_MAX);
  EXPECT_NE(RegionIndex::Nearby(square_index, {5, 1}, 0.1, 10).sole(), SIZE_MAX);
}

TEST(RegionNearby, NamesTheLowerOfEquallyNearElements) {
  // A comb's slots: points on a slot's middle line are equally far from
  // both walls (exactly, on these coordinates), and brute force names
  // the lower element; the list's order by distance from the centre must
  // not change that.
  std::vector<Point> v;
  for (int k = 0; k < 40; ++k) {
    const double x = 2.0 * k;
    v.insert(v.end(), {{x, 0}, {x, 10}, {x + 1, 10}, {x + 1, 0}});
  }
  v.insert(v.end(), {{80, -5}, {0, -5}});
  std::vector<Segment> comb;
  for (std::size_t i = 0; i < v.size(); ++i) comb.push_back({v[i], v[(i + 1) % v.size()], 0});
  const LoopSet set = build_loops(comb, 1e-9);
  const RegionIndex index(set.loops, RegionIndex::Layout::tree);
  int ties = 0;
  for (int slot = 0; slot < 39; ++slot) {
    const Point centre{2.0 * slot + 1.5, 5};
    const double spread = 4;
    const RegionIndex::Nearby nearby(index, centre, spread, index.nearest(centre).distance + spread);
    for (double y = 1; y <= 9; y += 0.5) {
      const Point p{centre.x, y};
      expect_brute_force(nearby, set.loops, p, "slot middle");
      // A tie: another element exactly as near, and the answer the lower.
      const RegionQuery got = nearby.nearest(p);
      std::size_t equally_near = 0, lowest = SIZE_MAX;
      for (std::size_t e = 0; e < index.elements().size(); ++e)
        if (index.distance_to(e, p) == got.distance) ++equally_near, lowest = std::min(lowest, e);
      if (equally_near >= 2) {
        ++ties;
        EXPECT_EQ(got.element, lowest) << "slot middle at (" << p.x << ", " << p.y << ")";
      }
    }
  }
  EXPECT_GT(ties, 39 * 10);  // most of those points are ties: the rule was exercised
}

TEST(RegionNearby, DistanceToOneElementAsTheSegmentsOwn) {
  // distance_to() (the index's prepared kernel) against the segment's own
  // nearest point, lines and arcs, near and far.
  std::mt19937_64 random(5);
  const LoopSet set = build_loops(parts::random_star_with_hole(random, 60), 1e-9);
  const RegionIndex index(set.loops, RegionIndex::Layout::tree);
  std::uniform_real_distribution<double> coordinate(-80, 80);
  for (int i = 0; i < 2000; ++i) {
    const Point p{coordinate(random), coordinate(random)};
    const std::size_t e = static_cast<std::size_t>(i) % index.elements().size();
    const Segment& s = index.elements()[e];
    const double want = distance(nearest_point(s, p), p);
    ASSERT_NEAR(index.distance_to(e, p), want, 1e-12 * (1 + want)) << "element " << e;
  }
}

TEST(RegionNearby, EmptyIndexAnswersAsNearest) {
  const RegionIndex index(std::vector<Loop>{}, RegionIndex::Layout::tree);
  const RegionIndex::Nearby nearby(index, {0, 0}, 1, 1);
  const RegionQuery got = nearby.nearest({0.5, 0}), want = index.nearest({0.5, 0});
  EXPECT_TRUE(std::isinf(got.distance));
  EXPECT_EQ(got.distance, want.distance);
  EXPECT_EQ(got.element, want.element);
  EXPECT_EQ(got.nearest.x, 0.5);
  EXPECT_EQ(got.nearest.y, 0.0);
}

}  // namespace region_nearby_test
