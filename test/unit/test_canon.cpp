/// @file test_canon.cpp
/// @brief rs274's canonical commands to motions (hand-computed positions),
/// LinuxCNC tool tables, and G43/G43.1/G49/G53 in our own interpreter.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

#include "gcode_program.hpp"
#include "io/error.hpp"
#include "motion/canon.hpp"
#include "motion/tool_table.hpp"

using namespace tk::motion;

using gcode_test::expect_point;

namespace {

std::vector<Motion> canon(const std::string& stream, CanonInterpreter& interpreter) {
  std::vector<Motion> motions;
  std::istringstream in(stream);
  std::string text;
  for (std::size_t line = 1; std::getline(in, text); ++line) interpreter.execute(text, line, motions);
  return motions;
}

std::string canon_error(const std::string& stream, InterpreterOptions options = {}) {
  try {
    CanonInterpreter interpreter(options);
    canon(stream, interpreter);
  } catch (const tk::Error& e) {
    return e.what();
  }
  return {};
}

}  // namespace

TEST(Canon, ReadsRs274LinesWithAndWithoutTheirCounterAndUnits) {
  CanonInterpreter c;
  const auto m = canon(
      "    1 N..... USE_LENGTH_UNITS(CANON_UNITS_INCHES)\n"
      "\n"
      "   12 N0010  SET_FEED_RATE(10.0000)\n"
      "STRAIGHT_FEED(1.0000, 2.0000, -0.5000, 0.0000, 0.0000, 0.0000)\n"
      "   14 N..... STRAIGHT_TRAVERSE(1.0000, 2.0000, -0.5000, 0.0000, 0.0000, 0.0000)\n"  // goes nowhere
      "   15 N..... COMMENT(\"a (comment) with, commas\")\n"
      "   16 N..... DWELL(1.5000)\n",
      c);
  ASSERT_EQ(m.size(), 2u);
  EXPECT_EQ(m[0].kind, MotionKind::linear);
  expect_point(m[0].end, 25.4, 50.8, -12.7);
  EXPECT_NEAR(m[0].feed, 254.0 / 60, 1e-12);  // 10 in/min in mm/s
  EXPECT_EQ(m[0].source_line, 4u);
  EXPECT_EQ(m[1].kind, MotionKind::dwell);
  EXPECT_EQ(m[1].duration, 1.5);
  EXPECT_EQ(c.unused_words().at("COMMENT"), 1u);
  EXPECT_EQ(c.blocks(), 6u);
}

// Machine = R(θ)(p + G92) + G5x + tool: rs274's G10 L2 P1 X5 R30 then G92 X1
// from machine (1, 0): G92 X = -4.4641 (printed by rs274), and X0 Y0 is
// then R(30°)(-4.4641, 0) + (5, 0).
TEST(Canon, OffsetsRotationAndToolLengthMapToMachineCoordinates) {
  CanonInterpreter c;
  const auto m = canon(
      "SET_G5X_OFFSET(1, 5.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)\n"
      "SET_XY_ROTATION(30.0000)\n"
      "SET_G92_OFFSET(-4.4641, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)\n"
      "USE_TOOL_LENGTH_OFFSET(0.0000 0.0000 12.5000, 0.0000 0.0000 0.0000, 0.0000 0.0000 0.0000)\n"
      "STRAIGHT_TRAVERSE(0.0000, 0.0000, -5.0000, 0.0000, 0.0000, 0.0000)\n",
      c);
  ASSERT_EQ(m.size(), 1u);
  const double t = std::numbers::pi / 6;
  expect_point(m[0].end, 5 - 4.4641 * std::cos(t), -4.4641 * std::sin(t), 7.5);
}

TEST(Canon, ArcsTakeTheirPlaneDirectionAndTurns) {
  CanonInterpreter c;
  const auto m = canon(
      "SET_FEED_RATE(60.0000)\n"
      "STRAIGHT_FEED(10.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)\n"
      "ARC_FEED(0.0000, 10.0000, 0.0000, 0.0000, 1, 2.0000, 0.0000, 0.0000, 0.0000)\n"  // XY, CCW, helix
      "SELECT_PLANE(CANON_PLANE_XZ)\n"
      // first = Z, second = X: from (0, 10, 2) around Z = 2, X = 5, clockwise, 3 turns
      "ARC_FEED(2.0000, 0.0000, 2.0000, 5.0000, -3, 10.0000, 0.0000, 0.0000, 0.0000)\n",
      c);
  ASSERT_EQ(m.size(), 3u);
  EXPECT_EQ(m[1].kind, MotionKind::arc);
  EXPECT_FALSE(m[1].clockwise);
  EXPECT_EQ(m[1].turns, 0u);
  expect_point(m[1].end, 0, 10, 2);
  expect_point(m[1].center, 0, 0, 0);
  EXPECT_EQ(m[2].axis0, 2);
  EXPECT_EQ(m[2].axis1, 0);
  EXPECT_EQ(m[2].axis2, 1);
  EXPECT_TRUE(m[2].clockwise);
  EXPECT_EQ(m[2].turns, 2u);
  expect_point(m[2].end, 0, 10, 2);
  expect_point(m[2].center, 5, 10, 2);
}

TEST(Canon, SpindleFollowingMovesAndRigidTapping) {
  CanonInterpreter c;
  const auto m = canon(
      "SET_SPINDLE_SPEED(0, 600.0000)\n"
      "START_SPINDLE_CLOCKWISE(0)\n"
      "START_SPEED_FEED_SYNC(1.500000,0)\n"
      "STRAIGHT_FEED(0.0000, 0.0000, -20.0000, 0.0000, 0.0000, 0.0000)\n"
      "RIGID_TAP(0.0000, 0.0000, -30.0000)\n"
      "STOP_SPEED_FEED_SYNCH()\n"
      "SET_FEED_MODE(0, 1)\n"
      "SET_FEED_RATE(0.1000)\n"
      "STRAIGHT_FEED(5.0000, 0.0000, -20.0000, 0.0000, 0.0000, 0.0000)\n",
      c);
  ASSERT_EQ(m.size(), 4u);
  EXPECT_TRUE(m[0].spindle_synchronised);
  EXPECT_NEAR(m[0].feed, 1.5 * 600 / 60, 1e-12);
  expect_point(m[1].end, 0, 0, -30);  // in, then back out where it started
  expect_point(m[2].start, 0, 0, -30);
  expect_point(m[2].end, 0, 0, -20);
  EXPECT_TRUE(m[2].spindle_synchronised);
  EXPECT_FALSE(m[3].spindle_synchronised);  // G95: a speed, not a position, follows the spindle
  EXPECT_NEAR(m[3].feed, 0.1 * 600 / 60, 1e-12);
  EXPECT_NE(canon_error("START_SPEED_FEED_SYNC(1.0,0)\nSTRAIGHT_FEED(1, 0, 0, 0, 0, 0)").find("spindle stopped"),
            std::string::npos);
}

TEST(Canon, AHelixOfNoRadiusIsTheLineAlongItsAxis) {
  CanonInterpreter c;
  const auto m =
      canon("SET_FEED_RATE(60)\nARC_FEED(0.0000, 0.0000, 0.0000, 0.0000, 1, -2.0000, 0.0000, 0.0000, 0.0000)\n", c);
  ASSERT_EQ(m.size(), 1u);
  EXPECT_EQ(m[0].kind, MotionKind::linear);
  expect_point(m[0].end, 0, 0, -2);
}

TEST(Canon, RefusesWhatItCannotStepAndStopsAtProgramEnd) {
  EXPECT_EQ(canon_error("STRAIGHT_FEED(1, 2)"), "STRAIGHT_FEED takes 6 or 9 arguments, not 2");
  EXPECT_EQ(canon_error("SET_FEED_RATE(1)\nSTRAIGHT_FEED(1, 2, x, 0, 0, 0)"), "bad number 'x'");
  EXPECT_EQ(canon_error("SET_FEED_RATE(nan)"), "bad number 'nan'");
  EXPECT_EQ(canon_error("STRAIGHT_FEED(1, 0, 0, 0, 0, 0)"), "a feed move at feed rate 0");
  EXPECT_NE(canon_error("G1 X1 F100").find("not a canonical command"), std::string::npos);
  EXPECT_NE(canon_error("   12 STRAIGHT_FEED(1, 0, 0, 0, 0, 0)").find("without an N field"), std::string::npos);
  EXPECT_NE(canon_error("NURBS_FEED(3, ...)").find("NURBS_FEED"), std::string::npos);
  EXPECT_EQ(canon_error("FROBNICATE()"), "canonical command FROBNICATE is not supported");
  EXPECT_EQ(canon_error("STRAIGHT_TRAVERSE(0, 0, 0, 0, 45.0, 0)"),
            "STRAIGHT_TRAVERSE moves the B axis to 45: gcode-pulse steps X, Y and Z only");
  EXPECT_NE(canon_error("SET_FEED_RATE(1)\nARC_FEED(10, 0, 0, 0, 1, 0, 0, 0, 0)").find("radius"), std::string::npos);
  EXPECT_NE(canon_error("STRAIGHT_TRAVERSE(2e6, 0, 0, 0, 0, 0)").find("beyond"), std::string::npos);

  InterpreterOptions lenient;
  lenient.lenient = true;
  std::vector<std::string> warnings;
  CanonInterpreter c(lenient);
  c.on_warning([&](const std::string& w) { warnings.push_back(w); });
  const auto m = canon(
      "STRAIGHT_TRAVERSE(1, 0, 0, 90, 0, 0)\nFROBNICATE()\nPROGRAM_END()\nSTRAIGHT_TRAVERSE(9, 9, 9, 0, 0, 0)\n", c);
  ASSERT_EQ(m.size(), 1u);
  EXPECT_EQ(warnings.size(), 2u);
  EXPECT_TRUE(c.program_ended());
  expect_point(c.position(), 1, 0, 0);
}

TEST(ToolTable, ReadsLinuxCncTablesAndRefusesBadLines) {
  const std::string path = testing::TempDir() + "tools.tbl";
  std::ofstream(path) << ";tools\nT1 P1 Z12.5 D6 ;first\n\nT7 P2 X-1 Z0.25 I0 J0 Q1 (lathe)\n";
  const ToolTable table = read_tool_table(path);
  ASSERT_EQ(table.size(), 2u);
  expect_point(table.at(1), 0, 0, 12.5);
  expect_point(table.at(7), -1, 0, 0.25);
  const auto error = [&](const std::string& text) {
    std::ofstream(path) << text;
    try {
      read_tool_table(path);
    } catch (const tk::Error& e) {
      return e.located_message();
    }
    return std::string();
  };
  EXPECT_EQ(error("T1 Z1\nP3 Z2\n"), path + ":2: a tool without its T word");
  EXPECT_EQ(error("T1 Z1\nT1 Z2\n"), path + ":2: tool T1 given twice");
  EXPECT_EQ(error("T1.5 Z1\n"), path + ":1: T1.5: a tool number is a whole number, 0 or more");
  EXPECT_EQ(error("T1 R3\n"), path + ":1: 'R' is no tool table word (T, P, X, Y, Z, D, I, J, Q...)");
  EXPECT_EQ(error(";nothing\n"), path + ":1: no tool in the tool table");
}

// LinuxCNC: G43 moves nothing; the next move of an axis ends at its
// coordinate plus the offset; G53 coordinates are the machine's.
TEST(GcodeInterpreter, ToolLengthOffsetsAsLinuxCncAppliesThem) {
  InterpreterOptions options;
  options.has_tool_table = true;
  options.tool_table = {{3, Vec3{0, 0, 10}}, {7, Vec3{1, 0, 20}}};
  GcodeInterpreter interpreter(options);
  const auto m = gcode_test::run(
      "T3 M6\nG43\nG0 X5\nG0 Z1\nG43 H7\nG0 X0 Z0\nG2 X2 Y0 I1 J0 F60\nG91 G0 Z1\nG90 G43.1 Z-2\nG0 Z0\n"
      "G53 G0 Z3\nG49\nG0 Z0\n",
      interpreter);
  ASSERT_EQ(m.size(), 8u);
  expect_point(m[0].end, 5, 0, 0);      // X alone: Z stays
  expect_point(m[1].end, 5, 0, 11);     // Z1 + 10
  expect_point(m[2].end, 1, 0, 20);     // tool 7: X + 1, Z + 20
  expect_point(m[3].center, 2, 0, 20);  // incremental centre from the start
  expect_point(m[3].end, 3, 0, 20);
  expect_point(m[4].end, 3, 0, 21);  // G91: no offset added
  expect_point(m[5].end, 3, 0, -2);  // G43.1 Z-2 (X keeps tool 7's, as rs274 does)
  expect_point(m[6].end, 3, 0, 3);   // G53: the machine's Z3
  expect_point(m[7].end, 3, 0, 0);
  EXPECT_NE(gcode_test::error_of("G43 H1").find("--tool-table"), std::string::npos);
  EXPECT_EQ(gcode_test::error_of("T0 M6 G43\nG43 H0\nG0 X1"), "");
  EXPECT_EQ(gcode_test::error_of("G91 G53 G0 X1"), "G53 in incremental distance mode (G91)");
  EXPECT_EQ(gcode_test::error_of("G53 G2 X1 R1 F10"), "G53 needs G0 or G1 motion");
  EXPECT_EQ(gcode_test::error_of("G43 H2", options), "G43: tool 2 is not in the tool table");
}
