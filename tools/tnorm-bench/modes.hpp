/// @file modes.hpp
/// @brief tnorm-bench's modes, one file each (eval, bench, laps, fll), and
/// the controller options they share; main.cpp wires the options to them.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "cli/tool_app.hpp"
#include "fuzzy/mamdani.hpp"
#include "vehicle/line_car.hpp"
#include "vehicle/line_track.hpp"

namespace tnorm_bench {

using tk::fuzzy::TNorm;

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

  void add_to(CLI::App& sub, bool many_tnorms);

  std::vector<TNorm> chosen_tnorms(bool default_all) const;

  tk::fuzzy::Defuzzifier defuzzifier(const tk::fuzzy::Defuzzifier& fallback) const;

  /// The controller: the paper's with `t`, or the FLL file's (with `t` when given).
  tk::fuzzy::Engine engine(std::optional<TNorm> t) const;

  tk::fuzzy::Mamdani controller(const tk::fuzzy::Engine& e) const;
};

std::string tnorm_label(const tk::fuzzy::Engine& e);

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
  double line_width = tk::vehicle::kTapeWidthMm;
  tk::vehicle::CarParameters car;  ///< the car options land here, but for the lag:
  double motor_tau_ms = tk::vehicle::CarParameters{}.motor_tau_s * 1000;
  CLI::Option *latency_option = nullptr, *noise_option = nullptr;
};

/// eval: left_motor and right_motor added to records with left, mid, right.
void run_eval(tk::cli::ToolApp& tool, const ControllerOptions& options);

/// bench: the inference timed per t-norm, one record each.
void run_bench(tk::cli::ToolApp& tool, const ControllerOptions& options, double seconds);

/// laps: a simulated car round a track, one record per t-norm.
void run_laps(tk::cli::ToolApp& tool, const ControllerOptions& options, const LapsOptions& laps);

/// fll: the controller as fuzzylite FLL.
void run_fll(const ControllerOptions& options);

}  // namespace tnorm_bench
