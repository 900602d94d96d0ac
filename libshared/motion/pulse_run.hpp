/// @file pulse_run.hpp
/// @brief gcode-pulse's pipeline: G-code lines -> interpreter -> planner
/// (speeds) -> stepper (lattice moves) -> timed pulses and a summary.
/// Streams: memory does not grow with the program's length.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <span>
#include <string>

#include "io/error.hpp"
#include "io/input_file.hpp"
#include "motion/canon.hpp"
#include "motion/gcode.hpp"
#include "motion/path_svg.hpp"
#include "motion/planner.hpp"
#include "motion/stepper.hpp"

namespace tk::motion {

struct PulseOptions {
  StepMethod method = StepMethod::nearest;
  std::array<double, 3> steps_per_mm{200, 200, 400};
  MachineLimits limits;
  InterpreterOptions interpreter;
  /// The input is LinuxCNC's canonical commands (`rs274 -g`, canon.hpp),
  /// not G-code (gcode-pulse --canon).
  bool canon = false;
  /// The most pulses a run may imply (gcode-pulse --max-pulses): the block
  /// whose motions would take the total past it is an error at its line.
  double max_pulses = kDefaultMaxPulses;
  static constexpr double kDefaultMaxPulses = 1e9;
};

/// What a run did, for --summary.
struct PulseSummary {
  std::array<std::uint64_t, 3> pulses{};
  std::array<double, 3> final_mm{};
  double duration_s = 0;
  double dwell_s = 0;
  double path_mm = 0;
  double max_deviation_mm = 0;
  double deviation_sq_sum = 0;
  std::uint64_t events = 0;
  std::array<double, 3> peak_rate{};   ///< steps/s: 1 / the shortest positive interval between two steps of an axis
  std::uint64_t coincident_steps = 0;  ///< steps of an axis at the same instant as its previous one
  std::uint64_t blocks = 0, motions = 0, feed_capped = 0;
  std::map<std::string, std::uint64_t> unused_words;

  double rms_deviation_mm() const;
};

/// What a program asks for, read as PulseRun::run_file reads it (the same
/// checks, the same end of the program) but neither planned nor stepped.
struct ProgramScan {
  double implied_pulses = 0;  ///< over the motions read (pulse_estimate.hpp)
  bool fails = false;         ///< reading stopped at a tk::Error: run_file throws it too
  Vec3 end{};                 ///< where the interpreter leaves the machine
};

/// One timed event: seconds from the program's start and the unit moves.
struct Pulse {
  double t = 0;
  std::array<std::int8_t, 3> delta{};
};

class PulseRun {
 public:
  using PulseSink = std::function<void(std::span<const Pulse>)>;

  /// `on_pulses` may be empty (summary only); warnings (lenient skips) go to `warn`.
  PulseRun(const PulseOptions& options, PulseSink on_pulses, std::function<void(const std::string&)> warn);

  /// Runs one program file ("-" is stdin). Throws tk::Error with the file
  /// and line of the first bad block, after every pulse before it.
  void run_file(const std::string& path);
  /// Draws the ideal and the stepped path over a window (see PathSvg).
  void draw(PathSvg* svg) { svg_ = svg; }
  /// Stops the machine after the last block and emits what is pending.
  void finish();
  /// Reads one program file without running it (a fuzz target's work budget).
  static ProgramScan scan(const std::string& path, const PulseOptions& options);

  PulseSummary summary() const;

 private:
  void run_lines(const std::string& path);
  bool read_motions(const io::InputFile& input, std::string_view text, bool& started);
  bool program_ended() const { return options_.canon ? canon_.program_ended() : interpreter_.program_ended(); }
  void check_counter_range(const Motion& motion) const;
  void check_synchronised_speed(const Motion& motion) const;
  void check_implied_pulses(const Motion& motion);
  void on_block(const PlannedBlock& block);

  PulseOptions options_;
  Location where_;  ///< the line being read, for warnings
  PulseSink on_pulses_;
  GcodeInterpreter interpreter_;
  CanonInterpreter canon_;
  Planner planner_;
  Stepper stepper_;
  Planner::Sink ready_;
  PulseSummary summary_;
  double clock_ = 0;  ///< start time of the next planned block
  std::array<double, 3> last_step_time_{-1, -1, -1};
  std::array<double, 3> shortest_interval_{};
  std::vector<Pulse> pulses_;
  PathSvg* svg_ = nullptr;
  std::array<std::int64_t, 3> lattice_{};  ///< followed only when drawing
  std::vector<Motion> motions_;
  double implied_pulses_ = 0;  ///< by the blocks read so far (pulse_estimate.hpp)
  bool scanning_ = false;      ///< read the motions, plan none (scan)
};

}  // namespace tk::motion
