/// @file test_gcode_threading.cpp
/// @brief Lathe work in the G-code interpreter and planner: G33
/// spindle-synchronised motion (speed K times S along the drive line,
/// LinuxCNC's errors, the start from rest) and G7/G8 diameter and radius
/// modes. Expected values are worked out by hand in the comments.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "gcode_program.hpp"
#include "io/error.hpp"
#include "motion/gcode.hpp"
#include "motion/planner.hpp"

using namespace tk::motion;

namespace {

using gcode_test::error_of;
using gcode_test::run;

void expect_exact_point(const Vec3& actual, double x, double y, double z, double tolerance = 1e-12) {
  EXPECT_NEAR(actual.x, x, tolerance);
  EXPECT_NEAR(actual.y, y, tolerance);
  EXPECT_NEAR(actual.z, z, tolerance);
}

/// Plans the motions with `limits` and returns the blocks in order.
std::vector<PlannedBlock> plan(const std::vector<Motion>& motions, const MachineLimits& limits) {
  std::vector<PlannedBlock> blocks;
  Planner planner(limits);
  const Planner::Sink keep = [&blocks](const PlannedBlock& block) { blocks.push_back(block); };
  for (const Motion& motion : motions) planner.add(motion, keep);
  planner.finish(keep);
  return blocks;
}

double total_duration(const std::vector<PlannedBlock>& blocks) {
  double seconds = 0;
  for (const PlannedBlock& block : blocks) seconds += block.duration;
  return seconds;
}

}  // namespace

// ---- G33: speed, modality, units ------------------------------------------

TEST(GcodeThreading, G33MovesAtKTimesTheSpindleSpeed) {
  const auto m = run("G21 G90 G18\nS300 M3\nG0 X10 Z2\nG33 Z-20 K2");
  ASSERT_EQ(m.size(), 2u);
  const Motion& thread = m[1];
  EXPECT_EQ(thread.kind, MotionKind::linear);
  EXPECT_TRUE(thread.spindle_synchronised);
  EXPECT_FALSE(m[0].spindle_synchronised);
  expect_exact_point(thread.start, 10, 0, 2);
  expect_exact_point(thread.end, 10, 0, -20);
  // 2 mm per revolution at 300 rpm: 600 mm/min, 10 mm/s.
  EXPECT_DOUBLE_EQ(thread.feed, 10.0);
  EXPECT_FALSE(thread.inverse_time);
}

TEST(GcodeThreading, G33IsModalButEveryBlockNeedsItsK) {
  GcodeInterpreter interpreter;
  const auto m = run("S120 M4\nG33 Z-10 K1.5\nZ-20 K3\nG0 X5", interpreter);
  ASSERT_EQ(m.size(), 3u);
  EXPECT_TRUE(m[1].spindle_synchronised);  // no G word: still G33
  expect_exact_point(m[1].end, 0, 0, -20);
  EXPECT_DOUBLE_EQ(m[0].feed, 1.5 * 120 / 60);  // 3 mm/s
  EXPECT_DOUBLE_EQ(m[1].feed, 3.0 * 120 / 60);  // 6 mm/s: each block's own K
  EXPECT_FALSE(m[2].spindle_synchronised);
  // LinuxCNC: "K word missing with G33" on a modal G33 block too.
  EXPECT_EQ(error_of("S120 M3\nG33 Z-10 K1.5\nZ-20"), "G33 without a K word (distance per spindle revolution)");
}

TEST(GcodeThreading, KIsMeasuredAlongTheDriveLine) {
  // A taper from X10 Z0 to X13 Z-20 (radius words, G8): the line is
  // sqrt(3^2 + 20^2) = sqrt(409) mm long. K1.5 at S400 moves the tool
  // 1.5 mm along that line per revolution: 10 mm/s on the path, so the
  // pass takes sqrt(409)/10 s and Z advances 1.5 * 20/sqrt(409) mm a turn.
  const auto m = run("S400 M3\nG0 X10\nG33 X13 Z-20 K1.5");
  ASSERT_EQ(m.size(), 2u);
  EXPECT_DOUBLE_EQ(m[1].feed, 10.0);
  const double length = std::hypot(m[1].end.x - m[1].start.x, m[1].end.z - m[1].start.z);
  EXPECT_NEAR(length, std::sqrt(409.0), 1e-12);
  const double revolutions = length / 1.5;
  EXPECT_NEAR(20 / revolutions, 1.5 * 20 / std::sqrt(409.0), 1e-12);
  EXPECT_LT(20 / revolutions, 1.5);  // less than K per turn along Z
}

TEST(GcodeThreading, KFollowsTheUnitsSDoesNot) {
  // 16 TPI: K0.0625 in = 1.5875 mm a turn; S600 stays rpm: 15.875 mm/s.
  const auto m = run("G20 S600 M3\nG33 Z-1 K0.0625");
  ASSERT_EQ(m.size(), 1u);
  EXPECT_DOUBLE_EQ(m[0].feed, 0.0625 * 25.4 * 600 / 60);
  expect_exact_point(m[0].end, 0, 0, -25.4);
}

TEST(GcodeThreading, FeedRateAndFeedModePlayNoPart) {
  // The modal F survives the G33 for the G1 after it.
  const auto m = run("G1 X1 F100\nS300 M3\nG33 Z-5 K1\nG1 X2");
  ASSERT_EQ(m.size(), 3u);
  EXPECT_DOUBLE_EQ(m[1].feed, 1.0 * 300 / 60);
  EXPECT_DOUBLE_EQ(m[2].feed, 100.0 / 60);
  // G93 needs an F on each G1; G33 takes none and is no inverse-time move.
  const auto inverse = run("G93\nS600 M3\nG33 Z-10 K1");
  ASSERT_EQ(inverse.size(), 1u);
  EXPECT_FALSE(inverse[0].inverse_time);
  EXPECT_DOUBLE_EQ(inverse[0].feed, 10.0);
}

TEST(GcodeThreading, TheSpindleCanStartOnTheG33Line) {
  // LinuxCNC sets S and starts the spindle before the motion of a block.
  const auto m = run("G33 Z-4 K0.5 S240 M3");
  ASSERT_EQ(m.size(), 1u);
  EXPECT_DOUBLE_EQ(m[0].feed, 2.0);
  // A G33 block that goes nowhere makes no motion but is still checked.
  EXPECT_TRUE(run("S100 M3\nG33 Z0 K1").empty());
  EXPECT_EQ(error_of("S100 M3\nG33 Z0"), "G33 without a K word (distance per spindle revolution)");
}

TEST(GcodeThreading, Errors) {
  EXPECT_EQ(error_of("S300 M3\nG33 Z-20"), "G33 without a K word (distance per spindle revolution)");
  EXPECT_EQ(error_of("S300 M3\nG33 Z-20 K0"), "G33 K0: the distance per spindle revolution must be positive");
  EXPECT_EQ(error_of("S300 M3\nG33 Z-20 K-1.5"), "G33 K-1.5: the distance per spindle revolution must be positive");
  EXPECT_EQ(error_of("S300 M3\nG33 Z-20 K2 F100"),
            "F100 with G33: its speed follows the spindle (K per revolution), not a feed rate");
  EXPECT_EQ(error_of("S300\nG33 Z-20 K2"), "G33 with the spindle stopped (M3 or M4 starts it)");
  EXPECT_EQ(error_of("S300 M3\nM5\nG33 Z-20 K2"), "G33 with the spindle stopped (M3 or M4 starts it)");
  EXPECT_EQ(error_of("G33 Z-20 K2 S300 M3 M5"), "M3 and M5 are both in the spindle group");
  EXPECT_EQ(error_of("M3\nG33 Z-20 K2"), "G33 without a spindle speed (S0, or no S word yet)");
  EXPECT_EQ(error_of("S0 M3\nG33 Z-20 K2"), "G33 without a spindle speed (S0, or no S word yet)");
  EXPECT_EQ(error_of("G96 D2000 S200 M3\nG33 Z-20 K2"),
            "G33 in constant surface speed mode (G96): S is no spindle speed in rpm (G97 selects rpm)");
  EXPECT_EQ(error_of("G96 D2000 S200 M3\nG97 S300\nG33 Z-20 K2"), "");
  EXPECT_EQ(error_of("S300 M3\nG33 K2"), "G33 without X, Y or Z words (it needs an end point)");
  EXPECT_EQ(error_of("S300 M3\nG33"), "G33 without X, Y or Z words (it needs an end point)");
  EXPECT_EQ(error_of("S-300"), "negative spindle speed S-300");
  // K on a line in G33 mode that does not move is used by nothing.
  EXPECT_EQ(error_of("S300 M3\nG33 Z-1 K1\nK1"), "K1: nothing on the line uses the K word");
  // Rigid tapping stays unsupported.
  EXPECT_EQ(error_of("S300 M3\nG33.1 Z-5 K1"), "G33.1 (rigid tapping) is not supported");
}

TEST(GcodeThreading, SpindleSpeedIsNoLongerAnUnusedWordTheMCodesStillAre) {
  GcodeInterpreter interpreter;
  run("S1000 M3\nG1 X1 F100 S2000\nM5", interpreter);
  const std::map<std::string, std::uint64_t> expected = {{"M3", 1}, {"M5", 1}};
  EXPECT_EQ(interpreter.unused_words(), expected);
}

// ---- G7 / G8 ----------------------------------------------------------------

TEST(GcodeThreading, DiameterModeHalvesXWords) {
  GcodeInterpreter interpreter;
  const auto m =
      run("G0 X20\n"        // G8 by default: radius 20
          "G7 X20 Z-1\n"    // G7 applies to its own line: radius 10
          "X30 Y4\n"        // Y and Z are not diameters
          "G91 X-4\n"       // incremental: the word is halved too, -2 mm
          "G8 X3\n"         // radius mode again: +3 mm
          "G90 G7 G20 X1",  // 1 in diameter: 12.7 mm radius
          interpreter);
  ASSERT_EQ(m.size(), 6u);
  expect_exact_point(m[0].end, 20, 0, 0);
  expect_exact_point(m[1].end, 10, 0, -1);
  expect_exact_point(m[2].end, 15, 4, -1);
  expect_exact_point(m[3].end, 13, 4, -1);
  expect_exact_point(m[4].end, 16, 4, -1);
  expect_exact_point(m[5].end, 12.7, 4, -1);
  expect_exact_point(interpreter.position(), 12.7, 4, -1);
  EXPECT_EQ(error_of("G7 G8"), "G7 and G8 are both in the lathe diameter mode group");
  EXPECT_TRUE(interpreter.unused_words().empty());  // G7 and G8 act
}

TEST(GcodeThreading, DiameterModeLeavesArcCentreWordsAndRRadii) {
  // G18, G7: start X10 (diameter) = radius 5, Z0; end X20 (radius 10) Z-5.
  // With I5 K0 as a radius offset the centre is X10 Z0, 5 from both ends.
  // Were I halved (2.5), the centre X7.5 Z0 would be 2.5 from the start
  // and sqrt(2.5^2 + 5^2) from the end: an error.
  const auto m = run("G18 G90 G7\nG0 X10 Z0\nG2 X20 Z-5 I5 K0 F100");
  ASSERT_EQ(m.size(), 2u);
  expect_exact_point(m[1].start, 5, 0, 0);
  expect_exact_point(m[1].end, 10, 0, -5);
  expect_exact_point(m[1].center, 10, 0, 0);
  // R5 from (5, 0) to (10, -5): a chord of sqrt(50) = 7.07 mm fits a
  // radius of 5 (it would not fit 2.5); the centre lies 5 from both ends.
  const auto r = run("G18 G90 G7\nG0 X10 Z0\nG2 X20 Z-5 R5 F100");
  ASSERT_EQ(r.size(), 2u);
  const auto distance = [](const Vec3& a, const Vec3& b) { return std::hypot(a.x - b.x, a.z - b.z); };
  EXPECT_NEAR(distance(r[1].center, r[1].start), 5, 1e-12);
  EXPECT_NEAR(distance(r[1].center, r[1].end), 5, 1e-12);
}

TEST(GcodeThreading, G33InDiameterMode) {
  // A taper pass from diameter 10 to 12 over Z-10: X radius 5 to 6.
  const auto m = run("G7 S500 M3\nG0 X10 Z0\nG33 X12 Z-10 K1");
  ASSERT_EQ(m.size(), 2u);
  expect_exact_point(m[1].start, 5, 0, 0);
  expect_exact_point(m[1].end, 6, 0, -10);
  EXPECT_DOUBLE_EQ(m[1].feed, 1.0 * 500 / 60);  // K is not halved
}

// ---- planning -----------------------------------------------------------------

TEST(GcodeThreading, APassAcceleratesLikeAnyMoveFromRestToRest) {
  // G33 Z-20 K2 at S300: 10 mm/s. With 500 mm/s^2 the tool needs 10/500 =
  // 0.02 s and 0.1 mm to reach it, as long to stop: 0.04 s and 0.2 mm, and
  // 19.8 mm of cruise at 10 mm/s = 1.98 s. In all 20/10 + 10/500 = 2.02 s.
  MachineLimits limits;
  limits.acceleration = 500;
  const auto blocks = plan(run("S300 M3\nG33 Z-20 K2"), limits);
  ASSERT_EQ(blocks.size(), 1u);
  EXPECT_DOUBLE_EQ(blocks[0].cruise_speed, 10.0);
  EXPECT_NEAR(blocks[0].cruise_ends - blocks[0].cruise_starts, 1.98, 1e-12);
  EXPECT_NEAR(blocks[0].duration, 2.02, 1e-12);
  EXPECT_FALSE(blocks[0].feed_capped);
}

TEST(GcodeThreading, APassStartsFromRestAfterAMoveThatDoesNotFollowTheSpindle) {
  // G1 Z-0.5 at F600 (10 mm/s) straight into G33 Z-20.5 at 10 mm/s. As
  // plain moves they would join at full speed: 20.5/10 + 10/500 = 2.07 s.
  // The control stops for the spindle's index between them: G1 0.5/10 +
  // 10/500 = 0.07 s, then G33 2.02 s: 2.09 s.
  MachineLimits limits;
  limits.acceleration = 500;
  const auto blocks = plan(run("S300 M3\nG1 Z-0.5 F600\nG33 Z-20.5 K2"), limits);
  ASSERT_EQ(blocks.size(), 2u);
  EXPECT_EQ(blocks[0].exit_speed, 0.0);
  EXPECT_EQ(blocks[1].entry_speed, 0.0);
  EXPECT_NEAR(total_duration(blocks), 2.09, 1e-12);
  // The same path with G1 only: 2.07 s.
  EXPECT_NEAR(total_duration(plan(run("G1 Z-0.5 F600\nZ-20.5"), limits)), 2.07, 1e-12);
  // G33 after G33 stays locked to the spindle and joins at speed: 2.07 s.
  const auto locked = plan(run("S300 M3\nG33 Z-0.5 K2\nG33 Z-20.5 K2"), limits);
  ASSERT_EQ(locked.size(), 2u);
  EXPECT_DOUBLE_EQ(locked[1].entry_speed, 10.0);
  EXPECT_NEAR(total_duration(locked), 2.07, 1e-12);
  // Leaving the thread is an ordinary junction: G33 then a collinear G1.
  const auto out = plan(run("S300 M3\nG33 Z-20 K2\nG1 Z-20.5 F600"), limits);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_DOUBLE_EQ(out[0].exit_speed, 10.0);
}

TEST(GcodeThreading, MachineSpeedCapAlongALine) {
  MachineLimits limits;
  limits.max_speed = 100;
  limits.rapid_speed = 200;
  limits.axis_speed = {50, MachineLimits::kNoLimit, 40};
  Motion along_z;
  along_z.end = Vec3{0, 0, -10};
  EXPECT_DOUBLE_EQ(machine_speed_cap(limits, along_z), 40.0);  // Z's own limit
  Motion taper;
  taper.end = Vec3{3, 0, -4};  // direction (0.6, 0, -0.8): X 50/0.6, Z 40/0.8 = 50
  EXPECT_DOUBLE_EQ(machine_speed_cap(limits, taper), 50.0);
  Motion along_y;
  along_y.end = Vec3{0, 10, 0};
  EXPECT_DOUBLE_EQ(machine_speed_cap(limits, along_y), 100.0);  // max_speed
  along_y.kind = MotionKind::rapid;
  EXPECT_DOUBLE_EQ(machine_speed_cap(limits, along_y), 200.0);  // rapid_speed
}
