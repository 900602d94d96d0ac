/// @file test_offset_polygons.cpp
/// @brief offset_polygons against Clipper's own ClipperOffset: with
/// Clipper's spikes at concave corners the same polygons point for point;
/// with the crossing points the same region (the two differ by slivers of
/// rounding along the edges, nowhere by a whole piece), on random star
/// polygons (concave corners of every sharpness, short edges), finely
/// divided wavy rings, a comb and a frame with holes, grown and shrunk.
/// With the notches the tool cannot enter filled first (offset_notches.hpp):
/// the region ClipperOffset draws from the unfilled paths, on gears, combs
/// and notches the tool does enter (wide, or widening inside a narrow neck).
#include <gtest/gtest.h>

#include <polyclipping/clipper.hpp>

#include <cmath>
#include <cstddef>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "cad/offset_notches.hpp"
#include "cad/offset_polygons.hpp"
#include "cad/region_union.hpp"
#include "test_volume.hpp"

namespace offset_polygons_test {  // named: the unity build joins the tests' anonymous namespaces

using namespace tk::cad;
using ClipperLib::cInt;
using ClipperLib::IntPoint;
using ClipperLib::Path;
using ClipperLib::Paths;
constexpr double kPi = std::numbers::pi;
constexpr double kScale = 1e6;  // a millimetre in Clipper units, as region_offset.cpp uses them

IntPoint polar(double r, double a) {
  return {cInt(std::llround(r * std::cos(a) * kScale)), cInt(std::llround(r * std::sin(a) * kScale))};
}

Path star(std::mt19937_64& random, int vertices) {
  std::uniform_real_distribution<double> radius(20, 40);
  Path p;
  for (int i = 0; i < vertices; ++i) p.push_back(polar(radius(random), 2 * kPi * i / vertices));
  return p;
}

Path wavy_ring(double radius, int vertices, int waves, double amplitude, bool clockwise) {
  Path p;
  for (int i = 0; i < vertices; ++i) {
    const double a = 2 * kPi * i / vertices;
    p.push_back(polar(radius + amplitude * std::sin(waves * a), clockwise ? -a : a));
  }
  return p;
}

Path comb(int teeth) {
  Path p;
  for (int k = 0; k < teeth; ++k) {
    const cInt x = cInt(2 * k * kScale);
    for (const auto& [dx, y] : {std::pair{0.0, 0.0}, {0.0, 10.0}, {1.0, 10.0}, {1.0, 0.0}})
      p.push_back({x + cInt(dx * kScale), cInt(y * kScale)});
  }
  p.push_back({cInt(2 * teeth * kScale), cInt(-5 * kScale)});
  p.push_back({0, cInt(-5 * kScale)});
  ClipperLib::ReversePath(p);  // counter-clockwise
  return p;
}

Paths frame_with_holes() {
  Path outer{{0, 0}, {cInt(60 * kScale), 0}, {cInt(60 * kScale), cInt(40 * kScale)}, {0, cInt(40 * kScale)}};
  Paths paths{outer};
  for (int i = 0; i < 3; ++i) {  // clockwise holes: a square, a thin slot, a fine circle
    const double x = 10 + 18 * i;
    if (i == 2) {
      Path circle;
      for (int k = 0; k < 400; ++k) circle.push_back(polar(5, -2 * kPi * k / 400));
      for (IntPoint& q : circle) q.X += cInt(x * kScale), q.Y += cInt(20 * kScale);
      paths.push_back(circle);
      continue;
    }
    const double w = i == 0 ? 8 : 0.6;
    paths.push_back({{cInt(x * kScale), cInt(10 * kScale)},
                     {cInt(x * kScale), cInt(30 * kScale)},
                     {cInt((x + w) * kScale), cInt(30 * kScale)},
                     {cInt((x + w) * kScale), cInt(10 * kScale)}});
  }
  return paths;
}

void clipper_offset(const Paths& paths, double delta, double arc_tolerance, ClipperLib::PolyTree& out) {
  ClipperLib::ClipperOffset offsetter;
  offsetter.ArcTolerance = arc_tolerance;
  offsetter.AddPaths(paths, ClipperLib::jtRound, ClipperLib::etClosedPolygon);
  offsetter.Execute(out, delta);
}

/// The tree's contours in its own order, each with its depth.
void flatten(const ClipperLib::PolyNode& node, int depth, std::vector<std::pair<int, Path>>& out) {
  for (const ClipperLib::PolyNode* child : node.Childs) {
    out.emplace_back(depth, child->Contour);
    flatten(*child, depth + 1, out);
  }
}

double area_of(const Paths& paths) {
  double sum = 0;
  for (const Path& p : paths) sum += ClipperLib::Area(p);
  return sum;
}

double perimeter_of(const Paths& paths) {
  double sum = 0;
  for (const Path& p : paths)
    for (std::size_t i = 0; i < p.size(); ++i) {
      const IntPoint a = p[i], b = p[(i + 1) % p.size()];
      sum += std::hypot(double(b.X - a.X), double(b.Y - a.Y));
    }
  return sum;
}

/// With Notches::filled, the polygons differ (round joins start from other
/// edges) by the joins' chords: `slack` units of width, times the perimeter.
void expect_like_clipper(const Paths& paths, double delta, double arc_tolerance, const std::string& what,
                         Notches notches = Notches::kept, double slack = 4) {
  ClipperLib::PolyTree theirs, spikes, crossing;
  clipper_offset(paths, delta, arc_tolerance, theirs);
  offset_polygons(paths, delta, arc_tolerance, spikes, ConcaveCorners::spikes);
  offset_polygons(paths, delta, arc_tolerance, crossing, ConcaveCorners::crossing, notches);
  std::vector<std::pair<int, Path>> a, b, c;
  flatten(theirs, 0, a), flatten(spikes, 0, b), flatten(crossing, 0, c);
  ASSERT_FALSE(a.empty()) << what;
  EXPECT_TRUE(a == b) << what << ": with spikes, not Clipper's polygons";
  // The crossing points: the same loops nested the same way, the region
  // the same but for slivers of rounding (a unit or two wide) along the boundary.
  ASSERT_EQ(a.size(), c.size()) << what;
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i].first, c[i].first) << what << ", loop " << i;
  Paths ours_paths, their_paths, difference;
  ClipperLib::PolyTreeToPaths(crossing, ours_paths);
  ClipperLib::PolyTreeToPaths(theirs, their_paths);
  ClipperLib::Clipper xor_of;
  xor_of.AddPaths(ours_paths, ClipperLib::ptSubject, true);
  xor_of.AddPaths(their_paths, ClipperLib::ptClip, true);
  xor_of.Execute(ClipperLib::ctXor, difference, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  const double apart = std::abs(area_of(difference)), allowed = slack * perimeter_of(their_paths);
  EXPECT_LE(apart, allowed) << what << ": regions differ by " << apart << " square units";
  EXPECT_GT(std::abs(area_of(their_paths)), 1e3 * allowed) << what << ": the bound must be small beside the region";
}

TEST(OffsetPolygons, StarsGrownAndShrunkAsClipperDrawsThem) {
  std::mt19937_64 random(24);
  const int stars = test_volume(40, 6);
  for (int i = 0; i < stars; ++i) {
    const Path p = star(random, 20 + 30 * (i % 7));
    for (const double mm : {0.3, 2.5, -0.3, -1.5})
      expect_like_clipper({p}, mm * kScale, 1e-3 * kScale, "star " + std::to_string(i) + " by " + std::to_string(mm));
  }
}

TEST(OffsetPolygons, FineWavyRingsWithFlatConcaveCorners) {
  for (const bool clockwise : {false, true})
    for (const int vertices : {test_volume(20000, 4000), 3001})
      for (const double mm : {1.0, -1.0, 0.05})
        expect_like_clipper({wavy_ring(100, vertices, 60, 1.5, clockwise)}, mm * kScale, 1e-4 * kScale,
                            "ring of " + std::to_string(vertices) + " by " + std::to_string(mm));
}

TEST(OffsetPolygons, CombAndFrameWithHoles) {
  for (const double mm : {0.3, 0.5, 1.0, -0.2, -0.4}) {
    expect_like_clipper({comb(test_volume(200, 40))}, mm * kScale, 1e-4 * kScale, "comb by " + std::to_string(mm));
    expect_like_clipper(frame_with_holes(), mm * kScale, 1e-4 * kScale, "frame by " + std::to_string(mm));
  }
}

/// Spikes `height` mm tall standing `pitch` mm apart at the root, as bench_region_build's gear.
Path gear(int spikes, double pitch, double height) {
  const double root = spikes * pitch / (2 * kPi);
  Path p;
  for (int i = 0; i < spikes; ++i) {
    p.push_back(polar(root, 2 * kPi * i / spikes));
    p.push_back(polar(root + height, 2 * kPi * (i + 0.5) / spikes));
  }
  return p;
}

std::size_t notches_filled(const Path& path, double delta, double arc_tolerance) {
  std::size_t filled = 0;
  const Path out = fill_notches(path, delta, arc_tolerance, 0.25 * std::abs(delta), filled);
  EXPECT_LE(out.size(), path.size());
  return filled;
}

// A filled notch that the tool could reach into by its sag (R - sqrt(R^2 -
// W^2 / 4), 0.03 mm for a gear's 0.5 mm mouth and R = 1) would grow the
// region by about 0.01 mm^2 a notch, against a slack
// of one chord tolerance (100 square units a unit of perimeter, about
// 0.0003 mm^2 a notch): the chords of a join that starts elsewhere.
constexpr double kTolerance = 1e-4 * kScale, kFilledSlack = kTolerance;

TEST(OffsetPolygons, NotchesTheToolCannotEnterFilledForTheSameRegion) {
  // 120 spikes: mouths 0.76 mm wide at the tips (fewer spikes, on a smaller
  // circle, would open wider).
  const Path spiky = gear(120, 0.5, 5);
  for (const double mm : {1.0, 0.5, 0.42, -1.0, -0.5}) {  // 0.42: the mouths 0.9 of the tool's width
    EXPECT_EQ(notches_filled(spiky, mm * kScale, kTolerance), 120u);
    expect_like_clipper({spiky}, mm * kScale, kTolerance, "gear by " + std::to_string(mm), Notches::filled,
                        kFilledSlack);
  }
  // Slots 1 mm wide: filled for a tool of 1 mm radius, not for one of 0.4 mm.
  const Path slots = comb(test_volume(60, 20));
  EXPECT_EQ(notches_filled(slots, 1.0 * kScale, kTolerance), std::size_t(test_volume(60, 20) - 1));
  EXPECT_EQ(notches_filled(slots, 0.4 * kScale, kTolerance), 0u);
  for (const double mm : {1.0, 0.6, 0.4, -0.4})
    expect_like_clipper({slots}, mm * kScale, kTolerance, "comb by " + std::to_string(mm), Notches::filled,
                        kFilledSlack);
  // A gear-shaped hole in a square: its notches turn the other way.
  const Path frame{{cInt(-30 * kScale), cInt(-30 * kScale)},
                   {cInt(30 * kScale), cInt(-30 * kScale)},
                   {cInt(30 * kScale), cInt(30 * kScale)},
                   {cInt(-30 * kScale), cInt(30 * kScale)}};
  const Path hole(spiky.rbegin(), spiky.rend());
  EXPECT_EQ(notches_filled(hole, 1.0 * kScale, kTolerance), 120u);
  EXPECT_EQ(notches_filled(hole, -0.5 * kScale, kTolerance), 120u);
  EXPECT_EQ(notches_filled(hole, -0.3 * kScale, kTolerance), 0u);  // mouths 0.76 mm wide
  for (const double mm : {1.0, -0.5, -0.3})
    expect_like_clipper({frame, hole}, mm * kScale, kTolerance, "gear hole by " + std::to_string(mm), Notches::filled,
                        kFilledSlack);
}

TEST(OffsetPolygons, NotchesOfRandomStarsFilledForTheSameRegion) {
  // Notches of every shape: runs of concave corners, mouths narrow and
  // wide, sides long and short, some convex, some not.
  std::mt19937_64 random(2411);
  std::size_t filled = 0;
  const int stars = test_volume(30, 6);
  for (int i = 0; i < stars; ++i) {
    const Path p = star(random, 12 + 9 * (i % 11));
    for (const double mm : {1.5, 4.0, 9.0, -1.5, -4.0}) {
      filled += notches_filled(p, mm * kScale, kTolerance);
      expect_like_clipper({p}, mm * kScale, kTolerance, "star " + std::to_string(i) + " by " + std::to_string(mm),
                          Notches::filled, kFilledSlack);
    }
  }
  EXPECT_GT(filled, std::size_t(stars));  // the test reaches the fills
}

TEST(OffsetPolygons, NotchesTheToolEntersKept) {
  // Wide V's: the mouth wider than the tool.
  EXPECT_EQ(notches_filled(gear(60, 3, 5), 1.0 * kScale, kTolerance), 0u);
  expect_like_clipper({gear(60, 3, 5)}, 1.0 * kScale, kTolerance, "wide gear", Notches::filled, kFilledSlack);
  // A narrow neck (0.8 mm) into a belly 3 mm wide that the tool reaches:
  // the belly's corners at the neck open wider than 90 degrees.
  Path bottle{{0, 0}, {cInt(20 * kScale), 0}, {cInt(20 * kScale), cInt(10 * kScale)}};
  for (const auto& [x, y] :
       {std::pair{10.4, 10.0}, {10.4, 9.5}, {11.5, 9.0}, {11.5, 5.0}, {8.5, 5.0}, {8.5, 9.0}, {9.6, 9.5}, {9.6, 10.0}})
    bottle.push_back({cInt(x * kScale), cInt(y * kScale)});
  bottle.push_back({0, cInt(10 * kScale)});
  ASSERT_TRUE(ClipperLib::Orientation(bottle));
  EXPECT_EQ(notches_filled(bottle, 1.0 * kScale, kTolerance), 0u);
  expect_like_clipper({bottle}, 1.0 * kScale, kTolerance, "bottle", Notches::filled, kFilledSlack);
  // An island reaching into a slot across its mouth: the filled slot would
  // cross it, so nothing is filled, and the region is Clipper's.
  const Path slots = comb(8);
  const Path island{{cInt(3.3 * kScale), cInt(8 * kScale)},
                    {cInt(3.7 * kScale), cInt(8 * kScale)},
                    {cInt(3.7 * kScale), cInt(14 * kScale)},
                    {cInt(3.3 * kScale), cInt(14 * kScale)}};
  std::size_t filled = 0;
  EXPECT_FALSE(simple_and_disjoint({fill_notches(slots, kScale, kTolerance, 0.25 * kScale, filled), island}));
  EXPECT_EQ(filled, 7u);
  EXPECT_TRUE(simple_and_disjoint({slots, island}));
  expect_like_clipper({slots, island}, 1.0 * kScale, kTolerance, "comb with an island", Notches::filled, kFilledSlack);
}

}  // namespace offset_polygons_test
