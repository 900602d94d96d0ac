/// @file main.cpp
/// @brief tnorm-bench: Könczöl & Gál's Mamdani line follower under six
/// t-norms: its motor commands for sensor readings (eval), its speed per
/// inference (bench), laps of a simulated car (laps), and the controller as
/// fuzzylite FLL (fll). Any FLL controller can stand in for the paper's.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "cli/number_option.hpp"
#include "cli/option_checks.hpp"
#include "cli/tool_app.hpp"
#include "fuzzy/fll.hpp"
#include "fuzzy/inference_timing.hpp"
#include "fuzzy/line_follower.hpp"
#include "fuzzy/mamdani.hpp"
#include "io/error.hpp"
#include "io/record_fields.hpp"
#include "io/record_reader.hpp"
#include "io/record_writer.hpp"
#include "vehicle/lap_svg.hpp"
#include "vehicle/line_car.hpp"
#include "vehicle/line_track.hpp"

namespace {

using namespace tk;
using fuzzy::TNorm;

constexpr TNorm kAllTNorms[] = {TNorm::minimum,     TNorm::product,       TNorm::drastic,
                                TNorm::lukasiewicz, TNorm::trigonometric, TNorm::hamacher};

/// Options that pick and shape the controller, shared by every mode.
struct ControllerOptions {
  std::vector<std::string> tnorms;
  int adc_bits = 10;
  std::string centroid;  ///< "" keeps the controller's own; "exact", "discrete", "discrete:N"
  double speed_factor = 2.0;
  std::string backward_slowly = "-45,-35,-25,-15";
  std::string implication = "minimum";
  std::string fll_path;
  double fire_threshold = 0;
  CLI::Option* adc_option = nullptr;

  void add_to(CLI::App& sub, bool many_tnorms) {
    auto* t = sub.add_option("--tnorm", tnorms,
                             many_tnorms
                                 ? "t-norm(s): minimum, product, drastic, lukasiewicz, trigonometric, hamacher, all"
                                 : "the rules' t-norm: minimum, product, drastic, lukasiewicz, trigonometric, hamacher")
                  ->type_name("NAME");
    if (!many_tnorms) t->expected(1);
    adc_option = sub.add_option("--adc", adc_bits, "the sensors' ADC: 10 (Arduino Uno) or 12 bits (ESP32)")
                     ->check(CLI::IsMember({10, 12}))
                     ->capture_default_str();
    sub.add_option("--centroid", centroid, "exact, or discrete[:N] (fuzzylite's, N samples, default 100)")
        ->type_name("KIND");
    sub.add_option("--speed-factor", speed_factor,
                   "scales the motor terms (the paper: 1.92 first, 2.0 in its Tables 1-2)")
        ->check(cli::range_check(0.1, 10))
        ->capture_default_str();
    sub.add_option("--backward-slowly", backward_slowly, "BACKWARD_SLOWLY's corners before scaling")
        ->capture_default_str()
        ->type_name("A,B,C,D");
    sub.add_option("--implication", implication, "minimum (clip) or product (scale)")
        ->check(CLI::IsMember({"minimum", "product"}))
        ->capture_default_str();
    sub.add_option("--fll", fll_path, "use this fuzzylite FLL controller instead of the paper's")->type_name("FILE");
    sub.add_option("--fire-threshold", fire_threshold, "rules fire from this activation on (fuzzylite: 1e-6)")
        ->check(cli::range_check(0, 1))
        ->capture_default_str()
        ->type_name("X");
  }

  std::vector<TNorm> chosen_tnorms(bool default_all) const {
    std::vector<TNorm> chosen;
    for (const std::string& name : tnorms) {
      if (name == "all") {
        chosen.assign(std::begin(kAllTNorms), std::end(kAllTNorms));
        continue;
      }
      const auto t = fuzzy::tnorm_from_name(name);
      if (!t) throw UsageError("--tnorm: unknown t-norm '" + name + "'");
      chosen.push_back(*t);
    }
    if (chosen.empty()) {
      if (default_all) return {std::begin(kAllTNorms), std::end(kAllTNorms)};
      if (fll_path.empty()) chosen.push_back(TNorm::minimum);
    }
    return chosen;
  }

  fuzzy::Defuzzifier defuzzifier(const fuzzy::Defuzzifier& fallback) const {
    if (centroid.empty()) return fallback;
    fuzzy::Defuzzifier d;
    if (centroid == "exact") {
      d.kind = fuzzy::Defuzzifier::Kind::exact;
    } else if (centroid.rfind("discrete", 0) == 0) {
      d.kind = fuzzy::Defuzzifier::Kind::discrete;
      if (centroid.size() > 8) {
        if (centroid[8] != ':') throw UsageError("--centroid: use exact, discrete or discrete:N");
        const std::uint64_t n = cli::parse_count(centroid.substr(9), "--centroid");
        if (n < 1 || n > 10'000'000) throw UsageError("--centroid: N must be from 1 to 10000000");
        d.resolution = static_cast<int>(n);
      }
    } else {
      throw UsageError("--centroid: use exact, discrete or discrete:N");
    }
    return d;
  }

  /// The controller: the paper's with `t`, or the FLL file's (with `t` when given).
  fuzzy::Engine engine(std::optional<TNorm> t) const {
    fuzzy::Engine e;
    if (!fll_path.empty()) {
      e = fuzzy::read_fll_file(fll_path);
      if (t) e.rule_block.conjunction = *t;
    } else {
      fuzzy::LineFollowerOptions o;
      o.adc_bits = adc_bits;
      o.speed_factor = speed_factor;
      o.implication = implication == "product" ? fuzzy::Implication::product : fuzzy::Implication::minimum;
      o.conjunction = t.value_or(TNorm::minimum);
      const std::vector<double> c = cli::parse_numbers(backward_slowly, "--backward-slowly", 4);
      if (!std::is_sorted(c.begin(), c.end()))
        throw UsageError("--backward-slowly " + backward_slowly +
                         ": the term needs its corners in order (A <= B <= C <= D)");
      o.backward_slowly = {c[0], c[1], c[2], c[3]};
      e = fuzzy::line_follower_engine(o);
    }
    for (auto& out : e.outputs) out.defuzzifier = defuzzifier(out.defuzzifier);
    return e;
  }

  fuzzy::Mamdani controller(const fuzzy::Engine& e) const {
    fuzzy::Mamdani m(e);
    m.set_fire_threshold(fire_threshold);
    return m;
  }
};

std::string tnorm_label(const fuzzy::Engine& e) { return std::string(fuzzy::tnorm_name(e.rule_block.conjunction)); }

void run_eval(cli::ToolApp& tool, const ControllerOptions& options) {
  const std::vector<TNorm> chosen = options.chosen_tnorms(false);
  if (chosen.size() > 1) throw UsageError("eval takes one --tnorm");
  const fuzzy::Engine engine = options.engine(chosen.empty() ? std::nullopt : std::optional<TNorm>(chosen[0]));
  fuzzy::Mamdani controller = options.controller(engine);
  const bool paper_controller = options.fll_path.empty();
  const double full_scale = options.adc_bits == 10 ? 1023 : 4095;
  io::RecordReader reader(tool.common().inputs);
  std::vector<std::string> input_names;
  for (const auto& input : engine.inputs) input_names.push_back(input.name);
  reader.expect_columns({input_names});
  io::RecordWriter writer(tool.output_format());
  std::vector<std::string> added;
  for (const auto& out : engine.outputs) added.push_back(out.name);
  writer.declare_fields(added);
  std::vector<double> in(engine.inputs.size()), out(engine.outputs.size());
  Record record;
  while (reader.next(record)) {
    const Location where = reader.where();
    for (std::size_t i = 0; i < in.size(); ++i) {
      in[i] = io::number_field(record, engine.inputs[i].name, where);
      if (paper_controller && (in[i] < 0 || in[i] > full_scale))
        throw Error(fmt::format("{} reading {} is outside the {}-bit ADC's 0..{}", engine.inputs[i].name, in[i],
                                options.adc_bits, full_scale),
                    where);
    }
    controller.evaluate(in, out);
    for (std::size_t o = 0; o < out.size(); ++o) {
      if (std::isnan(out[o])) record[engine.outputs[o].name] = nullptr;  // no rule fired and the default is nan
      else record[engine.outputs[o].name] = out[o];
    }
    writer.write(record);
  }
  writer.flush();
}

void run_bench(cli::ToolApp& tool, const ControllerOptions& options, double seconds) {
  io::RecordWriter writer(tool.output_format());
  const auto triples = fuzzy::protocol_triples(options.adc_bits);
  for (TNorm t : options.chosen_tnorms(true)) {
    const fuzzy::Engine engine = options.engine(t);
    if (engine.inputs.size() != 3) throw Error("bench needs a controller with three inputs (the sensors)");
    fuzzy::Mamdani controller = options.controller(engine);
    const fuzzy::InferenceTiming timing = fuzzy::time_inferences(controller, triples, seconds);
    const fuzzy::Defuzzifier& d = engine.outputs[0].defuzzifier;
    Record r;
    r["tnorm"] = tnorm_label(engine);
    r["ns_per_inference"] = std::round(timing.ns_per_inference * 10) / 10;
    r["ms_per_2x1024"] = std::round(timing.ms_per_2x1024 * 1e4) / 1e4;
    r["inferences"] = timing.inferences;
    r["centroid"] = d.kind == fuzzy::Defuzzifier::Kind::exact ? "exact" : "discrete";
    r["resolution"] = d.kind == fuzzy::Defuzzifier::Kind::exact ? Record() : Record(d.resolution);
    writer.write(r);
    writer.flush();
  }
}

struct LapsOptions {
  int laps = 3;
  std::string board = "uno";
  std::string no_rule = "stop";  ///< a motor none of whose rules fired: "stop" (its default, 0) or "hold"
  double latency_ms = 0;         ///< when given; else the board's loop time for the t-norm (the paper's Tables 3-4)
  double period_ms = 0;
  double time_limit = 120;
  std::string track_path;
  std::string oval = "1000,300";
  std::string svg_path, trace_path;
  std::uint64_t seed = 1;
  double noise = 0;  ///< when given; else the car's, scaled to the ADC
  double line_width = vehicle::kTapeWidthMm;
  vehicle::CarParameters car;  ///< the car options land here, but for the lag:
  double motor_tau_ms = vehicle::CarParameters{}.motor_tau_s * 1000;
  CLI::Option *latency_option = nullptr, *noise_option = nullptr;
};

/// The car for an ADC of `adc_bits` with the car options applied (their
/// ranges were checked as they were parsed).
vehicle::CarParameters car_from(const LapsOptions& laps, int adc_bits) {
  vehicle::CarParameters car = vehicle::CarParameters::with_adc_bits(adc_bits);
  if (laps.noise_option->count() > 0) car.noise_counts = laps.noise;
  car.sensor_spacing_mm = laps.car.sensor_spacing_mm;
  car.spot_sigma_mm = laps.car.spot_sigma_mm;
  car.motor_tau_s = laps.motor_tau_ms / 1000;
  car.deadband_units = laps.car.deadband_units;
  car.mm_per_s_per_unit = laps.car.mm_per_s_per_unit;
  car.wheel_base_mm = laps.car.wheel_base_mm;
  car.sensor_ahead_mm = laps.car.sensor_ahead_mm;
  return car;
}

/// The most simulation steps (physics steps and control samples, every
/// t-norm together) and trace points one laps run may take (tnorm-bench(1)):
/// about 2 min and 100 MB.
constexpr double kMaxLapSteps = 1e8, kMaxLapTracePoints = 1e6;

/// Refuses a run whose simulated time and steps imply more than the caps.
void check_laps_size(const LapsOptions& laps, const std::vector<double>& latencies_ms, bool tracing) {
  const vehicle::LapOptions defaults;
  double steps = 0;
  for (double latency_ms : latencies_ms) {
    const double period_s = laps.period_ms > 0 ? laps.period_ms / 1000
                            : latency_ms > 0   ? latency_ms / 1000
                                               : defaults.physics_step_s;
    steps += laps.time_limit * (1 / defaults.physics_step_s + 2 / period_s);  // a sample and a command per period
  }
  cli::require_run_size(steps, kMaxLapSteps, "simulation steps", "--time-limit, --period-ms, --latency-ms and --tnorm");
  if (tracing)
    cli::require_run_size(laps.time_limit / defaults.trace_interval_s * static_cast<double>(latencies_ms.size()),
                          kMaxLapTracePoints, "trace points (one per 10 ms)",
                          "--svg or --trace with --time-limit and --tnorm");
}

void run_laps(cli::ToolApp& tool, const ControllerOptions& options, const LapsOptions& laps) {
  const bool latency_given = laps.latency_option->count() > 0;
  const fuzzy::Board board = laps.board == "esp32" ? fuzzy::Board::esp32 : fuzzy::Board::uno;
  if (options.adc_option && options.adc_option->count() > 0 && options.adc_bits != fuzzy::board_adc_bits(board))
    throw UsageError(fmt::format("--adc {} contradicts --board {} ({} bits)", options.adc_bits, laps.board,
                                 fuzzy::board_adc_bits(board)));
  ControllerOptions controller_options = options;
  controller_options.adc_bits = fuzzy::board_adc_bits(board);
  std::vector<double> latencies_ms;
  for (TNorm t : controller_options.chosen_tnorms(false))
    latencies_ms.push_back(
        latency_given ? laps.latency_ms
                      : fuzzy::paper_ms_per_2x1024(board, controller_options.engine(t).rule_block.conjunction) / 1024);
  check_laps_size(laps, latencies_ms, !laps.svg_path.empty() || !laps.trace_path.empty());
  vehicle::Track track = [&] {
    if (!laps.track_path.empty()) return vehicle::read_track(laps.track_path, laps.line_width);
    const std::vector<double> oval = cli::parse_numbers(laps.oval, "--oval", 2);
    cli::require_range(oval[0], 0, 1e5, "--oval (straight, mm)");
    cli::require_range(oval[1], 10, 1e5, "--oval (radius, mm)");  // a chord per 5 mm of the bends
    return vehicle::oval_track(oval[0], oval[1], laps.line_width);
  }();
  const vehicle::CarParameters car = car_from(laps, controller_options.adc_bits);
  vehicle::LapOptions run;
  run.laps = laps.laps;
  run.control_period_s = laps.period_ms / 1000;
  run.time_limit_s = laps.time_limit;
  run.seed = laps.seed;

  io::RecordWriter writer(tool.output_format());
  std::vector<vehicle::LapRun> runs;
  std::unique_ptr<io::RecordFile> trace_file;
  if (!laps.trace_path.empty()) {
    trace_file = std::make_unique<io::RecordFile>(laps.trace_path, tool.output_format());
    trace_file->declare_fields(
        {"tnorm", "t", "x", "y", "heading", "left", "mid", "right", "left_motor", "right_motor"});
  }
  for (TNorm t : controller_options.chosen_tnorms(false)) {
    const fuzzy::Engine engine = controller_options.engine(t);
    if (engine.inputs.size() != 3 || engine.outputs.size() != 2)
      throw Error("laps needs a controller with three inputs (left, mid, right) and two outputs (left, right motor)");
    fuzzy::Mamdani controller = controller_options.controller(engine);
    // One pass of the board's loop computes both motors: Table 3 or 4 over 1024.
    const TNorm conjunction = engine.rule_block.conjunction;
    const double latency_ms = latency_given ? laps.latency_ms : fuzzy::paper_ms_per_2x1024(board, conjunction) / 1024;
    run.latency_s = latency_ms / 1000;
    double out[2];
    vehicle::MotorCommand held;  // the motors' last command, for --no-rule hold
    auto drive = [&](const vehicle::SensorReadings& s) {
      const double in[3] = {s.left, s.mid, s.right};
      controller.evaluate(in, out);
      const auto fired = controller.fired();
      const bool hold = laps.no_rule == "hold";
      held = {hold && fired[0] == 0 ? held.left : out[0], hold && fired[1] == 0 ? held.right : out[1]};
      return held;
    };
    std::vector<vehicle::TracePoint> trace;
    const bool tracing = !laps.svg_path.empty() || trace_file;
    const vehicle::LapResult result = vehicle::run_laps(track, car, run, drive, tracing ? &trace : nullptr);
    const std::string label = tnorm_label(engine);
    Record r;
    r["tnorm"] = label;
    r["completed"] = result.completed;
    r["lap_times_s"] = result.lap_times_s;
    r["total_s"] = result.total_s;
    r["excursions"] = result.excursions;
    r["max_deviation_mm"] = result.max_deviation_mm;
    r["rms_deviation_mm"] = result.rms_deviation_mm;
    r["stop_reason"] = result.stop_reason;
    const auto& s = result.readings_at_end;
    r["sensors_at_end"] = fuzzy::sensor_pattern(s.left, s.mid, s.right, controller_options.adc_bits);
    r["readings_at_end"] = {s.left, s.mid, s.right};
    r["distance_mm"] = result.distance_mm;
    r["board"] = laps.board;
    r["latency_ms"] = latency_ms;
    const auto paper = fuzzy::paper_three_laps_s(board, conjunction);
    r["paper_total_s"] = paper && laps.laps == 3 && !latency_given ? Record(*paper) : Record();
    writer.write(r);  // in CSV the arrays are JSON text in one cell
    writer.flush();
    if (trace_file) {
      for (const auto& p : trace) {
        Record tr;
        tr["tnorm"] = label;
        tr["t"] = p.t;
        tr["x"] = p.x;
        tr["y"] = p.y;
        tr["heading"] = p.heading;
        tr["left"] = p.readings.left;
        tr["mid"] = p.readings.mid;
        tr["right"] = p.readings.right;
        tr["left_motor"] = p.command.left;
        tr["right_motor"] = p.command.right;
        trace_file->write(tr);
      }
    }
    if (!laps.svg_path.empty()) runs.push_back({label, std::move(trace), result});
  }
  if (trace_file) trace_file->close();
  if (!laps.svg_path.empty()) vehicle::write_lap_svg(laps.svg_path, track, runs);
}

void run_fll(const ControllerOptions& options) {
  const std::vector<TNorm> chosen = options.chosen_tnorms(false);
  if (chosen.size() > 1) throw UsageError("fll takes one --tnorm");
  const fuzzy::Engine engine = options.engine(chosen.empty() ? std::nullopt : std::optional<TNorm>(chosen[0]));
  const std::string text = fuzzy::write_fll(engine);
  if (std::fwrite(text.data(), 1, text.size(), stdout) != text.size()) throw Error("write error on standard output");
}

}  // namespace

int main(int argc, char** argv) {
  cli::ToolApp tool("tnorm-bench",
                    "Konczol & Gal's fuzzy line follower under six t-norms: motor commands for sensor readings (eval), "
                    "ns per inference (bench), simulated laps (laps), the controller as fuzzylite FLL (fll).",
                    "See tnorm-bench(1).");
  CLI::App& app = tool.app();
  app.require_subcommand(1);

  ControllerOptions eval_options, bench_options, laps_options, fll_options;
  CLI::App* eval = app.add_subcommand("eval", "add left_motor and right_motor to records with left, mid, right");
  eval_options.add_to(*eval, false);
  eval->add_option("files", tool.common().inputs, "input files; standard input when none or '-'")->type_name("FILE");

  double seconds = 0.5;
  CLI::App* bench = app.add_subcommand("bench", "time the inference per t-norm: one record each");
  bench_options.add_to(*bench, true);
  bench->add_option("--seconds", seconds, "CPU time per t-norm")
      ->check(cli::range_check(0.001, 3600))
      ->capture_default_str()
      ->type_name("S");

  LapsOptions laps;
  CLI::App* lap = app.add_subcommand("laps", "drive a simulated car round a track: one record per t-norm");
  laps_options.add_to(*lap, true);
  lap->add_option("--laps", laps.laps, "laps to complete")->check(cli::count_check(1, 1000))->capture_default_str();
  lap->add_option("--board", laps.board,
                  "uno or esp32: the ADC, and each t-norm's loop time from the paper's Tables 3-4")
      ->check(CLI::IsMember({"uno", "esp32"}))
      ->capture_default_str();
  lap->add_option("--no-rule", laps.no_rule, "a motor none of whose rules fire: stop (0) or hold its last command")
      ->check(CLI::IsMember({"stop", "hold"}))
      ->capture_default_str();
  // An empty or garbled number is a usage error here, not CLI11's silent 0.
  // A loop under 10 us (the paper's fastest is 313 us) only stretches the run.
  const CLI::Validator loop_ms = cli::range_check(0.01, 1000, cli::ZeroAllowed::yes);
  laps.latency_option = lap->add_option("--latency-ms", laps.latency_ms,
                                        "sampling to command taking effect, for every t-norm (default: the board's)")
                            ->check(loop_ms)
                            ->type_name("MS");
  lap->add_option("--period-ms", laps.period_ms, "control period (0: the latency, a loop that runs back to back)")
      ->check(loop_ms)
      ->capture_default_str()
      ->type_name("MS");
  lap->add_option("--time-limit", laps.time_limit, "give up after this many simulated seconds")
      ->check(cli::range_check(0.01, 36000))
      ->capture_default_str();
  lap->add_option("--track", laps.track_path, "centre line as records with x, y in mm (a closed loop)")
      ->type_name("FILE");
  lap->add_option("--oval", laps.oval, "the default track: straight length and radius, mm")
      ->capture_default_str()
      ->type_name("L,R");
  lap->add_option("--line-width", laps.line_width, "width of the line (tape), mm")
      ->check(cli::range_check(1, 500))
      ->capture_default_str()
      ->type_name("MM");
  lap->add_option("--svg", laps.svg_path, "draw the track and each t-norm's path")->type_name("FILE");
  lap->add_option("--trace", laps.trace_path, "write the runs' time series (t, x, y, readings, commands)")
      ->type_name("FILE");
  lap->add_option("--seed", laps.seed, "seed of the sensor noise")->capture_default_str();
  laps.noise_option = lap->add_option("--noise", laps.noise,
                                      "sensor noise, ADC counts (standard deviation; default the car's, 3 at 10 bits)")
                          ->check(cli::range_check(0, 4096))  // a 12-bit ADC's full scale
                          ->type_name("COUNTS");
  struct CarOption {
    const char* name;
    double* value;
    const char* help;
    const char* unit;
    double low, high;
  };
  const CarOption car_options[] = {
      {"--sensor-spacing", &laps.car.sensor_spacing_mm, "mid sensor to each outer one, mm", "MM", 1, 500},
      {"--spot-sigma", &laps.car.spot_sigma_mm, "the sensors' spot on the floor, Gaussian sigma, mm", "MM", 0, 100},
      {"--sensor-ahead", &laps.car.sensor_ahead_mm, "sensor bar ahead of the axle, mm", "MM", 0, 1000},
      {"--wheel-base", &laps.car.wheel_base_mm, "distance between the wheels, mm", "MM", 10, 1000},
      {"--motor-tau-ms", &laps.motor_tau_ms, "wheel speed's first-order lag behind the command, ms", "MS", 0, 10000},
      {"--deadband", &laps.car.deadband_units, "command a wheel needs to turn", "UNITS", 0, 10000},
      {"--speed-per-unit", &laps.car.mm_per_s_per_unit, "wheel speed per command unit above that, mm/s", "MM/S", 0.001,
       1000},
  };
  for (const CarOption& o : car_options)
    lap->add_option(o.name, *o.value, o.help)
        ->check(cli::range_check(o.low, o.high))
        ->capture_default_str()
        ->type_name(o.unit);

  CLI::App* fll = app.add_subcommand("fll", "write the controller as fuzzylite FLL");
  fll_options.add_to(*fll, false);

  for (CLI::App* sub : app.get_subcommands({})) sub->fallthrough();  // --csv, -q after the subcommand

  return tool.run(argc, argv, [&] {
    if (eval->parsed()) run_eval(tool, eval_options);
    if (bench->parsed()) run_bench(tool, bench_options, seconds);
    if (lap->parsed()) run_laps(tool, laps_options, laps);
    if (fll->parsed()) run_fll(fll_options);
  });
}
