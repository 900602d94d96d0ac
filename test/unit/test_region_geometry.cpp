/// @file test_region_geometry.cpp
/// @brief Segment geometry against hand-computed arcs and dense sampling;
/// build_loops on gapped, shuffled, nested and broken drawings; RegionIndex
/// against brute_force_query on random regions of lines and arcs (stars,
/// holes, islands, many loops, extreme bulges), at random points and
/// exactly at vertices and on edges.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "cad/loops.hpp"
#include "cad/region_distance.hpp"
#include "cad/segment_geometry.hpp"
#include "io/error.hpp"
#include "region_probe.hpp"
#include "test_volume.hpp"

namespace {

using namespace tk::cad;
using probe::Comparison, probe::compare, probe::probe_points;

Segment line(Point a, Point b, std::uint32_t entity = 0) {
  Segment s;
  s.start = a, s.end = b, s.entity = entity, s.source_line = 10 + entity;
  return s;
}
Segment arc(Point a, Point b, double bulge, std::uint32_t entity = 0) {
  Segment s = line(a, b, entity);
  s.bulge = bulge;
  return s;
}
double dist(Point a, Point b) { return std::hypot(a.x - b.x, a.y - b.y); }

// --- segment geometry -------------------------------------------------------

TEST(SegmentGeometry, ArcShapeFromBulge) {
  const ArcShape half = arc_shape(arc({0, 0}, {2, 0}, 1));
  EXPECT_NEAR(half.centre.x, 1, 1e-15);
  EXPECT_NEAR(half.centre.y, 0, 1e-15);
  EXPECT_NEAR(half.radius, 1, 1e-15);
  EXPECT_NEAR(half.sweep, std::numbers::pi, 1e-15);
  EXPECT_NEAR(std::abs(half.start_angle), std::numbers::pi, 1e-15);
  // Counter-clockwise from (0,0) to (2,0) about (1,0) passes below.
  const Point middle = point_at(arc({0, 0}, {2, 0}, 1), 0.5);
  EXPECT_NEAR(middle.x, 1, 1e-15);
  EXPECT_NEAR(middle.y, -1, 1e-15);

  const double quarter = std::tan(std::numbers::pi / 8);
  const ArcShape ccw = arc_shape(arc({1, 0}, {0, 1}, quarter));
  EXPECT_NEAR(ccw.centre.x, 0, 1e-15);
  EXPECT_NEAR(ccw.centre.y, 0, 1e-15);
  EXPECT_NEAR(ccw.radius, 1, 1e-15);
  EXPECT_NEAR(ccw.sweep, std::numbers::pi / 2, 1e-15);
  EXPECT_NEAR(ccw.start_angle, 0, 1e-15);
  const ArcShape cw = arc_shape(arc({0, 1}, {1, 0}, -quarter));
  EXPECT_NEAR(cw.centre.x, 0, 1e-15);
  EXPECT_NEAR(cw.centre.y, 0, 1e-15);
  EXPECT_NEAR(cw.sweep, -std::numbers::pi / 2, 1e-15);
  EXPECT_NEAR(cw.start_angle, std::numbers::pi / 2, 1e-15);
  const Point m = point_at(arc({0, 1}, {1, 0}, -quarter), 0.5);
  EXPECT_NEAR(m.x, std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(m.y, std::sqrt(0.5), 1e-15);
  const Point tangent = tangent_at(arc({1, 0}, {0, 1}, quarter), 0);
  EXPECT_NEAR(tangent.x, 0, 1e-15);
  EXPECT_NEAR(tangent.y, 1, 1e-15);

  // Three quarters of a circle: bulge tan(3 pi / 8) > 1, centre right of the chord.
  const ArcShape major = arc_shape(arc({1, 0}, {0, 1}, -std::tan(3 * std::numbers::pi / 8)));
  EXPECT_NEAR(major.centre.x, 0, 1e-14);
  EXPECT_NEAR(major.centre.y, 0, 1e-14);
  EXPECT_NEAR(major.radius, 1, 1e-14);
  EXPECT_NEAR(bulge_of_sweep(std::numbers::pi), 1, 1e-15);
  EXPECT_FALSE(is_arc(arc({0, 0}, {1, 0}, 1e-13)));
  EXPECT_TRUE(is_arc(arc({0, 0}, {1, 0}, 1e-11)));
}

TEST(SegmentGeometry, LengthsBoxesAreasAndFlattening) {
  EXPECT_DOUBLE_EQ(segment_length(line({1, 1}, {4, 5})), 5);
  EXPECT_NEAR(segment_length(arc({2, 0}, {0, 2}, std::tan(std::numbers::pi / 8))), std::numbers::pi, 1e-14);
  EXPECT_NEAR(segment_length(arc({0, 0}, {2, 0}, -1)), std::numbers::pi, 1e-14);
  EXPECT_NEAR(segment_length(arc({0, 0}, {1, 0}, 1e-10)), 1, 1e-15);

  const Box half = bounding_box(arc({0, 0}, {2, 0}, 1));
  EXPECT_NEAR(half.min_x, 0, 1e-15);
  EXPECT_NEAR(half.max_x, 2, 1e-15);
  EXPECT_NEAR(half.min_y, -1, 1e-15);
  EXPECT_NEAR(half.max_y, 0, 1e-15);
  const Box major = bounding_box(arc({1, 0}, {0, 1}, -std::tan(3 * std::numbers::pi / 8)));  // via (0,-1), (-1,0)
  EXPECT_NEAR(major.min_x, -1, 1e-14);
  EXPECT_NEAR(major.min_y, -1, 1e-14);
  EXPECT_NEAR(major.max_x, 1, 1e-14);
  EXPECT_NEAR(major.max_y, 1, 1e-14);

  EXPECT_NEAR(arc_area(arc({0, 0}, {2, 0}, 1)), std::numbers::pi / 2, 1e-14);
  EXPECT_NEAR(arc_area(arc({0, 0}, {2, 0}, -1)), -std::numbers::pi / 2, 1e-14);
  EXPECT_EQ(arc_area(line({0, 0}, {2, 0})), 0);
  // A unit circle as two arcs encloses pi.
  EXPECT_NEAR(signed_area({arc({1, 0}, {-1, 0}, 1), arc({-1, 0}, {1, 0}, 1)}), std::numbers::pi, 1e-14);

  const Segment quarter = arc({1, 0}, {0, 1}, std::tan(std::numbers::pi / 8));
  const double tolerance = 1e-3;
  std::vector<Point> points;
  flatten(quarter, tolerance, points);
  const auto expected = static_cast<std::size_t>(std::ceil((std::numbers::pi / 2) / (2 * std::acos(1 - tolerance))));
  EXPECT_EQ(points.size(), expected);
  EXPECT_EQ(points.back().x, 0);
  EXPECT_EQ(points.back().y, 1);
  Point previous = quarter.start;
  for (const Point& p : points) {
    EXPECT_NEAR(std::hypot(p.x, p.y), 1, 1e-15);
    const Point mid{(p.x + previous.x) / 2, (p.y + previous.y) / 2};
    EXPECT_LE(1 - std::hypot(mid.x, mid.y), tolerance);
    previous = p;
  }
  points.clear();
  flatten(line({0, 0}, {3, 3}), tolerance, points);
  ASSERT_EQ(points.size(), 1u);
  points.clear();
  flatten(arc({0, 0}, {1, 0}, 0.5), 1e-30, points);
  EXPECT_EQ(points.size(), 100000u);
}

TEST(SegmentGeometry, NearestPointMatchesDenseSampling) {
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> coordinate(-5, 5), unit(0, 1);
  const double bulges[] = {0, 1e-9, -3e-6, 0.1, -0.4, 0.9, 1, -1, 1.7, -4, 30};
  for (double bulge : bulges)
    for (int shape = 0; shape < 6; ++shape) {
      const Segment s = arc({coordinate(random), coordinate(random)}, {coordinate(random), coordinate(random)}, bulge);
      const int samples = 40000;
      std::vector<Point> dense;
      for (int i = 0; i <= samples; ++i) dense.push_back(point_at(s, double(i) / samples));
      const double spacing = segment_length(s) / samples;
      for (int trial = 0, trials = test_volume(40, 10); trial < trials; ++trial) {
        const Point p{coordinate(random) * 2, coordinate(random) * 2};
        double t = -1;
        const Point q = nearest_point(s, p, &t);
        double sampled = INFINITY;
        for (const Point& d : dense) sampled = std::min(sampled, dist(p, d));
        EXPECT_LE(dist(p, q), sampled + 1e-12) << "bulge " << bulge;
        EXPECT_GE(dist(p, q), sampled - spacing) << "bulge " << bulge;
        ASSERT_GE(t, 0);
        ASSERT_LE(t, 1);
        EXPECT_LT(dist(point_at(s, t), q), 1e-9 * (1 + segment_length(s)));
      }
    }
  // Nearly straight: the middle of a 10-long chord with bulge 1e-10 sags 5e-10.
  const Point sag = nearest_point(arc({0, 0}, {10, 0}, 1e-10), {5, 1});
  EXPECT_NEAR(sag.x, 5, 1e-12);
  EXPECT_NEAR(sag.y, -5e-10, 1e-15);
  const Point flat = nearest_point(arc({0, 0}, {10, 0}, 1e-13), {5, 1});
  EXPECT_EQ(flat.y, 0);
  // Bulge 1e6: all but 4e-6 rad of the circle of radius 0.25 round (1.25, 5e-7).
  const Segment nearly_full = arc({1, 0}, {1, 1e-6}, 1e6);
  EXPECT_NEAR(arc_shape(nearly_full).radius, 0.25, 1e-12);
  EXPECT_NEAR(nearest_point(nearly_full, {2, 0}).x, 1.5, 1e-12);
  EXPECT_NEAR(nearest_point(nearly_full, {-3, -1e-3}).x, 1, 1e-8);
  EXPECT_EQ(nearest_point(nearly_full, {-3, 5e-7}).y, 0);  // in the gap: an end
}

TEST(SegmentGeometry, SubSegmentAndRayParity) {
  const Segment s = arc({1, 0}, {-1, 0}, 1);  // upper half of the unit circle
  const Segment part = sub_segment(s, 0.25, 0.75);
  EXPECT_NEAR(part.start.x, std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(part.end.y, std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(segment_length(part), std::numbers::pi / 2, 1e-14);
  const std::vector<Segment> circle = {s, arc({-1, 0}, {1, 0}, 1)};
  const auto inside = [&](Point p) {
    bool odd = false;
    for (const Segment& c : circle) odd ^= crosses_ray(c, p);
    return odd;
  };
  EXPECT_TRUE(inside({0, 0}));
  EXPECT_TRUE(inside({0.99, 0}));
  EXPECT_TRUE(inside({-0.5, 0.8}));
  EXPECT_FALSE(inside({1.01, 0}));
  EXPECT_FALSE(inside({-1.01, 0}));
  EXPECT_FALSE(inside({0.8, 0.8}));
  EXPECT_FALSE(inside({0, 1.0001}));
  // On the chords' line (both arcs' chords are the diameter) and on the circle.
  EXPECT_TRUE(inside({-0.999, 0}));
  EXPECT_FALSE(inside({-1.001, 0}));
  EXPECT_FALSE(inside({2, 0}));
  EXPECT_TRUE(left_of({0, 0}, {1, 0}, {5, 0}));  // moved up: left of +x
  EXPECT_FALSE(left_of({1, 0}, {0, 0}, {5, 0}));
  EXPECT_FALSE(left_of({0, 0}, {0, 1}, {0, 5}));  // moved right: right of +y
  EXPECT_TRUE(left_of({0, 1}, {0, 0}, {0, 5}));
}

// --- build_loops -------------------------------------------------------------

void expect_closed(const Loop& loop) {
  for (std::size_t i = 0; i < loop.segments.size(); ++i) {
    const Segment& a = loop.segments[i];
    const Segment& b = loop.segments[(i + 1) % loop.segments.size()];
    EXPECT_EQ(a.end.x, b.start.x);
    EXPECT_EQ(a.end.y, b.start.y);
  }
}

TEST(Loops, GappedShuffledReversedSquareCloses) {
  // Corners of a 10 x 10 square, each side ending 1e-4 short of the next.
  std::vector<Segment> sides = {line({0, 0}, {10 - 1e-4, 0}, 0), line({10, 1e-4}, {10, 10}, 1),
                                line({10, 10 + 1e-4}, {0, 10}, 2), line({-1e-4, 10}, {0, 1e-4}, 3)};
  std::swap(sides[1], sides[3]);
  std::swap(sides[0], sides[2]);
  for (std::size_t i : {0u, 3u}) {
    std::swap(sides[i].start, sides[i].end);
    sides[i].bulge = -sides[i].bulge;
  }
  const LoopSet set = build_loops(sides, 1e-3);
  ASSERT_EQ(set.loops.size(), 1u);
  EXPECT_TRUE(set.open_segments.empty());
  EXPECT_TRUE(set.loose_ends.empty());
  EXPECT_TRUE(set.t_junctions.empty());
  const Loop& loop = set.loops[0];
  EXPECT_EQ(loop.segments.size(), 4u);
  EXPECT_EQ(loop.depth, 0);
  EXPECT_EQ(loop.parent, -1);
  EXPECT_NEAR(loop.area, 100, 0.01);
  expect_closed(loop);
  // Same result whatever the order of the input.
  std::reverse(sides.begin(), sides.end());
  EXPECT_NEAR(build_loops(sides, 1e-3).loops.at(0).area, loop.area, 1e-12);
  // Tolerance smaller than the gaps: four open segments, eight loose ends.
  const LoopSet open = build_loops(sides, 1e-5);
  EXPECT_TRUE(open.loops.empty());
  EXPECT_EQ(open.open_segments.size(), 4u);
  EXPECT_EQ(open.loose_ends.size(), 8u);
}

std::vector<Segment> square(double x0, double y0, double x1, double y1, std::uint32_t entity, bool clockwise) {
  std::vector<Segment> s = {line({x0, y0}, {x1, y0}, entity), line({x1, y0}, {x1, y1}, entity),
                            line({x1, y1}, {x0, y1}, entity), line({x0, y1}, {x0, y0}, entity)};
  if (clockwise) {
    std::reverse(s.begin(), s.end());
    for (Segment& x : s) std::swap(x.start, x.end);
  }
  return s;
}

std::vector<Segment> circle(Point c, double r, std::uint32_t entity, bool clockwise) {
  const double b = clockwise ? -1 : 1;
  return {arc({c.x + r, c.y}, {c.x - r, c.y}, b, entity), arc({c.x - r, c.y}, {c.x + r, c.y}, b, entity)};
}

TEST(Loops, SquareWithCircularHole) {
  std::vector<Segment> all = circle({5, 5}, 2, 1, false);  // drawn counter-clockwise, and first
  for (const Segment& s : square(0, 0, 10, 10, 0, true)) all.push_back(s);
  const LoopSet set = build_loops(all, 1e-6);
  ASSERT_EQ(set.loops.size(), 2u);
  const Loop& outer = set.loops[0];
  const Loop& hole = set.loops[1];
  EXPECT_EQ(outer.depth, 0);
  EXPECT_NEAR(outer.area, 100, 1e-12);
  EXPECT_EQ(outer.segments.size(), 4u);
  EXPECT_EQ(hole.depth, 1);
  EXPECT_TRUE(hole.is_hole());
  EXPECT_EQ(hole.parent, 0);
  EXPECT_EQ(hole.segments.size(), 2u);
  EXPECT_NEAR(hole.area, -4 * std::numbers::pi, 1e-12);
  for (const Segment& s : hole.segments) EXPECT_LT(s.bulge, 0);  // clockwise
  expect_closed(outer);
  expect_closed(hole);
}

TEST(Loops, IslandInAHoleAndNesting) {
  std::vector<Segment> all = circle({10, 10}, 2, 2, true);
  for (const Segment& s : square(5, 5, 15, 15, 1, false)) all.push_back(s);
  for (const Segment& s : square(0, 0, 20, 20, 0, false)) all.push_back(s);
  for (const Segment& s : square(30, 0, 35, 5, 3, true)) all.push_back(s);  // a second part, beside
  const LoopSet set = build_loops(all, 1e-6);
  ASSERT_EQ(set.loops.size(), 4u);
  // Outer boundaries first (in input order), then holes, then islands.
  EXPECT_EQ(set.loops[0].depth, 0);
  EXPECT_NEAR(set.loops[0].area, 400, 1e-9);
  EXPECT_EQ(set.loops[1].depth, 0);
  EXPECT_NEAR(set.loops[1].area, 25, 1e-9);
  EXPECT_EQ(set.loops[1].parent, -1);
  EXPECT_EQ(set.loops[2].depth, 1);
  EXPECT_NEAR(set.loops[2].area, -100, 1e-9);
  EXPECT_EQ(set.loops[2].parent, 0);
  EXPECT_EQ(set.loops[3].depth, 2);
  EXPECT_NEAR(set.loops[3].area, 4 * std::numbers::pi, 1e-9);
  EXPECT_EQ(set.loops[3].parent, 2);
  EXPECT_FALSE(set.loops[3].is_hole());
}

TEST(Loops, LooseEndsAndTJunctions) {
  std::vector<Segment> all = square(0, 0, 10, 10, 0, false);
  all.push_back(line({5, 5}, {5, 1e-5}, 7));            // a stem ending on the bottom side
  all.push_back(line({20, 0}, {25, 0}, 8));             // a lone line
  all.push_back(line({25, 0}, {25, 0.5e-3 * 0.5}, 9));  // shorter than the tolerance: dropped
  const LoopSet set = build_loops(all, 1e-3);
  ASSERT_EQ(set.loops.size(), 1u);
  EXPECT_EQ(set.open_segments.size(), 2u);
  ASSERT_EQ(set.loose_ends.size(), 4u);
  EXPECT_EQ(set.loose_ends[0].at.x, 5);
  EXPECT_EQ(set.loose_ends[0].at.y, 5);
  EXPECT_EQ(set.loose_ends[0].entity, 7u);
  EXPECT_EQ(set.loose_ends[0].source_line, 17u);
  EXPECT_EQ(set.loose_ends[1].at.y, 1e-5);
  EXPECT_EQ(set.loose_ends[2].at.x, 20);
  EXPECT_EQ(set.loose_ends[3].at.x, 25);
  ASSERT_EQ(set.t_junctions.size(), 1u);
  const TJunction& t = set.t_junctions[0];
  EXPECT_EQ(t.at.x, 5);
  EXPECT_EQ(t.at.y, 1e-5);
  EXPECT_EQ(t.entity, 7u);
  EXPECT_EQ(t.source_line, 17u);
  EXPECT_EQ(t.touched_entity, 0u);
  EXPECT_EQ(t.touched_source_line, 10u);
}

TEST(Loops, JunctionsOfMoreThanTwoEnds) {
  // Two triangles touching at a vertex (a bow tie) give two loops; a
  // doubled side leaves the square closed and the copy open.
  std::vector<Segment> bow = {line({0, 0}, {2, 1}),  line({2, 1}, {2, -1}),   line({2, -1}, {0, 0}),
                              line({0, 0}, {-2, 1}), line({-2, 1}, {-2, -1}), line({-2, -1}, {0, 0})};
  const LoopSet tie = build_loops(bow, 1e-9);
  ASSERT_EQ(tie.loops.size(), 2u);
  EXPECT_NEAR(tie.loops[0].area, 2, 1e-12);
  EXPECT_NEAR(tie.loops[1].area, 2, 1e-12);
  EXPECT_TRUE(tie.loose_ends.empty());

  std::vector<Segment> doubled = square(0, 0, 10, 10, 0, false);
  doubled.push_back(line({0, 0}, {10, 0}, 5));
  const LoopSet set = build_loops(doubled, 1e-9);
  ASSERT_EQ(set.loops.size(), 1u);
  EXPECT_NEAR(set.loops[0].area, 100, 1e-12);
  ASSERT_EQ(set.open_segments.size(), 1u);
  EXPECT_EQ(set.open_segments[0].entity, 5u);
  EXPECT_EQ(set.loose_ends.size(), 2u);

  // Three lines meeting at a point: one end is left over.
  const LoopSet three = build_loops({line({0, 0}, {1, 0}), line({0, 0}, {0, 1}), line({0, 0}, {-1, -1})}, 1e-9);
  EXPECT_TRUE(three.loops.empty());
  EXPECT_EQ(three.open_segments.size(), 3u);
}

TEST(Loops, DegenerateAndBadInput) {
  // There and back again encloses nothing.
  const LoopSet flat = build_loops({line({0, 0}, {5, 0}), line({5, 0}, {0, 0})}, 1e-6);
  EXPECT_TRUE(flat.loops.empty());
  EXPECT_EQ(flat.open_segments.size(), 2u);
  EXPECT_THROW(build_loops({}, -1), tk::Error);
  EXPECT_THROW(build_loops({line({0, 0}, {NAN, 0})}, 1e-3), tk::Error);
  EXPECT_TRUE(build_loops({}, 0).loops.empty());
  // Zero tolerance joins exactly equal ends only.
  EXPECT_EQ(build_loops(square(0, 0, 1, 1, 0, true), 0).loops.size(), 1u);
}

TEST(Loops, ManySegmentsChainInOrder) {
  // A 100,000-gon, shuffled and partly reversed, in one piece.
  const int n = 100000;
  std::vector<Segment> polygon;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * std::numbers::pi * i / n, b = 2 * std::numbers::pi * (i + 1) / n;
    polygon.push_back(arc({std::cos(a), std::sin(a)}, {std::cos(b), std::sin(b)}, i % 3 ? 0 : 1e-7));
  }
  std::mt19937_64 random(5);
  std::shuffle(polygon.begin(), polygon.end(), random);
  for (std::size_t i = 0; i < polygon.size(); i += 2) {
    std::swap(polygon[i].start, polygon[i].end);
    polygon[i].bulge = -polygon[i].bulge;
  }
  const LoopSet set = build_loops(polygon, 1e-9);
  ASSERT_EQ(set.loops.size(), 1u);
  EXPECT_EQ(set.loops[0].segments.size(), std::size_t(n));
  EXPECT_NEAR(set.loops[0].area, std::numbers::pi, 1e-6);
  expect_closed(set.loops[0]);
}

// --- RegionIndex -------------------------------------------------------------

/// A star-shaped loop round `c` with n sides, alternately lines and arcs.
std::vector<Segment> star(std::mt19937_64& random, Point c, double radius, int n, double max_bulge) {
  std::uniform_real_distribution<double> r(0.55, 1), bulge(-max_bulge, max_bulge);
  std::vector<Point> corners;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * std::numbers::pi * i / n, rr = radius * (i % 2 ? r(random) : 1);
    corners.push_back({c.x + rr * std::cos(a), c.y + rr * std::sin(a)});
  }
  std::vector<Segment> loop;
  for (int i = 0; i < n; ++i) loop.push_back(arc(corners[i], corners[(i + 1) % n], i % 3 ? bulge(random) : 0));
  return loop;
}

TEST(Loops, RandomPartsComeBackWhole) {
  // Stars with arcs, holes and islands, cut into segments that are
  // shuffled, reversed at random and moved by up to a tenth of the
  // tolerance: the loops come back with their areas, nested and oriented,
  // and the region they bound is the same.
  std::mt19937_64 random(42);
  for (int trial = 0; trial < 5; ++trial) {
    std::vector<std::vector<Segment>> parts = {star(random, {0, 0}, 50, 200, 0.2), circle({20, 0}, 5, 0, true),
                                               star(random, {20, 0}, 3, 30, 0.2), star(random, {-15, 5}, 8, 60, 0.2),
                                               star(random, {120, 0}, 20, 90, 0.3)};
    std::vector<Segment> pieces;
    std::uniform_real_distribution<double> jitter(-1e-5, 1e-5);
    for (std::size_t k = 0; k < parts.size(); ++k)
      for (Segment s : parts[k]) {
        s.entity = static_cast<std::uint32_t>(k);
        s.start.x += jitter(random), s.start.y += jitter(random), s.end.x += jitter(random), s.end.y += jitter(random);
        if (random() % 2) std::swap(s.start, s.end), s.bulge = -s.bulge;
        pieces.push_back(s);
      }
    std::shuffle(pieces.begin(), pieces.end(), random);
    const LoopSet set = build_loops(pieces, 1e-4);
    ASSERT_EQ(set.loops.size(), parts.size());
    EXPECT_TRUE(set.open_segments.empty());
    EXPECT_TRUE(set.loose_ends.empty());
    EXPECT_TRUE(set.t_junctions.empty());
    const int depth[] = {0, 1, 2, 1, 0};
    std::vector<Loop> originals;
    for (std::size_t k = 0; k < parts.size(); ++k) originals.push_back({parts[k], depth[k], -1, signed_area(parts[k])});
    for (const Loop& loop : set.loops) {
      expect_closed(loop);
      const std::size_t k = loop.segments[0].entity;
      EXPECT_EQ(loop.depth, depth[k]) << k;
      EXPECT_EQ(loop.area > 0, loop.depth % 2 == 0);
      EXPECT_NEAR(std::abs(loop.area), std::abs(originals[k].area), 1e-2) << k;
      EXPECT_EQ(loop.parent < 0, loop.depth == 0);
      if (loop.parent >= 0) {
        EXPECT_EQ(set.loops[loop.parent].depth, loop.depth - 1);
      }
    }
    const RegionIndex rebuilt(set.loops), original(originals);
    for (const Point& p : probe_points(random, originals, 2000)) {
      const RegionQuery a = rebuilt.query(p), b = original.query(p);
      EXPECT_NEAR(a.distance, b.distance, 1e-4);
      if (std::abs(b.distance) > 1e-4) {
        EXPECT_EQ(a.inside(), b.inside());
      }
    }
  }
}

TEST(RegionIndex, SquareByHand) {
  const std::vector<Loop> loops = {{square(0, 0, 10, 10, 0, false), 0, -1, 100}};
  const RegionIndex index(loops);
  EXPECT_EQ(index.elements().size(), 4u);
  EXPECT_EQ(index.loop_of(3), 0u);
  const RegionQuery centre = index.query({5, 5});
  EXPECT_DOUBLE_EQ(centre.distance, -5);
  EXPECT_TRUE(centre.inside());
  const RegionQuery right = index.query({15, 4});
  EXPECT_DOUBLE_EQ(right.distance, 5);
  EXPECT_EQ(right.nearest.x, 10);
  EXPECT_EQ(right.nearest.y, 4);
  EXPECT_EQ(right.element, 1u);
  const RegionQuery corner = index.query({13, 14});
  EXPECT_DOUBLE_EQ(corner.distance, 5);
  EXPECT_EQ(corner.nearest.x, 10);
  EXPECT_EQ(corner.nearest.y, 10);
  EXPECT_DOUBLE_EQ(index.query({1e6, -3e6}).distance, brute_force_query(loops, {1e6, -3e6}).distance);
  const RegionIndex empty(std::vector<Loop>{});
  EXPECT_EQ(empty.query({1, 2}).distance, INFINITY);
  EXPECT_EQ(brute_force_query({}, {1, 2}).distance, INFINITY);
}

TEST(RegionIndex, MatchesBruteForceOnStarsWithHolesAndIslands) {
  std::mt19937_64 random(2024);
  std::vector<Loop> loops;
  loops.push_back({star(random, {0, 0}, 100, 600, 0.25), 0, -1, 0});
  for (int i = 0; i < 6; ++i) {
    const double a = 2 * std::numbers::pi * i / 6;
    loops.push_back({star(random, {40 * std::cos(a), 40 * std::sin(a)}, 12, 40 + 10 * i, 0.3), 1, 0, 0});
  }
  loops.push_back({circle({40, 0}, 3, 0, false), 2, 1, 0});  // an island in the first hole
  loops.push_back({circle({0, 0}, 20, 0, true), 1, 0, 0});
  loops.push_back({star(random, {0, 0}, 10, 30, 0.2), 2, 0, 0});
  const std::size_t count = test_volume(100000, 20000);
  const Comparison c = compare(loops, probe_points(random, loops, count));
  EXPECT_GT(c.sign_checked, count);
}

TEST(RegionIndex, MatchesBruteForceOnManyLoops) {
  std::mt19937_64 random(7);
  std::vector<Loop> loops;
  for (int i = 0; i < 15; ++i)
    for (int j = 0; j < 15; ++j) {
      const Point c{i * 10.0, j * 7.0};
      if ((i + j) % 3 == 0) loops.push_back({circle(c, 2 + 0.1 * i, 0, (i + j) % 2 == 1), 0, -1, 0});
      else loops.push_back({star(random, c, 3, 8 + (i * j) % 17, 0.4), 0, -1, 0});
    }
  loops.push_back({square(-10, -10, 150, 110, 0, false), 0, -1, 0});
  std::vector<Point> points = probe_points(random, loops, test_volume(100000, 20000));
  // Along the circles' diameters, which are their arcs' chords.
  std::uniform_real_distribution<double> x(-15, 155);
  for (int j = 0; j < 15; ++j)
    for (int i = 0, along = test_volume(400, 100); i < along; ++i) points.push_back({x(random), j * 7.0});
  compare(loops, points);
  const RegionIndex index(loops);
  const RegionQuery centre = index.query({0, 0});  // circle of radius 2 round the origin, inside the square
  EXPECT_DOUBLE_EQ(centre.distance, 2);
  EXPECT_FALSE(centre.inside());
  EXPECT_DOUBLE_EQ(index.query({0, 1.5}).distance, 0.5);
}

TEST(RegionIndex, MatchesBruteForceNearTheCentreOfAFineCircle) {
  // Every one of the 3,000 arcs is about as near to the centre: the index's
  // capped lists run out there and it finishes in its tree.
  const int n = 3000;
  std::vector<Segment> fine;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * std::numbers::pi * i / n, b = 2 * std::numbers::pi * (i + 1) / n;
    const Point from{10 * std::cos(a), 10 * std::sin(a)}, to{10 * std::cos(b), 10 * std::sin(b)};
    fine.push_back(arc(from, to, std::tan(std::numbers::pi / n / 2)));
  }
  const std::vector<Loop> loops = {{fine, 0, -1, 0}};
  std::mt19937_64 random(3);
  const int count = test_volume(5000, 1000);
  std::vector<Point> points = probe_points(random, loops, count);
  std::uniform_real_distribution<double> near_centre(-0.3, 0.3);
  for (int i = 0; i < count; ++i) points.push_back({near_centre(random), near_centre(random)});
  compare(loops, points);
  EXPECT_NEAR(RegionIndex(loops).query({0, 0}).distance, -10, 1e-12);
}

TEST(RegionIndex, MatchesBruteForceWithExtremeBulgesAndFarPoints) {
  std::mt19937_64 random(99);
  // Nearly straight arcs (centres 1e10 away) and arcs of more than half a
  // circle, on an outline with long and short sides; a hole that is a
  // three-quarter circle closed by a nearly flat arc.
  const std::vector<Segment> outline = {arc({0, 0}, {100, 0}, 1e-10),  arc({100, 0}, {100, 50}, -3e-9),
                                        arc({100, 50}, {60, 50}, 2.5), line({60, 50}, {40, 50}),
                                        arc({40, 50}, {0, 50}, -0.8),  arc({0, 50}, {0, 0}, 1e-11)};
  const std::vector<Segment> hole = {arc({20, 20}, {30, 20}, -std::tan(3 * std::numbers::pi / 8)),
                                     arc({30, 20}, {20, 20}, -1e-6)};
  const std::vector<Loop> loops = {{outline, 0, -1, 0}, {hole, 1, 0, 0}};
  std::vector<Point> points = probe_points(random, loops, 60000);
  std::uniform_real_distribution<double> far(-1e4, 1e4);
  for (int i = 0; i < 2000; ++i) points.push_back({far(random), far(random)});
  std::uniform_real_distribution<double> along(0, 100), hair(-1e-6, 1e-6);
  for (int i = 0; i < 5000; ++i) points.push_back({along(random), hair(random)});  // against the flat arc
  compare(loops, points);
}

}  // namespace
