/// @file test_invasion_sim.cpp
/// @brief The seed's experiment against closed-form kinematics: straight at
/// a straight boundary, the fixed-tolerance guard stops the tool exactly
/// feed x latency after the first sample inside T, so it invades when T is
/// below feed x latency and leaves T - feed x latency (within a period's
/// travel) otherwise; the latency-aware guard stops within a period's
/// travel of its margin. On a disc, at any approach angle, ours never
/// invades and leaves far less than the seed's 0.5 mm.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "cad/invasion_sim.hpp"
#include "io/error.hpp"

namespace {

using namespace tk::cad;

// The region y < 0; its boundary as a two-point loop, of which only the
// edge running toward -x has the region on its left (strokes from the
// other edge would start inside and are drawn again).
const std::vector<std::vector<Point>> kLine = {{{-100, 0}, {100, 0}}};
double above_line(Point p) { return p.y; }

TEST(InvasionSim, StraightAtALineMatchesTheKinematics) {
  InvasionSimOptions options;
  options.feed_mm_s = 50;
  options.latency_s = 0.09;  // 4.5 mm of coasting
  options.period_s = 0.001;  // 0.05 mm between samples
  options.max_angle_deg = 0;
  options.strokes = 200;
  const auto results = simulate_invasions(above_line, kLine, {1, 4, 5, 8}, options);
  ASSERT_EQ(results.size(), 5u);
  const double coast = 4.5, step = 0.05;
  for (int i = 0; i < 4; ++i) {
    const InvasionSimResult& r = results[i];
    EXPECT_EQ(r.guard, "fixed-tolerance");
    EXPECT_EQ(r.strokes, 200u);
    if (r.tolerance_mm < coast) {
      EXPECT_EQ(r.invasions, 200u) << r.tolerance_mm;
      EXPECT_EQ(r.success_rate, 0.0);
      EXPECT_GT(r.max_invasion_mm, coast - r.tolerance_mm - 1e-9);
      EXPECT_LE(r.max_invasion_mm, coast - r.tolerance_mm + step + 1e-9);
    } else {
      EXPECT_EQ(r.invasions, 0u) << r.tolerance_mm;
      EXPECT_EQ(r.success_rate, 1.0);
      EXPECT_GE(r.mean_undercut_mm, r.tolerance_mm - coast - step - 1e-9);
      EXPECT_LE(r.max_undercut_mm, r.tolerance_mm - coast + 1e-9);
    }
  }
  const InvasionSimResult& ours = results[4];
  EXPECT_EQ(ours.guard, "latency-aware");
  EXPECT_EQ(ours.invasions, 0u);
  EXPECT_GE(ours.mean_undercut_mm, options.margin_mm - 1e-9);
  EXPECT_LE(ours.max_undercut_mm, options.margin_mm + step + 1e-9);
}

// A disc of radius 20 at the origin: the region is inside it; its boundary
// counter-clockwise. Strokes come in at up to 60 degrees off the normal.
TEST(InvasionSim, OnADiscTheLatencyAwareGuardNeverInvadesAndCutsClose) {
  std::vector<Point> circle;
  for (int i = 0; i < 720; ++i) {
    const double a = 2 * std::numbers::pi * i / 720;
    circle.push_back({20 * std::cos(a), 20 * std::sin(a)});
  }
  const auto distance = [](Point p) { return std::hypot(p.x, p.y) - 20; };
  InvasionSimOptions options;
  options.strokes = 500;
  const auto results = simulate_invasions(distance, {circle}, {2, 5, 6}, options);
  ASSERT_EQ(results.size(), 4u);
  // The seed's guard at 2 mm: the tool coasts 4.5 mm at up to full speed
  // toward the disc: some strokes invade.
  EXPECT_GT(results[0].invasions, 0u);
  // At 6 mm it never invades, but leaves more than 0.5 mm on average.
  EXPECT_EQ(results[2].invasions, 0u);
  EXPECT_GT(results[2].mean_undercut_mm, 0.5);
  const InvasionSimResult& ours = results[3];
  EXPECT_EQ(ours.invasions, 0u);
  EXPECT_EQ(ours.success_rate, 1.0);
  // On a slant toward a convex boundary the distance falls ever slower as
  // the tool nears, so the first-order prediction stops a little early:
  // still well under the seed's 0.5 mm.
  EXPECT_LT(ours.mean_undercut_mm, 0.25);
  EXPECT_LT(ours.mean_undercut_mm, results[2].mean_undercut_mm / 4);
}

TEST(InvasionSim, SameStrokesForTheSameSeed) {
  InvasionSimOptions options;
  options.strokes = 50;
  const auto a = simulate_invasions(above_line, kLine, {5}, options);
  const auto b = simulate_invasions(above_line, kLine, {5}, options);
  EXPECT_EQ(a[0].mean_undercut_mm, b[0].mean_undercut_mm);
  EXPECT_EQ(a[1].mean_undercut_mm, b[1].mean_undercut_mm);
}

TEST(InvasionSim, RefusesBadOptions) {
  InvasionSimOptions options;
  options.feed_mm_s = 0;
  EXPECT_THROW(simulate_invasions(above_line, kLine, {1}, options), tk::Error);
  options = {};
  options.period_s = std::nan("");
  EXPECT_THROW(simulate_invasions(above_line, kLine, {1}, options), tk::Error);
  options = {};
  options.latency_s = -1;
  EXPECT_THROW(simulate_invasions(above_line, kLine, {1}, options), tk::Error);
  options = {};
  EXPECT_THROW(simulate_invasions(above_line, kLine, {-1}, options), tk::Error);
  EXPECT_THROW(simulate_invasions(above_line, {{{0, 0}}}, {1}, options), tk::Error);
  options.strokes = 0;
  EXPECT_THROW(simulate_invasions(above_line, kLine, {1}, options), tk::Error);
}

}  // namespace
