/// @file test_region_uncut.cpp
/// @brief The uncut search settles most samples by bounds (the gap is
/// 1-Lipschitz along the drawing) and asks the contour only where they
/// leave the answer open (region_uncut.cpp); its answer must be the plain
/// search's to the last bit: every sample's exact gap by brute force over
/// the contour's elements, runs above the threshold, each run's first
/// deepest sample refined by the same golden-section search, the runs
/// joined over corners the same way.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "cad/loops.hpp"
#include "cad/region_distance.hpp"
#include "cad/region_offset.hpp"
#include "cad/region_uncut.hpp"
#include "cad/segment_geometry.hpp"
#include "region_parts.hpp"
#include "test_volume.hpp"

namespace region_uncut_test {  // named: the unity build joins the tests' anonymous namespaces

using namespace tk::cad;

struct PlainSearch {
  std::vector<UncutSpan> spans;
  std::size_t questions = 0;  // the exact gaps it asks at least: uncut samples, 81 per run
};

/// The search written plainly: every sample's exact gap, by `gap_at`
/// (the distance to the contour's nearest element less R).
template <class Gap>
PlainSearch plain_search(const std::vector<Loop>& drawn, Gap gap_at, double radius, const OffsetOptions& options) {
  PlainSearch result;
  const double threshold = options.uncut_report_mm;
  const double step = std::max(radius / 8, 10 * options.tolerance);
  for (const Loop& loop : drawn) {
    std::vector<UncutSpan> runs;
    for (const Segment& s : loop.segments) {
      const std::size_t samples = std::min<std::size_t>(10000, 1 + static_cast<std::size_t>(segment_length(s) / step));
      std::vector<double> gaps;
      for (std::size_t i = 0; i <= samples; ++i) gaps.push_back(gap_at(point_at(s, double(i) / samples)));
      for (std::size_t i = 0; i <= samples; ++i) {
        if (gaps[i] <= threshold) continue;
        const std::size_t begin = i;
        std::size_t deepest = i;
        for (; i + 1 <= samples && gaps[i + 1] > threshold; ++i)
          if (gaps[i + 1] > gaps[deepest]) deepest = i + 1;
        result.questions += i - begin + 1 + 81;
        double lo = double(deepest == 0 ? 0 : deepest - 1) / samples;
        double hi = double(std::min(deepest + 1, samples)) / samples;
        const double golden = (std::sqrt(5.0) - 1) / 2;
        for (int k = 0; k < 40; ++k) {
          const double a = hi - golden * (hi - lo), b = lo + golden * (hi - lo);
          if (gap_at(point_at(s, a)) > gap_at(point_at(s, b))) {
            hi = b;
          } else {
            lo = a;
          }
        }
        const double depth = std::max(gaps[deepest], gap_at(point_at(s, 0.5 * (lo + hi))));
        runs.push_back(
            {point_at(s, double(begin) / samples), point_at(s, double(i) / samples), depth, s.entity, s.source_line});
      }
    }
    std::vector<UncutSpan> joined;
    for (const UncutSpan& run : runs)
      if (!joined.empty() && std::hypot(joined.back().to.x - run.from.x, joined.back().to.y - run.from.y) < 1e-9) {
        joined.back().to = run.to;
        joined.back().depth = std::max(joined.back().depth, run.depth);
      } else {
        joined.push_back(run);
      }
    if (joined.size() > 1 &&
        std::hypot(joined.back().to.x - joined.front().from.x, joined.back().to.y - joined.front().from.y) < 1e-9) {
      joined.front().from = joined.back().from;
      joined.front().depth = std::max(joined.front().depth, joined.back().depth);
      joined.pop_back();
    }
    result.spans.insert(result.spans.end(), joined.begin(), joined.end());
  }
  return result;
}

/// Same spans as the plain search, bit for bit, with the index's exact
/// distances (each the minimum over the elements as the index computes
/// them); and as with brute force's (computed apart, they may differ in
/// the last bit: depths to 1e-12). Returns the number of exact gaps
/// find_uncut asked, the plain search's least number, and the spans found.
struct Compared {
  std::size_t asked, plain, spans;
};
Compared expect_plain_search_spans(const std::vector<Segment>& segments, double radius, MachiningSide side,
                                   const std::string& what) {
  const LoopSet set = build_loops(segments, 1e-6);
  const OffsetOptions options{.tool_radius = radius, .side = side};
  const RegionOffset offset = offset_region(set.loops, RegionIndex(set.loops), options);
  UncutQueryCounts counts;
  const std::vector<UncutSpan> found = find_uncut(set.loops, offset.contour.get(), radius, options, &counts);
  const RegionIndex* contour = offset.contour.get();
  // No contour (the tool fits nowhere): all is uncut, R + 1 deep by find_uncut's convention.
  const auto by_index = [&](Point p) { return contour ? contour->nearest(p).distance - radius : radius + 1; };
  const auto by_brute_force = [&](Point p) {
    return offset.loops.empty() ? radius + 1 : std::abs(brute_force_query(offset.loops, p).distance) - radius;
  };
  const PlainSearch expected = plain_search(set.loops, by_index, radius, options);
  const PlainSearch brute = plain_search(set.loops, by_brute_force, radius, options);
  EXPECT_EQ(offset.uncut.size(), found.size()) << what;
  EXPECT_EQ(found.size(), expected.spans.size()) << what;
  EXPECT_EQ(found.size(), brute.spans.size()) << what;
  for (std::size_t i = 0; i < std::min(found.size(), expected.spans.size()); ++i) {
    const UncutSpan &got = found[i], &want = expected.spans[i];
    EXPECT_EQ(got.from.x, want.from.x) << what << ", span " << i;
    EXPECT_EQ(got.from.y, want.from.y) << what << ", span " << i;
    EXPECT_EQ(got.to.x, want.to.x) << what << ", span " << i;
    EXPECT_EQ(got.to.y, want.to.y) << what << ", span " << i;
    EXPECT_EQ(got.depth, want.depth) << what << ", span " << i;
    EXPECT_EQ(got.entity, want.entity) << what << ", span " << i;
    if (i < offset.uncut.size()) {
      EXPECT_EQ(offset.uncut[i].depth, got.depth) << what << ", span " << i;
    }
    if (i >= brute.spans.size()) continue;
    EXPECT_EQ(got.from.x, brute.spans[i].from.x) << what << ", span " << i;
    EXPECT_EQ(got.to.y, brute.spans[i].to.y) << what << ", span " << i;
    EXPECT_NEAR(got.depth, brute.spans[i].depth, 1e-12 * (1 + radius)) << what << ", span " << i;
  }
  return {counts.sampling + counts.deepest + counts.refining, expected.questions, found.size()};
}

std::string label(double radius, MachiningSide side) {
  return "R " + std::to_string(radius) + (side == MachiningSide::inside ? " inside" : " outside");
}

std::vector<Segment> moved(std::vector<Segment> part, double dx, double dy) {
  for (Segment& s : part) s.start.x += dx, s.start.y += dy, s.end.x += dx, s.end.y += dy;
  return part;
}

TEST(RegionUncut, GearsAsThePlainSearchFindsThem) {
  const int teeth = test_volume(40, 12);
  for (const double bulge : {0.0, -0.15, 0.2})
    for (const double radius : {0.3, 1.0})
      for (const MachiningSide side : {MachiningSide::outside, MachiningSide::inside}) {
        const std::vector<Segment> gear = parts::gear(teeth, side == MachiningSide::inside ? 3 : 5, 0.5, bulge);
        const std::string what = label(radius, side) + ", bulge " + std::to_string(bulge);
        const auto [asked, plain, spans] = expect_plain_search_spans(gear, radius, side, what);
        // Nearly all of a gear's flanks is left uncut: the plain search asks
        // every sample there, the bounds settle most of them. (The sanitizers'
        // 12-tooth gear, inside at R = 1, has flanks too short for a third:
        // 1,849 of 2,568 questions; fewer is all that is asked of it.)
        if (teeth == 40) {
          EXPECT_LT(3 * asked, plain) << what;
        } else {
          EXPECT_LT(asked, plain) << what;
        }
      }
}

TEST(RegionUncut, FarFromTheOriginAsThePlainSearchFindsThem) {
  // Coordinates in the thousands: the bounds' margin grows with them.
  for (const double radius : {0.3, 1.0}) {
    const Compared compared =
        expect_plain_search_spans(moved(parts::gear(test_volume(24, 8), 4, 0.5, 0.1), 4998.25, -3001.5), radius,
                                  MachiningSide::outside, label(radius, MachiningSide::outside) + ", moved");
    EXPECT_GT(compared.spans, 0u) << "no span to compare";
  }
}

TEST(RegionUncut, RandomPartsAsThePlainSearchFindsThem) {
  std::mt19937_64 random(424);
  for (int star = 0; star < test_volume(8, 3); ++star) {
    const std::vector<Segment> part = parts::random_star_with_hole(random, 6 + 3 * star);
    for (const double radius : {0.7, 2.5, 6.0, 40.0})
      for (const MachiningSide side : {MachiningSide::outside, MachiningSide::inside})
        expect_plain_search_spans(part, radius, side, "star " + std::to_string(star) + ", " + label(radius, side));
  }
}

TEST(RegionUncut, CombsAsThePlainSearchFindsThem) {
  // Slots narrower than the tool: each is uncut from wall to wall, deepest
  // inside its straight bottom (the search's convexity bound on a line
  // decides there), turned so that no line is axis-parallel.
  for (const double turn : {0.0, 0.3}) {
    const double c = std::cos(turn), s = std::sin(turn);
    std::vector<Point> corners;
    const int teeth = test_volume(12, 4);
    for (int k = 0; k < teeth; ++k) {
      const double x = 2.0 * k, width = 0.8 + 0.05 * (k % 5);
      corners.insert(corners.end(), {{x, 0}, {x, 6}, {x + width, 6}, {x + width, 0}});
    }
    corners.insert(corners.end(), {{2.0 * teeth, -3}, {0, -3}});
    std::vector<Segment> comb;
    for (std::size_t i = 0; i < corners.size(); ++i) {
      const Point a = corners[i], b = corners[(i + 1) % corners.size()];
      comb.push_back({{c * a.x - s * a.y, s * a.x + c * a.y}, {c * b.x - s * b.y, s * b.x + c * b.y}, 0});
    }
    for (const double radius : {0.7, 1.0})
      for (const MachiningSide side : {MachiningSide::outside, MachiningSide::inside}) {
        const Compared compared = expect_plain_search_spans(
            comb, radius, side, "comb turned " + std::to_string(turn) + ", " + label(radius, side));
        EXPECT_GT(compared.spans, 0u) << "no span to compare";
      }
  }
}

TEST(RegionUncut, SpikyStarsAsThePlainSearchFindsThem) {
  // Long thin spikes, arcs among them: spans of every length, deepest at
  // ends and inside, runs broken by a sample within reach.
  std::mt19937_64 random(2024);
  std::uniform_real_distribution<double> unit(0, 1);
  for (int part = 0; part < test_volume(6, 2); ++part) {
    std::vector<Point> corners;
    const int n = 12 + 4 * part;
    for (int i = 0; i < n; ++i) {
      const double angle = 2 * std::numbers::pi * i / n, r = (i % 2 ? 5 : 30) + 10 * unit(random);
      corners.push_back({r * std::cos(angle), r * std::sin(angle)});
    }
    std::vector<Segment> star;
    for (std::size_t i = 0; i < corners.size(); ++i)
      star.push_back(
          {corners[i], corners[(i + 1) % corners.size()], unit(random) < 0.25 ? 0.5 * (unit(random) - 0.5) : 0});
    for (const double radius : {0.5, 1.5, 4.0})
      for (const MachiningSide side : {MachiningSide::outside, MachiningSide::inside})
        expect_plain_search_spans(star, radius, side, "spiky " + std::to_string(part) + ", " + label(radius, side));
  }
}

}  // namespace region_uncut_test
