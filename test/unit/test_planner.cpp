/// @file test_planner.cpp
/// @brief The trapezoid planner against closed-form kinematics: a single
/// move's duration and its time at any point, collinear blocks that never
/// slow down, a right-angle corner at grbl's junction-deviation speed, the
/// centripetal limit on arcs, a dwell that stops, a window of look-ahead
/// that only ever raises speeds.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "io/error.hpp"
#include "motion/planner.hpp"

namespace {

using namespace tk::motion;

Motion feed_line(Vec3 from, Vec3 to, double feed) {
  Motion m;
  m.start = from;
  m.end = to;
  m.feed = feed;
  return m;
}

std::vector<PlannedBlock> plan(const std::vector<Motion>& motions, MachineLimits limits) {
  Planner planner(limits);
  std::vector<PlannedBlock> out;
  auto sink = [&](const PlannedBlock& b) { out.push_back(b); };
  for (const Motion& m : motions) planner.add(m, sink);
  planner.finish(sink);
  return out;
}

TEST(Planner, OneMoveIsATrapezoidWithTheClosedFormTimes) {
  MachineLimits limits;
  limits.acceleration = 100;
  limits.max_speed = 1000;
  const auto blocks = plan({feed_line({0, 0, 0}, {10, 0, 0}, 10)}, limits);
  ASSERT_EQ(blocks.size(), 1u);
  const PlannedBlock& b = blocks[0];
  // 0.1 s to reach 10 mm/s over 0.5 mm, 9 mm at 10 mm/s, 0.1 s to stop.
  EXPECT_NEAR(b.duration, 1.1, 1e-12);
  EXPECT_NEAR(b.time_at(0.5), 0.1, 1e-12);
  EXPECT_NEAR(b.time_at(0.125), std::sqrt(2 * 0.125 / 100), 1e-12);
  EXPECT_NEAR(b.time_at(5), 0.1 + 4.5 / 10, 1e-12);
  EXPECT_NEAR(b.time_at(10), 1.1, 1e-12);
  EXPECT_NEAR(b.time_at(9.875), 1.1 - std::sqrt(2 * 0.125 / 100), 1e-9);
  double previous = -1;
  for (int i = 0; i <= 1000; ++i) {
    const double t = b.time_at(i * 0.01);
    EXPECT_GE(t, previous);
    previous = t;
  }
}

TEST(Planner, AShortMoveNeverReachesItsFeedAndPeaksHalfway) {
  MachineLimits limits;
  limits.acceleration = 100;
  const auto blocks = plan({feed_line({0, 0, 0}, {1, 0, 0}, 100)}, limits);
  ASSERT_EQ(blocks.size(), 1u);
  EXPECT_NEAR(blocks[0].cruise_speed, 10, 1e-12);  // sqrt(a * L)
  EXPECT_NEAR(blocks[0].duration, 0.2, 1e-12);
}

TEST(Planner, CollinearBlocksKeepTheirSpeedAndCornersSlowToTheJunctionSpeed) {
  MachineLimits limits;
  limits.acceleration = 100;
  limits.junction_deviation = 0.01;
  const auto straight = plan({feed_line({0, 0, 0}, {10, 0, 0}, 10), feed_line({10, 0, 0}, {20, 0, 0}, 10)}, limits);
  ASSERT_EQ(straight.size(), 2u);
  EXPECT_NEAR(straight[0].exit_speed, 10, 1e-12);
  EXPECT_NEAR(straight[1].entry_speed, 10, 1e-12);
  EXPECT_NEAR(straight[0].duration + straight[1].duration, 2.1, 1e-12);
  // A right angle: sin(45 deg) = 0.7071; v^2 = a * d * s / (1 - s).
  const auto corner = plan({feed_line({0, 0, 0}, {10, 0, 0}, 10), feed_line({10, 0, 0}, {10, 10, 0}, 10)}, limits);
  const double s = std::sqrt(0.5);
  EXPECT_NEAR(corner[0].exit_speed, std::sqrt(100 * 0.01 * s / (1 - s)), 1e-12);
  // Reversal: a full stop.
  const auto back = plan({feed_line({0, 0, 0}, {10, 0, 0}, 10), feed_line({10, 0, 0}, {0, 0, 0}, 10)}, limits);
  EXPECT_EQ(back[0].exit_speed, 0);
}

TEST(Planner, ArcsAreLimitedByCentripetalAcceleration) {
  MachineLimits limits;
  limits.acceleration = 100;
  Motion arc;
  arc.kind = MotionKind::arc;
  arc.start = {1, 0, 0};
  arc.end = {-1, 0, 0};
  arc.center = {0, 0, 0};
  arc.feed = 1000;
  const auto blocks = plan({arc}, limits);
  ASSERT_EQ(blocks.size(), 1u);
  EXPECT_LE(blocks[0].cruise_speed, std::sqrt(100 * 1.0) + 1e-12);
  EXPECT_NEAR(blocks[0].length, M_PI, 1e-12);
}

TEST(Planner, ADwellStopsTheMachineAndAddsItsTime) {
  MachineLimits limits;
  limits.acceleration = 100;
  Motion dwell;
  dwell.kind = MotionKind::dwell;
  dwell.duration = 2.5;
  const auto blocks =
      plan({feed_line({0, 0, 0}, {10, 0, 0}, 10), dwell, feed_line({10, 0, 0}, {20, 0, 0}, 10)}, limits);
  ASSERT_EQ(blocks.size(), 3u);
  EXPECT_EQ(blocks[0].exit_speed, 0);
  EXPECT_EQ(blocks[1].duration, 2.5);
  EXPECT_EQ(blocks[2].entry_speed, 0);
}

TEST(Planner, ALongerLookaheadOnlyShortensTheProgram) {
  std::vector<Motion> zigzag;
  Vec3 at{};
  for (int i = 0; i < 300; ++i) {
    const Vec3 next{at.x + 0.5, (i % 2) ? 0.0 : 0.05, 0};
    zigzag.push_back(feed_line(at, next, 50));
    at = next;
  }
  double previous = INFINITY;
  for (std::size_t window : {1u, 4u, 16u, 256u}) {
    MachineLimits limits;
    limits.acceleration = 200;
    limits.lookahead = window;
    double total = 0;
    for (const PlannedBlock& b : plan(zigzag, limits)) {
      total += b.duration;
      // Every block's speeds are reachable within it.
      EXPECT_LE(b.exit_speed * b.exit_speed, b.entry_speed * b.entry_speed + 2 * 200 * b.length + 1e-9);
      EXPECT_LE(b.entry_speed * b.entry_speed, b.exit_speed * b.exit_speed + 2 * 200 * b.length + 1e-9);
    }
    EXPECT_LE(total, previous + 1e-9) << window;
    previous = total;
  }
}

}  // namespace

// Per-axis limits, worked by hand: on a line at 45 degrees in XY each axis
// carries cos 45 of the path's speed and acceleration, so an X limit of
// 10 mm/s and 100 mm/s^2 allows 10/cos45 = 14.142 mm/s and 141.42 mm/s^2
// along the path. 100 mm long: 100/14.142 s cruising plus v/a = 0.1 s.
TEST(Planner, AxisLimitsCapSpeedAndAccelerationByTheAxisShare) {
  MachineLimits limits;
  limits.acceleration = 1000;
  limits.max_speed = 1000;
  limits.axis_speed = {10, 1000, 1000};
  limits.axis_acceleration = {100, 1000, 1000};
  const double side = 100 / std::sqrt(2.0);
  const auto blocks = plan({feed_line({0, 0, 0}, {side, side, 0}, 100)}, limits);
  ASSERT_EQ(blocks.size(), 1u);
  EXPECT_NEAR(blocks[0].cruise_speed, 10 * std::sqrt(2.0), 1e-9);
  EXPECT_NEAR(blocks[0].acceleration, 100 * std::sqrt(2.0), 1e-9);
  EXPECT_NEAR(blocks[0].duration, 100 / (10 * std::sqrt(2.0)) + 0.1, 1e-9);
  EXPECT_TRUE(blocks[0].feed_capped);
  // Along Y only, X's limits do not apply.
  const auto along_y = plan({feed_line({0, 0, 0}, {0, 100, 0}, 100)}, limits);
  EXPECT_NEAR(along_y[0].cruise_speed, 100, 1e-9);
  EXPECT_NEAR(along_y[0].acceleration, 1000, 1e-9);
  EXPECT_FALSE(along_y[0].feed_capped);
}

// G0 runs at what the slowest axis it uses allows, and that is no "cap"
// of a programmed feed.
TEST(Planner, RapidsRunAtTheAxisLimit) {
  MachineLimits limits;
  limits.acceleration = 100;
  limits.rapid_speed = 100;
  limits.axis_speed = {1000, 1000, 5};
  Motion rapid = feed_line({0, 0, 0}, {0, 0, -10}, 0);
  rapid.kind = MotionKind::rapid;
  const auto blocks = plan({rapid}, limits);
  EXPECT_NEAR(blocks[0].cruise_speed, 5, 1e-12);
  EXPECT_NEAR(blocks[0].duration, 10.0 / 5 + 5.0 / 100, 1e-9);
  EXPECT_FALSE(blocks[0].feed_capped);
}

// A helix rising 2*pi*10 mm over one turn of radius 10 is at 45 degrees:
// the plane's axes carry cos 45 at most, Z sin 45.
TEST(Planner, HelixSharesItsSpeedBetweenPlaneAndRise) {
  MachineLimits limits;
  limits.acceleration = 1e6;
  limits.max_speed = 1000;
  limits.axis_speed = {1000, 1000, 3};
  Motion helix;
  helix.kind = MotionKind::arc;
  helix.start = {10, 0, 0};
  helix.end = {10, 0, 2 * M_PI * 10};
  helix.center = {0, 0, 0};
  helix.feed = 600;
  const auto blocks = plan({helix}, limits);
  ASSERT_EQ(blocks.size(), 1u);
  EXPECT_NEAR(blocks[0].length, 2 * M_PI * 10 * std::sqrt(2.0), 1e-9);
  EXPECT_NEAR(blocks[0].cruise_speed, 3 * std::sqrt(2.0), 1e-9);
}

TEST(Planner, RefusesNonPositiveAxisLimits) {
  MachineLimits limits;
  limits.axis_speed = {10, 0, 10};
  EXPECT_THROW(Planner{limits}, tk::Error);
  limits.axis_speed = {10, 10, 10};
  limits.axis_acceleration = {10, 10, -1};
  EXPECT_THROW(Planner{limits}, tk::Error);
}
