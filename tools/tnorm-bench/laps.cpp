/// @file laps.cpp
/// @brief tnorm-bench laps: a simulated car driven round a track by the
/// controller under each t-norm, its laps, trace and drawing.
#include <fmt/format.h>

#include <memory>

#include "cli/number_option.hpp"
#include "cli/option_checks.hpp"
#include "fuzzy/line_follower.hpp"
#include "io/error.hpp"
#include "io/record_writer.hpp"
#include "modes.hpp"
#include "vehicle/lap_svg.hpp"

namespace tnorm_bench {

using namespace tk;

namespace {

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

}  // namespace

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

}  // namespace tnorm_bench
