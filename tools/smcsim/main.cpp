/// @file main.cpp
/// @brief smcsim: sliding-mode control of a linear-motor feed drive (Rubio,
/// Ibeas & Kollár) against PID and the P-PD cascade, as a time series, a
/// summary, or a sweep of gains run on every core.
#include <fmt/format.h>

#include <cmath>
#include <thread>

#include "cli/number_option.hpp"
#include "cli/tool_app.hpp"
#include "concurrency/ordered_pool.hpp"
#include "control/feed_drive_plot.hpp"
#include "control/feed_drive_sim.hpp"
#include "io/error.hpp"
#include "io/record_writer.hpp"

namespace {

using namespace tk::control;

/// The gains a sweep may vary; one value each outside a sweep.
struct GainGrids {
  std::string lambda = "40", alpha = "200", beta = "200";
};

struct SweepPoint {
  FeedDriveConfig config;
};

const std::vector<std::string> kSummaryFields{
    "controller", "Lambda", "alpha", "beta", "rms_error_mm", "max_error_mm", "rms_velocity_error_mm_s", "rms_s", "chattering",
    "hf_share", "effort_rms_n", "max_force_n", "saturated_share", "measured_s", "plant_steps", "diverged"};

tk::Record summary_record(const FeedDriveConfig& c, const FeedDriveSummary& s) {
  tk::Record r{{"controller", controller_name(c.gains.kind)}};
  if (c.gains.kind == ControllerKind::smc) r["Lambda"] = c.gains.switching;
  if (c.gains.kind == ControllerKind::sta) r["alpha"] = c.gains.alpha, r["beta"] = c.gains.beta;
  r["rms_error_mm"] = s.rms_error_mm, r["max_error_mm"] = s.max_error_mm;
  r["rms_velocity_error_mm_s"] = s.rms_velocity_error_mm_s, r["rms_s"] = s.rms_s;
  r["chattering"] = s.chattering_n_s, r["hf_share"] = s.hf_share;
  r["effort_rms_n"] = s.effort_rms_n, r["max_force_n"] = s.max_force_n, r["saturated_share"] = s.saturated_share;
  r["measured_s"] = s.measured_s, r["plant_steps"] = s.plant_steps, r["diverged"] = s.diverged;
  if (s.diverged) r["diverged_at_s"] = s.diverged_at_s;
  return r;
}

double single_value(const std::string& text, const char* option) {
  const std::vector<double> values = tk::cli::parse_grid(text, option);
  if (values.size() != 1) throw tk::UsageError(fmt::format("{} takes one value here; ranges are for 'smcsim sweep'", option));
  return values[0];
}

void run_sweep(FeedDriveConfig base, const GainGrids& grids, unsigned threads, tk::io::OutputFormat format) {
  std::vector<SweepPoint> points;
  if (base.gains.kind == ControllerKind::smc) {
    for (const double lambda : tk::cli::parse_grid(grids.lambda, "--Lambda")) {
      base.gains.switching = lambda;
      points.push_back({base});
    }
  } else if (base.gains.kind == ControllerKind::sta) {
    for (const double alpha : tk::cli::parse_grid(grids.alpha, "--alpha"))
      for (const double beta : tk::cli::parse_grid(grids.beta, "--beta")) {
        base.gains.alpha = alpha, base.gains.beta = beta;
        points.push_back({base});
      }
  } else {
    throw tk::UsageError("a sweep varies --Lambda (smc) or --alpha and --beta (sta)");
  }
  for (const SweepPoint& p : points) p.config.validate();  // every setting checked before any runs
  tk::io::RecordWriter writer(format);
  writer.declare_fields(kSummaryFields);
  tk::OrderedPool<SweepPoint, tk::Record> pool(
      threads, [](SweepPoint& p) { return summary_record(p.config, simulate_feed_drive(p.config)); },
      [&](tk::Record& r) { writer.write(r); });
  for (SweepPoint& p : points) pool.submit(std::move(p));
  pool.finish();
  writer.flush();
}

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
          values = {s.t_s, s.x_ref_mm, s.x_mm, s.error_mm, s.error_rate_mm_s, s.surface_mm_s, s.force_n, s.disturbance_n};
          writer.write_numbers(values, 0);
        },
        every);
  }
  if (summary_only) {
    writer.declare_fields(kSummaryFields);
    writer.write(summary_record(config, summary));
  }
  writer.flush();
  if (plotting) plot.write(svg_path, fmt::format("smcsim --controller {}: {}", controller_name(config.gains.kind), config.reference.describe()));
  if (summary.diverged && !summary_only)
    throw tk::Error(fmt::format("the loop diverged at t = {} s (error beyond {} mm)", summary.diverged_at_s, config.divergence_mm));
}

}  // namespace

int main(int argc, char** argv) {
  tk::cli::ToolApp tool("smcsim",
                        "Sliding-mode control of a linear-motor feed drive (Rubio, Ibeas & Kollár) against PID and the "
                        "P-PD cascade: simulates the sampled loop with a micro-milling cutting force and writes a time "
                        "series (t, x_ref, x, e, e_dot, S, F, F_d), a --summary record, or, with 'sweep', one summary "
                        "per gain setting.",
                        "Lengths in mm, forces in N; gains Lambda, alpha, beta in the --units force unit. See smcsim(1).");
  tool.add_threads_option();
  FeedDriveConfig c;
  GainGrids grids;
  std::string controller = "smc", units = "mm", reference = "sine", reference_file, svg_path;
  double amplitude = 1, omega = 3, step_at = 0, slope = 1;
  bool summary_only = false, seed_sign = false, no_cut = false;
  std::uint64_t every = 10;
  CLI::App& app = tool.app();
  const std::string ctl = "Controllers", plant = "Plant", ref = "Reference", cut = "Cutting force", sim = "Simulation", out = "Output";
  app.add_option("--controller", controller, "smc, sta, pid or ppd")->check(CLI::IsMember({"smc", "sta", "pid", "ppd"}))->capture_default_str()->group(ctl);
  app.add_option("--Lambda", grids.lambda, "smc: switching gain Λ (force unit; a range in a sweep)")->capture_default_str()->type_name("F")->group(ctl);
  app.add_option("--alpha", grids.alpha, "sta: α (a range in a sweep)")->capture_default_str()->group(ctl);
  app.add_option("--beta", grids.beta, "sta: β (a range in a sweep)")->capture_default_str()->group(ctl);
  app.add_option("--mu", c.gains.mu, "surface S = ė + μ e + λ ∫e: μ, 1/s")->capture_default_str()->group(ctl);
  app.add_option("--lambda", c.gains.lambda, "surface: λ, 1/s²")->capture_default_str()->group(ctl);
  app.add_option("--boundary-layer", c.gains.boundary_layer, "smc: sat(S/φ) instead of sign(S), φ in mm/s... (0: sign)")->capture_default_str()->type_name("PHI")->group(ctl);
  app.add_flag("--seed-sign", seed_sign, "switch with −Λ sign(S) as the seed writes it (destabilises: see smcsim(1))")->group(ctl);
  app.add_option("--pid-bandwidth", c.gains.pid_bandwidth_hz, "pid: default gains place a triple pole here, Hz")->capture_default_str()->type_name("HZ")->group(ctl);
  app.add_option("--kp", c.gains.kp, "pid: proportional gain, kg/s² (N/m)")->group(ctl);
  app.add_option("--ki", c.gains.ki, "pid: integral gain, kg/s³")->group(ctl);
  app.add_option("--kd", c.gains.kd, "pid: derivative gain, kg/s")->group(ctl);
  app.add_option("--pid-ff", c.gains.pid_feedforward, "pid: share of m̂ ẍ_ref + b̂ ẋ_ref fed forward, 0-1")->capture_default_str()->group(ctl);
  app.add_option("--kv", c.gains.position_gain, "ppd: position loop gain K_v, 1/s")->capture_default_str()->group(ctl);
  app.add_option("--velocity-bandwidth", c.gains.velocity_bandwidth_hz, "ppd: velocity P gain = m̂·2π·this, Hz")->capture_default_str()->type_name("HZ")->group(ctl);
  app.add_option("--kvp", c.gains.velocity_p, "ppd: velocity loop P gain, kg/s (overrides the bandwidth)")->group(ctl);
  app.add_option("--kvd", c.gains.velocity_d, "ppd: velocity loop D gain, kg")->capture_default_str()->group(ctl);
  app.add_option("--velocity-ff", c.gains.velocity_feedforward, "ppd: share of the reference velocity fed forward, 0-1")->capture_default_str()->group(ctl);

  app.add_option("--mass", c.plant.mass_kg, "the axis's mass m, kg")->capture_default_str()->group(plant);
  app.add_option("--damping", c.plant.damping_kg_s, "viscous damping b, kg/s")->capture_default_str()->group(plant);
  app.add_option("--mass-end", c.plant.mass_end_kg, "the mass drifts linearly to this by the end (material removal)")->group(plant);
  app.add_option("--damping-end", c.plant.damping_end_kg_s, "the damping drifts linearly to this by the end (lubricant)")->group(plant);
  app.add_option("--mass-estimate", c.mass_estimate_kg, "m̂, the controller's mass")->capture_default_str()->group(plant);
  app.add_option("--damping-estimate", c.damping_estimate_kg_s, "b̂, the controller's damping")->capture_default_str()->group(plant);
  app.add_option("--kt", c.amplifier_a_v, "current amplifier gain K_t, A/V")->capture_default_str()->group(plant);
  app.add_option("--ka", c.force_constant_n_a, "motor force constant K_a, N/A")->capture_default_str()->group(plant);
  app.add_option("--voltage-limit", c.voltage_limit_v, "the amplifier's input saturates at ± this, V")->capture_default_str()->group(plant);

  app.add_option("--reference", reference, "sine, step or ramp")->check(CLI::IsMember({"sine", "step", "ramp"}))->capture_default_str()->group(ref);
  app.add_option("--reference-file", reference_file, "records t, x (mm), optionally v, a: the reference from samples")->type_name("FILE")->group(ref);
  app.add_option("--amplitude", amplitude, "sine amplitude or step height, mm")->capture_default_str()->type_name("MM")->group(ref);
  app.add_option("--omega", omega, "sine frequency, rad/s")->capture_default_str()->group(ref);
  app.add_option("--slope", slope, "ramp speed, mm/s")->capture_default_str()->group(ref);
  app.add_option("--start", step_at, "step or ramp start, s")->capture_default_str()->type_name("S")->group(ref);

  app.add_flag("--no-cut", no_cut, "no cutting force")->group(cut);
  app.add_option("--teeth", c.cut.teeth, "flutes")->capture_default_str()->group(cut);
  app.add_option("--tool-diameter", c.cut.diameter_mm, "mm")->capture_default_str()->group(cut);
  app.add_option("--spindle", c.cut.spindle_rpm, "spindle speed, rpm")->capture_default_str()->group(cut);
  app.add_option("--axial-depth", c.cut.axial_depth_mm, "mm")->capture_default_str()->group(cut);
  app.add_option("--radial-depth", c.cut.radial_depth_mm, "mm (up-milling); default a full slot")->group(cut);
  app.add_option("--feed", c.cut.feed_mm_min, "mm/min")->capture_default_str()->group(cut);
  app.add_option("--ktc", c.cut.ktc_n_mm2, "tangential shear coefficient, N/mm²")->capture_default_str()->group(cut);
  app.add_option("--krc", c.cut.krc_n_mm2, "radial shear coefficient, N/mm²")->capture_default_str()->group(cut);
  app.add_option("--kte", c.cut.kte_n_mm, "tangential edge coefficient, N/mm")->capture_default_str()->group(cut);
  app.add_option("--kre", c.cut.kre_n_mm, "radial edge coefficient, N/mm")->capture_default_str()->group(cut);

  app.add_option("--duration", c.duration_s, "simulated time, s")->capture_default_str()->type_name("S")->group(sim);
  app.add_option("--period", c.period_s, "control period, s")->capture_default_str()->type_name("S")->group(sim);
  app.add_option("--substeps", c.substeps, "exact plant steps per control period")->capture_default_str()->type_name("N")->group(sim);
  app.add_option("--encoder", c.encoder_mm, "encoder resolution, mm (0: none)")->capture_default_str()->type_name("MM")->group(sim);
  app.add_option("--position-filter", c.position_filter_hz, "low-pass on the position estimate, Hz (0: none)")->capture_default_str()->type_name("HZ")->group(sim);
  app.add_option("--velocity-filter", c.velocity_filter_hz, "low-pass on the velocity estimate, Hz (0: none)")->capture_default_str()->type_name("HZ")->group(sim);
  app.add_option("--units", units, "mm: gains in kg·mm/s² (the seed's scale); m: in newtons")->check(CLI::IsMember({"mm", "m"}))->capture_default_str()->group(sim);
  app.add_option("--initial-position", c.initial_position_mm, "x(0), mm (default: on the reference)")->type_name("MM")->group(sim);
  app.add_option("--initial-velocity", c.initial_velocity_mm_s, "ẋ(0), mm/s (default: the reference's)")->type_name("MM/S")->group(sim);

  app.add_flag("--summary", summary_only, "one summary record instead of the time series")->group(out);
  app.add_option("--every", every, "a time-series record every N control periods")->capture_default_str()->type_name("N")->group(out);
  app.add_option("--settle", c.settle_s, "summary figures from this time on, s")->capture_default_str()->type_name("S")->group(out);
  app.add_option("--hf-cutoff", c.hf_cutoff_hz, "hf_share: share of F's power above this, Hz")->capture_default_str()->type_name("HZ")->group(out);
  app.add_option("--svg", svg_path, "the seed's four panels (position, errors, control) as SVG")->type_name("FILE")->group(out);
  CLI::App* sweep = app.add_subcommand("sweep", "one summary record per gain setting (--Lambda, or --alpha and --beta, as FROM:TO:STEP), on -j threads");
  sweep->fallthrough();

  return tool.run(argc, argv, [&] {
    c.gains.kind = parse_controller_kind(controller);
    c.gains.switching_sign = seed_sign ? -1 : 1;
    c.length_unit_m = units == "m" ? 1 : 1e-3;
    c.cut.enabled = !no_cut;
    if (every < 1) throw tk::UsageError("--every must be at least 1");
    if (!reference_file.empty())
      c.reference = Reference::from_records(reference_file);
    else if (reference == "step")
      c.reference = Reference::step(amplitude, step_at);
    else if (reference == "ramp")
      c.reference = Reference::ramp(slope, step_at);
    else
      c.reference = Reference::sine(amplitude, omega);
    if (sweep->parsed()) {
      if (!svg_path.empty()) throw tk::UsageError("--svg draws one run, not a sweep");
      unsigned threads = tool.common().threads;
      if (app.get_option("--threads")->count() == 0) threads = std::max(1u, std::thread::hardware_concurrency());
      run_sweep(c, grids, threads, tool.output_format());
      return;
    }
    c.gains.switching = single_value(grids.lambda, "--Lambda");
    c.gains.alpha = single_value(grids.alpha, "--alpha");
    c.gains.beta = single_value(grids.beta, "--beta");
    run_single(c, summary_only, every, svg_path, tool.output_format());
  });
}
