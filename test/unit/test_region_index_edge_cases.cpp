/// @file test_region_index_edge_cases.cpp
/// @brief RegionIndex against brute_force_query where its grid is at an
/// extreme: a strip thousands of times longer than thick (more than 4,096
/// cells a side, which the grid once capped), outlines split into many
/// collinear pieces and drawn twice over (exact ties everywhere), an edge
/// nearly but not quite level, and boundaries of one or two elements.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "cad/loops.hpp"
#include "cad/region_distance.hpp"
#include "region_probe.hpp"

namespace {

using namespace tk::cad;

Segment element(Point a, Point b, double bulge = 0) {
  Segment s;
  s.start = a, s.end = b, s.bulge = bulge;
  return s;
}

Loop closed(const std::vector<Point>& corners) {
  Loop loop;
  for (std::size_t i = 0; i < corners.size(); ++i)
    loop.segments.push_back(element(corners[i], corners[(i + 1) % corners.size()]));
  return loop;
}

/// Random points over [x0, x1] x [y0, y1].
std::vector<Point> scatter(std::mt19937_64& random, std::size_t count, double x0, double x1, double y0, double y1) {
  std::uniform_real_distribution<double> x(x0, x1), y(y0, y1);
  std::vector<Point> points;
  for (std::size_t i = 0; i < count; ++i) points.push_back({x(random), y(random)});
  return points;
}

/// A bar 6,000 mm long and 1.3 mm thick with a saw-toothed top of 8,000
/// teeth: about sqrt(8,000 x 4,600) = 6,000 cells a side.
TEST(RegionIndexEdgeCases, StripLongerThanTheOldGridCapMatchesBruteForce) {
  std::vector<Point> v;
  const int teeth = 8000;
  for (int i = 0; i <= teeth; ++i) v.push_back({6000.0 * i / teeth, i % 2 ? 1.3 : 1.0});
  v.push_back({6000, 0}), v.push_back({0, 0});
  const std::vector<Loop> loops{closed(v)};
  std::mt19937_64 random(41);
  std::vector<Point> points = scatter(random, 1500, -300, 6300, -1, 2.3);
  for (const Point& p : scatter(random, 1000, 0, 6000, 0.9, 1.4)) points.push_back(p);  // among the teeth
  for (int i = 0; i < 300; ++i)
    points.push_back({6000.0 * (13 * i) / teeth, i % 3 ? 1.15 : 0.5});  // on vertices' verticals
  const probe::Comparison c = probe::compare(loops, points);
  EXPECT_GT(c.sign_checked, 2500u);
}

/// Squares whose sides are cut into many collinear pieces, one of them
/// drawn twice (its interior cancels, even-odd): points near them have
/// several equally near elements, which must be named by the lowest index.
TEST(RegionIndexEdgeCases, CollinearAndDuplicatedPiecesMatchBruteForce) {
  const auto cut_square = [](double x0, double y0, double side, int pieces) {
    std::vector<Point> v;
    const Point corners[4] = {{x0, y0}, {x0 + side, y0}, {x0 + side, y0 + side}, {x0, y0 + side}};
    for (int c = 0; c < 4; ++c)
      for (int k = 0; k < pieces; ++k) {
        const Point a = corners[c], b = corners[(c + 1) % 4];
        v.push_back({a.x + (b.x - a.x) * k / pieces, a.y + (b.y - a.y) * k / pieces});
      }
    return closed(v);
  };
  std::vector<Loop> loops{cut_square(0, 0, 64, 256), cut_square(16, 16, 8, 32), cut_square(16, 16, 8, 32),
                          cut_square(40, 40, 16, 1)};
  std::mt19937_64 random(42);
  std::vector<Point> points = probe::probe_points(random, loops, 3000);
  for (int y = -8; y <= 72; y += 2)
    for (int x = -8; x <= 72; ++x) points.push_back({x * 1.0, y * 1.0});  // integer points: exact ties
  probe::compare(loops, points);
}

/// An edge so nearly level (a rise of 9e-9 a millimetre) that the chords
/// along it round to u = (1, 9e-9) with ux exactly 1: the tree's rectangles
/// there are oriented all the same, and a search that took a node of them
/// for axis-aligned boxes misjudged them by the rise times x (some 9e-6 mm
/// here), passing over a vertex's lower-indexed element for its equally
/// near neighbour (element 21 named at vertex 21, where brute force names 20).
TEST(RegionIndexEdgeCases, ANearlyLevelEdgeMatchesBruteForce) {
  std::vector<Point> v;
  const double rise = 9e-9;
  for (int i = 0; i <= 400; ++i) v.push_back({1000.0 + i, 1 + rise * i});
  v.push_back({1400, 60}), v.push_back({1000, 60});
  const std::vector<Loop> loops{closed(v)};
  std::mt19937_64 random(44);
  std::vector<Point> points = probe::probe_points(random, loops, 1000);
  for (int i = 0; i <= 400; ++i)  // on every vertex of the level edge, and a hair either side of it
    for (const double off : {0.0, 1e-9, -1e-9}) points.push_back({1000.0 + i, 1 + rise * i + off});
  probe::compare(loops, points);
}

/// The smallest closed boundaries: a line there and back (a slit, no
/// inside), an arc closed by its chord, a half circle closed by another.
TEST(RegionIndexEdgeCases, OneOrTwoElementsMatchBruteForce) {
  std::mt19937_64 random(43);
  const std::vector<std::vector<Segment>> boundaries{
      {element({0, 0}, {10, 3}), element({10, 3}, {0, 0})},
      {element({0, 0}, {10, 0}, 0.4), element({10, 0}, {0, 0})},
      {element({-5, 2}, {-5, 2.5}, 1.0), element({-5, 2.5}, {-5, 2}, 1.0)}};
  for (const std::vector<Segment>& boundary : boundaries) {
    const std::vector<Loop> loops{Loop{boundary}};
    probe::compare(loops, probe::probe_points(random, loops, 2000));
    probe::compare(loops, scatter(random, 1000, -1e3, 1e3, -1e3, 1e3));  // far outside the grid
  }
}

}  // namespace
