/// @file test_gcode_corpus.cpp
/// @brief Runs the real G-code programs of the shared corpus (LinuxCNC,
/// Estlcam, Mach3...) through the lexer and interpreter with the default,
/// strict options; skipped when the corpus is absent.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
// GCC 12 warns falsely inside <regex> under -O2 with the sanitizers.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <regex>
#pragma GCC diagnostic pop
#include <numbers>
#include <sstream>

#include "io/error.hpp"
#include "motion/gcode.hpp"
#include "project_paths.hpp"

using namespace tk::motion;

namespace {

void expect_point(const Vec3& actual, const Vec3& expected, double tolerance = 1e-9) {
  EXPECT_NEAR(actual.x, expected.x, tolerance);
  EXPECT_NEAR(actual.y, expected.y, tolerance);
  EXPECT_NEAR(actual.z, expected.z, tolerance);
}

/// Runs a whole file; a tk::Error fails the test with file:line.
std::vector<Motion> run_file(const std::filesystem::path& file, GcodeInterpreter& interpreter) {
  std::vector<Motion> motions;
  std::ifstream in(file);
  std::string text;
  std::size_t line = 0;
  try {
    while (std::getline(in, text)) interpreter.execute(lex_gcode_line(text), ++line, motions);
  } catch (const tk::Error& error) {
    ADD_FAILURE() << file.filename() << ":" << line << ": " << error.what();
  }
  return motions;
}

std::vector<std::filesystem::path> corpus_files() {
  std::vector<std::filesystem::path> files;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(tk::test::corpus_folder("gcode"), error)) {
    const auto extension = entry.path().extension();
    if (extension == ".ngc" || extension == ".gcode") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

/// Independent of the interpreter: the last X, Y and Z words in mm, for
/// programs in absolute mode (a regular expression over the text with the
/// comments removed; G20/G70 and G21/G71 switch units; M2/M30 end).
Vec3 last_programmed_position(const std::filesystem::path& file) {
  static const std::regex comments(R"(\([^)]*\)|;.*)");
  static const std::regex word(R"(([A-Za-z])\s*([-+]?[0-9.]+))");
  std::ifstream in(file);
  std::string text;
  Vec3 position;
  double unit = 1;
  while (std::getline(in, text)) {
    text = std::regex_replace(text, comments, "");
    bool ended = false;
    for (std::sregex_iterator it(text.begin(), text.end(), word), end; it != end; ++it) {
      const char letter = static_cast<char>(std::toupper((*it)[1].str()[0]));
      const double value = std::stod((*it)[2].str());
      if (letter == 'G' && (value == 20 || value == 70)) unit = 25.4;
      if (letter == 'G' && (value == 21 || value == 71)) unit = 1;
      if (letter == 'G') {
        EXPECT_NE(value, 91) << file << ": this check needs absolute mode";
      }
      if (letter == 'M' && (value == 2 || value == 30)) ended = true;
      if (letter >= 'X' && letter <= 'Z') position[letter - 'X'] = value * unit;
    }
    if (ended) break;
  }
  return position;
}

}  // namespace

TEST(GcodeCorpus, EveryProgramRunsToItsLastProgrammedPosition) {
  const auto files = corpus_files();
  if (files.empty()) GTEST_SKIP() << "no G-code corpus at " << tk::test::corpus_folder("gcode");
  for (const auto& file : files) {
    SCOPED_TRACE(file.filename().string());
    // Not lenient; tools of no length, so that G43 leaves the last
    // programmed position where the words put it.
    InterpreterOptions options;
    options.has_tool_table = true;
    for (int tool = 0; tool < 100; ++tool) options.tool_table[tool] = Vec3{};
    GcodeInterpreter interpreter(options);
    const std::vector<Motion> motions = run_file(file, interpreter);
    ASSERT_FALSE(motions.empty());
    expect_point(interpreter.position(), last_programmed_position(file));
    // The motions join up, and arcs keep their radius within tolerance.
    Vec3 at;
    for (const Motion& motion : motions) {
      expect_point(motion.start, at, 0);
      at = motion.end;
      if (motion.kind != MotionKind::arc) continue;
      const auto radius = [&motion](const Vec3& p) {
        return std::hypot(p[motion.axis0] - motion.center[motion.axis0], p[motion.axis1] - motion.center[motion.axis1]);
      };
      EXPECT_LE(std::abs(radius(motion.end) - radius(motion.start)), 0.5) << "line " << motion.source_line;
      EXPECT_EQ(motion.center[motion.axis2], motion.start[motion.axis2]);
    }
  }
}

TEST(GcodeCorpus, ConstructsOfParticularPrograms) {
  const auto folder = tk::test::corpus_folder("gcode");
  if (!std::filesystem::exists(folder / "linuxcnc_3dtest.ngc")) GTEST_SKIP() << "no G-code corpus at " << folder;
  // 3dtest: a full circle in each plane, given by I/J/K only.
  GcodeInterpreter dtest;
  int full_circles = 0;
  for (const Motion& m : run_file(folder / "linuxcnc_3dtest.ngc", dtest))
    if (m.kind == MotionKind::arc && std::abs(arc_sweep(m) - 2 * std::numbers::pi) < 1e-9) ++full_circles;
  EXPECT_EQ(full_circles, 3);
  EXPECT_TRUE(dtest.program_ended());
  // tort: helical arcs in all three planes.
  GcodeInterpreter tort;
  int helical[3] = {0, 0, 0};
  for (const Motion& m : run_file(folder / "linuxcnc_tort.ngc", tort))
    if (m.kind == MotionKind::arc && m.end[m.axis2] != m.start[m.axis2]) ++helical[m.axis2];
  EXPECT_GT(helical[0], 0);
  EXPECT_GT(helical[1], 0);
  EXPECT_GT(helical[2], 0);
  EXPECT_EQ(tort.unused_words().at("M0"), 1u);
  // The Mach3 program: G80 beside G00, G71, M62/M63 P1, T1M06, CRLF, '%'.
  GcodeInterpreter mach3;
  run_file(folder / "gcoders_tweakie_program_3.gcode", mach3);
  EXPECT_EQ(mach3.unused_words().at("G80"), 1u);
  EXPECT_EQ(mach3.unused_words().at("M62"), 54u);
  EXPECT_EQ(mach3.unused_words().at("M63"), 30u);
  EXPECT_EQ(mach3.unused_words().at("M6"), 1u);
  EXPECT_EQ(mach3.unused_words().count("P"), 0u);
  EXPECT_TRUE(mach3.program_ended());
}
