/// @file test_region_union.cpp
/// @brief The offset's even-odd union skipped for simple disjoint loops
/// (region_union.hpp): the sweep's verdict against a brute-force check of
/// every pair of edges (exact rational parameters, not orientations) on
/// random polygons of a small grid, where touching, collinear overlaps and
/// shared vertices abound; and the skipped union against Clipper's own,
/// polygon by polygon, and the offset Clipper draws from either.
#include <gtest/gtest.h>

#include <polyclipping/clipper.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <random>
#include <utility>
#include <vector>

#include "cad/region_union.hpp"
#include "test_volume.hpp"

namespace region_union_test {  // named: the unity build joins the tests' anonymous namespaces

using namespace tk::cad;
using ClipperLib::cInt;
using ClipperLib::IntPoint;
using ClipperLib::Path;
using ClipperLib::Paths;
__extension__ typedef __int128 Wide;

struct Rational {  // num / den, den > 0
  Wide num, den;
};
bool operator<(Rational a, Rational b) { return a.num * b.den < b.num * a.den; }
bool operator==(Rational a, Rational b) { return a.num * b.den == b.num * a.den; }
bool operator<=(Rational a, Rational b) { return !(b < a); }
Rational ratio(Wide num, Wide den) { return den < 0 ? Rational{-num, -den} : Rational{num, den}; }

Wide cross(IntPoint a, IntPoint b) { return Wide(a.X) * b.Y - Wide(a.Y) * b.X; }
Wide dot(IntPoint a, IntPoint b) { return Wide(a.X) * b.X + Wide(a.Y) * b.Y; }
IntPoint minus(IntPoint a, IntPoint b) { return {a.X - b.X, a.Y - b.Y}; }

/// Where p0 + s (p1 - p0) meets q0 + t (q1 - q0), s and t in [0, 1]: the
/// range of s it meets over (empty: first > second). Brute force by
/// parameters, independent of the sweep's orientation tests.
std::pair<Rational, Rational> meeting(IntPoint p0, IntPoint p1, IntPoint q0, IntPoint q1) {
  const IntPoint d1 = minus(p1, p0), d2 = minus(q1, q0), w = minus(q0, p0);
  const Rational none{1, 1}, empty_end{0, 1};
  const Wide denominator = cross(d1, d2);
  if (denominator != 0) {
    const Rational s = ratio(cross(w, d2), denominator), t = ratio(cross(w, d1), denominator);
    const Rational zero{0, 1}, one{1, 1};
    if (zero <= s && s <= one && zero <= t && t <= one) return {s, s};
    return {none, empty_end};
  }
  if (cross(w, d1) != 0) return {none, empty_end};  // parallel apart
  const Wide length2 = dot(d1, d1);
  Rational a = ratio(dot(w, d1), length2), b = ratio(dot(minus(q1, p0), d1), length2);
  if (b < a) std::swap(a, b);
  const Rational lo = std::max(a, Rational{0, 1}), hi = std::min(b, Rational{1, 1});
  if (hi < lo) return {none, empty_end};
  return {lo, hi};
}

/// Every pair of edges: consecutive edges of a path may meet at their
/// shared vertex only, others not at all.
bool brute_force_simple(const Paths& paths) {
  struct E {
    IntPoint a, b;
    std::size_t path, index, size;
  };
  std::vector<E> edges;
  for (std::size_t p = 0; p < paths.size(); ++p) {
    if (paths[p].size() < 3) return false;
    for (std::size_t i = 0; i < paths[p].size(); ++i) {
      const IntPoint a = paths[p][i], b = paths[p][(i + 1) % paths[p].size()];
      if (a == b) return false;
      edges.push_back({a, b, p, i, paths[p].size()});
    }
  }
  for (std::size_t i = 0; i < edges.size(); ++i)
    for (std::size_t j = i + 1; j < edges.size(); ++j) {
      const E& e = edges[i];
      const E& f = edges[j];
      const auto [lo, hi] = meeting(e.a, e.b, f.a, f.b);
      if (hi < lo) continue;
      const bool f_follows = e.path == f.path && (e.index + 1) % e.size == f.index;
      const bool e_follows = e.path == f.path && (f.index + 1) % f.size == e.index;
      // Allowed: the one point e.b (s = 1) where f starts, or e.a (s = 0) where f ends.
      if (f_follows && lo == Rational{1, 1}) continue;
      if (e_follows && hi == Rational{0, 1}) continue;
      return false;
    }
  return true;
}

Paths random_polygons(std::mt19937_64& random, int grid, int most_paths, int most_vertices) {
  std::uniform_int_distribution<int> coordinate(0, grid), path_count(1, most_paths), vertices(3, most_vertices);
  Paths paths(path_count(random));
  for (Path& path : paths) {
    const int n = vertices(random);
    for (int i = 0; i < n; ++i) path.push_back({coordinate(random), coordinate(random)});
  }
  return paths;
}

TEST(RegionUnion, SweepAgreesWithEveryPairOnSmallGrids) {
  std::mt19937_64 random(24);
  const int cases = test_volume(200000, 20000);
  int simple = 0;
  for (int k = 0; k < cases; ++k) {
    // Small grids for degenerate meetings; few vertices so some come out simple.
    const int grid = 2 + k % 7;
    const Paths paths = random_polygons(random, grid, 3, 3 + k % 5);
    const bool expected = brute_force_simple(paths);
    simple += expected;
    ASSERT_EQ(simple_and_disjoint(paths), expected) << "case " << k;
  }
  EXPECT_GT(simple, cases / 50);  // both verdicts are exercised
}

/// A star of `n` corners at distinct angles round `centre` (simple), its
/// corners snapped to multiples of `snap` (ties in height, collinear runs)
/// unless 0.
Path star(std::mt19937_64& random, int n, IntPoint centre, double inner, double outer, bool clockwise, cInt snap) {
  std::uniform_real_distribution<double> radius(inner, outer);
  Path path;
  for (int i = 0; i < n; ++i) {
    const double angle = 2 * std::numbers::pi * (i + 0.5) / n;
    const double r = radius(random);
    IntPoint p{centre.X + cInt(std::llround(r * std::cos(angle))), centre.Y + cInt(std::llround(r * std::sin(angle)))};
    if (snap) p = {p.X / snap * snap, p.Y / snap * snap};
    if (path.empty() || !(path.back() == p)) path.push_back(p);
  }
  if (clockwise) std::reverse(path.begin(), path.end());
  return path;
}

/// Teeth 10,000 tall, 1,000 wide and apart on a 5,000 bar, counter-clockwise: many corners at one height.
Path comb(int teeth, IntPoint at) {
  Path path;
  for (int k = 0; k < teeth; ++k) {
    const cInt x = at.X + 2000 * k;
    path.insert(path.end(), {{x, at.Y}, {x, at.Y + 10000}, {x + 1000, at.Y + 10000}, {x + 1000, at.Y}});
  }
  path.insert(path.end(), {{at.X + 2000 * teeth, at.Y - 5000}, {at.X, at.Y - 5000}});
  std::reverse(path.begin(), path.end());
  return path;
}

/// Each path from its least vertex, the paths in order: the same polygons
/// whatever vertex each starts at and in whatever order they come.
Paths canonical(Paths paths) {
  for (Path& path : paths)
    std::rotate(path.begin(),
                std::min_element(path.begin(), path.end(),
                                 [](IntPoint a, IntPoint b) { return a.X != b.X ? a.X < b.X : a.Y < b.Y; }),
                path.end());
  std::sort(paths.begin(), paths.end(), [](const Path& a, const Path& b) {
    return std::lexicographical_compare(a.begin(), a.end(), b.begin(), b.end(),
                                        [](IntPoint p, IntPoint q) { return p.X != q.X ? p.X < q.X : p.Y < q.Y; });
  });
  return paths;
}

Paths clipper_union(const Paths& paths) {
  ClipperLib::Clipper clipper;
  clipper.AddPaths(paths, ClipperLib::ptSubject, true);
  Paths out;
  clipper.Execute(ClipperLib::ctUnion, out, ClipperLib::pftEvenOdd, ClipperLib::pftEvenOdd);
  return out;
}

ClipperLib::Paths clipper_offset(const Paths& paths, double delta) {
  ClipperLib::ClipperOffset offset;
  offset.ArcTolerance = 100;
  offset.AddPaths(paths, ClipperLib::jtRound, ClipperLib::etClosedPolygon);
  ClipperLib::PolyTree tree;
  offset.Execute(tree, delta);
  Paths out;
  ClipperLib::PolyTreeToPaths(tree, out);
  return out;
}

/// Random nested stars (an outer star, stars as holes in it, islands in
/// those; corners on a coarse grid in some), combs, in shuffled order, some
/// with collinear and repeated vertices added; some with a hole pushed
/// across the outer boundary, some with a hole oriented as an outer loop.
TEST(RegionUnion, SkippedUnionIsClippersUnion) {
  std::mt19937_64 random(7);
  const int cases = test_volume(3000, 300);
  int skipped = 0;
  for (int k = 0; k < cases; ++k) {
    const bool crossing = k % 5 == 4, misoriented = k % 7 == 6;
    const cInt snap = k % 3 == 0 ? 0 : k % 3 == 1 ? 1000 : 100;
    std::vector<std::pair<Path, bool>> loops;  // a path, and whether it is an outer boundary
    if (k % 4 == 3) {
      loops.push_back({comb(3 + k % 9, {0, 0}), true});
      if (k % 8 == 3) loops.push_back({comb(2, {-20000, 0}), true});
    } else {
      loops.push_back({star(random, 40, {0, 0}, 80000, 100000, false, snap), true});
      for (int h = 0; h < 3; ++h) {
        // The crossing hole reaches from radius 70,000 to 110,000: across the outer star's boundary.
        const bool crosses = crossing && h == 1;
        const IntPoint centre{cInt(crosses ? 0 : -40000 + 40000 * h), cInt(crosses ? 90000 : random() % 20000)};
        loops.push_back(
            {star(random, 12, centre, crosses ? 20000 : 8000, crosses ? 20000 : 15000, !misoriented || h != 0, snap),
             false});
        loops.push_back({star(random, 6, centre, 2000, 5000, false, snap), true});
      }
    }
    if (k % 3 == 0) {  // a collinear midpoint and a repeated vertex on the first loop, the first point closing it
      Path& p = loops[0].first;
      const IntPoint d = minus(p[1], p[0]);
      if (d.X % 2 == 0 && d.Y % 2 == 0) p.insert(p.begin() + 1, IntPoint{p[0].X + d.X / 2, p[0].Y + d.Y / 2});
      p.insert(p.begin() + 3, p[3]);
      p.push_back(p[0]);
    }
    std::shuffle(loops.begin(), loops.end(), random);
    Paths paths;
    std::vector<bool> outer;
    for (const auto& [path, is_outer] : loops) paths.push_back(path), outer.push_back(is_outer);
    const Paths expected = clipper_union(paths);
    Paths ours = paths;
    const bool skip = even_odd_union(ours, outer);
    skipped += skip;
    EXPECT_EQ(skip, k % 4 == 3 || (!crossing && !misoriented)) << "case " << k;  // combs are simple
    ASSERT_EQ(canonical(ours), canonical(expected)) << "case " << k;
    // What counts downstream: Clipper's offset of either is the same, the
    // same polygons from the same vertices in the same order.
    for (const double delta : {3000.0, -3000.0, 700.0, -1500.0})
      ASSERT_EQ(clipper_offset(expected, delta), clipper_offset(ours, delta)) << "case " << k << ", offset " << delta;
  }
  EXPECT_GT(skipped, cases / 3);
}

TEST(RegionUnion, WithoutCollinearDropsStraightRunsAndRepeats) {
  const Path square{{0, 0}, {5, 0}, {10, 0}, {10, 0}, {10, 10}, {0, 10}, {0, 3}, {0, 0}};
  EXPECT_EQ(without_collinear(square), (Path{{0, 0}, {10, 0}, {10, 10}, {0, 10}}));
  // Clipper's union agrees.
  EXPECT_EQ(canonical({without_collinear(square)}), canonical(clipper_union({square})));
}

}  // namespace region_union_test
