/// @file test_toolpath_arcs.cpp
/// @brief Which arcs toolpath_gcode writes as G1 (dxf2region(1), TOOLPATH):
/// sagitta within half the printed micrometre, or a sweep under 1e-5 rad as
/// the printed numbers give it (LinuxCNC cuts a whole circle under 1e-6).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

#include "cad/loops.hpp"
#include "cad/toolpath.hpp"

namespace {

using tk::cad::Loop;
using tk::cad::Point;
using tk::cad::Segment;

/// The one motion block that toolpath_gcode writes for a loop holding only
/// the arc round (cx, cy), radius r, from angle a over `sweep` (signed).
std::string written_arc(double cx, double cy, double r, double a, double sweep) {
  Segment arc;
  arc.start = {cx + r * std::cos(a), cy + r * std::sin(a)};
  arc.end = {cx + r * std::cos(a + sweep), cy + r * std::sin(a + sweep)};
  arc.bulge = std::tan(sweep / 4);
  Loop loop;
  loop.segments = {arc};
  tk::cad::ToolpathOptions options;
  options.climb = false;  // as drawn
  std::istringstream lines(tk::cad::toolpath_gcode({loop}, options));
  std::string line, motion;
  while (std::getline(lines, line))
    if (line.rfind("G1 X", 0) == 0 || line.rfind("G2 ", 0) == 0 || line.rfind("G3 ", 0) == 0) motion += line;
  return motion.substr(0, 2);
}

/// The sweep whose sagitta r (1 - cos(sweep / 2)) is `sagitta`.
double sweep_for_sagitta(double r, double sagitta) { return 2 * std::acos(1 - sagitta / r); }

}  // namespace

TEST(ToolpathArcs, NanometreArcBecomesALine) {
  // edgeminer's corner at tool radius 20: 9.6e-7 rad, 19 nm long.
  EXPECT_EQ(written_arc(10, 10, 20, 0.3, -9.6e-7), "G1");
  EXPECT_EQ(written_arc(10, 10, 20, 0.3, 4e-7), "G1");
}

TEST(ToolpathArcs, SagittaWithinHalfAMicrometreIsALine) {
  EXPECT_EQ(written_arc(0, 0, 1, 0.2, sweep_for_sagitta(1, 0.4e-6)), "G1");
  EXPECT_EQ(written_arc(0, 0, 1, 0.2, sweep_for_sagitta(1, 0.7e-6)), "G3");
  EXPECT_EQ(written_arc(0, 0, 1, 0.2, -sweep_for_sagitta(1, 0.7e-6)), "G2");
}

TEST(ToolpathArcs, ShortSweepOfAHugeArcIsALine) {
  // Radius 100 km, 8e-6 rad: 800 mm long, sagitta 0.8 µm; at 2e-5 rad, 5 µm.
  EXPECT_EQ(written_arc(0, 0, 1e8, 1, 8e-6), "G1");
  EXPECT_EQ(written_arc(0, 0, 1e8, 1, 2e-5), "G3");
}

TEST(ToolpathArcs, HalfAndNearlyWholeCirclesStayArcs) {
  EXPECT_EQ(written_arc(60, 30, 2, std::numbers::pi / 2, std::numbers::pi), "G3");
  EXPECT_EQ(written_arc(60, 30, 2, -std::numbers::pi / 2, -std::numbers::pi), "G2");
  EXPECT_EQ(written_arc(0, 0, 5, 0, 2 * std::numbers::pi - 1e-3), "G3");
}
