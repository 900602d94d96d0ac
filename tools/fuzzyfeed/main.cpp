/// @file main.cpp
/// @brief fuzzyfeed: the fuzzy adaptive feed-rate override of Stryczek &
/// Orawczak, as a filter over spindle-load records (one record per IPO
/// cycle) and as a closed-loop simulation of a turning pass (--simulate).
#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <memory>

#include "cli/option_checks.hpp"
#include "cli/tool_app.hpp"
#include "io/error.hpp"
#include "io/record_fields.hpp"
#include "io/record_reader.hpp"
#include "io/record_writer.hpp"
#include "machining/feed_override.hpp"
#include "machining/turning_profile.hpp"
#include "machining/turning_sim.hpp"
#include "machining/turning_svg.hpp"

namespace {

using namespace tk::machining;

/// The most IPO cycles a run with --trace may take (fuzzyfeed(1), OPTIONS).
constexpr double kMaxTraceCycles = 2e6;

/// The stream mode: each record gets the law's answer to its load.
void filter_records(const std::vector<std::string>& inputs, const FeedOverrideParams& law_params,
                    tk::io::OutputFormat format) {
  FeedOverride law(law_params);
  tk::io::RecordWriter writer(format);
  writer.declare_fields({"wk", "override", "feed_out"});
  tk::io::RecordReader reader(inputs.empty() ? std::vector<std::string>{"-"} : inputs);
  reader.expect_columns({{"t", "load"}});
  tk::Record record;
  double previous_t = -std::numeric_limits<double>::infinity();
  while (reader.next(record)) {
    const tk::Location where = reader.where();
    const double t = tk::io::number_field(record, "t", where);
    if (!(t > previous_t)) throw tk::Error(fmt::format("t must increase strictly: {} after {}", t, previous_t), where);
    previous_t = t;
    const double load = tk::io::number_field(record, "load", where);
    if (!(load >= 0 && load <= 100)) throw tk::Error(fmt::format("load {} is outside 0-100 % of rated", load), where);
    const std::optional<double> feed = tk::io::optional_number_field(record, "feed", where);
    if (feed && *feed < 0) throw tk::Error(fmt::format("feed {} is negative", *feed), where);
    const OverrideStep step = law.step(load);
    record["wk"] = step.wk;
    record["override"] = step.override_pct;
    if (feed) {
      const double feed_out = *feed * step.override_pct / 100;
      if (!std::isfinite(feed_out)) throw tk::Error(fmt::format("feed {} times the override overflows", *feed), where);
      record["feed_out"] = feed_out;
    }
    writer.write(record);
  }
  writer.flush();
}

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

tk::Record segment_record(const SegmentStats& s) {
  return {{"record", "segment"},
          {"segment", s.index},
          {"z_from", s.segment.z_from_mm},
          {"z_to", s.segment.z_to_mm},
          {"depth", s.segment.depth_mm},
          {"start_s", s.start_s},
          {"duration_s", s.duration_s},
          {"load_at_100_pct", s.load_at_100_pct},
          {"mean_load_pct", s.mean_load_pct},
          {"max_load_pct", s.max_load_pct},
          {"mean_override_pct", s.mean_override_pct},
          {"settled_override_pct", s.settled_override_pct},
          {"oscillation_pct", s.oscillation_pct},
          {"override_sd_pct", s.override_sd_pct}};
}

}  // namespace

int main(int argc, char** argv) {
  tk::cli::ToolApp tool(
      "fuzzyfeed",
      "Fuzzy adaptive feed-rate override, Stryczek & Orawczak's formulas (1)-(7): reads spindle-load "
      "records (t, load, optionally feed), one per IPO cycle, and adds the correction coefficient wk and "
      "the new override; or simulates a turning pass under the law (--simulate).",
      "See fuzzyfeed(1).");
  tool.add_input_files("load records (t, load[, feed]); standard input when none or '-'");
  FeedOverrideParams law;
  TurningParams process;
  std::string variant = "original", profile_path, trace_path, svg_path;
  double power_kw = 9;
  bool simulate = false, segments = false;
  CLI::App& app = tool.app();
  const std::string law_group = "The law (both modes)", sim_group = "Simulation (with --simulate)";
  app.add_option("--mz", law.mz_pct, "M_z, the spindle load (% of rated torque) to hold")
      ->capture_default_str()
      ->type_name("PCT")
      ->group(law_group);
  app.add_option("--variant", variant, "original: formulas (1)-(4); modified: (5), (6), (3), (7)")
      ->check(CLI::IsMember({"original", "modified"}))
      ->capture_default_str()
      ->group(law_group);
  app.add_option("--k", law.k, "modified, (5): W_k = k exp(...) below M_z")->capture_default_str()->group(law_group);
  app.add_option("--p", law.p, "modified, (6): W_k = p exp(...) + (1 - p) above M_z")
      ->capture_default_str()
      ->group(law_group);
  app.add_option("--d", law.d_pct, "modified, (7): O_n = W_k (O_a - d) + d above M_z, %")
      ->capture_default_str()
      ->type_name("PCT")
      ->group(law_group);
  app.add_option("--initial-override", law.initial_override_pct, "O_a before the first cycle, %")
      ->capture_default_str()
      ->type_name("PCT")
      ->group(law_group);
  app.add_option("--min-override", law.min_override_pct, "a floor for the override, % (0: none; the ceiling is 200)")
      ->capture_default_str()
      ->type_name("PCT")
      ->group(law_group);
  app.add_flag("--simulate", simulate, "simulate a turning pass under the law and write a summary record")
      ->group(sim_group);
  std::vector<CLI::Option*> sim_options{
      app.add_option("--profile", profile_path, "allowance profile records (z_from, z_to, depth or z, depth; mm)")
          ->type_name("FILE"),
      app.add_option("--trace", trace_path, "write one record per IPO cycle to FILE")->type_name("FILE"),
      app.add_option("--svg", svg_path, "plot load and override against time to FILE")->type_name("FILE"),
      app.add_flag("--segments", segments, "a record per constant-allowance segment before the summary"),
      app.add_option("--feed", process.feed_mm_rev, "programmed feed, mm/rev")->capture_default_str()->type_name("MM"),
      app.add_option("--cutting-speed", process.cutting_speed_m_min, "v_c, m/min")
          ->capture_default_str()
          ->type_name("V"),
      app.add_option("--diameter", process.diameter_mm, "workpiece diameter, mm (constant spindle speed from v_c)")
          ->capture_default_str()
          ->type_name("MM"),
      app.add_option("--power", power_kw, "the main drive's rated power, kW")->capture_default_str()->type_name("KW"),
      app.add_option("--efficiency", process.cutting.efficiency, "η of the main drive")->capture_default_str(),
      app.add_option("--kc11", process.cutting.kc11_n_mm2, "Kienzle k_c1.1, N/mm² (E295)")->capture_default_str(),
      app.add_option("--mc", process.cutting.mc, "Kienzle exponent m_c (E295)")->capture_default_str(),
      app.add_option("--kappa", process.cutting.kappa_deg, "the tool's setting angle κ_r, degrees")
          ->capture_default_str(),
      app.add_option("--ipo", process.ipo_s, "interpolation cycle, s")->capture_default_str()->type_name("S"),
      app.add_option("--kv", process.kv, "the feed axis's servo gain K_v, (m/min)/mm")
          ->capture_default_str()
          ->type_name("KV"),
      app.add_option("--lag", process.load_smoothing_s, "smoothing time constant of the load signal, s")
          ->capture_default_str()
          ->type_name("S"),
      app.add_option("--noise", process.noise_pct, "σ of the load signal's noise, % of rated")
          ->capture_default_str()
          ->type_name("PCT"),
      app.add_option("--seed", process.seed, "of the noise")->capture_default_str()->type_name("N"),
      app.add_option("--above-tol", process.above_tolerance, "time_above_mz counts load above (1 + this) M_z")
          ->capture_default_str()
          ->type_name("FRAC")};
  for (CLI::Option* option : sim_options) option->group(sim_group);

  return tool.run(argc, argv, [&] {
    law.variant = parse_override_variant(variant);
    validate(law);
    if (!simulate) {
      for (CLI::Option* option : sim_options)
        if (option->count() > 0) throw tk::UsageError(option->get_name() + " goes with --simulate");
      filter_records(tool.common().inputs, law, tool.output_format());
      return;
    }
    if (!tool.common().inputs.empty())
      throw tk::UsageError("--simulate reads no records (use --profile FILE for the allowance)");
    process.cutting.rated_power_w = power_kw * 1000;
    validate(process);
    if (!profile_path.empty()) process.profile = read_profile(profile_path);
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

    tk::Record summary{{"record", "summary"},
                       {"variant", variant},
                       {"mz", law.mz_pct},
                       {"machining_time_s", run.time_s},
                       {"baseline_time_s", baseline.time_s},
                       {"time_ratio", run.time_s / baseline.time_s},
                       {"time_above_mz_s", run.time_above_mz_s},
                       {"baseline_time_above_mz_s", baseline.time_above_mz_s},
                       {"override_oscillation_pct", run.oscillation_pct},
                       {"override_sd_pct", run.override_sd_pct},
                       {"oscillation_segment", run.oscillation_segment},
                       {"mean_override_pct", run.mean_override_pct},
                       {"mean_load_pct", run.mean_load_pct},
                       {"max_load_pct", run.max_load_pct},
                       {"baseline_max_load_pct", baseline.max_load_pct},
                       {"cycles", run.cycles},
                       {"length_mm", process.profile.back().z_to_mm - process.profile.front().z_from_mm},
                       {"spindle_rpm", spindle_speed_rev_s(process) * 60}};
    tk::io::RecordWriter writer(tool.output_format());
    if (segments) {
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
  });
}
