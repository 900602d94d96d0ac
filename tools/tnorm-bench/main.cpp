/// @file main.cpp
/// @brief tnorm-bench: Könczöl & Gál's Mamdani line follower under six
/// t-norms: its motor commands for sensor readings (eval), its speed per
/// inference (bench), laps of a simulated car (laps), and the controller as
/// fuzzylite FLL (fll). Any FLL controller can stand in for the paper's.
/// Each mode is a file of its own (modes.hpp); this one wires the options.
#include "cli/option_checks.hpp"
#include "cli/tool_app.hpp"
#include "modes.hpp"

using namespace tk;
using namespace tnorm_bench;

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
