/// @file bench_region_query.cpp
/// @brief dxf2region's signed-distance index against brute force on a
/// 10,000-element boundary: a 700-tooth gear of lines and arcs with a
/// splined bore, bolt holes and slots. Both answer the same 20,000 points
/// (four fifths uniform over the box enlarged by 10 %, one fifth within a
/// hair of the boundary); the index runs over them 50 times to be
/// measurable. Goals: at least 100x brute force per query, and 5 million
/// queries per second. Answers are compared on every run. A second figure
/// times a tool's path (positions 0.05 mm apart), the invasion check's
/// real workload.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <vector>

#include "bench_common.hpp"
#include "cad/loops.hpp"
#include "cad/region_distance.hpp"
#include "cad/segment_geometry.hpp"

namespace {

using namespace tk::cad;
constexpr double kPi = std::numbers::pi;

Point polar(double r, double a) { return {r * std::cos(a), r * std::sin(a)}; }

Segment piece(Point a, Point b, double bulge = 0) {
  Segment s;
  s.start = a, s.end = b, s.bulge = bulge;
  return s;
}

/// Teeth of `per_tooth` segments each: a flank of lines bending outward,
/// tip arc, the mirrored flank, root arc. Counter-clockwise.
std::vector<Segment> gear(double root, double tip, int teeth, int per_tooth) {
  const int flank = (per_tooth - 2) / 2;
  const double pitch = 2 * kPi / teeth;
  std::vector<std::pair<Point, double>> corners;  // with the bulge of the segment leaving it
  const auto flank_at = [&](double a, double f, double from, double turn) {
    return polar(root + (tip - root) * f, a + (from + turn * std::sqrt(f)) * pitch);
  };
  for (int t = 0; t < teeth; ++t) {
    const double a = t * pitch;
    for (int i = 0; i < flank; ++i) corners.emplace_back(flank_at(a, double(i) / flank, 0.35, 0.12), 0);
    corners.emplace_back(polar(tip, a + 0.47 * pitch), std::tan(0.12 * pitch / 4));
    for (int i = flank; i > 0; --i) corners.emplace_back(flank_at(a, double(i) / flank, 0.71, -0.12), 0);
    corners.emplace_back(polar(root, a + 0.71 * pitch), std::tan(0.64 * pitch / 4));  // to the next tooth
  }
  std::vector<Segment> loop;
  for (std::size_t i = 0; i < corners.size(); ++i)
    loop.push_back(piece(corners[i].first, corners[(i + 1) % corners.size()].first, corners[i].second));
  return loop;
}

std::vector<Segment> circle(Point c, double r) {
  return {piece({c.x + r, c.y}, {c.x - r, c.y}, 1), piece({c.x - r, c.y}, {c.x + r, c.y}, 1)};
}

/// A slot: two straight sides and two half-circle ends.
std::vector<Segment> slot(Point c, double angle, double length, double r) {
  const Point d = polar(1, angle), n = {-d.y, d.x};
  const Point a{c.x - d.x * length / 2, c.y - d.y * length / 2}, b{c.x + d.x * length / 2, c.y + d.y * length / 2};
  return {piece({a.x - n.x * r, a.y - n.y * r}, {b.x - n.x * r, b.y - n.y * r}),
          piece({b.x - n.x * r, b.y - n.y * r}, {b.x + n.x * r, b.y + n.y * r}, 1),
          piece({b.x + n.x * r, b.y + n.y * r}, {a.x + n.x * r, a.y + n.y * r}),
          piece({a.x + n.x * r, a.y + n.y * r}, {a.x - n.x * r, a.y - n.y * r}, 1)};
}

std::vector<Segment> part() {
  std::vector<Segment> all = gear(95, 100, 700, 12);               // 8,400
  for (const Segment& s : gear(14, 16, 60, 20)) all.push_back(s);  // splined bore, 1,200
  for (int i = 0; i < 100; ++i) {                                  // bolt holes, 200
    const double r = i % 2 ? 70 : 45;
    for (const Segment& s : circle(polar(r, 2 * kPi * i / 100 + (i % 2) * 0.02), 1.2)) all.push_back(s);
  }
  for (int i = 0; i < 50; ++i)  // slots, 200
    for (const Segment& s : slot(polar(58, 2 * kPi * (i + 0.5) / 50), 2 * kPi * (i + 0.5) / 50 + kPi / 2, 3, 0.8))
      all.push_back(s);
  return all;
}

}  // namespace

int main() {
  const int repeats = bench::repeats({"BENCH_REGION_QUERY_REPEATS", "BENCH_REPEATS"}, 5);
  const LoopSet set = build_loops(part(), 1e-6);
  std::size_t elements = 0;
  for (const Loop& l : set.loops) elements += l.segments.size();
  if (elements != 10000 || !set.open_segments.empty()) bench::fail("the test part did not close into 10,000 elements");
  RegionIndex* index = nullptr;
  const double build = bench::time_cpu([&] {  // with its whole grid (queries would build it tile by tile)
    index = new RegionIndex(set.loops);
    index->prepare();
  });

  std::mt19937_64 random(2026);
  std::vector<Point> points;
  std::uniform_real_distribution<double> box(-110, 110), t(0, 1), hair(-1e-3, 1e-3);
  std::uniform_int_distribution<std::size_t> which(0, elements - 1);
  for (int i = 0; i < 16000; ++i) points.push_back({box(random), box(random)});
  for (int i = 0; i < 4000; ++i) {
    const Segment& s = index->elements()[which(random)];
    const Point on = point_at(s, t(random));
    points.push_back({on.x + hair(random), on.y + hair(random)});
  }
  std::printf(
      "bench_region_query: RegionIndex vs brute force, %zu elements in %zu loops, %zu points "
      "(index 50 passes, brute force 1), %d repeats\n",
      elements, set.loops.size(), points.size(), repeats);
  std::printf("FIGURE index_build %.1f ms\n", build * 1e3);

  const int passes = 50;
  bench::Results results("bench_region_query");
  std::vector<double> ours_rate, peer_rate;
  std::vector<RegionQuery> slow(points.size());
  double checksum = 0;
  for (int r = 0; r < repeats; ++r) {
    // Times are for one pass over the points each, so ratio = speed ratio.
    const auto [ours, peer] = bench::time_interleaved(
        [&] {
          for (int pass = 0; pass < passes; ++pass)
            for (const Point& p : points) checksum += index->query(p).distance;
        },
        [&] {
          for (std::size_t i = 0; i < points.size(); ++i) slow[i] = brute_force_query(set.loops, points[i]);
        });
    for (std::size_t i = 0; i < points.size(); ++i) {
      const RegionQuery fast = index->query(points[i]);
      const double tolerance = 1e-12 * std::max(1.0, std::abs(slow[i].distance));
      if (std::abs(std::abs(fast.distance) - std::abs(slow[i].distance)) > tolerance ||
          (std::abs(slow[i].distance) >= 1e-9 && fast.inside() != slow[i].inside()))
        bench::fail("index and brute force disagree at point " + std::to_string(i));
    }
    ours_rate.push_back(double(passes) * double(points.size()) / ours);
    peer_rate.push_back(double(points.size()) / peer);
    results.add(ours / passes, peer);
  }
  results.report(100);
  std::printf("FIGURE queries_per_s_index %.2f million (goal 5)\n", bench::median(ours_rate) / 1e6);
  // The invasion check's own workload: a tool moving at 50 mm/s sampled
  // every millisecond (0.05 mm apart), straight strokes between random
  // points of the box, so consecutive queries fall in neighbouring leaves.
  std::vector<Point> path;
  Point at{box(random), box(random)};
  while (path.size() < 400000) {
    const Point to{box(random), box(random)};
    const double length = std::hypot(to.x - at.x, to.y - at.y);
    const int steps = std::max(1, static_cast<int>(length / 0.05));
    for (int i = 0; i < steps; ++i)
      path.push_back({at.x + (to.x - at.x) * i / steps, at.y + (to.y - at.y) * i / steps});
    at = to;
  }
  std::vector<double> path_rate;
  for (int r = 0; r < repeats; ++r) {
    const double seconds = bench::time_cpu([&] {
      for (const Point& p : path) checksum += index->query(p).distance;
    });
    path_rate.push_back(double(path.size()) / seconds);
  }
  std::printf("FIGURE queries_per_s_tool_path %.2f million (%zu positions 0.05 mm apart, median of %d)\n",
              bench::median(path_rate) / 1e6, path.size(), repeats);
  std::printf("FIGURE queries_per_s_brute_force %.0f\n", bench::median(peer_rate));
  if (checksum == 0) std::printf("(checksum %g)\n", checksum);  // keeps the timed queries
  delete index;
  return 0;
}
