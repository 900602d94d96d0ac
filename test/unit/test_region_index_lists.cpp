/// @file test_region_index_lists.cpp
/// @brief RegionIndex's leaf candidate lists (pruned at one quartering of
/// each leaf) keep every element that can be nearest somewhere in the
/// leaf: the index against brute_force_query (the oracle) on ring, gear and
/// comb outlines made of arcs as well as lines, at points packed densely
/// round the boundary (many per leaf, into the leaves' corners, where a
/// list pruned too hard would first miss the winner) and uniformly over
/// the box. Distances, the element named (the lowest index of equally near
/// ones) and the nearest point must be brute force's exactly.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "cad/loops.hpp"
#include "cad/region_distance.hpp"
#include "cad/segment_geometry.hpp"
#include "region_probe.hpp"
#include "test_volume.hpp"

namespace {

using namespace tk::cad;
constexpr double kPi = std::numbers::pi;

Point polar(Point c, double r, double a) { return {c.x + r * std::cos(a), c.y + r * std::sin(a)}; }

/// A closed loop through `corners`, each piece with the bulge given for it.
Loop chain(const std::vector<Point>& corners, const std::vector<double>& bulges) {
  Loop loop;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    Segment s;
    s.start = corners[i], s.end = corners[(i + 1) % corners.size()], s.bulge = bulges[i % bulges.size()];
    loop.segments.push_back(s);
  }
  return loop;
}

/// A wavy ring whose pieces alternate between arcs bulging either way and lines.
Loop arc_ring(std::size_t n, Point c, double radius) {
  std::vector<Point> v;
  for (std::size_t i = 0; i < n; ++i) {
    const double a = 2 * kPi * double(i) / double(n);
    v.push_back(polar(c, radius * (1 + 0.015 * std::sin(60 * a)), a));
  }
  return chain(v, {0.2, 0, -0.15});
}

/// Teeth of a flank line, a tip arc, the other flank and a root arc.
Loop arc_gear(std::size_t teeth, double root, double tip) {
  std::vector<Point> v;
  const double pitch = 2 * kPi / double(teeth);
  for (std::size_t t = 0; t < teeth; ++t) {
    const double a = double(t) * pitch;
    v.insert(v.end(), {polar({0, 0}, root, a), polar({0, 0}, tip, a + 0.3 * pitch), polar({0, 0}, tip, a + 0.5 * pitch),
                       polar({0, 0}, root, a + 0.8 * pitch)});
  }
  return chain(v, {0, std::tan(0.2 * pitch / 4), 0, std::tan(0.2 * pitch / 4)});
}

/// Teeth with round tips (half circles) on a bar.
Loop arc_comb(std::size_t teeth) {
  std::vector<Point> v;
  std::vector<double> bulges;
  for (std::size_t k = 0; k < teeth; ++k) {
    const double x = 2 * double(k);
    v.insert(v.end(), {{x, 0}, {x, 10}, {x + 1, 10}, {x + 1, 0}});
    bulges.insert(bulges.end(), {0, -1, 0, 0});
  }
  v.insert(v.end(), {{2 * double(teeth), -5}, {0, -5}});
  bulges.insert(bulges.end(), {0, 0});
  Loop loop = chain(v, bulges);
  return loop;
}

/// Random points within `reach` of random points of the boundary: many to a
/// leaf, at all distances up to a few cells, inside and out.
std::vector<Point> near_boundary(std::mt19937_64& random, const std::vector<Loop>& loops, double reach,
                                 std::size_t count) {
  std::vector<const Segment*> all;
  for (const Loop& l : loops)
    for (const Segment& s : l.segments) all.push_back(&s);
  std::uniform_int_distribution<std::size_t> which(0, all.size() - 1);
  std::uniform_real_distribution<double> t(0, 1), off(-reach, reach);
  std::vector<Point> points;
  for (std::size_t i = 0; i < count; ++i) {
    const Point on = point_at(*all[which(random)], t(random));
    points.push_back({on.x + off(random), on.y + off(random)});
  }
  return points;
}

void expect_brute_force_answers(const std::vector<Loop>& loops, double reach, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::vector<Point> points = probe::probe_points(random, loops, test_volume(4000, 1000));
  for (const double scale : {reach, reach / 8}) {
    const std::vector<Point> near = near_boundary(random, loops, scale, test_volume(8000, 2000));
    points.insert(points.end(), near.begin(), near.end());
  }
  const probe::Comparison c = probe::compare(loops, points);
  EXPECT_EQ(c.points, points.size());
}

TEST(RegionIndexLists, ArcRingMatchesBruteForce) { expect_brute_force_answers({arc_ring(3000, {0, 0}, 100)}, 8, 241); }

TEST(RegionIndexLists, ArcGearMatchesBruteForce) { expect_brute_force_answers({arc_gear(700, 95, 100)}, 3, 242); }

TEST(RegionIndexLists, ArcCombMatchesBruteForce) { expect_brute_force_answers({arc_comb(500)}, 3, 243); }

/// The three as holes of one plate, so that lists of different outlines meet.
TEST(RegionIndexLists, ArcShapesAsHolesMatchBruteForce) {
  const std::vector<Loop> loops{chain({{-150, -150}, {1200, -150}, {1200, 150}, {-150, 150}}, {0}),
                                arc_ring(1500, {0, 0}, 60), arc_gear(200, 40, 44), arc_comb(250)};
  // The gear and comb moved clear of the ring.
  std::vector<Loop> placed = loops;
  for (Segment& s : placed[2].segments) s.start.x += 250, s.end.x += 250;
  for (Segment& s : placed[3].segments) s.start.x += 400, s.end.x += 400;
  expect_brute_force_answers(placed, 4, 244);
}

}  // namespace
