/// @file main.cpp
/// @brief smcsim: sliding-mode control of a linear-motor feed drive (Rubio,
/// Ibeas & Kollár) against PID and the P-PD cascade, as a time series, a
/// summary, or a sweep of gains run on every core. The modes are files of
/// their own (modes.hpp); this one wires the options.
#include <fmt/format.h>

#include <algorithm>
#include <thread>

#include "cli/option_checks.hpp"
#include "cli/tool_app.hpp"
#include "control/reference.hpp"
#include "io/error.hpp"
#include "modes.hpp"

using namespace smcsim;

int main(int argc, char** argv) {
  tk::cli::ToolApp tool("smcsim",
                        "Sliding-mode control of a linear-motor feed drive (Rubio, Ibeas & Kollár) against PID and the "
                        "P-PD cascade: simulates the sampled loop with a micro-milling cutting force and writes a time "
                        "series (t, x_ref, x, e, e_dot, S, F, F_d), a --summary record, or, with 'sweep', one summary "
                        "per gain setting.",
                        "Lengths in mm, forces in N; gains Lambda, alpha, beta in the --units force unit. Real values "
                        "lie within ±1e12 (positive ones from 1e-12); a run is at most 1e7 control periods and 1e8 "
                        "plant steps. See smcsim(1).");
  tool.add_threads_option();
  FeedDriveConfig c;
  GainGrids grids;
  std::string controller = "smc", units = "mm", reference = "sine", reference_file, svg_path;
  double amplitude = 1, omega = 3, step_at = 0, slope = 1;
  bool summary_only = false, seed_sign = false, seed_bracket = false, no_cut = false;
  std::uint64_t every = 10;
  const CLI::Validator finite_value = tk::cli::number_check(tk::cli::NumberDomain::finite),
                       non_negative = tk::cli::number_check(tk::cli::NumberDomain::non_negative),
                       positive = tk::cli::number_check(tk::cli::NumberDomain::positive),
                       fraction = tk::cli::number_check(tk::cli::NumberDomain::fraction);
  CLI::App& app = tool.app();
  const std::string ctl = "Controllers", plant = "Plant", ref = "Reference", cut = "Cutting force", sim = "Simulation",
                    out = "Output";
  app.add_option("--controller", controller, "smc, sta, pid or ppd")
      ->check(CLI::IsMember({"smc", "sta", "pid", "ppd"}))
      ->capture_default_str()
      ->group(ctl);
  app.add_option("--Lambda", grids.lambda, "smc: switching gain Λ (force unit; a range in a sweep)")
      ->capture_default_str()
      ->type_name("F")
      ->group(ctl);
  app.add_option("--alpha", grids.alpha, "sta: α (a range in a sweep)")
      ->capture_default_str()
      ->type_name("F")
      ->group(ctl);
  app.add_option("--beta", grids.beta, "sta: β (a range in a sweep)")
      ->capture_default_str()
      ->type_name("F")
      ->group(ctl);
  app.add_option("--mu", c.gains.mu, "surface S = ė + μ e + λ ∫e: μ, 1/s")
      ->check(non_negative)
      ->capture_default_str()
      ->group(ctl);
  app.add_option("--lambda", c.gains.lambda, "surface: λ, 1/s²")
      ->check(non_negative)
      ->capture_default_str()
      ->group(ctl);
  app.add_option("--boundary-layer", c.gains.boundary_layer,
                 "smc: sat(S/φ) instead of sign(S); φ in length units per second (0: sign)")
      ->check(non_negative)
      ->capture_default_str()
      ->type_name("PHI")
      ->group(ctl);
  app.add_flag("--seed-sign", seed_sign,
               "smc, sta: switch with −Λ sign(S) as the paper writes it (destabilises: see smcsim(1))")
      ->group(ctl);
  app.add_flag("--seed-bracket", seed_bracket,
               "smc, sta: the bracket of the paper's eq. 8-9, m̂[ẍ_ref + (b/m)ẋ_ref + λe] with b/m read b̂/m̂, not F_eq "
               "(see smcsim(1))")
      ->group(ctl);
  app.add_option("--pid-bandwidth", c.gains.pid_bandwidth_hz, "pid: default gains place a triple pole here, Hz")
      ->check(tk::cli::range_check(1e-3, 1e5))
      ->capture_default_str()
      ->type_name("HZ")
      ->group(ctl);
  app.add_option("--kp", c.gains.kp, "pid: proportional gain, kg/s² (N/m)")->check(non_negative)->group(ctl);
  app.add_option("--ki", c.gains.ki, "pid: integral gain, kg/s³")->check(non_negative)->group(ctl);
  app.add_option("--kd", c.gains.kd, "pid: derivative gain, kg/s")->check(non_negative)->group(ctl);
  app.add_option("--pid-ff", c.gains.pid_feedforward, "pid: share of m̂ ẍ_ref + b̂ ẋ_ref fed forward, 0-1")
      ->check(fraction)
      ->capture_default_str()
      ->group(ctl);
  app.add_option("--kv", c.gains.position_gain, "ppd: position loop gain K_v, 1/s")
      ->check(non_negative)
      ->capture_default_str()
      ->group(ctl);
  app.add_option("--velocity-bandwidth", c.gains.velocity_bandwidth_hz, "ppd: velocity P gain = m̂·2π·this, Hz")
      ->check(tk::cli::range_check(1e-3, 1e5))
      ->capture_default_str()
      ->type_name("HZ")
      ->group(ctl);
  app.add_option("--kvp", c.gains.velocity_p, "ppd: velocity loop P gain, kg/s (overrides the bandwidth)")
      ->check(non_negative)
      ->group(ctl);
  app.add_option("--kvd", c.gains.velocity_d, "ppd: velocity loop D gain, kg")
      ->check(non_negative)
      ->capture_default_str()
      ->group(ctl);
  app.add_option("--velocity-ff", c.gains.velocity_feedforward, "ppd: share of the reference velocity fed forward, 0-1")
      ->check(fraction)
      ->capture_default_str()
      ->group(ctl);

  app.add_option("--mass", c.plant.mass_kg, "the axis's mass m, kg")
      ->check(tk::cli::range_check(1e-3, 1e4))
      ->capture_default_str()
      ->group(plant);
  app.add_option("--damping", c.plant.damping_kg_s, "viscous damping b, kg/s")
      ->check(non_negative)
      ->capture_default_str()
      ->group(plant);
  app.add_option("--mass-end", c.plant.mass_end_kg, "the mass drifts linearly to this by the end (material removal)")
      ->check(tk::cli::range_check(1e-3, 1e4))
      ->group(plant);
  app.add_option("--damping-end", c.plant.damping_end_kg_s,
                 "the damping drifts linearly to this by the end (lubricant)")
      ->check(non_negative)
      ->group(plant);
  app.add_option("--mass-estimate", c.mass_estimate_kg, "m̂, the controller's mass")
      ->check(tk::cli::range_check(1e-3, 1e4))
      ->capture_default_str()
      ->group(plant);
  app.add_option("--damping-estimate", c.damping_estimate_kg_s, "b̂, the controller's damping")
      ->check(non_negative)
      ->capture_default_str()
      ->group(plant);
  app.add_option("--kt", c.amplifier_a_v, "current amplifier gain K_t, A/V")
      ->check(tk::cli::range_check(1e-3, 1000))
      ->capture_default_str()
      ->group(plant);
  app.add_option("--ka", c.force_constant_n_a, "motor force constant K_a, N/A")
      ->check(tk::cli::range_check(1e-3, 1e4))
      ->capture_default_str()
      ->group(plant);
  app.add_option("--voltage-limit", c.voltage_limit_v, "the amplifier's input saturates at ± this, V")
      ->check(tk::cli::range_check(0.01, 1000))
      ->capture_default_str()
      ->group(plant);

  CLI::Option* reference_option = app.add_option("--reference", reference, "sine, step or ramp")
                                      ->check(CLI::IsMember({"sine", "step", "ramp"}))
                                      ->capture_default_str()
                                      ->group(ref);
  CLI::Option* file_option =
      app.add_option("--reference-file", reference_file,
                     "records t, x (mm), optionally v, a: the reference from samples ('-': stdin)")
          ->type_name("FILE")
          ->group(ref);
  CLI::Option* amplitude_option = app.add_option("--amplitude", amplitude, "sine amplitude or step height, mm")
                                      ->check(tk::cli::range_check(-1e4, 1e4))
                                      ->capture_default_str()
                                      ->type_name("MM")
                                      ->group(ref);
  CLI::Option* omega_option = app.add_option("--omega", omega, "sine frequency, rad/s")
                                  ->check(tk::cli::range_check(0, 1e6))
                                  ->capture_default_str()
                                  ->group(ref);
  CLI::Option* slope_option = app.add_option("--slope", slope, "ramp speed, mm/s")
                                  ->check(tk::cli::range_check(-1e5, 1e5))
                                  ->capture_default_str()
                                  ->group(ref);
  CLI::Option* start_option = app.add_option("--start", step_at, "step or ramp start, s")
                                  ->check(finite_value)
                                  ->capture_default_str()
                                  ->type_name("S")
                                  ->group(ref);
  for (CLI::Option* shape : {reference_option, amplitude_option, omega_option, slope_option, start_option})
    file_option->excludes(shape);

  app.add_flag("--no-cut", no_cut, "no cutting force")->group(cut);
  app.add_option("--teeth", c.cut.teeth, "flutes")
      ->check(tk::cli::count_check(1, 64))
      ->capture_default_str()
      ->group(cut);
  app.add_option("--tool-diameter", c.cut.diameter_mm, "mm")
      ->check(tk::cli::range_check(0.01, 100))
      ->capture_default_str()
      ->group(cut);
  app.add_option("--spindle", c.cut.spindle_rpm, "spindle speed, rpm")
      ->check(tk::cli::range_check(1, 1e6))
      ->capture_default_str()
      ->group(cut);
  app.add_option("--axial-depth", c.cut.axial_depth_mm, "mm")
      ->check(tk::cli::range_check(1e-4, 100))
      ->capture_default_str()
      ->group(cut);
  app.add_option("--radial-depth", c.cut.radial_depth_mm, "mm (up-milling); default a full slot")
      ->check(tk::cli::range_check(1e-4, 100))
      ->group(cut);
  app.add_option("--feed", c.cut.feed_mm_min, "mm/min")
      ->check(tk::cli::range_check(0, 1e5))
      ->capture_default_str()
      ->group(cut);
  app.add_option("--ktc", c.cut.ktc_n_mm2, "tangential shear coefficient, N/mm²")
      ->check(finite_value)
      ->capture_default_str()
      ->group(cut);
  app.add_option("--krc", c.cut.krc_n_mm2, "radial shear coefficient, N/mm²")
      ->check(finite_value)
      ->capture_default_str()
      ->group(cut);
  app.add_option("--kte", c.cut.kte_n_mm, "tangential edge coefficient, N/mm")
      ->check(finite_value)
      ->capture_default_str()
      ->group(cut);
  app.add_option("--kre", c.cut.kre_n_mm, "radial edge coefficient, N/mm")
      ->check(finite_value)
      ->capture_default_str()
      ->group(cut);

  app.add_option("--duration", c.duration_s, "simulated time, s")
      ->check(tk::cli::range_check(1e-6, 1e5))
      ->capture_default_str()
      ->type_name("S")
      ->group(sim);
  app.add_option("--period", c.period_s, "control period, s")
      ->check(tk::cli::range_check(1e-7, 1))
      ->capture_default_str()
      ->type_name("S")
      ->group(sim);
  app.add_option("--substeps", c.substeps, "exact plant steps per control period")
      ->check(tk::cli::count_check(1, 100000))
      ->capture_default_str()
      ->type_name("N")
      ->group(sim);
  app.add_option("--encoder", c.encoder_mm, "encoder resolution, mm (0: none)")
      ->check(tk::cli::range_check(0, 1))
      ->capture_default_str()
      ->type_name("MM")
      ->group(sim);
  app.add_option("--position-filter", c.position_filter_hz, "low-pass on the position estimate, Hz (0: none)")
      ->check(tk::cli::range_check(0, 1e7))
      ->capture_default_str()
      ->type_name("HZ")
      ->group(sim);
  app.add_option("--velocity-filter", c.velocity_filter_hz, "low-pass on the velocity estimate, Hz (0: none)")
      ->check(tk::cli::range_check(0, 1e7))
      ->capture_default_str()
      ->type_name("HZ")
      ->group(sim);
  app.add_option("--units", units, "mm: gains in kg·mm/s² (mN); m: in newtons (see smcsim(1), UNITS)")
      ->check(CLI::IsMember({"mm", "m"}))
      ->capture_default_str()
      ->group(sim);
  app.add_option("--initial-position", c.initial_position_mm, "x(0), mm (default: on the reference)")
      ->check(finite_value)
      ->type_name("MM")
      ->group(sim);
  app.add_option("--initial-velocity", c.initial_velocity_mm_s, "ẋ(0), mm/s (default: the reference's)")
      ->check(finite_value)
      ->type_name("MM/S")
      ->group(sim);

  app.add_flag("--summary", summary_only, "one summary record instead of the time series")->group(out);
  app.add_option("--every", every, "a time-series record every N control periods")
      ->check(tk::cli::count_check(1, 1000000000000))
      ->capture_default_str()
      ->type_name("N")
      ->group(out);
  app.add_option("--settle", c.settle_s, "summary figures from this time on, s")
      ->check(non_negative)
      ->capture_default_str()
      ->type_name("S")
      ->group(out);
  app.add_option("--hf-cutoff", c.hf_cutoff_hz, "hf_share: share of F's power above this, Hz (0: not computed)")
      ->check(tk::cli::range_check(0, 1e7))
      ->capture_default_str()
      ->type_name("HZ")
      ->group(out);
  app.add_option("--svg", svg_path, "the paper's four panels (position, errors, control) as SVG")
      ->type_name("FILE")
      ->group(out);
  CLI::App* sweep = app.add_subcommand(
      "sweep", "one summary record per gain setting (--Lambda, or --alpha and --beta, as FROM:TO:STEP), on -j threads");
  sweep->fallthrough();

  return tool.run(argc, argv, [&] {
    c.gains.kind = parse_controller_kind(controller);
    if ((seed_sign || seed_bracket) && c.gains.kind != ControllerKind::smc && c.gains.kind != ControllerKind::sta)
      throw tk::UsageError(
          fmt::format("--seed-sign and --seed-bracket change the sliding-mode laws (smc, sta), not {}", controller));
    c.gains.switching_sign = seed_sign ? -1 : 1;
    c.gains.printed_bracket = seed_bracket;
    c.length_unit_m = units == "m" ? 1 : 1e-3;
    c.cut.enabled = !no_cut;
    const auto given = [&](const char* option) { return app.get_option(option)->count() > 0; };
    if (sweep->parsed()) {
      if (!svg_path.empty()) throw tk::UsageError("--svg draws one run, not a sweep");
      if (c.gains.kind == ControllerKind::pid || c.gains.kind == ControllerKind::ppd)
        throw tk::UsageError(
            fmt::format("a sweep varies --Lambda (smc) or --alpha and --beta (sta), not {} gains", controller));
      if (c.gains.kind == ControllerKind::smc && (given("--alpha") || given("--beta")))
        throw tk::UsageError("--alpha and --beta are sta gains; a sweep of smc varies --Lambda");
      if (c.gains.kind == ControllerKind::sta && given("--Lambda"))
        throw tk::UsageError("--Lambda is an smc gain; a sweep of sta varies --alpha and --beta");
    } else {
      c.gains.switching = single_value(grids.lambda, "--Lambda");
      c.gains.alpha = single_value(grids.alpha, "--alpha");
      c.gains.beta = single_value(grids.beta, "--beta");
    }
    check_combination(c);  // before a reference file is read
    if (!reference_file.empty()) c.reference = Reference::from_records(reference_file);
    else if (reference == "step") c.reference = Reference::step(amplitude, step_at);
    else if (reference == "ramp") c.reference = Reference::ramp(slope, step_at);
    else c.reference = Reference::sine(amplitude, omega);
    if (sweep->parsed()) {
      unsigned threads = tool.common().threads;
      if (!given("--threads")) threads = std::max(1u, std::thread::hardware_concurrency());
      run_sweep(c, grids, threads, tool.output_format());
      return;
    }
    run_single(c, summary_only, every, svg_path, tool.output_format());
  });
}
