/// @file main.cpp
/// @brief subtune: active control of a lathe by dimensional sub-tuning
/// (Georgiev, Chetrokov & Salapateva) as a filter over measured sizes; the
/// force-induced-error model of its adaptive control (model, feed, correct);
/// and a simulated batch comparing sub-tuning with the SPC charts.
#include <fmt/format.h>

#include <limits>
#include <optional>

#include "cli/option_checks.hpp"
#include "cli/tool_app.hpp"
#include "io/error.hpp"
#include "modes.hpp"

using namespace subtune;

int main(int argc, char** argv) {
  tk::cli::ToolApp tool(
      "subtune",
      "Active control of a lathe by dimensional sub-tuning (Georgiev, Chetrokov & Salapateva): reads the "
      "measured size of each finished part, in order, fits the regression line A_T(i) = a + i b to the current run, "
      "tests the difference dA = a - A_T(N) (eq. 3-6) and adds n, a, b, s, t, t_crit, decision (insufficient, "
      "none, subtune) and the correction dA. 'model', 'feed' and 'correct' "
      "fit and apply the force-induced-error model; --simulate compares sub-tuning with Shewhart, EWMA "
      "and CUSUM charts on a simulated batch.",
      "Sizes and errors in mm, feeds in mm/rev. See subtune(1).");
  tool.add_input_files(
      "records with the size (JSON Lines, CSV, or one number per line); standard input when none or '-'");
  SubTuneSettings tuning;
  ChartSettings charts;
  LatheSettings lathe;
  SimulationOptions sim;
  std::string alternative = "two-sided", statistic = "slope", correct_to = "start", field = "size", svg_path;
  std::optional<double> lower, upper;
  bool simulate_flag = false;
  using tk::cli::count_check, tk::cli::range_check;
  // The ranges of subtune(1), OPTIONS: sizes within the ±1 km lengths the
  // records may hold, spreads and drifts of a lathe, feeds of a lathe
  // (fuzzyfeed's), chart constants past the published tables.
  const CLI::Validator size_range = range_check(-kMaxLengthMm, kMaxLengthMm), feed_range = range_check(0.001, 5);
  const CLI::Validator alpha_check(
      [](std::string& text) {
        double v = 0;
        return CLI::detail::lexical_cast(text, v) && v >= 1e-12 && v < 1
                   ? std::string()
                   : "must be a number from 1e-12 to below 1, not " + text;
      },
      "in [1e-12, 1)");
  CLI::App& app = tool.app();
  const std::string test = "The sub-tuning test", out = "Output", lathe_group = "Simulated lathe (with --simulate)",
                    chart_group = "Charts (--simulate, or the filter with a chart --policy)";
  app.add_option("--alpha", tuning.alpha, "significance level of the test of dA (the paper prints none)")
      ->check(alpha_check)
      ->capture_default_str()
      ->group(test);
  app.add_option("--alternative", alternative,
                 "two-sided (either drift, the default), greater (growing sizes only) or less")
      ->check(CLI::IsMember({"two-sided", "greater", "less"}))
      ->capture_default_str()
      ->group(test);
  app.add_option("--statistic", statistic,
                 "slope: Student's t of the difference (5) with its regression standard error, N-2 df (level alpha); "
                 "paper: eq. (6) as printed, 2(N-1) df (alarms on noise about half the time at alpha 0.05)")
      ->check(CLI::IsMember({"slope", "paper"}))
      ->capture_default_str()
      ->group(test);
  app.add_option("--min-parts", tuning.min_parts, "no decision before a run has this many parts")
      ->check(count_check(3, 1000000))
      ->capture_default_str()
      ->type_name("N")
      ->group(test);
  app.add_option("--resolution", tuning.resolution,
                 "gauge resolution, mm: s (or S_N) is at least its rounding noise r/sqrt(12)")
      ->check(range_check(0, 10))
      ->capture_default_str()
      ->type_name("MM")
      ->group(test);
  app.add_option("--correct-to", correct_to,
                 "start: by the paper's dA = a - A_T(N), back to the run's starting level; nominal: to --nominal")
      ->check(CLI::IsMember({"start", "nominal"}))
      ->capture_default_str()
      ->group(test);
  app.add_option("--field", field, "the field holding the size")->capture_default_str()->group(out);
  app.add_option("--lower", lower, "lower tolerance limit, mm (a record's 'lower' field overrides it)")
      ->check(size_range)
      ->type_name("MM")
      ->group(out);
  app.add_option("--upper", upper, "upper tolerance limit, mm (a record's 'upper' field overrides it)")
      ->check(size_range)
      ->type_name("MM")
      ->group(out);
  app.add_option("--svg", svg_path, "plot sizes, the regression and the offset against part number to FILE")
      ->type_name("FILE")
      ->group(out);

  CLI::Option* nominal_option =
      app.add_option("--nominal", lathe.nominal_mm, "nominal size, mm (the simulated part's; --correct-to nominal's)")
          ->check(size_range)
          ->capture_default_str()
          ->type_name("MM")
          ->group(out);
  app.add_flag("--simulate", simulate_flag, "simulate a batch and write one summary record per policy")
      ->group(lathe_group);
  app.add_option("--policy", sim.policy,
                 "the filter: subtune (default), or a chart (shewhart, ewma, cusum; needs --nominal and --sigma); "
                 "--simulate: one of these, none, or all (default)")
      ->check(CLI::IsMember({"all", "none", "subtune", "shewhart", "ewma", "cusum"}))
      ->group(test);
  std::vector<CLI::Option*> sim_options{
      app.add_option("--parts", lathe.parts, "parts in the batch")
          ->check(count_check(1, 100000000))
          ->capture_default_str()
          ->type_name("N"),
      app.add_option("--wear", lathe.wear_mm_per_part, "tool wear: size drift per part, mm")
          ->check(range_check(-1, 1))
          ->capture_default_str()
          ->type_name("MM"),
      app.add_option("--thermal", lathe.thermal_mm, "thermal drift's final amplitude, mm")
          ->check(range_check(-10, 10))
          ->capture_default_str()
          ->type_name("MM"),
      app.add_option("--thermal-parts", lathe.thermal_parts, "thermal drift's time constant, parts")
          ->check(range_check(0.01, 1e8))
          ->capture_default_str()
          ->type_name("N"),
      app.add_option("--allowance", lathe.allowance_mm, "mean allowance (depth of cut), mm")
          ->check(range_check(0.001, 100))
          ->capture_default_str()
          ->type_name("MM"),
      app.add_option("--allowance-sd", lathe.allowance_sd_mm, "its standard deviation, mm")
          ->check(range_check(0, 100))
          ->capture_default_str()
          ->type_name("MM"),
      app.add_option("--feed", lathe.feed_mm_rev, "feed, mm/rev")
          ->check(feed_range)
          ->capture_default_str()
          ->type_name("F"),
      app.add_option("--process-sd", lathe.process_sd_mm, "random size variation, mm")
          ->check(range_check(0, 1))
          ->capture_default_str()
          ->type_name("MM"),
      app.add_option("--gauge-sd", lathe.gauge_sd_mm, "measurement noise, mm")
          ->check(range_check(0, 1))
          ->capture_default_str()
          ->type_name("MM"),
      app.add_flag("--compensate", lathe.compensate_force,
                   "adaptive control: correct each part's set-up for its allowance through the model"),
      app.add_option("--seed", lathe.seed, "of the random draws")
          ->check(count_check(0, kMaxSeed))
          ->capture_default_str()
          ->type_name("N"),
      app.add_option("--arl-runs", sim.arl_runs, "simulated runs per ARL")
          ->check(count_check(2, 10000000))
          ->capture_default_str()
          ->type_name("N"),
      app.add_option("--arl-cap", sim.arl_cap, "an ARL run stops here without an alarm")
          ->check(count_check(1, 100000000))
          ->capture_default_str()
          ->type_name("N"),
      app.add_option("--shift", sim.shift_sigma, "arl_shift: a step of this many sigma from the first part")
          ->check(range_check(-100, 100))
          ->capture_default_str()
          ->type_name("SIGMA"),
      app.add_option("--drift", sim.drift_sigma, "arl_drift: a drift of this many sigma per part")
          ->check(range_check(-10, 10))
          ->capture_default_str()
          ->type_name("SIGMA"),
      app.add_option("--trace", sim.trace_path, "write one record per simulated part to FILE")->type_name("FILE")};
  for (CLI::Option* o : sim_options) o->group(lathe_group);
  std::string sim_model_path;
  sim_options.push_back(
      app.add_option("--sim-model", sim_model_path, "the lathe's force-error model from FILE (default: y = 0.01 a)")
          ->type_name("FILE")
          ->group(lathe_group));
  std::vector<CLI::Option*> chart_options{
      app.add_option("--sigma", sim.sigma,
                     "the charts' sigma, mm (--simulate's default: the stable process's exact one)")
          ->check(range_check(1e-9, 10))
          ->type_name("MM"),
      app.add_option("--shewhart-l", charts.shewhart_l, "Shewhart limits at ± L sigma")
          ->check(range_check(0.5, 10))
          ->capture_default_str()
          ->type_name("L"),
      app.add_option("--ewma-lambda", charts.ewma_lambda, "EWMA weight λ")
          ->check(range_check(1e-6, 1))
          ->capture_default_str()
          ->type_name("λ"),
      app.add_option("--ewma-l", charts.ewma_l, "EWMA limits at ± L sigma_z")
          ->check(range_check(0.5, 10))
          ->capture_default_str()
          ->type_name("L"),
      app.add_option("--cusum-k", charts.cusum_k, "CUSUM reference value, sigma")
          ->check(range_check(0, 10))
          ->capture_default_str()
          ->type_name("K"),
      app.add_option("--cusum-h", charts.cusum_h, "CUSUM decision interval, sigma")
          ->check(range_check(0.1, 100))
          ->capture_default_str()
          ->type_name("H")};
  for (CLI::Option* o : chart_options) o->group(chart_group);

  std::vector<std::string> sub_inputs;
  bool residuals = false;
  std::string model_path, coefficient_text;
  FeedRange range{0, 0.05, 0.5};
  double fixed_feed = std::numeric_limits<double>::quiet_NaN();
  CLI::App* model_cmd = app.add_subcommand(
      "model", "fit y = b0 + b1 a + b2 f + b12 a f + b11 a² + b22 f² to calibration records (a, f, y)");
  model_cmd->add_option("files", sub_inputs, "calibration records; standard input when none or '-'");
  model_cmd->add_flag("--residuals", residuals, "a record per calibration point (fitted, residual) before the model");
  CLI::App* feed_cmd = app.add_subcommand(
      "feed", "for each record's allowance a, the feed in [--feed-min, --feed-max] giving y = --target");
  CLI::App* correct_cmd = app.add_subcommand(
      "correct", "for each record's allowance a, the set-up correction -y(a, f) at --feed (or the record's f)");
  for (CLI::App* cmd : {feed_cmd, correct_cmd}) {
    cmd->add_option("files", sub_inputs, "records with a (mm); standard input when none or '-'");
    cmd->add_option("--model", model_path, "the model record written by 'subtune model'")->type_name("FILE");
    cmd->add_option("--coefficients", coefficient_text, "the model as b0,b1,b2,b12,b11,b22 instead")
        ->type_name("B0,...");
  }
  feed_cmd->add_option("--target", range.target, "the error y to hold, mm")
      ->check(range_check(-100, 100))
      ->capture_default_str()
      ->type_name("MM");
  feed_cmd->add_option("--feed-min", range.f_min, "mm/rev")->check(feed_range)->capture_default_str()->type_name("F");
  feed_cmd->add_option("--feed-max", range.f_max, "mm/rev")->check(feed_range)->capture_default_str()->type_name("F");
  correct_cmd->add_option("--feed", fixed_feed, "the fixed feed, mm/rev (a record's f overrides it)")
      ->check(feed_range)
      ->type_name("F");
  for (CLI::App* cmd : {model_cmd, feed_cmd, correct_cmd}) cmd->fallthrough();

  return tool.run(argc, argv, [&] {
    tuning.alternative = alternative == "greater" ? Alternative::greater
                         : alternative == "less"  ? Alternative::less
                                                  : Alternative::two_sided;
    tuning.statistic = statistic == "paper" ? TrendStatistic::paper : TrendStatistic::slope;
    if (tuning.alternative != Alternative::two_sided && tuning.alpha >= 0.5)
      throw tk::UsageError(fmt::format("--alpha {} with --alternative {}: a one-sided test needs alpha below 0.5",
                                       tuning.alpha, alternative));
    if (correct_to == "nominal") {
      if (!simulate_flag && nominal_option->count() == 0) throw tk::UsageError("--correct-to nominal needs --nominal");
      tuning.target = lathe.nominal_mm;
    }
    const std::vector<std::string>& inputs = tool.common().inputs;
    if (model_cmd->parsed()) {
      fit_model(sub_inputs, residuals, tool.output_format());
      return;
    }
    if (feed_cmd->parsed() || correct_cmd->parsed()) {
      if (model_path.empty() == coefficient_text.empty())
        throw tk::UsageError("give the model as --model FILE or --coefficients, one of them");
      const ForceErrorModel m = load_model(model_path, coefficient_text);
      if (feed_cmd->parsed()) {
        if (range.f_min > range.f_max)
          throw tk::UsageError(fmt::format("--feed-min {} is above --feed-max {}", range.f_min, range.f_max));
        apply_model(sub_inputs, m, range, 0, tool);
      } else {
        apply_model(sub_inputs, m, std::nullopt, fixed_feed, tool);
      }
      return;
    }
    if (!simulate_flag) {
      for (CLI::Option* o : sim_options)
        if (o->count() > 0) throw tk::UsageError(o->get_name() + " goes with --simulate");
      if (lower && upper && *lower > *upper)
        throw tk::UsageError(fmt::format("--lower {} is above --upper {}", *lower, *upper));
      if (sim.policy == "all" || sim.policy == "none")
        throw tk::UsageError("the filter runs one policy: subtune, shewhart, ewma or cusum");
      const PolicyKind kind = sim.policy.empty() ? PolicyKind::subtune : parse_policy(sim.policy);
      if (kind == PolicyKind::subtune) {
        for (CLI::Option* o : chart_options)
          if (o->count() > 0) throw tk::UsageError(o->get_name() + " goes with a chart --policy or --simulate");
        filter_sizes(inputs, tuning, field, {lower, upper}, svg_path, tool);
        return;
      }
      if (nominal_option->count() == 0 || !sim.sigma)
        throw tk::UsageError(
            fmt::format("--policy {} needs the target and the in-control sigma: --nominal and --sigma", sim.policy));
      charts.target = lathe.nominal_mm, charts.sigma = *sim.sigma;
      const std::unique_ptr<AdjustmentPolicy> chart = make_policy(kind, tuning, charts);
      filter_chart(inputs, *chart, field, {lower, upper}, svg_path, tool);
      return;
    }
    if (!inputs.empty()) throw tk::UsageError("--simulate reads no records");
    if (!svg_path.empty()) sim.svg_path = svg_path;
    const double half_band = 0.02;  // the default band: ± 20 µm round the nominal
    lathe.lower_mm = lower.value_or(lathe.nominal_mm - half_band);
    lathe.upper_mm = upper.value_or(lathe.nominal_mm + half_band);
    if (!sim_model_path.empty()) lathe.force_model = load_model(sim_model_path, "");
    simulate(lathe, tuning, charts, sim, tool);
  });
}
