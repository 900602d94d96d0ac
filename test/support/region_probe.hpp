/// @file region_probe.hpp
/// @brief RegionIndex against brute_force_query (the oracle) at probe
/// points: random ones over the loops' box enlarged by 10 %, every vertex,
/// points on edges and a hair off them. Shared by the unit tests.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "cad/loops.hpp"
#include "cad/region_distance.hpp"
#include "cad/segment_geometry.hpp"

namespace tk::cad::probe {

struct Comparison {
  std::size_t points = 0, sign_checked = 0;
};

/// The same answer without the sign (nearest()): the element and point
/// exactly, the distance exactly query()'s magnitude.
inline void expect_same_nearest(const RegionQuery& unsigned_answer, const RegionQuery& signed_answer, Point p,
                                const char* what) {
  EXPECT_EQ(unsigned_answer.element, signed_answer.element) << what << ' ' << p.x << ' ' << p.y;
  EXPECT_EQ(unsigned_answer.distance, std::abs(signed_answer.distance)) << what << ' ' << p.x << ' ' << p.y;
  EXPECT_EQ(unsigned_answer.nearest.x, signed_answer.nearest.x) << what << ' ' << p.x << ' ' << p.y;
  EXPECT_EQ(unsigned_answer.nearest.y, signed_answer.nearest.y) << what << ' ' << p.x << ' ' << p.y;
}

/// Both layouts' query() against brute force; nearest() against query(),
/// on the tree with hints: the last answer's element (as along a path)
/// and, every third point, an unrelated one.
inline Comparison compare(const std::vector<Loop>& loops, const std::vector<Point>& points) {
  const RegionIndex index(loops), tree(loops, RegionIndex::Layout::tree);
  std::size_t elements = 0, hint = SIZE_MAX;
  for (const Loop& l : loops) elements += l.segments.size();
  Comparison result;
  for (const Point& p : points) {
    const RegionQuery slow = brute_force_query(loops, p), by_tree = tree.query(p);
    EXPECT_EQ(by_tree.element, slow.element) << "tree " << p.x << ' ' << p.y;
    EXPECT_EQ(by_tree.nearest.x, slow.nearest.x) << "tree " << p.x << ' ' << p.y;
    EXPECT_EQ(by_tree.nearest.y, slow.nearest.y) << "tree " << p.x << ' ' << p.y;
    if (std::abs(slow.distance) >= 1e-9) {
      EXPECT_EQ(by_tree.inside(), slow.inside()) << "tree " << p.x << ' ' << p.y;
    }
    if (result.points % 3 == 2 && elements > 0) hint = (result.points * 7919) % elements;
    const RegionQuery hinted = tree.nearest(p, hint);
    expect_same_nearest(hinted, by_tree, p, "hinted");
    hint = hinted.element;
    const RegionQuery fast = index.query(p);
    expect_same_nearest(index.nearest(p), fast, p, "grid nearest");
    const double tolerance = 1e-12 * std::max(1.0, std::abs(slow.distance));
    ++result.points;
    EXPECT_NEAR(std::abs(fast.distance), std::abs(slow.distance), tolerance) << p.x << ' ' << p.y;
    EXPECT_NEAR(std::hypot(fast.nearest.x - p.x, fast.nearest.y - p.y), std::abs(fast.distance), 1e-9 * std::max(1.0, std::abs(slow.distance)));
    // Of equally near elements, the lowest index (brute force's scan order):
    // the element and the nearest point on it are exactly brute force's.
    EXPECT_EQ(fast.element, slow.element) << p.x << ' ' << p.y;
    EXPECT_EQ(fast.nearest.x, slow.nearest.x) << p.x << ' ' << p.y;
    EXPECT_EQ(fast.nearest.y, slow.nearest.y) << p.x << ' ' << p.y;
    if (std::abs(slow.distance) >= 1e-9) {
      ++result.sign_checked;
      EXPECT_EQ(fast.inside(), slow.inside()) << p.x << ' ' << p.y << " at " << slow.distance;
    }
    if (testing::Test::HasFailure()) break;  // one report is enough
  }
  return result;
}

/// Random points in the loops' box enlarged by 10 %, every vertex, points
/// on edges, and points a hair off edges.
inline std::vector<Point> probe_points(std::mt19937_64& random, const std::vector<Loop>& loops, std::size_t count) {
  Box box = bounding_box(loops[0].segments[0]);
  for (const Loop& l : loops)
    for (const Segment& s : l.segments) {
      const Box b = bounding_box(s);
      box = {std::min(box.min_x, b.min_x), std::min(box.min_y, b.min_y), std::max(box.max_x, b.max_x),
             std::max(box.max_y, b.max_y)};
    }
  const double mx = 0.05 * (box.max_x - box.min_x), my = 0.05 * (box.max_y - box.min_y);
  std::uniform_real_distribution<double> x(box.min_x - mx, box.max_x + mx), y(box.min_y - my, box.max_y + my);
  std::uniform_real_distribution<double> t(0, 1), off(-1, 1);
  std::vector<Point> points;
  for (std::size_t i = 0; i < count; ++i) points.push_back({x(random), y(random)});
  for (const Loop& l : loops)
    for (const Segment& s : l.segments) {
      points.push_back(s.start);
      points.push_back(point_at(s, t(random)));
      const Point on = point_at(s, t(random)), tangent = tangent_at(s, 0.5);
      for (double h : {1e-12, 1e-8, 1e-4})
        points.push_back({on.x - tangent.y * h * off(random), on.y + tangent.x * h * off(random)});
    }
  return points;
}

}  // namespace tk::cad::probe
