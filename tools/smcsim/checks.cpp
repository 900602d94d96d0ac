/// @file checks.cpp
/// @brief smcsim's checks of the options and of a run's figures, shared by
/// its modes.
#include <fmt/format.h>

#include <cmath>

#include "cli/number_option.hpp"
#include "cli/option_checks.hpp"
#include "io/error.hpp"
#include "modes.hpp"

namespace smcsim {

namespace {

/// One run's length: about 5 s of work and 300 MB (the force samples and
/// their spectrum for hf_share) at the default 10 substeps.
constexpr double kMaxPeriods = 1e7, kMaxPlantSteps = 1e8;

}  // namespace

const FeedDriveSummary& checked(const FeedDriveSummary& s) {
  if (s.diverged) return s;  // its figures are written as null
  for (const double v : {s.rms_error_mm, s.max_error_mm, s.rms_velocity_error_mm_s, s.rms_s, s.chattering_n_s,
                         s.hf_share, s.effort_rms_n, s.max_force_n, s.saturated_share})
    if (!std::isfinite(v)) throw tk::Error("the run's figures overflowed (is the reference beyond 1e12 mm?)");
  return s;
}

std::vector<double> gain_grid(const std::string& text, const char* option) {
  const std::vector<double> values = tk::cli::parse_grid(text, option, kMaxSweepPoints);
  for (const double v : values)
    if (const std::string problem = tk::cli::out_of_domain(v, tk::cli::NumberDomain::non_negative); !problem.empty())
      throw tk::UsageError(fmt::format("{}: {}, not {}", option, problem, v));
  return values;
}

double single_value(const std::string& text, const char* option) {
  const std::vector<double> values = gain_grid(text, option);
  if (values.size() != 1)
    throw tk::UsageError(fmt::format("{} takes one value here; ranges are for 'smcsim sweep'", option));
  return values[0];
}

void check_combination(const FeedDriveConfig& c) {
  if (c.period_s > c.duration_s)
    throw tk::UsageError(fmt::format("--period {} s is longer than --duration {} s", c.period_s, c.duration_s));
  const double periods = c.duration_s / c.period_s;
  if (periods > kMaxPeriods)
    throw tk::UsageError(fmt::format("--duration {} s at --period {} s is {:.3g} control periods; at most {:g}",
                                     c.duration_s, c.period_s, periods, kMaxPeriods));
  if (periods * c.substeps > kMaxPlantSteps)
    throw tk::UsageError(fmt::format("--substeps {} over {:.3g} control periods is {:.3g} plant steps; at most {:g}",
                                     c.substeps, periods, periods * c.substeps, kMaxPlantSteps));
  if (c.settle_s >= c.duration_s)
    throw tk::UsageError(fmt::format("--settle {} s leaves nothing of --duration {} s", c.settle_s, c.duration_s));
  if (c.cut.radial_depth_mm > c.cut.diameter_mm)
    throw tk::UsageError(fmt::format("--radial-depth {} mm is more than --tool-diameter {} mm", c.cut.radial_depth_mm,
                                     c.cut.diameter_mm));
  c.validate();  // anything left is the library's to name
}

}  // namespace smcsim
