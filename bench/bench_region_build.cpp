/// @file bench_region_build.cpp
/// @brief dxf2region from DXF to a ready index, stage by stage, on three
/// shapes of 1k, 10k and 100k elements (one closed LWPOLYLINE each, tool
/// radius 1 mm, machining outside):
///  - ring: a wavy ring, radius 100 mm with 60 waves of 1.5 mm, the
///    outline divided ever finer round a wide empty interior;
///  - gear: spikes 5 mm tall, 0.5 mm apart at the root (the tool fits
///    between none), the radius growing with their number;
///  - comb: teeth 10 mm tall, 1 mm wide, 1 mm apart, on a 5 mm bar.
/// Each DXF is written to a temporary directory and read back as dxf2region
/// reads it. The peer is Boost.Geometry's packed R-tree over the same
/// segments, built and queried (nearest segment) in the same run; its
/// distances check ours. Goals (issue 24): 10k elements ready in <= 0.1 s,
/// 100k in <= 1.5 s, build-time exponent <= 1.2 from 10k to 100k, >= 5
/// million random queries a second and >= 10 million along a tool path.
/// `bench_region_build --write-dxf DIR` only writes the nine DXFs.
/// Environment: BENCH_REGION_BUILD_REPEATS or BENCH_REPEATS (default 3; at
/// least 7 for the 1k and 10k parts, and 5 rounds for the exponent),
/// BENCH_REGION_BUILD_SIZES (default "1000,10000,100000"),
/// BENCH_REGION_BUILD_SHAPES (default "ring,gear,comb").
#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include <unistd.h>

#include "bench_common.hpp"
#include "cad/dxf_reader.hpp"
#include "cad/loops.hpp"
#include "cad/part.hpp"
#include "cad/region_distance.hpp"
#include "cad/region_offset.hpp"
#include "cad/segment_geometry.hpp"

namespace {

using namespace tk::cad;
namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;
using BPoint = bg::model::d2::point_xy<double>;
using BSegment = bg::model::segment<BPoint>;
using BValue = std::pair<BSegment, std::uint32_t>;
constexpr double kPi = std::numbers::pi;

std::vector<Point> ring(std::size_t n) {
  std::vector<Point> v;
  for (std::size_t i = 0; i < n; ++i) {
    const double a = 2 * kPi * double(i) / double(n), r = 100 + 1.5 * std::sin(60 * a);
    v.push_back({r * std::cos(a), r * std::sin(a)});
  }
  return v;
}

std::vector<Point> gear(std::size_t n) {
  const std::size_t spikes = n / 2;
  const double root = double(spikes) * 0.5 / (2 * kPi);
  std::vector<Point> v;
  for (std::size_t i = 0; i < spikes; ++i) {
    const double a = 2 * kPi * double(i) / double(spikes), b = 2 * kPi * (double(i) + 0.5) / double(spikes);
    v.push_back({root * std::cos(a), root * std::sin(a)});
    v.push_back({(root + 5) * std::cos(b), (root + 5) * std::sin(b)});
  }
  return v;
}

std::vector<Point> comb(std::size_t n) {
  const std::size_t teeth = (n - 2) / 4;
  std::vector<Point> v;
  for (std::size_t k = 0; k < teeth; ++k) {
    const double x = 2 * double(k);
    v.insert(v.end(), {{x, 0}, {x, 10}, {x + 1, 10}, {x + 1, 0}});
  }
  v.insert(v.end(), {{2 * double(teeth), -5}, {0, -5}});
  return v;
}

void write_dxf(const std::string& path, const std::vector<Point>& vertices) {
  std::ofstream out(path);
  out << "0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n";
  out << "0\nLWPOLYLINE\n8\n0\n90\n" << vertices.size() << "\n70\n1\n";
  char buffer[64];
  for (const Point& p : vertices) {
    std::snprintf(buffer, sizeof buffer, "%.17g", p.x);
    out << "10\n" << buffer << "\n";
    std::snprintf(buffer, sizeof buffer, "%.17g", p.y);
    out << "20\n" << buffer << "\n";
  }
  out << "0\nENDSEC\n0\nEOF\n";
  if (!out) bench::fail("cannot write " + path);
}

struct Shape {
  const char* name;
  std::vector<Point> (*make)(std::size_t);
};
const Shape kShapes[] = {{"ring", ring}, {"gear", gear}, {"comb", comb}};

struct Stages {
  double read = 0, loops = 0, index = 0, first = 0, tiles = 0, total = 0;
  OffsetStageTimes offset;
};

/// DXF to region and its indexes in one go, as dxf2region writes a region.
double time_total(const std::string& path) {
  return bench::time_cpu([&] {
    const Part part = load_part(path, {}, [](const std::string&) {});
    OffsetOptions plain;
    plain.tool_radius = 1;
    const RegionOffset region = offset_region(part.loops.loops, *part.index, plain);
    if (!region.contour) bench::fail("no contour for " + path);
  });
}

/// The stages one at a time (as load_part and offset_region run them), then
/// the whole from DXF to ready indexes in one go.
Stages time_stages(const std::string& path) {
  Stages s;
  Drawing drawing;
  s.read = bench::time_cpu([&] { drawing = read_dxf_file(path); });
  LoopSet set;
  s.loops = bench::time_cpu([&] { set = build_loops(drawing.segments, 1e-3); });
  std::unique_ptr<RegionIndex> index;
  s.index = bench::time_cpu([&] { index = std::make_unique<RegionIndex>(set.loops); });
  // The grid is laid out by the first signed-distance query (--check and
  // --simulate ask them; the region does not), and built tile by tile as
  // queries land: the first one's, then all the others at once.
  s.first = bench::time_cpu([&] { index->query({0, 0}); });
  s.tiles = bench::time_cpu([&] { index->prepare(); });
  index = std::make_unique<RegionIndex>(set.loops);  // the offset's, as load_part makes it
  OffsetOptions options;
  options.tool_radius = 1;
  options.stage_times = &s.offset;
  offset_region(set.loops, *index, options);
  s.total = time_total(path);
  return s;
}

/// The exponent of the total's growth from the 10k part to the 100k one,
/// from rounds that time the two alternately: the median of the rounds'
/// ratios, so that a burst of load on this shared machine falls on both
/// sizes of a round rather than on one size's every run.
double growth_exponent(const std::string& path_10k, const std::string& path_100k, int rounds) {
  std::vector<double> ratios;
  for (int r = 0; r < rounds; ++r) {
    const double small = time_total(path_10k), large = time_total(path_100k);
    ratios.push_back(large / small);
  }
  return std::log10(bench::median(ratios));
}

Stages median_stages(const std::vector<Stages>& runs) {
  const auto of = [&](auto field) {
    std::vector<double> v;
    for (const Stages& s : runs) v.push_back(field(s));
    return bench::median(v);
  };
  Stages m;
  m.read = of([](const Stages& s) { return s.read; });
  m.loops = of([](const Stages& s) { return s.loops; });
  m.index = of([](const Stages& s) { return s.index; });
  m.first = of([](const Stages& s) { return s.first; });
  m.tiles = of([](const Stages& s) { return s.tiles; });
  m.total = of([](const Stages& s) { return s.total; });
  m.offset.even_odd_union = of([](const Stages& s) { return s.offset.even_odd_union; });
  m.offset.clipper_offset = of([](const Stages& s) { return s.offset.clipper_offset; });
  m.offset.exact_recovery = of([](const Stages& s) { return s.offset.exact_recovery; });
  m.offset.contour_index = of([](const Stages& s) { return s.offset.contour_index; });
  m.offset.uncut = of([](const Stages& s) { return s.offset.uncut; });
  return m;
}

struct Rates {
  double index_build = 0, rtree_build = 0, random = 0, path = 0, rtree_random = 0, rtree_path = 0;
};

/// Random points over the box enlarged by 10 %, and a tool path: straight
/// strokes between random points, positions 0.05 mm apart.
Rates time_queries(const std::vector<Loop>& loops, int repeats) {
  Rates rates;
  std::vector<BValue> values;
  Box box{1e300, 1e300, -1e300, -1e300};
  for (const Loop& loop : loops)
    for (const Segment& s : loop.segments) {
      values.push_back({BSegment{{s.start.x, s.start.y}, {s.end.x, s.end.y}}, std::uint32_t(values.size())});
      box = {std::min(box.min_x, s.start.x), std::min(box.min_y, s.start.y), std::max(box.max_x, s.start.x),
             std::max(box.max_y, s.start.y)};
    }
  const double mx = 0.1 * (box.max_x - box.min_x), my = 0.1 * (box.max_y - box.min_y);
  std::mt19937_64 random(2026);
  std::uniform_real_distribution<double> ux(box.min_x - mx, box.max_x + mx), uy(box.min_y - my, box.max_y + my);
  std::vector<Point> points(200000), path;
  for (Point& p : points) p = {ux(random), uy(random)};
  Point at{ux(random), uy(random)};
  while (path.size() < 400000) {
    const Point to{ux(random), uy(random)};
    const int steps = std::max(1, static_cast<int>(std::hypot(to.x - at.x, to.y - at.y) / 0.05));
    for (int i = 0; i < steps && path.size() < 400000; ++i)
      path.push_back({at.x + (to.x - at.x) * i / steps, at.y + (to.y - at.y) * i / steps});
    at = to;
  }
  std::vector<double> index_build, rtree_build, random_rate, path_rate, rtree_random, rtree_path;
  double checksum = 0;
  for (int r = 0; r < repeats; ++r) {
    std::unique_ptr<RegionIndex> index;
    index_build.push_back(bench::time_cpu([&] {  // the tree and the whole grid, ready for the queries timed
      index = std::make_unique<RegionIndex>(loops);
      index->prepare();
    }));
    std::unique_ptr<bgi::rtree<BValue, bgi::rstar<16>>> tree;
    rtree_build.push_back(
        bench::time_cpu([&] { tree = std::make_unique<bgi::rtree<BValue, bgi::rstar<16>>>(values); }));
    const auto ours = [&](const std::vector<Point>& at_points) {
      for (const Point& p : at_points) checksum += index->query(p).distance;
    };
    const auto peer = [&](const std::vector<Point>& at_points) {
      for (const Point& p : at_points)
        for (auto it = tree->qbegin(bgi::nearest(BPoint{p.x, p.y}, 1)); it != tree->qend(); ++it)
          checksum += it->second;
    };
    const auto [ours_random, peer_random] = bench::time_interleaved([&] { ours(points); }, [&] { peer(points); });
    const auto [ours_path, peer_path] = bench::time_interleaved([&] { ours(path); }, [&] { peer(path); });
    random_rate.push_back(double(points.size()) / ours_random);
    rtree_random.push_back(double(points.size()) / peer_random);
    path_rate.push_back(double(path.size()) / ours_path);
    rtree_path.push_back(double(path.size()) / peer_path);
    // The peer's nearest distance checks ours (the shapes are all lines).
    for (std::size_t i = 0; i < points.size(); i += 97) {
      const BPoint q{points[i].x, points[i].y};
      double theirs = 1e300;
      for (auto it = tree->qbegin(bgi::nearest(q, 1)); it != tree->qend(); ++it) theirs = bg::distance(q, it->first);
      const double mine = std::abs(index->query(points[i]).distance);
      if (std::abs(mine - theirs) > 1e-9 * std::max(1.0, theirs))
        bench::fail("RegionIndex and Boost's rtree disagree at random point " + std::to_string(i));
    }
  }
  if (checksum == 0) std::printf("(checksum %g)\n", checksum);  // keeps the timed queries
  rates.index_build = bench::median(index_build);
  rates.rtree_build = bench::median(rtree_build);
  rates.random = bench::median(random_rate);
  rates.path = bench::median(path_rate);
  rates.rtree_random = bench::median(rtree_random);
  rates.rtree_path = bench::median(rtree_path);
  return rates;
}

std::vector<std::size_t> sizes() {
  std::vector<std::size_t> out;
  const char* text = std::getenv("BENCH_REGION_BUILD_SIZES");
  std::string list = text ? text : "1000,10000,100000";
  for (std::size_t at = 0; at < list.size();) {
    const std::size_t comma = std::min(list.find(',', at), list.size());
    out.push_back(std::stoul(list.substr(at, comma - at)));
    at = comma + 1;
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 3 && std::string(argv[1]) == "--write-dxf") {
    for (const Shape& shape : kShapes)
      for (std::size_t n : sizes())
        write_dxf(std::string(argv[2]) + "/" + shape.name + "_" + std::to_string(n) + ".dxf", shape.make(n));
    return 0;
  }
  const int repeats = bench::repeats({"BENCH_REGION_BUILD_REPEATS", "BENCH_REPEATS"}, 3);
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("bench_region_build." + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  // The smaller parts take a fraction of a second a run: more runs steady
  // their medians against this shared machine's bursts of load.
  const auto runs_at = [&](std::size_t n) { return n <= 10000 ? std::max(repeats, 7) : repeats; };
  std::printf(
      "bench_region_build: DXF to ready index (tool radius 1 mm, outside), CPU ms, medians of %d runs (%d at 100k)\n",
      runs_at(10000), runs_at(100000));
  std::printf("%-6s %7s %7s %7s %7s %7s %7s %7s %7s %7s %8s %7s %7s | %7s %7s | %6s %6s %6s %6s\n", "shape", "n",
              "read", "loops", "index", "union", "offset", "exact", "contour", "uncut", "TOTAL", "first", "tiles",
              "build", "rtree", "rand", "rtree", "path", "rtree");
  double total_10k = 0, total_100k = 0, checkable_10k = 0, checkable_100k = 0, whole_10k = 0, whole_100k = 0;
  double worst_random = 1e300, worst_path = 1e300;
  const char* only = std::getenv("BENCH_REGION_BUILD_SHAPES");
  for (const Shape& shape : kShapes) {
    if (only && std::string(only).find(shape.name) == std::string::npos) continue;
    std::string path_10k, path_100k;
    for (std::size_t n : sizes()) {
      const std::string path = (dir / (std::string(shape.name) + "_" + std::to_string(n) + ".dxf")).string();
      write_dxf(path, shape.make(n));
      std::vector<Stages> runs;
      for (int r = 0; r < runs_at(n); ++r) runs.push_back(time_stages(path));
      const Stages m = median_stages(runs);
      const Part part = load_part(path, {}, [](const std::string&) {});
      const Rates q = time_queries(part.loops.loops, repeats);
      std::size_t elements = 0;
      for (const Loop& loop : part.loops.loops) elements += loop.segments.size();
      std::printf(
          "%-6s %7zu %7.1f %7.1f %7.1f %7.1f %7.1f %7.1f %7.1f %7.1f %8.1f %7.1f %7.1f | %7.2f %7.2f | %6.2f %6.2f "
          "%6.2f %6.2f\n",
          shape.name, elements, m.read * 1e3, m.loops * 1e3, m.index * 1e3, m.offset.even_odd_union * 1e3,
          m.offset.clipper_offset * 1e3, m.offset.exact_recovery * 1e3, m.offset.contour_index * 1e3,
          m.offset.uncut * 1e3, m.total * 1e3, m.first * 1e3, m.tiles * 1e3, q.index_build * 1e3, q.rtree_build * 1e3,
          q.random / 1e6, q.rtree_random / 1e6, q.path / 1e6, q.rtree_path / 1e6);
      std::fflush(stdout);
      if (n == 10000) path_10k = path, total_10k = std::max(total_10k, m.total);
      if (n == 100000) path_100k = path, total_100k = std::max(total_100k, m.total);
      if (n == 10000) checkable_10k = std::max(checkable_10k, m.total + m.first);
      if (n == 100000) checkable_100k = std::max(checkable_100k, m.total + m.first);
      if (n == 10000) whole_10k = std::max(whole_10k, m.total + m.first + m.tiles);
      if (n == 100000) whole_100k = std::max(whole_100k, m.total + m.first + m.tiles);
      worst_random = std::min(worst_random, q.random), worst_path = std::min(worst_path, q.path);
    }
    if (!path_10k.empty() && !path_100k.empty()) {
      const int rounds = std::max(repeats, 5);
      std::printf(
          "FIGURE region_build_exponent_%s %.2f (goal <= 1.2, 10k to 100k; median of %d rounds alternating them)\n",
          shape.name, growth_exponent(path_10k, path_100k, rounds), rounds);
      std::fflush(stdout);
    }
  }
  std::printf(
      "(index: the drawing's box tree; TOTAL: DXF to region and its indexes, as dxf2region writes a region; first: "
      "the drawing index's first signed-distance query (--check, --simulate), which lays out its grid and builds "
      "one tile; tiles: all the other tiles, which later queries build where they land; build and rtree: the "
      "drawing's index with its whole grid against Boost's packed R-tree; rand / path: million queries a second, "
      "ours signed distance + nearest point, the rtree's nearest segment)\n");
  if (total_10k > 0) std::printf("FIGURE region_ready_10k_worst %.3f s (goal <= 0.1)\n", total_10k);
  if (total_100k > 0) std::printf("FIGURE region_ready_100k_worst %.3f s (goal <= 1.5)\n", total_100k);
  if (checkable_10k > 0) std::printf("FIGURE region_and_first_query_10k_worst %.3f s (goal <= 0.1)\n", checkable_10k);
  if (checkable_100k > 0)
    std::printf("FIGURE region_and_first_query_100k_worst %.3f s (goal <= 1.5)\n", checkable_100k);
  if (whole_10k > 0) std::printf("FIGURE region_and_whole_grid_10k_worst %.3f s\n", whole_10k);
  if (whole_100k > 0) std::printf("FIGURE region_and_whole_grid_100k_worst %.3f s\n", whole_100k);
  std::printf("FIGURE region_queries_random_worst %.2f million/s (goal 5)\n", worst_random / 1e6);
  std::printf("FIGURE region_queries_path_worst %.2f million/s (goal 10)\n", worst_path / 1e6);
  std::filesystem::remove_all(dir);
  return 0;
}
