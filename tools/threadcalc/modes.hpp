/// @file modes.hpp
/// @brief threadcalc's modes, one file each (the records, the --gcode
/// program), and the options they share; main.cpp wires the options to them.
#pragma once

#include <string>
#include <vector>

#include "cli/tool_app.hpp"
#include "io/error.hpp"
#include "threads/thread_report.hpp"

namespace threadcalc {

using namespace tk::threads;

struct Options {
  MemberChoice choice = MemberChoice::from_class;
  TurningSettings turning;
  int decimals = 4;
  std::string field = "designation";
};

/// The program's ranges (threadcalc(1), PROGRAMS), as validate() checks them.
constexpr double kMaxLengthMm = 10000, kMinRpm = 1, kMaxRpm = 100000, kMaxRunInMm = 1000;

struct ProgramOptions {
  std::string style;
  double length = 0;
  double rpm = 0;
  double cutting_speed = 100;
  double max_rpm = 3000;
  double clearance = 1;
  double run_in = 0;
  double acceleration = 500;
};

/// Warns of each of the result's warnings, at `where`.
inline void warn_all(const ThreadResult& result, const tk::Location& where, const tk::cli::ToolApp& tool) {
  for (const std::string& warning : result.warnings) tool.warn(tk::Error(warning, where).located_message());
}

/// The default mode: a record per member of each designation, from the
/// arguments or from the records of `inputs`.
void write_records(const std::vector<std::string>& designations, const std::vector<std::string>& inputs,
                   const Options& o, const tk::cli::ToolApp& tool);

/// --gcode: the threading program of the one designation.
void write_program(const std::vector<std::string>& designations, Options o, const ProgramOptions& p,
                   const tk::cli::ToolApp& tool);

}  // namespace threadcalc
