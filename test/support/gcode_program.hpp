/// @file gcode_program.hpp
/// @brief Test helpers shared by the G-code unit tests: a whole program
/// through the interpreter, and the error it gives.
#pragma once

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "io/error.hpp"
#include "motion/gcode.hpp"

namespace gcode_test {

/// Runs a program (lines separated by '\n') through `interpreter`.
inline std::vector<tk::motion::Motion> run(const std::string& program, tk::motion::GcodeInterpreter& interpreter) {
  std::vector<tk::motion::Motion> motions;
  std::istringstream in(program);
  std::string text;
  for (std::size_t line = 1; std::getline(in, text); ++line)
    interpreter.execute(tk::motion::lex_gcode_line(text), line, motions);
  return motions;
}

inline std::vector<tk::motion::Motion> run(const std::string& program) {
  tk::motion::GcodeInterpreter interpreter;
  return run(program, interpreter);
}

/// Each coordinate of `actual` within `tolerance` mm of (x, y, z).
inline void expect_point(const tk::motion::Vec3& actual, double x, double y, double z, double tolerance = 1e-9) {
  EXPECT_NEAR(actual.x, x, tolerance);
  EXPECT_NEAR(actual.y, y, tolerance);
  EXPECT_NEAR(actual.z, z, tolerance);
}

/// The error message a program gives, "" for none.
inline std::string error_of(const std::string& program, tk::motion::InterpreterOptions options = {}) {
  try {
    tk::motion::GcodeInterpreter interpreter(options);
    run(program, interpreter);
  } catch (const tk::Error& error) {
    return error.what();
  }
  return {};
}

}  // namespace gcode_test
