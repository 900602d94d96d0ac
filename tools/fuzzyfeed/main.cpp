/// @file main.cpp
/// @brief fuzzyfeed: the fuzzy adaptive feed-rate override of Stryczek &
/// Orawczak, as a filter over spindle-load records (one record per IPO
/// cycle) and as a closed-loop simulation of a turning pass (--simulate).
/// Each mode is a file of its own (modes.hpp); this one wires the options.
#include "cli/tool_app.hpp"
#include "io/error.hpp"
#include "modes.hpp"

using namespace fuzzyfeed;

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
  SimulateSettings sim;
  bool simulate = false;
  CLI::App& app = tool.app();
  const std::string law_group = "The law (both modes)", sim_group = "Simulation (with --simulate)";
  app.add_option("--mz", law.mz_pct, "M_z, the spindle load (% of rated torque) to hold")
      ->capture_default_str()
      ->type_name("PCT")
      ->group(law_group);
  app.add_option("--variant", sim.variant, "original: formulas (1)-(4); modified: (5), (6), (3), (7)")
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
      app.add_option("--profile", sim.profile_path, "allowance profile records (z_from, z_to, depth or z, depth; mm)")
          ->type_name("FILE"),
      app.add_option("--trace", sim.trace_path, "write one record per IPO cycle to FILE")->type_name("FILE"),
      app.add_option("--svg", sim.svg_path, "plot load and override against time to FILE")->type_name("FILE"),
      app.add_flag("--segments", sim.segments, "a record per constant-allowance segment before the summary"),
      app.add_option("--feed", process.feed_mm_rev, "programmed feed, mm/rev")->capture_default_str()->type_name("MM"),
      app.add_option("--cutting-speed", process.cutting_speed_m_min, "v_c, m/min")
          ->capture_default_str()
          ->type_name("V"),
      app.add_option("--diameter", process.diameter_mm, "workpiece diameter, mm (constant spindle speed from v_c)")
          ->capture_default_str()
          ->type_name("MM"),
      app.add_option("--power", sim.power_kw, "the main drive's rated power, kW")
          ->capture_default_str()
          ->type_name("KW"),
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
    law.variant = parse_override_variant(sim.variant);
    validate(law);
    if (!simulate) {
      for (CLI::Option* option : sim_options)
        if (option->count() > 0) throw tk::UsageError(option->get_name() + " goes with --simulate");
      filter_records(tool.common().inputs, law, tool.output_format());
      return;
    }
    if (!tool.common().inputs.empty())
      throw tk::UsageError("--simulate reads no records (use --profile FILE for the allowance)");
    fuzzyfeed::simulate(sim, law, process, tool);
  });
}
