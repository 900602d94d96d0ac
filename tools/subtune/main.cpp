/// @file main.cpp
/// @brief subtune: active control of a lathe by dimensional sub-tuning
/// (Georgiev, Chetrokov & Salapateva) as a filter over measured sizes; the
/// force-induced-error model of its adaptive control (model, feed, correct);
/// and a simulated batch comparing sub-tuning with the SPC charts.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "cli/number_option.hpp"
#include "cli/option_checks.hpp"
#include "cli/tool_app.hpp"
#include "io/error.hpp"
#include "io/number_column.hpp"
#include "io/record_fields.hpp"
#include "io/record_reader.hpp"
#include "io/record_writer.hpp"
#include "machining/force_error_model.hpp"
#include "quality/lathe_sim.hpp"
#include "quality/size_plot.hpp"

namespace {

using namespace tk::quality;
using tk::machining::ForceErrorModel;

/// Lengths beyond a kilometre, or nonzero ones below 1e-100 mm, are a unit
/// or parsing mistake; the bounds also keep the run's sums of squares inside
/// double range (squares of differences below ~1e-154 would underflow to 0
/// and make the spread vanish).
constexpr double kMaxLengthMm = 1e6, kMinLengthMm = 1e-100;

/// The force-error model's coefficients given as --coefficients, in magnitude.
constexpr double kMaxCoefficient = 1e6;

/// Seeds: any whole number of up to 19 digits.
constexpr std::uint64_t kMaxSeed = 9'999'999'999'999'999'999ULL;

double length_field(const tk::Record& record, const std::string& key, const tk::Location& where) {
  const double v = tk::io::number_field(record, key, where);
  if (std::abs(v) > kMaxLengthMm) throw tk::Error(fmt::format("{} = {} mm is beyond ±{:g} mm", key, v, kMaxLengthMm), where);
  if (v != 0 && std::abs(v) < kMinLengthMm)
    throw tk::Error(fmt::format("{} = {} mm is below {:g} mm in magnitude (and not 0)", key, v, kMinLengthMm), where);
  return v;
}

/// The legend of the policy's level line in the plots.
std::string level_label(PolicyKind kind) {
  switch (kind) {
    case PolicyKind::subtune: return "regression A_T at the part";
    case PolicyKind::ewma: return "EWMA level (target + z)";
    case PolicyKind::cusum: return "CUSUM estimate of the mean";
    case PolicyKind::shewhart: return "the point (Shewhart)";
    case PolicyKind::none: break;
  }
  return "level";
}

/// Writes the plot, saying so when it holds only the first parts.
void write_plot(const SizePlot& plot, const std::string& path, const SizePlotInfo& info, const tk::cli::ToolApp& tool) {
  if (plot.truncated()) tool.warn(fmt::format("the plot shows the first {} parts only", SizePlot::kMaxParts));
  plot.write(path, info);
}

/// Tolerance limits given as options, overridden per record by fields.
struct Limits {
  std::optional<double> lower, upper;
};

/// The record's own limits, else the options'.
Limits limits_of(const tk::Record& record, const Limits& options, const tk::Location& where) {
  Limits l{tk::io::optional_number_field(record, "lower", where), tk::io::optional_number_field(record, "upper", where)};
  if (!l.lower) l.lower = options.lower;
  if (!l.upper) l.upper = options.upper;
  return l;
}

bool within(double size, const Limits& l) { return (!l.lower || size >= *l.lower) && (!l.upper || size <= *l.upper); }

void filter_sizes(const std::vector<std::string>& inputs, const SubTuneSettings& settings, const std::string& field,
                  const Limits& limits, const std::string& svg_path, const tk::cli::ToolApp& tool) {
  SubTuner tuner(settings);
  tk::io::RecordReader reader(inputs, tk::io::number_column_probe(field));
  tk::io::RecordWriter writer(tool.output_format());
  // CSV always has an in_tolerance column (empty where no limits apply), since
  // any record may bring limits of its own; JSON has the field only where one does.
  const bool tolerance_column = tool.output_format() == tk::io::OutputFormat::csv || limits.lower || limits.upper;
  const std::vector<std::string> own{"run", "n", "a", "b", "s", "t", "t_crit", "df", "decision", "correction", "offset"};
  std::vector<std::string> fields = own;
  if (tolerance_column) fields.push_back("in_tolerance");
  SizePlot plot;
  SizePlotInfo info;
  info.lower = limits.lower.value_or(info.lower), info.upper = limits.upper.value_or(info.upper);
  std::uint64_t parts = 0;
  std::vector<tk::io::Cell> row;
  bool fast = false;
  tk::Record record;
  while (reader.next(record)) {
    const tk::Location where = reader.where();
    const double size = length_field(record, field, where);
    if (parts == 0) {
      // A stream that starts with bare sizes (a number column) takes the
      // writer's fast path, no record built, and the size is a field the
      // writer must be told of; other inputs carry it in place.
      fast = record.size() == 1;
      if (fast) fields.insert(fields.begin(), field);
      writer.declare_fields(fields);
    }
    const SubTuneStep step = tuner.observe(size);
    ++parts;
    const Limits l = limits_of(record, limits, where);
    const bool judged = l.lower || l.upper, in_tolerance = within(size, l);
    using tk::io::Cell;
    row.assign({Cell::integer(static_cast<long long>(step.run)), Cell::integer(static_cast<long long>(step.n)), Cell::real(step.a),
                Cell::real(step.b), Cell::real(step.s), Cell::real(step.t), Cell::real(step.t_crit),
                step.df > 0 ? Cell::integer(static_cast<long long>(step.df)) : Cell::real(NAN), Cell::text(decision_name(step.decision)),
                Cell::real(step.correction), Cell::real(step.offset)});
    if (fast && record.size() == 1) {
      row.insert(row.begin(), Cell::real(size));
      if (tolerance_column) row.push_back(judged ? Cell::boolean(in_tolerance) : Cell::real(NAN));
      writer.write_row(row);
    } else {
      for (std::size_t i = 0; i < own.size(); ++i) record[own[i]] = tk::io::cell_value(row[i]);
      if (judged) record["in_tolerance"] = in_tolerance;
      writer.write(record);
    }
    if (!svg_path.empty()) plot.add(static_cast<double>(parts), size, step.a + step.b * static_cast<double>(step.n), step.offset);
  }
  writer.flush();
  if (!svg_path.empty()) {
    info.title = fmt::format("subtune: {} parts, alpha {:g}", parts, settings.alpha);
    write_plot(plot, svg_path, info, tool);
  }
}

/// The filter under a chart instead of sub-tuning: per part the chart's
/// statistic and limit, its level, and whether to adjust.
void filter_chart(const std::vector<std::string>& inputs, AdjustmentPolicy& chart, const std::string& field, const Limits& limits,
                  const std::string& svg_path, const tk::cli::ToolApp& tool) {
  tk::io::RecordReader reader(inputs, tk::io::number_column_probe(field));
  tk::io::RecordWriter writer(tool.output_format());
  std::vector<std::string> fields{"n", "statistic", "limit", "level", "decision", "correction", "offset"};
  const bool csv = tool.output_format() == tk::io::OutputFormat::csv;
  if (csv || limits.lower || limits.upper) fields.push_back("in_tolerance");
  SizePlot plot;
  std::uint64_t parts = 0, since_adjustment = 0;
  double offset = 0;
  tk::Record record;
  while (reader.next(record)) {
    const tk::Location where = reader.where();
    const double size = length_field(record, field, where);
    if (parts++ == 0) {
      if (record.size() == 1) fields.insert(fields.begin(), field);
      writer.declare_fields(fields);
    }
    const PolicyStep step = chart.observe(size);
    ++since_adjustment;
    if (step.alarm) offset += step.correction;
    record["n"] = since_adjustment;
    record["statistic"] = step.statistic, record["limit"] = step.limit;
    record["level"] = step.level;
    record["decision"] = step.alarm ? "adjust" : "none";
    record["correction"] = step.correction, record["offset"] = offset;
    if (const Limits l = limits_of(record, limits, where); l.lower || l.upper) record["in_tolerance"] = within(size, l);
    writer.write(record);
    if (step.alarm) since_adjustment = 0;
    if (!svg_path.empty()) plot.add(static_cast<double>(parts), size, step.level, offset);
  }
  writer.flush();
  if (!svg_path.empty()) {
    const std::string name(policy_name(chart.kind()));
    write_plot(plot, svg_path, {.title = fmt::format("subtune --policy {}: {} parts", name, parts),
                          .level_label = level_label(chart.kind()),
                          .lower = limits.lower.value_or(NAN),
                          .upper = limits.upper.value_or(NAN)},
               tool);
  }
}

// ---- the force-error model -------------------------------------------------

const std::array<const char*, 6> kCoefficientNames{"b0", "b1", "b2", "b12", "b11", "b22"};

std::array<double*, 6> coefficients(ForceErrorModel& m) { return {&m.b0, &m.b1, &m.b2, &m.b12, &m.b11, &m.b22}; }

void fit_model(const std::vector<std::string>& inputs, bool residuals, tk::io::OutputFormat format) {
  std::vector<tk::machining::CalibrationPoint> points;
  std::vector<tk::Record> records;
  tk::io::RecordReader reader(inputs);
  reader.expect_columns({{"a", "f", "y"}});
  tk::Record record;
  while (reader.next(record)) {
    const tk::Location where = reader.where();
    points.push_back({length_field(record, "a", where), length_field(record, "f", where), length_field(record, "y", where)});
    if (residuals) records.push_back(std::move(record));
  }
  if (points.empty()) throw tk::Error("no calibration records (a, f, y) in the input");
  const tk::machining::ForceErrorFit fit = tk::machining::fit_force_error_model(points);
  tk::io::RecordWriter writer(format);
  std::vector<std::string> columns{"record"};
  tk::Record model{{"record", "model"}};
  ForceErrorModel m = fit.model;
  for (std::size_t k = 0; k < 6; ++k) model[kCoefficientNames[k]] = *coefficients(m)[k];
  model["points"] = fit.points, model["r2"] = fit.r2, model["adjusted_r2"] = fit.adjusted_r2;
  model["residual_sd"] = fit.residual_sd, model["condition"] = fit.condition;
  if (residuals) {
    for (const auto& [key, value] : records.front().items()) columns.push_back(key);
    columns.insert(columns.end(), {"fitted", "residual"});
  }
  for (const auto& [key, value] : model.items())
    if (key != "record") columns.push_back(key);
  writer.declare_fields(columns);  // CSV: one header for both kinds of record
  for (std::size_t i = 0; i < records.size(); ++i) {
    tk::Record r{{"record", "point"}};
    for (auto& [key, value] : records[i].items()) r[key] = value;
    r["fitted"] = fit.fitted[i], r["residual"] = fit.residuals[i];
    writer.write(r);
  }
  writer.write(model);
  writer.flush();
}

/// The model from --coefficients, or from the last record of FILE that has all six.
ForceErrorModel load_model(const std::string& path, const std::string& coefficient_text) {
  ForceErrorModel m;
  if (!coefficient_text.empty()) {
    const std::vector<double> values = tk::cli::parse_numbers(coefficient_text, "--coefficients", 6);
    for (std::size_t k = 0; k < 6; ++k) {
      // Millimetres per unit of a, f and their products: ±1e6 keeps y finite
      // for every allowance and feed the tool takes.
      tk::cli::require_range(values[k], -kMaxCoefficient, kMaxCoefficient, "--coefficients");
      *coefficients(m)[k] = values[k];
    }
    return m;
  }
  tk::io::RecordReader reader({path});
  tk::Record record;
  bool found = false;
  while (reader.next(record)) {
    bool complete = true;
    for (const char* name : kCoefficientNames) complete = complete && record.contains(name);
    if (!complete) continue;
    for (std::size_t k = 0; k < 6; ++k) *coefficients(m)[k] = tk::io::number_field(record, kCoefficientNames[k], reader.where());
    found = true;
  }
  if (!found) throw tk::Error(fmt::format("{}: no model record (b0, b1, b2, b12, b11, b22); make one with 'subtune model'", path));
  return m;
}

struct FeedRange {
  double target = 0, f_min = 0, f_max = 0;
};

void apply_model(const std::vector<std::string>& inputs, const ForceErrorModel& m, std::optional<FeedRange> feed_range,
                 double fixed_feed, const tk::cli::ToolApp& tool) {
  tk::io::RecordReader reader(inputs, tk::io::number_column_probe("a"));
  tk::io::RecordWriter writer(tool.output_format());
  writer.declare_fields(feed_range ? std::vector<std::string>{"feed", "predicted_error", "feed_status", "error_min", "error_max"}
                                   : std::vector<std::string>{"predicted_error", "correction"});
  std::uint64_t unsolved = 0;
  tk::Record record;
  while (reader.next(record)) {
    const tk::Location where = reader.where();
    const double a = length_field(record, "a", where);
    if (a < 0) throw tk::Error(fmt::format("allowance a = {} mm is negative", a), where);
    if (feed_range) {
      const tk::machining::FeedChoice choice = tk::machining::feed_for_error(m, a, feed_range->target, feed_range->f_min, feed_range->f_max);
      record["feed"] = choice.feed, record["predicted_error"] = choice.error;
      record["feed_status"] = tk::machining::feed_status_name(choice.status);
      record["error_min"] = choice.error_min, record["error_max"] = choice.error_max;
      if (choice.status == tk::machining::FeedStatus::none) ++unsolved;
    } else {
      const std::optional<double> record_feed = tk::io::optional_number_field(record, "f", where);
      if (!record_feed && std::isnan(fixed_feed)) throw tk::Error("no feed: give --feed or an f field in the record", where);
      const double f = record_feed.value_or(fixed_feed);
      if (!(f > 0)) throw tk::Error(fmt::format("feed f = {} mm/rev must be positive", f), where);
      const double y = m.error_at(a, f);
      record["predicted_error"] = y, record["correction"] = tk::machining::setup_correction(m, a, f);
    }
    writer.write(record);
  }
  writer.flush();
  if (unsolved > 0)
    tool.warn(fmt::format("{} workpiece(s) have no feed in [{:g}, {:g}] mm/rev giving y = {:g} mm (feed_status none; "
                          "error_min and error_max give the reachable range)",
                          unsolved, feed_range->f_min, feed_range->f_max, feed_range->target));
}

// ---- the simulated batch ---------------------------------------------------

/// The most parts a --simulate run may imply, every ARL run counted to
/// --arl-cap (subtune(1), OPTIONS): the defaults imply 2.4e9, about three
/// minutes at 10-18 M parts/s when no policy alarms.
constexpr double kMaxSimulatedParts = 3e9;
/// The most records --trace may write (about 170 bytes each: 350 MB).
constexpr double kMaxTraceRecords = 2e6;

struct SimulationOptions {
  std::string policy;  ///< empty: all
  std::uint64_t arl_runs = 2000, arl_cap = 100000;
  double shift_sigma = 1, drift_sigma = 0.1;
  std::optional<double> sigma;
  std::string trace_path, svg_path;
};

void simulate(const LatheSettings& lathe, const SubTuneSettings& subtune, ChartSettings charts, const SimulationOptions& o,
              const tk::cli::ToolApp& tool) {
  validate(lathe);
  charts.target = lathe.nominal_mm;
  charts.sigma = o.sigma.value_or(in_control_sigma(lathe));
  if (!(charts.sigma > 0)) throw tk::UsageError("the stable process has no spread (all noise 0): give --sigma for the charts");
  std::vector<PolicyKind> kinds;
  if (o.policy.empty() || o.policy == "all")
    kinds = {PolicyKind::none, PolicyKind::subtune, PolicyKind::shewhart, PolicyKind::ewma, PolicyKind::cusum};
  else
    kinds = {parse_policy(o.policy)};
  if (!o.svg_path.empty() && kinds.size() != 1) throw tk::UsageError("--svg draws one policy's batch: give --policy too");

  // Each policy makes the batch twice (as given and stable) and, but
  // 'none', three ARL estimates of --arl-runs runs of up to --arl-cap parts.
  const double policies = static_cast<double>(kinds.size()), parts = static_cast<double>(lathe.parts);
  const double charted = policies - static_cast<double>(std::ranges::count(kinds, PolicyKind::none));
  tk::cli::require_run_size(policies * 2 * parts + charted * 3 * static_cast<double>(o.arl_runs) * static_cast<double>(o.arl_cap),
                            kMaxSimulatedParts, "simulated parts at most (every ARL run to its cap)",
                            "--parts, --arl-runs, --arl-cap and --policy");
  std::optional<tk::io::RecordFile> trace;
  if (!o.trace_path.empty()) {
    tk::cli::require_run_size(policies * parts, kMaxTraceRecords, "trace records (one a part and policy)",
                              "--trace with --parts and --policy");
    trace.emplace(o.trace_path, tool.output_format());
    trace->declare_fields({"policy", "part", "allowance", "size", "measured", "alarm", "correction", "offset"});
  }
  tk::io::RecordWriter writer(tool.output_format());
  writer.declare_fields({"policy", "parts", "in_tolerance_share", "mean_abs_deviation_mm", "rms_deviation_mm", "max_abs_deviation_mm",
                         "corrections", "false_alarms", "arl0", "arl0_se", "arl_shift", "arl_shift_se", "arl_drift", "arl_drift_se",
                         "sigma_mm"});
  for (const PolicyKind kind : kinds) {
    const std::unique_ptr<AdjustmentPolicy> policy = make_policy(kind, subtune, charts);
    SizePlot plot;
    const std::string name(policy_name(kind));
    const LatheOutcome run = simulate_lathe(lathe, *policy, [&](const PartRecord& p) {
      if (trace) {
        trace->write({{"policy", name}, {"part", p.part}, {"allowance", p.allowance_mm}, {"size", p.size_mm}, {"measured", p.measured_mm},
                      {"alarm", p.alarm}, {"correction", p.correction_mm}, {"offset", p.offset_mm}});
      }
      if (!o.svg_path.empty()) plot.add(static_cast<double>(p.part), p.measured_mm, p.level_mm, p.offset_mm, p.size_mm);
    });
    const LatheOutcome stable = simulate_lathe(stable_process(lathe), *policy);
    tk::Record r{{"policy", name},
                 {"parts", run.parts},
                 {"in_tolerance_share", static_cast<double>(run.in_tolerance) / static_cast<double>(run.parts)},
                 {"mean_abs_deviation_mm", run.mean_abs_deviation_mm},
                 {"rms_deviation_mm", run.rms_deviation_mm},
                 {"max_abs_deviation_mm", run.max_abs_deviation_mm},
                 {"corrections", run.corrections},
                 {"false_alarms", stable.corrections}};
    if (kind != PolicyKind::none) {
      const auto arl = [&](double shift, double drift, std::uint64_t salt) {
        return average_run_length(kind, subtune, charts, shift, drift, o.arl_runs, lathe.seed * 7 + salt, o.arl_cap);
      };
      const RunLengthEstimate in_control = arl(0, 0, 1), shifted = arl(o.shift_sigma, 0, 2), drifting = arl(0, o.drift_sigma, 3);
      r["arl0"] = in_control.mean, r["arl0_se"] = in_control.standard_error;
      r["arl_shift"] = shifted.mean, r["arl_shift_se"] = shifted.standard_error;
      r["arl_drift"] = drifting.mean, r["arl_drift_se"] = drifting.standard_error;
      const std::uint64_t censored = in_control.censored + shifted.censored + drifting.censored;
      if (censored > 0)
        tool.warn(fmt::format("policy {}: {} ARL run(s) reached --arl-cap {} without an alarm; those ARLs are lower bounds", name, censored, o.arl_cap));
    } else {
      for (const char* f : {"arl0", "arl0_se", "arl_shift", "arl_shift_se", "arl_drift", "arl_drift_se"}) r[f] = nullptr;
    }
    r["sigma_mm"] = charts.sigma;
    writer.write(r);
    if (!o.svg_path.empty()) {
      write_plot(plot, o.svg_path, {.title = fmt::format("subtune --simulate --policy {}: {} parts, {} corrections, {:.1f} % in tolerance", name,
                                                   run.parts, run.corrections, 100.0 * static_cast<double>(run.in_tolerance) / static_cast<double>(run.parts)),
                              .level_label = level_label(kind),
                              .nominal = lathe.nominal_mm, .lower = lathe.lower_mm, .upper = lathe.upper_mm},
                 tool);
    }
  }
  writer.flush();
  if (trace) trace->close();
}

}  // namespace

int main(int argc, char** argv) {
  tk::cli::ToolApp tool("subtune",
                        "Active control of a lathe by dimensional sub-tuning (Georgiev, Chetrokov & Salapateva): reads the "
                        "measured size of each finished part, in order, fits the regression line A_T(i) = a + i b to the current run, "
                        "tests the difference dA = a - A_T(N) (eq. 3-6) and adds n, a, b, s, t, t_crit, decision (insufficient, "
                        "none, subtune) and the correction dA. 'model', 'feed' and 'correct' "
                        "fit and apply the force-induced-error model; --simulate compares sub-tuning with Shewhart, EWMA "
                        "and CUSUM charts on a simulated batch.",
                        "Sizes and errors in mm, feeds in mm/rev. See subtune(1).");
  tool.add_input_files("records with the size (JSON Lines, CSV, or one number per line); standard input when none or '-'");
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
        return CLI::detail::lexical_cast(text, v) && v >= 1e-12 && v < 1 ? std::string() : "must be a number from 1e-12 to below 1, not " + text;
      },
      "in [1e-12, 1)");
  CLI::App& app = tool.app();
  const std::string test = "The sub-tuning test", out = "Output", lathe_group = "Simulated lathe (with --simulate)",
                    chart_group = "Charts (--simulate, or the filter with a chart --policy)";
  app.add_option("--alpha", tuning.alpha, "significance level of the test of dA (the paper prints none)")->check(alpha_check)->capture_default_str()->group(test);
  app.add_option("--alternative", alternative, "two-sided (either drift, the default), greater (growing sizes only) or less")
      ->check(CLI::IsMember({"two-sided", "greater", "less"}))->capture_default_str()->group(test);
  app.add_option("--statistic", statistic,
                 "slope: Student's t of the difference (5) with its regression standard error, N-2 df (level alpha); "
                 "paper: eq. (6) as printed, 2(N-1) df (alarms on noise about half the time at alpha 0.05)")
      ->check(CLI::IsMember({"slope", "paper"}))->capture_default_str()->group(test);
  app.add_option("--min-parts", tuning.min_parts, "no decision before a run has this many parts")->check(count_check(3, 1000000))->capture_default_str()->type_name("N")->group(test);
  app.add_option("--resolution", tuning.resolution, "gauge resolution, mm: s (or S_N) is at least its rounding noise r/sqrt(12)")->check(range_check(0, 10))->capture_default_str()->type_name("MM")->group(test);
  app.add_option("--correct-to", correct_to, "start: by the paper's dA = a - A_T(N), back to the run's starting level; nominal: to --nominal")
      ->check(CLI::IsMember({"start", "nominal"}))->capture_default_str()->group(test);
  app.add_option("--field", field, "the field holding the size")->capture_default_str()->group(out);
  app.add_option("--lower", lower, "lower tolerance limit, mm (a record's 'lower' field overrides it)")->check(size_range)->type_name("MM")->group(out);
  app.add_option("--upper", upper, "upper tolerance limit, mm (a record's 'upper' field overrides it)")->check(size_range)->type_name("MM")->group(out);
  app.add_option("--svg", svg_path, "plot sizes, the regression and the offset against part number to FILE")->type_name("FILE")->group(out);

  CLI::Option* nominal_option = app.add_option("--nominal", lathe.nominal_mm, "nominal size, mm (the simulated part's; --correct-to nominal's)")->check(size_range)->capture_default_str()->type_name("MM")->group(out);
  app.add_flag("--simulate", simulate_flag, "simulate a batch and write one summary record per policy")->group(lathe_group);
  app.add_option("--policy", sim.policy,
                 "the filter: subtune (default), or a chart (shewhart, ewma, cusum; needs --nominal and --sigma); "
                 "--simulate: one of these, none, or all (default)")
      ->check(CLI::IsMember({"all", "none", "subtune", "shewhart", "ewma", "cusum"}))->group(test);
  std::vector<CLI::Option*> sim_options{
      app.add_option("--parts", lathe.parts, "parts in the batch")->check(count_check(1, 100000000))->capture_default_str()->type_name("N"),
      app.add_option("--wear", lathe.wear_mm_per_part, "tool wear: size drift per part, mm")->check(range_check(-1, 1))->capture_default_str()->type_name("MM"),
      app.add_option("--thermal", lathe.thermal_mm, "thermal drift's final amplitude, mm")->check(range_check(-10, 10))->capture_default_str()->type_name("MM"),
      app.add_option("--thermal-parts", lathe.thermal_parts, "thermal drift's time constant, parts")->check(range_check(0.01, 1e8))->capture_default_str()->type_name("N"),
      app.add_option("--allowance", lathe.allowance_mm, "mean allowance (depth of cut), mm")->check(range_check(0.001, 100))->capture_default_str()->type_name("MM"),
      app.add_option("--allowance-sd", lathe.allowance_sd_mm, "its standard deviation, mm")->check(range_check(0, 100))->capture_default_str()->type_name("MM"),
      app.add_option("--feed", lathe.feed_mm_rev, "feed, mm/rev")->check(feed_range)->capture_default_str()->type_name("F"),
      app.add_option("--process-sd", lathe.process_sd_mm, "random size variation, mm")->check(range_check(0, 1))->capture_default_str()->type_name("MM"),
      app.add_option("--gauge-sd", lathe.gauge_sd_mm, "measurement noise, mm")->check(range_check(0, 1))->capture_default_str()->type_name("MM"),
      app.add_flag("--compensate", lathe.compensate_force, "adaptive control: correct each part's set-up for its allowance through the model"),
      app.add_option("--seed", lathe.seed, "of the random draws")->check(count_check(0, kMaxSeed))->capture_default_str()->type_name("N"),
      app.add_option("--arl-runs", sim.arl_runs, "simulated runs per ARL")->check(count_check(2, 10000000))->capture_default_str()->type_name("N"),
      app.add_option("--arl-cap", sim.arl_cap, "an ARL run stops here without an alarm")->check(count_check(1, 100000000))->capture_default_str()->type_name("N"),
      app.add_option("--shift", sim.shift_sigma, "arl_shift: a step of this many sigma from the first part")->check(range_check(-100, 100))->capture_default_str()->type_name("SIGMA"),
      app.add_option("--drift", sim.drift_sigma, "arl_drift: a drift of this many sigma per part")->check(range_check(-10, 10))->capture_default_str()->type_name("SIGMA"),
      app.add_option("--trace", sim.trace_path, "write one record per simulated part to FILE")->type_name("FILE")};
  for (CLI::Option* o : sim_options) o->group(lathe_group);
  std::string sim_model_path;
  sim_options.push_back(app.add_option("--sim-model", sim_model_path, "the lathe's force-error model from FILE (default: y = 0.01 a)")->type_name("FILE")->group(lathe_group));
  std::vector<CLI::Option*> chart_options{
      app.add_option("--sigma", sim.sigma, "the charts' sigma, mm (--simulate's default: the stable process's exact one)")->check(range_check(1e-9, 10))->type_name("MM"),
      app.add_option("--shewhart-l", charts.shewhart_l, "Shewhart limits at ± L sigma")->check(range_check(0.5, 10))->capture_default_str()->type_name("L"),
      app.add_option("--ewma-lambda", charts.ewma_lambda, "EWMA weight λ")->check(range_check(1e-6, 1))->capture_default_str()->type_name("λ"),
      app.add_option("--ewma-l", charts.ewma_l, "EWMA limits at ± L sigma_z")->check(range_check(0.5, 10))->capture_default_str()->type_name("L"),
      app.add_option("--cusum-k", charts.cusum_k, "CUSUM reference value, sigma")->check(range_check(0, 10))->capture_default_str()->type_name("K"),
      app.add_option("--cusum-h", charts.cusum_h, "CUSUM decision interval, sigma")->check(range_check(0.1, 100))->capture_default_str()->type_name("H")};
  for (CLI::Option* o : chart_options) o->group(chart_group);

  std::vector<std::string> sub_inputs;
  bool residuals = false;
  std::string model_path, coefficient_text;
  FeedRange range{0, 0.05, 0.5};
  double fixed_feed = std::numeric_limits<double>::quiet_NaN();
  CLI::App* model_cmd = app.add_subcommand("model", "fit y = b0 + b1 a + b2 f + b12 a f + b11 a² + b22 f² to calibration records (a, f, y)");
  model_cmd->add_option("files", sub_inputs, "calibration records; standard input when none or '-'");
  model_cmd->add_flag("--residuals", residuals, "a record per calibration point (fitted, residual) before the model");
  CLI::App* feed_cmd = app.add_subcommand("feed", "for each record's allowance a, the feed in [--feed-min, --feed-max] giving y = --target");
  CLI::App* correct_cmd = app.add_subcommand("correct", "for each record's allowance a, the set-up correction -y(a, f) at --feed (or the record's f)");
  for (CLI::App* cmd : {feed_cmd, correct_cmd}) {
    cmd->add_option("files", sub_inputs, "records with a (mm); standard input when none or '-'");
    cmd->add_option("--model", model_path, "the model record written by 'subtune model'")->type_name("FILE");
    cmd->add_option("--coefficients", coefficient_text, "the model as b0,b1,b2,b12,b11,b22 instead")->type_name("B0,...");
  }
  feed_cmd->add_option("--target", range.target, "the error y to hold, mm")->check(range_check(-100, 100))->capture_default_str()->type_name("MM");
  feed_cmd->add_option("--feed-min", range.f_min, "mm/rev")->check(feed_range)->capture_default_str()->type_name("F");
  feed_cmd->add_option("--feed-max", range.f_max, "mm/rev")->check(feed_range)->capture_default_str()->type_name("F");
  correct_cmd->add_option("--feed", fixed_feed, "the fixed feed, mm/rev (a record's f overrides it)")->check(feed_range)->type_name("F");
  for (CLI::App* cmd : {model_cmd, feed_cmd, correct_cmd}) cmd->fallthrough();

  return tool.run(argc, argv, [&] {
    tuning.alternative = alternative == "greater" ? Alternative::greater : alternative == "less" ? Alternative::less : Alternative::two_sided;
    tuning.statistic = statistic == "paper" ? TrendStatistic::paper : TrendStatistic::slope;
    if (tuning.alternative != Alternative::two_sided && tuning.alpha >= 0.5)
      throw tk::UsageError(fmt::format("--alpha {} with --alternative {}: a one-sided test needs alpha below 0.5", tuning.alpha, alternative));
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
      if (model_path.empty() == coefficient_text.empty()) throw tk::UsageError("give the model as --model FILE or --coefficients, one of them");
      const ForceErrorModel m = load_model(model_path, coefficient_text);
      if (feed_cmd->parsed()) {
        if (range.f_min > range.f_max) throw tk::UsageError(fmt::format("--feed-min {} is above --feed-max {}", range.f_min, range.f_max));
        apply_model(sub_inputs, m, range, 0, tool);
      } else {
        apply_model(sub_inputs, m, std::nullopt, fixed_feed, tool);
      }
      return;
    }
    if (!simulate_flag) {
      for (CLI::Option* o : sim_options)
        if (o->count() > 0) throw tk::UsageError(o->get_name() + " goes with --simulate");
      if (lower && upper && *lower > *upper) throw tk::UsageError(fmt::format("--lower {} is above --upper {}", *lower, *upper));
      if (sim.policy == "all" || sim.policy == "none") throw tk::UsageError("the filter runs one policy: subtune, shewhart, ewma or cusum");
      const PolicyKind kind = sim.policy.empty() ? PolicyKind::subtune : parse_policy(sim.policy);
      if (kind == PolicyKind::subtune) {
        for (CLI::Option* o : chart_options)
          if (o->count() > 0) throw tk::UsageError(o->get_name() + " goes with a chart --policy or --simulate");
        filter_sizes(inputs, tuning, field, {lower, upper}, svg_path, tool);
        return;
      }
      if (nominal_option->count() == 0 || !sim.sigma)
        throw tk::UsageError(fmt::format("--policy {} needs the target and the in-control sigma: --nominal and --sigma", sim.policy));
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
