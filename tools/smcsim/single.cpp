/// @file single.cpp
/// @brief smcsim's single run: the time series, or the --summary record,
/// and the --svg plot.
#include <fmt/format.h>

#include <cmath>

#include "control/feed_drive_plot.hpp"
#include "control/feed_drive_report.hpp"
#include "io/error.hpp"
#include "modes.hpp"

namespace smcsim {

void run_single(const FeedDriveConfig& config, bool summary_only, std::uint64_t every, const std::string& svg_path,
                tk::io::OutputFormat format) {
  tk::io::RecordWriter writer(format);
  FeedDrivePlot plot;
  const bool plotting = !svg_path.empty();
  FeedDriveSummary summary;
  if (summary_only && !plotting) {
    summary = simulate_feed_drive(config);
  } else {
    if (!summary_only) writer.declare_fields({"t", "x_ref", "x", "e", "e_dot", "S", "F", "F_d"});
    std::vector<double> values(8);
    summary = simulate_feed_drive(
        config,
        [&](const FeedDriveSample& s) {
          if (plotting) plot.add(s);
          if (summary_only) return;
          values = {s.t_s,          s.x_ref_mm, s.x_mm,         s.error_mm, s.error_rate_mm_s,
                    s.surface_mm_s, s.force_n,  s.disturbance_n};
          for (const double v : values)  // the records stay JSON: no inf or nan in them
            if (!std::isfinite(v))
              throw tk::Error(fmt::format("the run overflowed at t = {} s (is the reference beyond 1e12 mm?)", s.t_s));
          writer.write_numbers(values, 0);
        },
        every);
  }
  if (summary_only) {
    writer.declare_fields(kSummaryFields);
    writer.write(summary_record(config, checked(summary)));
  }
  writer.flush();
  if (plotting) {
    const ControllerGains& g = config.gains;
    const bool sliding = g.kind == ControllerKind::smc || g.kind == ControllerKind::sta;
    std::string gains = g.kind == ControllerKind::smc   ? fmt::format(" --Lambda {:g}", g.switching)
                        : g.kind == ControllerKind::sta ? fmt::format(" --alpha {:g} --beta {:g}", g.alpha, g.beta)
                                                        : std::string();
    if (sliding && g.printed_bracket) gains += " --seed-bracket";
    if (sliding && g.switching_sign < 0) gains += " --seed-sign";
    plot.write(svg_path, fmt::format("smcsim --controller {}{}: {}", controller_name(g.kind), gains,
                                     config.reference.describe()));
  }
  if (summary.diverged && !summary_only)
    throw tk::Error(
        fmt::format("the loop diverged at t = {} s (error beyond {} mm)", summary.diverged_at_s, config.divergence_mm));
}

}  // namespace smcsim
