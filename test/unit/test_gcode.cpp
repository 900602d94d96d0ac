/// @file test_gcode.cpp
/// @brief Unit tests for the G-code lexer and modal interpreter (the real
/// programs of the corpus: test_gcode_corpus.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <sstream>

#include "gcode_program.hpp"
#include "io/error.hpp"
#include "motion/gcode.hpp"

using namespace tk::motion;

namespace {

using gcode_test::error_of;
using gcode_test::expect_point;
using gcode_test::run;

#define EXPECT_ERROR(program, text)                                                       \
  do {                                                                                    \
    const std::string message_ = error_of(program);                                       \
    EXPECT_NE(message_.find(text), std::string::npos) << "program: " << (program) << "\n" \
                                                      << "error: '" << message_ << "'";   \
  } while (0)

}  // namespace

// ---- lexer ------------------------------------------------------------

TEST(GcodeLexer, PackedCaseInsensitiveWords) {
  const GcodeLine line = lex_gcode_line("g00G21g17 G90.1 n099\tx-.5 Y+1 z1. i.5");
  ASSERT_EQ(line.words.size(), 8u);  // N is dropped
  const std::string letters = "GGGGXYZI";
  const double values[] = {0, 21, 17, 90.1, -0.5, 1, 1, 0.5};
  for (std::size_t i = 0; i < line.words.size(); ++i) {
    EXPECT_EQ(line.words[i].letter, letters[i]);
    EXPECT_DOUBLE_EQ(line.words[i].value, values[i]);
  }
  // Blanks inside a word are ignored, as LinuxCNC does.
  const GcodeLine spaced = lex_gcode_line("G 1 X 1 2.5\r");
  ASSERT_EQ(spaced.words.size(), 2u);
  EXPECT_DOUBLE_EQ(spaced.words[1].value, 12.5);
}

TEST(GcodeLexer, CommentsMessagesPercentAndBlockDelete) {
  const GcodeLine commented = lex_gcode_line("G1 (move) X1 ; the rest (is ignored #");
  ASSERT_EQ(commented.words.size(), 2u);
  EXPECT_EQ(commented.words[1].letter, 'X');
  EXPECT_TRUE(commented.message.empty());
  EXPECT_EQ(lex_gcode_line("(MSG, Hello world )").message, "Hello world");
  EXPECT_EQ(lex_gcode_line("(msg,note axis positions)").message, "note axis positions");
  EXPECT_TRUE(lex_gcode_line("(message, not one)").message.empty());
  EXPECT_TRUE(lex_gcode_line("%").percent);
  EXPECT_TRUE(lex_gcode_line("  % (tape start)\r").percent);
  EXPECT_FALSE(lex_gcode_line("G1 X1").percent);
  const GcodeLine deleted = lex_gcode_line(" /G1 X1");
  EXPECT_TRUE(deleted.block_delete);
  EXPECT_EQ(deleted.words.size(), 2u);
  EXPECT_TRUE(lex_gcode_line("").words.empty());
  EXPECT_TRUE(lex_gcode_line(" \t(only a comment)\r").words.empty());
}

TEST(GcodeLexer, Errors) {
  const auto lex_error = [](const std::string& text) {
    try {
      lex_gcode_line(text);
    } catch (const tk::Error& error) {
      return std::string(error.what());
    }
    return std::string();
  };
  EXPECT_EQ(lex_error("G1 (open"), "unclosed comment");
  EXPECT_EQ(lex_error("(a (b) c)"), "nested comment");
  EXPECT_EQ(lex_error("G1 x1.2.3"), "bad number 'x1.2.3'");
  EXPECT_EQ(lex_error("X--1"), "bad number 'X--1'");
  EXPECT_EQ(lex_error("X1-2"), "bad number 'X1-2'");
  EXPECT_EQ(lex_error("X."), "bad number 'X.'");
  EXPECT_EQ(lex_error("G1 X"), "letter 'X' without a number");
  EXPECT_EQ(lex_error("G1 x Y1"), "letter 'X' without a number");
  EXPECT_EQ(lex_error("Xinf"), "bad number 'Xinf'");
  EXPECT_EQ(lex_error("x NaN"), "bad number 'xNaN'");
  EXPECT_NE(lex_error("X" + std::string(65, '1')).find("longer than 64 characters"), std::string::npos);
  EXPECT_EQ(lex_error("X" + std::string(64, '1')), "");
  const std::string canon_hint = " (rs274 -g FILE | gcode-pulse --canon runs the whole language)";
  EXPECT_EQ(lex_error("#1=5"), "unexpected character '#': parameters are not supported" + canon_hint);
  EXPECT_EQ(lex_error("G1 X[1+2]"), "letter 'X' without a number");
  EXPECT_EQ(lex_error("[1]"), "unexpected character '[': expressions are not supported" + canon_hint);
  EXPECT_EQ(lex_error("O100 sub"), "'O' words (subroutines) are not supported" + canon_hint);
  EXPECT_EQ(lex_error("G1 ^45 @10"),
            "'^' is LinuxCNC's polar angle word: polar coordinates are not supported" + canon_hint);
  EXPECT_EQ(lex_error("G1 @10"),
            "'@' is LinuxCNC's polar distance word: polar coordinates are not supported" + canon_hint);
  EXPECT_EQ(lex_error("M3 $1 S100"), "'$' is LinuxCNC's spindle selection word: one spindle only, no '$'" + canon_hint);
  EXPECT_EQ(lex_error("G1 X1 \x01"), "unexpected byte 0x01");
  EXPECT_EQ(lex_error("G1 \xff"), "unexpected byte 0xff");
  EXPECT_EQ(lex_error("(\x7f)"), "unexpected byte 0x7f");
  EXPECT_EQ(lex_error("(diameter \xc3\x98 3)"), "");  // UTF-8 in comments is fine
  EXPECT_EQ(lex_error("1.5"), "unexpected character '1'");
  EXPECT_EQ(lex_error("G1 /X1"), "unexpected character '/': block delete must start the line");
  EXPECT_EQ(lex_error("% G1"), "'%' must be alone on its line");
  EXPECT_EQ(lex_error("G1 %"), "'%' must be alone on its line");
}

// ---- modal groups, words, units and distance modes ----------------------

TEST(GcodeInterpreter, ModalGroupConflictsAndRepeatedWords) {
  EXPECT_ERROR("G1 G2 X1 F100", "G1 and G2 are both in the motion group");
  EXPECT_ERROR("G20 G21", "G20 and G21 are both in the units group");
  EXPECT_ERROR("G90 G91", "G90 and G91 are both in the distance mode group");
  EXPECT_ERROR("G17 G18", "both in the plane group");
  EXPECT_ERROR("G54 G55", "both in the coordinate system group");
  EXPECT_ERROR("G93 G94", "both in the feed rate mode group");
  EXPECT_ERROR("G4 P1 G53", "G4 and G53 are both in the non-modal group");
  EXPECT_ERROR("M3 M5", "M3 and M5 are both in the spindle group");
  EXPECT_ERROR("M8 M9", "M8 and M9 are both in the coolant group");
  EXPECT_ERROR("M0 M2", "M0 and M2 are both in the stopping group");
  EXPECT_ERROR("M3 M03", "M3 and M3 are both in the spindle group");
  EXPECT_EQ(error_of("M7 M8"), "");  // mist and flood together, as in LinuxCNC
  EXPECT_ERROR("G1 X1 X2 F100", "two X words on one line");
  EXPECT_ERROR("F1 F2", "two F words on one line");
  EXPECT_ERROR("G12 X1", "unknown G code G12");
  EXPECT_ERROR("G1.25 X1", "bad G code G1.25");
  EXPECT_ERROR("M3.5", "bad M code M3.5");
  EXPECT_ERROR("G1 X1 F100 R5", "R5: nothing on the line uses the R word");
  EXPECT_ERROR("G0 X1 I1", "nothing on the line uses the I word");
  EXPECT_ERROR("G0 X1 P1", "nothing on the line uses the P word");
}

TEST(GcodeInterpreter, UnitsAndFeed) {
  std::vector<Motion> m = run("G20 G1 X1 F10\nG21 G1 X10\nG70 G0 Y1\nG71 G0 Y1");
  ASSERT_EQ(m.size(), 4u);
  expect_point(m[0].end, 25.4, 0, 0);
  EXPECT_DOUBLE_EQ(m[0].feed, 254.0 / 60);  // 10 in/min
  EXPECT_DOUBLE_EQ(m[1].feed, 254.0 / 60);  // a feed keeps its speed across G21
  expect_point(m[1].end, 10, 0, 0);
  EXPECT_EQ(m[2].kind, MotionKind::rapid);
  EXPECT_EQ(m[2].feed, 0);
  expect_point(m[2].end, 10, 25.4, 0);
  expect_point(m[3].end, 10, 1, 0);
  EXPECT_DOUBLE_EQ(run("G1 X1 F600")[0].feed, 10);  // mm/min to mm/s, mm by default

  EXPECT_ERROR("G1 X1", "feed rate is zero");
  EXPECT_ERROR("F0 G1 X1", "feed rate is zero");
  EXPECT_ERROR("G1 Y1 F0", "feed rate is zero");
  EXPECT_ERROR("F-5", "negative feed rate F-5");
  EXPECT_EQ(error_of("G1 X0 Y0"), "");  // no move, so no feed needed
}

TEST(GcodeInterpreter, IncrementalAndModalMotion) {
  GcodeInterpreter interpreter;
  const auto m =
      run("G91 G0 X1 Y1\nX1\nG1 Z-2 F60\nG90 X5\nY2 Z1\nF100 S2000 M3\nT2 M6\n\n(comment)\nN50", interpreter);
  ASSERT_EQ(m.size(), 5u);
  expect_point(m[1].end, 2, 1, 0);
  EXPECT_EQ(m[1].kind, MotionKind::rapid);
  expect_point(m[2].end, 2, 1, -2);
  EXPECT_EQ(m[3].kind, MotionKind::linear);  // modal G1
  expect_point(m[3].end, 5, 1, -2);
  expect_point(m[4].end, 5, 2, 1);
  EXPECT_EQ(m[4].source_line, 5u);
  EXPECT_EQ(interpreter.blocks(), 7u);                   // blank, comment and N-only lines are no blocks
  EXPECT_EQ(run("G0 X0 Y0 Z0\nG1 X0 F100").size(), 0u);  // no move, no motion
}

TEST(GcodeInterpreter, MotionCancelAndMach3G80) {
  EXPECT_ERROR("G80\nX1", "axis words with no motion mode (after G80)");
  EXPECT_ERROR("G80 X1", "axis words with no motion mode (after G80)");
  GcodeInterpreter interpreter;
  // Mach3/Fanuc: G80 beside G00 only cancels canned cycles.
  const auto m = run("G00G21G17G90G40G49G80\nX1 Y2", interpreter);
  ASSERT_EQ(m.size(), 1u);
  EXPECT_EQ(m[0].kind, MotionKind::rapid);
  EXPECT_EQ(interpreter.unused_words().at("G80"), 1u);
  EXPECT_EQ(error_of("G80\nG1 X1 F100"), "");
}

TEST(GcodeInterpreter, CoordinateLimits) {
  EXPECT_ERROR("G0 X1000000000", "coordinate X1000000000 beyond ±1000000 mm");
  EXPECT_ERROR("G91 G0 X600000\nX600000", "coordinate X1200000 beyond ±1000000 mm");
  EXPECT_ERROR("G20 G0 Y-40000", "coordinate Y-1016000 beyond");
  EXPECT_EQ(error_of("G0 X1000000 Y-1000000"), "");
  InterpreterOptions small;
  small.max_coordinate_mm = 100;
  EXPECT_NE(error_of("G0 Z100.5", small).find("beyond ±100 mm"), std::string::npos);
}

TEST(GcodeInterpreter, Dwell) {
  const auto m = run("G0 X1\nG4 P1.5\nG4 P0");
  ASSERT_EQ(m.size(), 2u);
  EXPECT_EQ(m[1].kind, MotionKind::dwell);
  EXPECT_DOUBLE_EQ(m[1].duration, 1.5);
  expect_point(m[1].start, 1, 0, 0);
  expect_point(m[1].end, 1, 0, 0);
  EXPECT_ERROR("G4", "G4 (dwell) without a P word");
  EXPECT_ERROR("G4 P-1", "negative dwell time");
}

TEST(GcodeInterpreter, InverseTime) {
  const auto m = run("G93 G1 X10 F2\nG2 X20 R5 F6");
  ASSERT_EQ(m.size(), 2u);
  EXPECT_TRUE(m[0].inverse_time);
  EXPECT_DOUBLE_EQ(m[0].duration, 30);
  EXPECT_DOUBLE_EQ(m[0].feed, 10.0 / 30);
  EXPECT_DOUBLE_EQ(m[1].duration, 10);
  EXPECT_NEAR(m[1].feed, 5 * std::numbers::pi / 10, 1e-12);  // a half circle of radius 5 in 10 s
  EXPECT_ERROR("G93 G1 X10 F2\nX20", "G1 in inverse time mode (G93) without an F word");
  EXPECT_ERROR("G93 G1 X10 F0", "feed rate is zero");
  EXPECT_ERROR("G93 G1 X1 F1\nG94 G1 X2", "feed rate is zero");  // G94 needs a new F
  EXPECT_EQ(error_of("G93 G1 X1 F1\nG94 G1 X2 F100"), "");
}

// ---- arcs -------------------------------------------------------------

TEST(GcodeArc, CentreFormatAndArcDistanceModes) {
  const auto m = run("G0 X10\nG3 X0 Y10 I-10 F60\nG0 X10 Y5\nG90.1 G3 X0 Y15 I0 J5\nG91.1 G2 X10 Y5 I0 J-10");
  ASSERT_EQ(m.size(), 5u);
  EXPECT_EQ(m[1].kind, MotionKind::arc);
  EXPECT_FALSE(m[1].clockwise);
  expect_point(m[1].center, 0, 0, 0);
  EXPECT_NEAR(arc_sweep(m[1]), std::numbers::pi / 2, 1e-12);
  EXPECT_DOUBLE_EQ(m[1].feed, 1);
  expect_point(m[3].center, 0, 5, 0);  // absolute centre
  expect_point(m[4].center, 0, 5, 0);  // centre relative to the start (0, 15)
  EXPECT_TRUE(m[4].clockwise);
  EXPECT_NEAR(arc_sweep(m[4]), std::numbers::pi / 2, 1e-12);
}

TEST(GcodeArc, RadiusFormat) {
  struct Case {
    const char* block;
    double centre_y, sweep;
  };
  const double h = std::sqrt(75.0);  // 8.660254: the centre's distance from the chord for R10
  const Case cases[] = {{"G2 X10 R5", 0, std::numbers::pi},
                        {"G2 X10 R-5", 0, std::numbers::pi},
                        {"G3 X10 R5", 0, std::numbers::pi},
                        {"G2 X10 R10", -h, std::numbers::pi / 3},
                        {"G2 X10 R-10", h, 5 * std::numbers::pi / 3},
                        {"G3 X10 R10", h, std::numbers::pi / 3},
                        {"G3 X10 R-10", -h, 5 * std::numbers::pi / 3},
                        {"G2 X10 R4.999", 0, std::numbers::pi}};
  for (const Case& c : cases) {
    const auto m = run(std::string("F100\n") + c.block);
    ASSERT_EQ(m.size(), 1u) << c.block;
    expect_point(m[0].center, 5, c.centre_y, 0, 1e-9);
    EXPECT_NEAR(arc_sweep(m[0]), c.sweep, 1e-9) << c.block;
  }
  EXPECT_ERROR("F100 G2 X10 R4.99", "arc radius too small to reach the end point");
  EXPECT_ERROR("F100 G2 Z1 R4", "the end point equals the start point");
  EXPECT_ERROR("F100 G2 X10 R5 I5", "G2 with both R and I/J words");
  EXPECT_ERROR("F100 G2 X10", "G2 without R or I/J words");
  EXPECT_ERROR("F100 G2 X0.001 R0.001", "zero-radius arc");
}

TEST(GcodeArc, FullCirclesTurnsAndHelix) {
  const auto m = run("G0 X10\nG2 I-10 F100\nG2 X10 Y0 I-10 P3\nG3 X-10 Z5 I-10");
  ASSERT_EQ(m.size(), 4u);
  expect_point(m[1].end, 10, 0, 0);
  expect_point(m[1].center, 0, 0, 0);
  EXPECT_EQ(m[1].turns, 0u);
  EXPECT_NEAR(arc_sweep(m[1]), 2 * std::numbers::pi, 1e-12);
  EXPECT_EQ(m[2].turns, 2u);
  EXPECT_NEAR(arc_sweep(m[2]), 6 * std::numbers::pi, 1e-12);
  // Helix: the normal axis moves linearly; the centre stays at the start's Z.
  expect_point(m[3].end, -10, 0, 5);
  expect_point(m[3].center, 0, 0, 0);
  EXPECT_NEAR(arc_sweep(m[3]), std::numbers::pi, 1e-12);
  EXPECT_ERROR("F100 G2 X1 I1 P0", "the number of turns must be a positive whole number");
  EXPECT_ERROR("F100 G2 X1 I1 P1.5", "the number of turns must be a positive whole number");
  // An M code taking P owns it: the arc makes one turn.
  EXPECT_EQ(run("F100 G2 X2 I1 M62 P3")[0].turns, 0u);
}

TEST(GcodeArc, PlanesG18AndG19) {
  const auto m = run("G18 G0 X10\nG2 X0 Z10 I-10 K0 F60\nG19 G0 X0 Y10 Z0\nG3 Y0 Z10 J-10");
  ASSERT_EQ(m.size(), 4u);
  EXPECT_EQ(m[1].axis0, 2);
  EXPECT_EQ(m[1].axis1, 0);
  EXPECT_EQ(m[1].axis2, 1);
  expect_point(m[1].center, 0, 0, 0);
  EXPECT_NEAR(arc_sweep(m[1]), std::numbers::pi / 2, 1e-12);  // clockwise seen from +Y, from +X to +Z
  EXPECT_EQ(m[3].axis0, 1);
  EXPECT_EQ(m[3].axis1, 2);
  EXPECT_EQ(m[3].axis2, 0);
  expect_point(m[3].center, 0, 0, 0);
  EXPECT_NEAR(arc_sweep(m[3]), std::numbers::pi / 2, 1e-12);
  // R arcs in G18: from X10 to Z10 the short way round.
  const auto r = run("G18 G0 X10\nG2 X0 Z10 R10 F60");
  expect_point(r[1].center, 0, 0, 0);
  EXPECT_ERROR("F100 G17 G2 X1 K1", "K word with G2 in the G17 plane: its centre words are I/J");
  EXPECT_ERROR("F100 G18 G2 X1 J1", "J word with G2 in the G18 plane: its centre words are I/K");
  EXPECT_ERROR("F100 G19 G3 Y1 I1", "I word with G3 in the G19 plane: its centre words are J/K");
}

TEST(GcodeArc, EndRadiusTolerance) {
  // Within 0.005 mm, or within 0.1% of the radius and 0.5 mm.
  EXPECT_EQ(error_of("G0 X1\nG3 X-1.004 I-1 F100"), "");
  EXPECT_EQ(error_of("G0 X10\nG3 X-10.009 I-10 F100"), "");
  EXPECT_EQ(error_of("G0 X1000\nG3 X-1000.4 I-1000 F100"), "");
  EXPECT_ERROR("G0 X1\nG3 X-1.006 I-1 F100", "radius to end of arc differs from radius to start");
  EXPECT_ERROR("G0 X100\nG3 X-100.2 I-100 F100", "radius to end of arc differs");
  EXPECT_ERROR("G0 X1000\nG3 X-1000.6 I-1000 F100", "radius to end of arc differs");
  // Inches: 0.0005 in, 0.05 in.
  EXPECT_EQ(error_of("G20 G0 X0.1\nG3 X-0.1004 I-0.1 F100"), "");
  EXPECT_ERROR("G20 G0 X0.1\nG3 X-0.1006 I-0.1 F100", "radius to end of arc differs");
  EXPECT_EQ(error_of("G20 G0 X100\nG3 X-100.04 I-100 F100"), "");  // 0.04 in, under 0.1%
  EXPECT_ERROR("G20 G0 X100\nG3 X-100.06 I-100 F100", "radius to end of arc differs");
  EXPECT_ERROR("G2 X1 I0 F100", "zero-radius arc");
}

// ---- unsupported words, lenient mode, unused words, program end ---------

TEST(GcodeInterpreter, UnsupportedWords) {
  EXPECT_ERROR("G41 D1", "G41 (cutter radius compensation) is not supported");
  EXPECT_ERROR("G42.1 D1", "G42.1 (cutter radius compensation) is not supported");
  EXPECT_ERROR("G33.1 Z-1 K1", "G33.1 (rigid tapping) is not supported");  // G33 and G7: test_gcode_threading.cpp
  EXPECT_ERROR("G76 P1 Z-1", "G76 (threading cycle) is not supported");
  EXPECT_ERROR("G81 X1 Y1 Z-1 R1", "G81 (canned cycle) is not supported");
  EXPECT_ERROR("G73 X1 Z-1 R1 Q1", "G73 (canned cycle) is not supported");
  EXPECT_ERROR("G38.2 Z-10 F10", "G38.2 (probing) is not supported");
  EXPECT_ERROR("G28", "G28 (return to home) is not supported");
  EXPECT_ERROR("G30.1", "G30.1 (storing the second home position) is not supported");
  EXPECT_ERROR("G92 X0", "G92 (coordinate system offset) is not supported");
  EXPECT_ERROR("G10 L2 P1 X0", "G10 (setting offsets and tool data) is not supported");
  EXPECT_ERROR("G5 X1 I1 J1 P1 Q1", "G5 (cubic spline) is not supported");
  EXPECT_ERROR("G17.1", "G17.1 (UV plane) is not supported");
  EXPECT_ERROR("G95 F1", "G95 (feed per revolution) is not supported");
  EXPECT_ERROR("G1 X1 A1 F100", "axis word A1 is not supported (3 axes only: X, Y, Z)");
  EXPECT_ERROR("W2", "axis word W2 is not supported");
  EXPECT_EQ(error_of("G53 G0 X1"), "");  // no offsets: machine coordinates are the program's
}

TEST(GcodeInterpreter, LenientSkipsWithWarnings) {
  InterpreterOptions options;
  options.lenient = true;
  GcodeInterpreter interpreter(options);
  std::vector<std::string> warnings;
  interpreter.on_warning([&warnings](const std::string& warning) { warnings.push_back(warning); });
  const auto m =
      run("G41 D2 G1 X10 F100\n"  // the word goes, the move stays
          "G1 X20 A5\n"           // the A word goes
          "G81 X1 Y1 Z-1 R1\n"    // a canned cycle: no move
          "X2 Y2\n"               // still in the skipped mode
          "G80\n"
          "G28 X0\n"  // its X is no move
          "G0 X5 Y5",
          interpreter);
  ASSERT_EQ(m.size(), 3u);
  expect_point(m[0].end, 10, 0, 0);
  expect_point(m[1].end, 20, 0, 0);
  expect_point(m[2].start, 20, 0, 0);
  expect_point(m[2].end, 5, 5, 0);
  const std::vector<std::string> expected = {
      "skipped G41 (cutter radius compensation)", "skipped A5 (3 axes only: X, Y, Z)", "skipped G81 (canned cycle)",
      "skipped this line's motion: G81 (canned cycle) mode", "skipped G28 (return to home)"};
  EXPECT_EQ(warnings, expected);
  EXPECT_NE(error_of("G12", options).find("unknown G code G12"), std::string::npos);  // even when lenient
}

TEST(GcodeInterpreter, UnusedWordsAndProgramEnd) {
  GcodeInterpreter interpreter;
  const auto m =
      run("N10 G17 G21 G90 G94 G40 G49 G54 G64 P0.01 Q0.01 G98\n"
          "M03 S1000\nM3\nT1 M06\nH1\nM62 P1\nM63 P1\nM7 M8\nM9\nM0\nM1\nG97\nG61\n"
          "/G0 X100\n"  // block delete switch on: skipped
          "G0 X1\nM30\nG0 X5\nM3",
          interpreter);
  ASSERT_EQ(m.size(), 1u);
  expect_point(interpreter.position(), 1, 0, 0);
  EXPECT_TRUE(interpreter.program_ended());
  const std::map<std::string, std::uint64_t> expected = {{"G40", 1}, {"G54", 1}, {"G61", 1}, {"G64", 1}, {"G97", 1},
                                                         {"G98", 1}, {"H", 1},   {"M0", 1},  {"M1", 1},  {"M3", 2},
                                                         {"M6", 1},  {"M62", 1}, {"M63", 1}, {"M7", 1},  {"M8", 1},
                                                         {"M9", 1},  {"T", 1}};  // S is not here: G33 follows it
  EXPECT_EQ(interpreter.unused_words(), expected);
  EXPECT_EQ(interpreter.blocks(), 15u);
  EXPECT_FALSE(GcodeInterpreter().program_ended());
  GcodeInterpreter m2;
  run("M2\nG0 X1", m2);
  EXPECT_TRUE(m2.program_ended());
  expect_point(m2.position(), 0, 0, 0);
}
