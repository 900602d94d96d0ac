/// @file fuzz_gcode.cpp
/// @brief libFuzzer target: bytes as a G-code program, run through the whole
/// gcode-pulse pipeline (tk::motion::PulseRun: lexer -> interpreter ->
/// planner -> stepper -> timed pulses), and each line through
/// tk::motion::lex_gcode_line directly.
///
/// The first byte chooses the options and the rest is the program (the
/// seeds are programs with one such byte in front):
///   byte % 3        method: nearest (or direct, below), bresenham, dda
///   byte / 3 % 2    lenient off, on
///   byte / 6 % 3    steps per mm: {200,200,400}, {1,1,1}, {1000,3,57}
///   byte / 18 % 2   with byte % 3 = 0: nearest, direct (the paper's rule)
/// Coordinates are limited to ±1000 mm (InterpreterOptions::max_coordinate_mm)
/// and inputs should be run with -max_len=4096.
///
/// Work budget: a program may legitimately ask for billions of steps within
/// those limits (an arc may make up to 1e6 turns with P, and a few hundred
/// 2000 mm moves at 1000 steps/mm fit in 4 KiB). Before the pipeline runs,
/// the program is read alone (tk::motion::PulseRun::scan: the interpreter and
/// run_file's checks, nothing planned or stepped) and the step pulses its
/// motions imply are summed (motion/pulse_estimate.hpp); above kStepBudget
/// the pipeline is skipped (lexing and interpreting still run). The estimate
/// comes from the path, not from the stepper, so a stepper that makes far
/// more events than its path needs still shows as a timeout.
/// TK_FUZZ_SKIP=budget runs every input in full (to time a skipped one).
///
/// tk::Error is the expected rejection; any other exception, crash,
/// sanitizer report, hang or huge allocation is a bug.
///
/// Oracles (switch off by name with TK_FUZZ_SKIP=a,b while a finding is open):
///   words  a lexed word has an upper-case letter other than N (N words are
///          dropped) and a finite value
///   event  every step event moves each axis by -1, 0 or +1 and at least
///          one axis (one of the 26 lattice neighbours)
///   time   pulse times are finite, never go back by more than 1 ns, and end
///          within the summary's duration
///   end    after a program that runs without error, the pulses add up to the
///          stepper's position, which is the interpreter's final position
///          quantised to steps (a block ends exactly on its commanded end)
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "fuzz_common.hpp"
#include "io/error.hpp"
#include "motion/gcode.hpp"
#include "motion/pulse_run.hpp"

namespace {

using tk::fuzz::MemoryFile;
using namespace tk::motion;

constexpr double kMaxCoordinateMm = 1000;
/// Implied step pulses above which the pipeline is skipped (see the file comment).
constexpr double kStepBudget = 1e5;

constexpr std::array<std::array<double, 3>, 3> kStepsPerMm{{{200, 200, 400}, {1, 1, 1}, {1000, 3, 57}}};

PulseOptions options_from(unsigned char byte) {
  PulseOptions options;
  constexpr StepMethod kMethods[3] = {StepMethod::nearest, StepMethod::bresenham, StepMethod::dda};
  options.method = byte % 3 == 0 && (byte / 18) % 2 != 0 ? StepMethod::direct : kMethods[byte % 3];
  options.interpreter.lenient = (byte / 3) % 2 != 0;
  options.steps_per_mm = kStepsPerMm[(byte / 6) % 3];
  options.interpreter.max_coordinate_mm = kMaxCoordinateMm;
  return options;
}

/// The program's lines as InputFile returns them (split at '\n', one
/// trailing '\r' dropped).
std::vector<std::string_view> split_lines(std::string_view program) {
  std::vector<std::string_view> lines;
  while (!program.empty()) {
    const std::size_t end = program.find('\n');
    std::string_view line = program.substr(0, end);
    program = end == std::string_view::npos ? std::string_view() : program.substr(end + 1);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    lines.push_back(line);
  }
  return lines;
}

void check_words(const GcodeLine& line) {
  if (!tk::fuzz::oracle_enabled("words")) return;
  for (const GcodeWord& word : line.words) {
    if (word.letter < 'A' || word.letter > 'Z' || word.letter == 'N')
      tk::fuzz::invariant_failed("words", "a word with letter byte " + std::to_string(int(word.letter)));
    if (!std::isfinite(word.value))
      tk::fuzz::invariant_failed("words", std::string("a word ") + word.letter + " with a non-finite value");
  }
}

void run(std::string_view bytes) {
  static MemoryFile file("fuzz-gcode");
  if (bytes.empty()) return;
  const PulseOptions options = options_from(static_cast<unsigned char>(bytes[0]));
  const std::string_view program = bytes.substr(1);

  // The lexer on every line by itself (after a NUL too: InputFile stops there).
  const std::vector<std::string_view> lines = split_lines(program);
  for (std::string_view text : lines) {
    try {
      check_words(lex_gcode_line(text));
    } catch (const tk::Error&) {
    }
  }

  file.assign(program);
  const ProgramScan plan = PulseRun::scan(file.path(), options);
  if (!(plan.implied_pulses <= kStepBudget) && tk::fuzz::oracle_enabled("budget")) return;

  std::array<std::int64_t, 3> moved{};
  double last_t = 0;
  const bool check_event = tk::fuzz::oracle_enabled("event"), check_time = tk::fuzz::oracle_enabled("time");
  auto on_pulses = [&](std::span<const Pulse> pulses) {
    for (const Pulse& pulse : pulses) {
      bool any = false;
      for (int axis = 0; axis < 3; ++axis) {
        const int d = pulse.delta[axis];
        if (check_event && (d < -1 || d > 1))
          tk::fuzz::invariant_failed(
              "event", "axis " + std::to_string(axis) + " moved " + std::to_string(d) + " steps in one event");
        any = any || d != 0;
        moved[axis] += d;
      }
      if (check_event && !any) tk::fuzz::invariant_failed("event", "an event that moves no axis");
      if (check_time) {
        if (!std::isfinite(pulse.t)) tk::fuzz::invariant_failed("time", "a pulse at a non-finite time");
        if (pulse.t < last_t - 1e-9 * std::max(1.0, last_t))
          tk::fuzz::invariant_failed(
              "time", "a pulse at " + std::to_string(pulse.t) + " s after one at " + std::to_string(last_t) + " s");
      }
      last_t = std::max(last_t, pulse.t);
    }
  };

  PulseRun pulse_run(options, on_pulses, [](const std::string&) {});
  bool failed = false;
  try {
    pulse_run.run_file(file.path());
    pulse_run.finish();
  } catch (const tk::Error&) {
    failed = true;
  }
  const PulseSummary summary = pulse_run.summary();
  if (check_time && !(last_t <= summary.duration_s + 1e-9 * std::max(1.0, summary.duration_s)))
    tk::fuzz::invariant_failed("time", "a pulse at " + std::to_string(last_t) + " s after the program's end at " +
                                           std::to_string(summary.duration_s) + " s");
  if (failed || plan.fails || !tk::fuzz::oracle_enabled("end")) return;
  for (int axis = 0; axis < 3; ++axis) {
    const double spm = options.steps_per_mm[axis];
    const auto stepper = static_cast<std::int64_t>(std::llround(summary.final_mm[axis] * spm));
    const auto commanded = static_cast<std::int64_t>(std::round(plan.end[axis] * spm));
    if (moved[axis] != stepper || stepper != commanded)
      tk::fuzz::invariant_failed("end", "axis " + std::to_string(axis) + ": pulses add up to " +
                                            std::to_string(moved[axis]) + " steps, the stepper is at " +
                                            std::to_string(stepper) + ", the program ends at " +
                                            std::to_string(commanded));
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // No catch beyond tk::Error: any other exception reaches std::terminate
  // while its throw site is still on the stack, so the report shows it.
  run(std::string_view(reinterpret_cast<const char*>(data), size));
  return 0;
}
