/// @file simulate.cpp
/// @brief fuzzyfeed --simulate: a turning pass under the override law, its
/// summary (and segment) records, the per-cycle trace and the plot.
#include <fmt/format.h>

#include <memory>
#include <optional>

#include "cli/option_checks.hpp"
#include "io/error.hpp"
#include "machining/turning_profile.hpp"
#include "machining/turning_report.hpp"
#include "machining/turning_svg.hpp"
#include "modes.hpp"

namespace fuzzyfeed {

namespace {

/// The most IPO cycles a run with --trace may take (fuzzyfeed(1), OPTIONS).
constexpr double kMaxTraceCycles = 2e6;

/// The trace file: one record per IPO cycle, through the fast numeric path.
class TraceFile {
 public:
  TraceFile(const std::string& path, tk::io::OutputFormat format, double programmed_feed)
      : file_(path, format), feed_(programmed_feed) {
    file_.declare_fields({"t", "z", "depth", "chip", "load_true", "load", "wk", "override", "feed", "feed_out"});
  }
  void add(const TraceSample& s) {
    values_.assign({s.t_s, s.z_mm, s.depth_mm, s.chip_mm, s.load_true_pct, s.load_pct, s.step.wk, s.step.override_pct,
                    feed_, feed_ * s.step.override_pct / 100});
    file_.write_numbers(values_, 0);
  }
  void close() { file_.close(); }

 private:
  tk::io::RecordFile file_;
  double feed_;
  std::vector<double> values_;
};

}  // namespace

void simulate(const SimulateSettings& settings, const FeedOverrideParams& law, TurningParams process,
              tk::cli::ToolApp& tool) {
  const std::string& variant = settings.variant;
  const std::string &trace_path = settings.trace_path, &svg_path = settings.svg_path;
  process.cutting.rated_power_w = settings.power_kw * 1000;
  validate(process);
  if (!settings.profile_path.empty()) process.profile = read_profile(settings.profile_path);
  check_profile(process.profile);

  std::unique_ptr<TraceFile> trace;
  if (!trace_path.empty()) {
    // A trace line is about 110 bytes: at most ~250 MB of trace, and a
    // run that the law slows past the cap stops there (exit 1).
    tk::cli::require_run_size(baseline_time_s(process) / process.ipo_s, kMaxTraceCycles,
                              "trace records (IPO cycles at 100 %; raise --feed or --ipo, or shorten the profile)",
                              "--trace with --feed, --cutting-speed, --diameter, --ipo and the profile's length");
    process.max_cycles = kMaxTraceCycles;
    trace = std::make_unique<TraceFile>(trace_path, tool.output_format(), process.feed_mm_rev);
  }
  TurningSvg plot;
  const RunStats run = simulate_turning(process, law, law.mz_pct, [&](const TraceSample& s) {
    if (trace) trace->add(s);
    if (!svg_path.empty()) plot.add(s.t_s, s.load_pct, s.load_true_pct, s.step.override_pct, s.depth_mm);
  });
  if (trace) trace->close();
  const RunStats baseline = simulate_turning(process, std::nullopt, law.mz_pct);
  if (!svg_path.empty()) {
    if (plot.truncated())
      tool.warn(fmt::format("the plot shows the first {} IPO cycles only", TurningSvg::kMaxSamples));
    TurningPlotInfo info;
    info.mz_pct = law.mz_pct;
    info.title = fmt::format(
        "fuzzyfeed --variant {}: M_z {:g} %, {:g} mm/rev, v_c {:g} m/min, IPO {:g} ms, K_v {:g}, "
        "lag {:g} ms, noise {:g} %; {:.1f} s against {:.1f} s at 100 %",
        variant, law.mz_pct, process.feed_mm_rev, process.cutting_speed_m_min, process.ipo_s * 1e3, process.kv,
        process.load_smoothing_s * 1e3, process.noise_pct, run.time_s, baseline.time_s);
    plot.write(svg_path, info);
  }

  const tk::Record summary = summary_record(variant, law.mz_pct, run, baseline, process);
  tk::io::RecordWriter writer(tool.output_format());
  if (settings.segments) {
    std::vector<std::string> columns;
    const tk::Record segment_shape = segment_record(SegmentStats{});
    for (const auto& [key, value] : segment_shape.items()) columns.push_back(key);
    for (const auto& [key, value] : summary.items())
      if (key != "record") columns.push_back(key);
    writer.declare_fields(columns);  // CSV: one header for both kinds of record
    for (const SegmentStats& s : run.segments) writer.write(segment_record(s));
  }
  writer.write(summary);
  writer.flush();
}

}  // namespace fuzzyfeed
