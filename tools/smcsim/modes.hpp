/// @file modes.hpp
/// @brief smcsim's modes, one file each (a single run, a sweep of gains),
/// and the option checks they share; main.cpp wires the options to them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "control/feed_drive_sim.hpp"
#include "io/record_writer.hpp"

namespace smcsim {

using namespace tk::control;

/// Settings in one sweep (for sta, the product of the --alpha and --beta grids).
constexpr std::size_t kMaxSweepPoints = 100000;

/// The gains a sweep may vary; one value each outside a sweep.
struct GainGrids {
  std::string lambda = "40", alpha = "200", beta = "200";
};

/// A summary with an inf or NaN figure (a reference file's huge values) is
/// an error, not a record with nulls in it.
const FeedDriveSummary& checked(const FeedDriveSummary& s);

/// --Lambda, --alpha or --beta: a number or FROM:TO:STEP, each value a usable gain.
std::vector<double> gain_grid(const std::string& text, const char* option);

double single_value(const std::string& text, const char* option);

/// Option combinations the per-option checks cannot see, named as options.
void check_combination(const FeedDriveConfig& c);

/// One run: its time series, or --summary's record, and --svg.
void run_single(const FeedDriveConfig& config, bool summary_only, std::uint64_t every, const std::string& svg_path,
                tk::io::OutputFormat format);

/// sweep: one summary record per gain setting, on `threads` threads.
void run_sweep(const FeedDriveConfig& base, const GainGrids& grids, unsigned threads, tk::io::OutputFormat format);

}  // namespace smcsim
