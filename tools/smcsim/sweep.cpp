/// @file sweep.cpp
/// @brief smcsim sweep: one summary record per gain setting, run on every core.
#include <fmt/format.h>

#include "cli/option_checks.hpp"
#include "concurrency/ordered_pool.hpp"
#include "control/feed_drive_report.hpp"
#include "io/error.hpp"
#include "modes.hpp"

namespace smcsim {

namespace {

/// Plant steps in one sweep, every setting together: about 200 s of one core.
constexpr double kMaxSweepPlantSteps = 1e9;

}  // namespace

void run_sweep(const FeedDriveConfig& base, const GainGrids& grids, unsigned threads, tk::io::OutputFormat format) {
  // The points carry only their gains: the base configuration (a reference
  // file's samples) is copied per running simulation, not per point.
  std::vector<ControllerGains> points;
  ControllerGains gains = base.gains;
  if (base.gains.kind == ControllerKind::smc) {
    for (const double lambda : gain_grid(grids.lambda, "--Lambda")) {
      gains.switching = lambda;
      points.push_back(gains);
    }
  } else {
    const std::vector<double> alphas = gain_grid(grids.alpha, "--alpha"), betas = gain_grid(grids.beta, "--beta");
    if (alphas.size() * betas.size() > kMaxSweepPoints)
      throw tk::UsageError(fmt::format("--alpha and --beta make {} × {} settings; a sweep takes at most {}",
                                       alphas.size(), betas.size(), kMaxSweepPoints));
    for (const double alpha : alphas)
      for (const double beta : betas) {
        gains.alpha = alpha, gains.beta = beta;
        points.push_back(gains);
      }
  }
  tk::cli::require_run_size(static_cast<double>(points.size()) * static_cast<double>(base.periods()) * base.substeps,
                            kMaxSweepPlantSteps, "plant steps",
                            "the sweep's settings, --duration, --period and --substeps");
  tk::io::RecordWriter writer(format);
  writer.declare_fields(kSummaryFields);
  std::vector<tk::Record> diverged;  // written after every setting that held, so that they sort last
  tk::OrderedPool<ControllerGains, tk::Record> pool(
      threads,
      [&base](ControllerGains& g) {
        FeedDriveConfig c = base;
        c.gains = g;
        return summary_record(c, checked(simulate_feed_drive(c)));
      },
      [&](tk::Record& r) {
        if (r["diverged"].get<bool>()) diverged.push_back(std::move(r));
        else writer.write(r);
      });
  for (ControllerGains& p : points) pool.submit(p);
  pool.finish();
  for (const tk::Record& r : diverged) writer.write(r);
  writer.flush();
}

}  // namespace smcsim
