/// @file simulate.cpp
/// @brief subtune --simulate: a simulated batch per policy, against the charts.
#include <fmt/format.h>

#include <algorithm>
#include <optional>

#include "cli/option_checks.hpp"
#include "cli/tool_app.hpp"
#include "io/error.hpp"
#include "io/record_writer.hpp"
#include "modes.hpp"
#include "quality/subtune_report.hpp"

namespace subtune {

// ---- the simulated batch ---------------------------------------------------

/// The most parts a --simulate run may imply, every ARL run counted to
/// --arl-cap (subtune(1), OPTIONS): the defaults imply 2.4e9, about three
/// minutes at 10-18 M parts/s when no policy alarms.
constexpr double kMaxSimulatedParts = 3e9;
/// The most records --trace may write (about 170 bytes each: 350 MB).
constexpr double kMaxTraceRecords = 2e6;

void simulate(const LatheSettings& lathe, const SubTuneSettings& subtune, ChartSettings charts,
              const SimulationOptions& o, const tk::cli::ToolApp& tool) {
  validate(lathe);
  charts.target = lathe.nominal_mm;
  charts.sigma = o.sigma.value_or(in_control_sigma(lathe));
  if (!(charts.sigma > 0))
    throw tk::UsageError("the stable process has no spread (all noise 0): give --sigma for the charts");
  std::vector<PolicyKind> kinds;
  if (o.policy.empty() || o.policy == "all")
    kinds = {PolicyKind::none, PolicyKind::subtune, PolicyKind::shewhart, PolicyKind::ewma, PolicyKind::cusum};
  else kinds = {parse_policy(o.policy)};
  if (!o.svg_path.empty() && kinds.size() != 1)
    throw tk::UsageError("--svg draws one policy's batch: give --policy too");

  // Each policy makes the batch twice (as given and stable) and, but
  // 'none', three ARL estimates of --arl-runs runs of up to --arl-cap parts.
  const double policies = static_cast<double>(kinds.size()), parts = static_cast<double>(lathe.parts);
  const double charted = policies - static_cast<double>(std::ranges::count(kinds, PolicyKind::none));
  tk::cli::require_run_size(
      policies * 2 * parts + charted * 3 * static_cast<double>(o.arl_runs) * static_cast<double>(o.arl_cap),
      kMaxSimulatedParts, "simulated parts at most (every ARL run to its cap)",
      "--parts, --arl-runs, --arl-cap and --policy");
  std::optional<tk::io::RecordFile> trace;
  if (!o.trace_path.empty()) {
    tk::cli::require_run_size(policies * parts, kMaxTraceRecords, "trace records (one a part and policy)",
                              "--trace with --parts and --policy");
    trace.emplace(o.trace_path, tool.output_format());
    trace->declare_fields(trace_fields());
  }
  tk::io::RecordWriter writer(tool.output_format());
  writer.declare_fields(batch_summary_fields());
  for (const PolicyKind kind : kinds) {
    const std::unique_ptr<AdjustmentPolicy> policy = make_policy(kind, subtune, charts);
    SizePlot plot;
    const std::string name(policy_name(kind));
    const LatheOutcome run = simulate_lathe(lathe, *policy, [&](const PartRecord& p) {
      if (trace) trace->write(trace_record(name, p));
      if (!o.svg_path.empty()) plot.add(static_cast<double>(p.part), p.measured_mm, p.level_mm, p.offset_mm, p.size_mm);
    });
    const LatheOutcome stable = simulate_lathe(stable_process(lathe), *policy);
    std::optional<PolicyRunLengths> run_lengths;
    if (kind != PolicyKind::none) {
      const auto arl = [&](double shift, double drift, std::uint64_t salt) {
        return average_run_length(kind, subtune, charts, shift, drift, o.arl_runs, lathe.seed * 7 + salt, o.arl_cap);
      };
      run_lengths = PolicyRunLengths{arl(0, 0, 1), arl(o.shift_sigma, 0, 2), arl(0, o.drift_sigma, 3)};
      const std::uint64_t censored =
          run_lengths->in_control.censored + run_lengths->shifted.censored + run_lengths->drifting.censored;
      if (censored > 0)
        tool.warn(
            fmt::format("policy {}: {} ARL run(s) reached --arl-cap {} without an alarm; those ARLs are lower bounds",
                        name, censored, o.arl_cap));
    }
    const tk::Record r = batch_summary(name, run, stable, run_lengths, charts.sigma);
    writer.write(r);
    if (!o.svg_path.empty()) {
      write_plot(
          plot, o.svg_path,
          {.title = fmt::format("subtune --simulate --policy {}: {} parts, {} corrections, {:.1f} % in tolerance", name,
                                run.parts, run.corrections,
                                100.0 * static_cast<double>(run.in_tolerance) / static_cast<double>(run.parts)),
           .level_label = level_label(kind),
           .nominal = lathe.nominal_mm,
           .lower = lathe.lower_mm,
           .upper = lathe.upper_mm},
          tool);
    }
  }
  writer.flush();
  if (trace) trace->close();
}

}  // namespace subtune
