/// @file test_region_contour_index.cpp
/// @brief The contour's index without its grid (OffsetOptions::contour_grid
/// false: the box tree alone, asked with hints along the drawing) finds the
/// same stretches out of reach as with it, each where brute force over the
/// contour finds material left; and hinted nearest() queries along a path
/// name exactly brute force's element, whatever the hint.
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
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

namespace region_contour_index_test {  // named: the unity build joins the tests' anonymous namespaces

using namespace tk::cad;

std::vector<Segment> closed(const std::vector<Point>& v, double bulge = 0) {
  std::vector<Segment> out;
  for (std::size_t i = 0; i < v.size(); ++i) out.push_back({v[i], v[(i + 1) % v.size()], bulge});
  return out;
}

using parts::gear;

/// Teeth 10 mm tall and 1 mm wide, `gap` mm apart, on a 5 mm bar.
std::vector<Segment> comb(int teeth, double gap) {
  std::vector<Point> v;
  for (int k = 0; k < teeth; ++k) {
    const double x = (1 + gap) * k;
    v.insert(v.end(), {{x, 0}, {x, 10}, {x + 1, 10}, {x + 1, 0}});
  }
  v.insert(v.end(), {{(1 + gap) * teeth, -5}, {0, -5}});
  return closed(v);
}

double brute_force_gap(const std::vector<Loop>& contour, Point p, double radius) {
  return std::abs(brute_force_query(contour, p).distance) - radius;
}

void expect_same_uncut(const std::vector<Segment>& segments, double radius, MachiningSide side,
                       const std::string& what) {
  const LoopSet set = build_loops(segments, 1e-6);
  const RegionIndex index(set.loops);
  OffsetOptions options;
  options.tool_radius = radius;
  options.side = side;
  options.contour_grid = true;
  const RegionOffset gridded = offset_region(set.loops, index, options);
  options.contour_grid = false;
  const RegionOffset tree = offset_region(set.loops, index, options);
  ASSERT_TRUE(tree.contour) << what;
  // Exactly the same numbers: both indexes name the nearest element by the same rule.
  ASSERT_EQ(gridded.uncut.size(), tree.uncut.size()) << what;
  for (std::size_t i = 0; i < tree.uncut.size(); ++i) {
    EXPECT_EQ(gridded.uncut[i].from.x, tree.uncut[i].from.x) << what;
    EXPECT_EQ(gridded.uncut[i].from.y, tree.uncut[i].from.y) << what;
    EXPECT_EQ(gridded.uncut[i].to.x, tree.uncut[i].to.x) << what;
    EXPECT_EQ(gridded.uncut[i].to.y, tree.uncut[i].to.y) << what;
    EXPECT_EQ(gridded.uncut[i].depth, tree.uncut[i].depth) << what;
    // Brute force over the contour: material is left at both ends of the
    // span, and no deeper than the depth reported.
    for (const Point p : {tree.uncut[i].from, tree.uncut[i].to}) {
      const double gap = brute_force_gap(tree.loops, p, radius);
      EXPECT_GT(gap, options.uncut_report_mm) << what << ", span " << i;
      EXPECT_LE(gap, tree.uncut[i].depth + 1e-12) << what << ", span " << i;
    }
  }
  // With no span reported, brute force finds the whole drawing within reach
  // at a sample of its points.
  if (tree.uncut.empty()) {
    for (const Loop& loop : set.loops)
      for (std::size_t k = 0; k < loop.segments.size(); k += 7)
        EXPECT_LE(brute_force_gap(tree.loops, point_at(loop.segments[k], 0.5), radius), options.uncut_report_mm)
            << what;
  }
}

std::string label(double radius, MachiningSide side) {
  return "R " + std::to_string(radius) + (side == MachiningSide::inside ? " inside" : " outside");
}

TEST(RegionContourIndex, TreeFindsTheSameUncutSpansOnGears) {
  for (const double bulge : {0.0, -0.15})
    for (const double radius : {0.3, 1.0, 3.0})
      for (const MachiningSide side : {MachiningSide::outside, MachiningSide::inside}) {
        const double height = side == MachiningSide::inside ? 3 : 5;
        expect_same_uncut(gear(test_volume(60, 16), height, 1.5, bulge), radius, side,
                          label(radius, side) + ", bulge " + std::to_string(bulge));
      }
}

TEST(RegionContourIndex, TreeFindsTheSameUncutSpansOnCombs) {
  for (const double gap : {0.5, 1.0, 3.0})
    for (const double radius : {0.4, 1.0})
      for (const MachiningSide side : {MachiningSide::outside, MachiningSide::inside})
        expect_same_uncut(comb(test_volume(80, 20), gap), radius, side,
                          label(radius, side) + ", gap " + std::to_string(gap));
}

TEST(RegionContourIndex, TreeFindsTheSameUncutSpansOnRandomParts) {
  std::mt19937_64 random(2024);
  for (int star = 0; star < test_volume(8, 3); ++star) {
    const std::vector<Segment> part = parts::random_star_with_hole(random, 6 + 3 * star);
    for (const double radius : {0.7, 2.5})
      for (const MachiningSide side : {MachiningSide::outside, MachiningSide::inside})
        expect_same_uncut(part, radius, side, "star " + std::to_string(star) + ", R " + std::to_string(radius));
  }
}

/// Points along a zigzag over a comb with duplicated pieces (exact ties),
/// asked of the tree with the last answer as the hint, then with a far
/// element as the hint, then with none: brute force's element every time.
TEST(RegionContourIndex, HintedQueriesAlongAPathMatchBruteForce) {
  std::vector<Segment> part = comb(test_volume(40, 12), 1);
  const std::size_t drawn = part.size();
  for (std::size_t i = 0; i < drawn; i += 5) part.push_back(part[i]);  // drawn twice: even-odd cancels, ties stay
  const std::vector<Loop> loops{{part, 0, -1, 0}};
  const RegionIndex tree(loops, RegionIndex::Layout::tree), grid(loops);
  std::size_t last = SIZE_MAX;
  const double width = 2.0 * double(test_volume(40, 12));
  int checked = 0;
  for (double y = -7; y <= 13; y += 0.37)
    for (double x = -2; x <= width + 2; x += 0.093) {
      const Point p{x, y};
      const RegionQuery slow = brute_force_query(loops, p);
      for (const std::size_t hint : {last, std::size_t(0), part.size() - 1, SIZE_MAX}) {
        const RegionQuery fast = tree.nearest(p, hint);
        ASSERT_EQ(fast.element, slow.element) << x << ' ' << y << " hint " << hint;
        ASSERT_EQ(fast.distance, std::abs(slow.distance)) << x << ' ' << y << " hint " << hint;
        ASSERT_EQ(fast.nearest.x, slow.nearest.x) << x << ' ' << y;
        ASSERT_EQ(fast.nearest.y, slow.nearest.y) << x << ' ' << y;
      }
      const RegionQuery gridded = grid.nearest(p);
      ASSERT_EQ(gridded.element, slow.element) << x << ' ' << y;
      ASSERT_EQ(gridded.distance, std::abs(slow.distance)) << x << ' ' << y;
      last = slow.element;
      ++checked;
    }
  EXPECT_GT(checked, 1000);
}

}  // namespace region_contour_index_test
