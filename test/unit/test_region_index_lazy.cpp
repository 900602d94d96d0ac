/// @file test_region_index_lazy.cpp
/// @brief RegionIndex's grid is laid out by the first query() and built
/// tile by tile where queries land: nearest() before it (the tree) and
/// after it (built tiles, the tree elsewhere) names the same element at
/// the same distance as brute force; threads asking at once, in the same
/// tiles or in others, all get brute force's answers (a tile asked for by
/// several at once is built by one, the others waiting); and an index built
/// whole by prepare() and one built tile by tile both give brute force's
/// element, distance and nearest point, to the bit.
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <future>
#include <limits>
#include <random>
#include <vector>

#include "cad/loops.hpp"
#include "cad/region_distance.hpp"
#include "region_parts.hpp"
#include "test_volume.hpp"

namespace region_index_lazy_test {  // named: the unity build joins the tests' anonymous namespaces

using namespace tk::cad;
using tk::cad::parts::random_star_with_hole;

std::vector<Point> random_points(std::mt19937_64& random, int count) {
  std::uniform_real_distribution<double> coordinate(-60, 60);
  std::vector<Point> points;
  for (int i = 0; i < count; ++i) points.push_back({coordinate(random), coordinate(random)});
  return points;
}

/// Brute force's answers: the element and the signed distance.
struct Expected {
  std::size_t element;
  double distance;
};

std::vector<Expected> brute_force(const std::vector<Loop>& loops, const std::vector<Point>& points) {
  std::vector<Expected> out;
  for (const Point& p : points) {
    const RegionQuery q = brute_force_query(loops, p);
    out.push_back({q.element, q.distance});
  }
  return out;
}

/// How many of query()'s answers differ from brute force's, asking from point `first` on, round to it.
std::size_t wrong_answers(const RegionIndex& index, const std::vector<Point>& points,
                          const std::vector<Expected>& expected, std::size_t first) {
  std::size_t wrong = 0;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const std::size_t i = (first + k) % points.size();
    const RegionQuery q = index.query(points[i]);
    wrong += q.element != expected[i].element || q.distance != expected[i].distance;
  }
  return wrong;
}

TEST(RegionIndexLazyGrid, NearestBeforeAndAfterTheFirstQueryAgreeWithBruteForce) {
  std::mt19937_64 random(7);
  const LoopSet set = build_loops(random_star_with_hole(random, test_volume(600, 150)), 1e-9);
  const std::vector<Point> points = random_points(random, test_volume(3000, 400));
  const std::vector<Expected> expected = brute_force(set.loops, points);
  const RegionIndex index(set.loops);
  for (std::size_t i = 0; i < points.size(); ++i) {  // the tree: no query() yet
    const RegionQuery q = index.nearest(points[i]);
    ASSERT_EQ(q.element, expected[i].element) << "before, point " << i;
    ASSERT_EQ(q.distance, std::abs(expected[i].distance)) << "before, point " << i;
  }
  ASSERT_EQ(index.query(points[0]).distance, expected[0].distance);  // builds the grid
  for (std::size_t i = 0; i < points.size(); ++i) {
    const RegionQuery near = index.nearest(points[i]), signed_distance = index.query(points[i]);
    ASSERT_EQ(near.element, expected[i].element) << "after, point " << i;
    ASSERT_EQ(near.distance, std::abs(expected[i].distance)) << "after, point " << i;
    ASSERT_EQ(signed_distance.element, expected[i].element) << "after, point " << i;
    ASSERT_EQ(signed_distance.distance, expected[i].distance) << "after, point " << i;
  }
}

TEST(RegionIndexLazyGrid, ThreadsAskingAtOnceGetBruteForcesAnswers) {
  std::mt19937_64 random(11);
  for (int round = 0; round < test_volume(8, 2); ++round) {
    const LoopSet set = build_loops(random_star_with_hole(random, test_volume(3000, 600)), 1e-9);
    const std::vector<Point> points = random_points(random, test_volume(2000, 300));
    const std::vector<Expected> expected = brute_force(set.loops, points);
    // Two threads from opposite ends of the list (mostly other tiles), then
    // four in the same order (each tile asked for by all at about once).
    for (const std::size_t threads : {2, 4}) {
      const RegionIndex index(set.loops);
      const auto ask = [&](std::size_t first) { return wrong_answers(index, points, expected, first); };
      std::vector<std::future<std::size_t>> others;
      for (std::size_t t = 1; t < threads; ++t)
        others.push_back(std::async(std::launch::async, ask, threads == 2 ? points.size() / 2 : 0));
      EXPECT_EQ(ask(0), 0u) << "round " << round << ", " << threads << " threads";
      for (auto& other : others) EXPECT_EQ(other.get(), 0u) << "round " << round << ", " << threads << " threads";
    }
  }
}

TEST(RegionIndexLazyGrid, PreparedWholeAndBuiltTileByTileBothAnswerAsBruteForce) {
  std::mt19937_64 random(17);
  const LoopSet set = build_loops(random_star_with_hole(random, test_volume(2000, 400)), 1e-9);
  const std::vector<Point> points = random_points(random, test_volume(4000, 500));
  const RegionIndex whole(set.loops), lazy(set.loops);
  whole.prepare();
  for (std::size_t i = 0; i < points.size(); ++i) {
    const RegionQuery want = brute_force_query(set.loops, points[i]);
    for (const RegionIndex* index : {&whole, &lazy}) {
      const RegionQuery got = index->query(points[i]);
      const char* which = index == &whole ? "prepared, point " : "tile by tile, point ";
      ASSERT_EQ(got.element, want.element) << which << i;
      ASSERT_EQ(got.distance, want.distance) << which << i;
      ASSERT_EQ(got.nearest.x, want.nearest.x) << which << i;
      ASSERT_EQ(got.nearest.y, want.nearest.y) << which << i;
    }
  }
  const RegionIndex empty(std::vector<Loop>{});
  empty.prepare();  // nothing to build
  EXPECT_EQ(empty.query({1, 2}).distance, std::numeric_limits<double>::infinity());
}

}  // namespace region_index_lazy_test
