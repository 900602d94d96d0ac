/// @file test_region_index_shapes.cpp
/// @brief RegionIndex against brute_force_query on the shapes that made its
/// build slow (bench_region_build's): a finely divided wavy ring round a
/// wide empty interior (cells with too many nearly equidistant elements
/// keep no list), a gear of spikes narrower than its cells, and a long comb
/// whose inside flags are chained across thousands of cells; also as holes
/// in a plate, so that the chain passes in and out of the region.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "cad/loops.hpp"
#include "cad/region_distance.hpp"
#include "region_probe.hpp"
#include "test_volume.hpp"

namespace {

using namespace tk::cad;

Loop polygon(const std::vector<Point>& corners) {
  Loop loop;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    Segment s;
    s.start = corners[i], s.end = corners[(i + 1) % corners.size()];
    loop.segments.push_back(s);
  }
  return loop;
}

Loop wavy_ring(std::size_t n, Point c, double radius) {
  std::vector<Point> v;
  for (std::size_t i = 0; i < n; ++i) {
    const double a = 2 * std::numbers::pi * double(i) / double(n), r = radius * (1 + 0.015 * std::sin(60 * a));
    v.push_back({c.x + r * std::cos(a), c.y + r * std::sin(a)});
  }
  return polygon(v);
}

Loop spiky_gear(std::size_t spikes) {
  const double root = double(spikes) * 0.5 / (2 * std::numbers::pi);
  std::vector<Point> v;
  for (std::size_t i = 0; i < spikes; ++i) {
    const double a = 2 * std::numbers::pi * double(i) / double(spikes),
                 b = 2 * std::numbers::pi * (double(i) + 0.5) / double(spikes);
    v.push_back({root * std::cos(a), root * std::sin(a)});
    v.push_back({(root + 5) * std::cos(b), (root + 5) * std::sin(b)});
  }
  return polygon(v);
}

Loop comb(std::size_t teeth, double y0) {
  std::vector<Point> v;
  for (std::size_t k = 0; k < teeth; ++k) {
    const double x = 2 * double(k);
    v.insert(v.end(), {{x, y0}, {x, y0 + 10}, {x + 1, y0 + 10}, {x + 1, y0}});
  }
  v.insert(v.end(), {{2 * double(teeth), y0 - 5}, {0, y0 - 5}});
  return polygon(v);
}

TEST(RegionIndexShapes, WavyRingMatchesBruteForce) {
  std::mt19937_64 random(24);
  const std::vector<Loop> loops{wavy_ring(3000, {0, 0}, 100)};
  const std::size_t count = test_volume(5000, 1500);
  const probe::Comparison c = probe::compare(loops, probe::probe_points(random, loops, count));
  EXPECT_GT(c.sign_checked, count);
}

TEST(RegionIndexShapes, SpikyGearMatchesBruteForce) {
  std::mt19937_64 random(25);
  const std::vector<Loop> loops{spiky_gear(1000)};
  probe::compare(loops, probe::probe_points(random, loops, test_volume(5000, 1500)));
}

TEST(RegionIndexShapes, LongCombMatchesBruteForce) {
  std::mt19937_64 random(26);
  const std::vector<Loop> loops{comb(600, 0)};
  probe::compare(loops, probe::probe_points(random, loops, test_volume(5000, 1500)));
}

TEST(RegionIndexShapes, CombsAndRingsAsHolesMatchBruteForce) {
  std::mt19937_64 random(27);
  std::vector<Loop> loops{polygon({{-20, -150}, {1300, -150}, {1300, 150}, {-20, 150}}), comb(600, 20), comb(300, -60)};
  for (int i = 0; i < 5; ++i) loops.push_back(wavy_ring(200, {100 + 220.0 * i, -110}, 20));
  probe::compare(loops, probe::probe_points(random, loops, test_volume(5000, 1500)));
}

/// The element a query names where several are exactly equally near (the
/// middle of a slot, round a convex corner, on a vertex): the lowest index,
/// whatever leaf or tree node the query went through. A grid of quarter
/// millimetres over integer outlines lands on many exact ties; they are
/// counted by brute force over the elements in reverse order, which names
/// the highest index instead.
TEST(RegionIndexShapes, EquallyNearElementsNameTheLowestIndex) {
  std::vector<Loop> loops{polygon({{-10, -20}, {150, -20}, {150, 30}, {-10, 30}}), comb(60, 5),
                          polygon({{20, -15}, {40, -15}, {40, -5}, {20, -5}})};
  std::vector<Loop> reversed(loops.rbegin(), loops.rend());
  for (Loop& l : reversed) std::reverse(l.segments.begin(), l.segments.end());
  std::size_t elements = 0;
  for (const Loop& l : loops) elements += l.segments.size();
  std::vector<Point> grid;
  const int step = test_volume(1, 2);  // every other row and column under the sanitizers
  for (int y = -100; y <= 140; y += step)
    for (int x = -60; x <= 620; x += step) grid.push_back({x * 0.25, y * 0.25});
  std::size_t ties = 0;
  for (const Point& p : grid)
    ties += brute_force_query(loops, p).element != elements - 1 - brute_force_query(reversed, p).element;
  EXPECT_GT(ties, 1000u / (step * step));
  probe::compare(loops, grid);
}

}  // namespace
