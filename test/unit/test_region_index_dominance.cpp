/// @file test_region_index_dominance.cpp
/// @brief The index's dominance test (an element, or a box, farther than a
/// point q from every point of a square) against brute force: wherever it
/// says so, |p - q| + margin < d(p, e) must hold at every point of a dense
/// lattice over the square and at random points in it, the distance
/// worked out from the element's centre and angles (not by the index's
/// kernel, which works in the chord's frame). The test asks only the
/// square's corners (its comment in region_index_impl.hpp says why that
/// is enough); squares are drawn round the elements' ends, on
/// them and near them, and arcs sweep up to nearly a full turn.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "cad/region_index_impl.hpp"
#include "cad/segment_geometry.hpp"

namespace {

using namespace tk::cad;
using namespace tk::cad::region_index;

double segment_distance(Point a, Point b, Point p) {
  const double dx = b.x - a.x, dy = b.y - a.y, length2 = dx * dx + dy * dy;
  const double t = length2 > 0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / length2, 0.0, 1.0) : 0;
  return std::hypot(p.x - a.x - t * dx, p.y - a.y - t * dy);
}

/// The distance from p to the element, worked out by angles (atan2) from
/// the bulge's centre and sweep, not by the index's chord frame.
double element_distance(const Segment& s, Point p) {
  if (s.bulge == 0) return segment_distance(s.start, s.end, p);
  const double cx = s.end.x - s.start.x, cy = s.end.y - s.start.y, chord = std::hypot(cx, cy);
  const double offset = chord / 2 * (1 - s.bulge * s.bulge) / (2 * s.bulge);  // along the chord's left normal
  const Point centre{(s.start.x + s.end.x) / 2 - cy / chord * offset, (s.start.y + s.end.y) / 2 + cx / chord * offset};
  const double radius = std::hypot(s.start.x - centre.x, s.start.y - centre.y);
  const double sweep = 4 * std::atan(std::abs(s.bulge));
  // Counter-clockwise from `from` through `sweep`.
  const Point from = s.bulge > 0 ? s.start : s.end;
  const double a0 = std::atan2(from.y - centre.y, from.x - centre.x);
  double turn = std::atan2(p.y - centre.y, p.x - centre.x) - a0;
  while (turn < 0) turn += 2 * std::numbers::pi;
  while (turn >= 2 * std::numbers::pi) turn -= 2 * std::numbers::pi;
  if (turn <= sweep) return std::abs(std::hypot(p.x - centre.x, p.y - centre.y) - radius);
  return std::min(std::hypot(p.x - s.start.x, p.y - s.start.y), std::hypot(p.x - s.end.x, p.y - s.end.y));
}

/// The distance from p to the box: to its nearest point, p clamped into it.
double box_distance(const Box& b, Point p) {
  return std::hypot(p.x - std::clamp(p.x, b.min_x, b.max_x), p.y - std::clamp(p.y, b.min_y, b.max_y));
}

/// Points of the square: a lattice of 41 x 41 and 400 random ones.
std::vector<Point> sample(const Square& s, std::mt19937_64& random) {
  std::vector<Point> out;
  for (int i = 0; i <= 40; ++i)
    for (int j = 0; j <= 40; ++j) out.push_back({s.x0 + (s.x1 - s.x0) * i / 40, s.y0 + (s.y1 - s.y0) * j / 40});
  std::uniform_real_distribution<double> u(0, 1);
  for (int i = 0; i < 400; ++i) out.push_back({s.x0 + (s.x1 - s.x0) * u(random), s.y0 + (s.y1 - s.y0) * u(random)});
  return out;
}

struct Tally {
  int said = 0, asked = 0;
};

/// Draws a square near the element, and q at a random point near it;
/// checks the test's yes against brute force.
void check_element(const Segment& s, std::mt19937_64& random, Tally& tally) {
  const Kernel k = make_kernel(s);
  const Box b = bounding_box(s);
  const double extent = std::max(b.max_x - b.min_x, b.max_y - b.min_y);
  std::uniform_real_distribution<double> where(-1.5, 1.5), side(0.02, 1.2), t(0, 1);
  for (int trial = 0; trial < 40; ++trial) {
    // The square round a point near an end, the centre or anywhere near.
    const Point anchor = trial % 4 == 0 ? s.start : trial % 4 == 1 ? s.end : point_at(s, t(random));
    const double half = side(random) * extent / 2;
    const double off = trial % 8 < 4 ? extent : extent / 10;  // half the squares on or next to the element
    const Point c{anchor.x + where(random) * off, anchor.y + where(random) * off};
    const Square square{c.x - half, c.y - half, c.x + half, c.y + half};
    // q: a point whose distance from the square's centre is below the element's, often just.
    const double d = element_distance(s, c);
    // The oracle and the index's kernel agree where both are asked.
    ASSERT_NEAR(d, std::sqrt(distance2(k, c)), 1e-9 * (extent + d));
    const double angle = 2 * std::numbers::pi * t(random), r = d * (0.3 + 0.69 * t(random));
    const Point q{c.x + r * std::cos(angle), c.y + r * std::sin(angle)};
    const double margin = 1e-9 * extent;
    ++tally.asked;
    if (!Dominance(square, q, margin).dominated(k)) continue;
    ++tally.said;
    for (const Point p : sample(square, random))
      ASSERT_LT(std::hypot(p.x - q.x, p.y - q.y), element_distance(s, p) + 1e-9 * extent)
          << "bulge " << s.bulge << " square centre " << c.x << "," << c.y << " half " << half;
  }
}

TEST(RegionIndexDominance, ElementTestAgreesWithBruteForce) {
  std::mt19937_64 random(24);
  std::uniform_real_distribution<double> coordinate(-10, 10), bulge(-30, 30), small(-1, 1);
  Tally tally;
  for (int i = 0; i < 600; ++i) {
    Segment s;
    s.start = {coordinate(random), coordinate(random)}, s.end = {coordinate(random), coordinate(random)};
    // Lines, shallow arcs, and arcs sweeping most of a turn (|bulge| up to 30: about 352 degrees).
    s.bulge = i % 3 == 0 ? 0 : i % 3 == 1 ? small(random) : bulge(random);
    check_element(s, random, tally);
  }
  // The test is not vacuous: it says yes often, and no often.
  EXPECT_GT(tally.said, tally.asked / 10);
  EXPECT_LT(tally.said, tally.asked * 9 / 10);
}

TEST(RegionIndexDominance, BoxTestAgreesWithBruteForce) {
  std::mt19937_64 random(25);
  std::uniform_real_distribution<double> coordinate(-10, 10), extent(0.1, 6), side(0.05, 4), t(0, 1);
  Tally tally;
  for (int i = 0; i < 3000; ++i) {
    const double x = coordinate(random), y = coordinate(random);
    const Box box{x, y, x + extent(random), y + extent(random)};
    const double half = side(random);
    const Point c{coordinate(random), coordinate(random)};
    const Square square{c.x - half, c.y - half, c.x + half, c.y + half};
    const double d = box_distance(box, c);
    const double angle = 2 * std::numbers::pi * t(random), r = d * (0.3 + 0.69 * t(random));
    const Point q{c.x + r * std::cos(angle), c.y + r * std::sin(angle)};
    ++tally.asked;
    if (!Dominance(square, q, 1e-9).dominated(box)) continue;
    ++tally.said;
    for (const Point p : sample(square, random))
      ASSERT_LT(std::hypot(p.x - q.x, p.y - q.y), box_distance(box, p) + 1e-9) << "trial " << i;
  }
  EXPECT_GT(tally.said, tally.asked / 10);
  EXPECT_LT(tally.said, tally.asked * 9 / 10);
}

}  // namespace
