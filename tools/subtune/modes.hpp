/// @file modes.hpp
/// @brief subtune's modes, one file each (filter_subtune, filter_chart,
/// model_fit, model_apply, simulate), and what they share; main.cpp wires
/// the options to them.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "cli/tool_app.hpp"
#include "io/error.hpp"
#include "io/record.hpp"
#include "io/record_writer.hpp"
#include "machining/force_error_model.hpp"
#include "quality/lathe_sim.hpp"
#include "quality/size_plot.hpp"

namespace subtune {

using namespace tk::quality;
using tk::machining::ForceErrorModel;

/// Lengths beyond a kilometre, or nonzero ones below 1e-100 mm, are a unit
/// or parsing mistake; the bounds also keep the run's sums of squares inside
/// double range (squares of differences below ~1e-154 would underflow to 0
/// and make the spread vanish).
constexpr double kMaxLengthMm = 1e6, kMinLengthMm = 1e-100;

/// The force-error model's coefficients given as --coefficients, in magnitude.
constexpr double kMaxCoefficient = 1e6;

/// Seeds: any whole number of up to 19 digits.
constexpr std::uint64_t kMaxSeed = 9'999'999'999'999'999'999ULL;

/// A length field in mm within ±kMaxLengthMm; tk::Error at `where` otherwise.
double length_field(const tk::Record& record, const std::string& key, const tk::Location& where);

/// The legend of the policy's level line in the plots.
std::string level_label(PolicyKind kind);

/// Writes the plot, saying so when it holds only the first parts.
void write_plot(const SizePlot& plot, const std::string& path, const SizePlotInfo& info, const tk::cli::ToolApp& tool);

/// Tolerance limits given as options, overridden per record by fields.
struct Limits {
  std::optional<double> lower, upper;
};

/// The record's own limits, else the options'.
Limits limits_of(const tk::Record& record, const Limits& options, const tk::Location& where);
bool within(double size, const Limits& l);

/// The filter: sub-tuning's decision per measured size.
void filter_sizes(const std::vector<std::string>& inputs, const SubTuneSettings& settings, const std::string& field,
                  const Limits& limits, const std::string& svg_path, const tk::cli::ToolApp& tool);
/// The filter under a chart instead of sub-tuning: per part the chart's
/// statistic and limit, its level, and whether to adjust.
void filter_chart(const std::vector<std::string>& inputs, AdjustmentPolicy& chart, const std::string& field,
                  const Limits& limits, const std::string& svg_path, const tk::cli::ToolApp& tool);

/// 'subtune model': the force-error model fitted to calibration records.
void fit_model(const std::vector<std::string>& inputs, bool residuals, tk::io::OutputFormat format);
/// The model from --coefficients, or from the last record of FILE that has all six.
ForceErrorModel load_model(const std::string& path, const std::string& coefficient_text);

struct FeedRange {
  double target = 0, f_min = 0, f_max = 0;
};

/// 'subtune feed' (with a feed range) and 'subtune correct' (without).
void apply_model(const std::vector<std::string>& inputs, const ForceErrorModel& m, std::optional<FeedRange> feed_range,
                 double fixed_feed, const tk::cli::ToolApp& tool);

struct SimulationOptions {
  std::string policy;  ///< empty: all
  std::uint64_t arl_runs = 2000, arl_cap = 100000;
  double shift_sigma = 1, drift_sigma = 0.1;
  std::optional<double> sigma;
  std::string trace_path, svg_path;
};

/// --simulate: one summary record per policy.
void simulate(const LatheSettings& lathe, const SubTuneSettings& subtune, ChartSettings charts,
              const SimulationOptions& o, const tk::cli::ToolApp& tool);

}  // namespace subtune
