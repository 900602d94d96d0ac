/// @file pulse_run.cpp
#include "motion/pulse_run.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "io/error.hpp"
#include "io/input_file.hpp"
#include "motion/arc_geometry.hpp"
#include "motion/pulse_estimate.hpp"

namespace tk::motion {

double PulseSummary::rms_deviation_mm() const {
  return events ? std::sqrt(deviation_sq_sum / static_cast<double>(events)) : 0.0;
}

PulseRun::PulseRun(const PulseOptions& options, PulseSink on_pulses, std::function<void(const std::string&)> warn)
    : options_(options),
      on_pulses_(std::move(on_pulses)),
      interpreter_(options.interpreter),
      canon_(options.interpreter),
      planner_(options.limits),
      stepper_(options.method, options.steps_per_mm) {
  auto located = [this, warn = std::move(warn)](const std::string& message) {
    if (warn) warn(Error(message, where_).located_message());
  };
  interpreter_.on_warning(located);
  canon_.on_warning(located);
  ready_ = [this](const PlannedBlock& block) { on_block(block); };
  stepper_.set_position(stepper_.quantise(options.interpreter.start));
  lattice_ = stepper_.position();
  shortest_interval_.fill(INFINITY);
}

void PulseRun::run_file(const std::string& path) {
  // Whatever stops the run (bad G-code, a NUL byte, a file that cannot be
  // read), every block before it runs and the machine stops there first.
  try {
    run_lines(path);
  } catch (...) {
    finish();
    throw;
  }
}

void PulseRun::run_lines(const std::string& path) {
  io::InputFile input(path);
  std::string_view text;
  bool started = false;  // a block or an opening '%' seen
  // M2/M30 (PROGRAM_END) end the program: the lines after it are not read at all.
  while (!program_ended() && input.next(text)) {
    motions_.clear();
    where_ = input.where();
    try {
      if (!read_motions(input, text, started)) break;
      for (const Motion& motion : motions_) {
        check_counter_range(motion);
        check_synchronised_speed(motion);
        check_implied_pulses(motion);
      }
    } catch (const Error& e) {
      throw Error(e.what(), input.where());
    }
    if (scanning_) continue;
    for (const Motion& motion : motions_) {
      ++summary_.motions;
      planner_.add(motion, ready_);
    }
  }
  // rs274 exits 0 on an error and simply stops printing: a stream without
  // its PROGRAM_END() is a program LinuxCNC did not finish.
  if (options_.canon && !canon_.program_ended())
    throw Error("the canonical commands end without PROGRAM_END(): rs274 stopped early (its standard error says why)",
                Location{input.where().file, input.line_number()});
}

/// One line's motions into motions_: canonical commands, or G-code. False
/// at the '%' that closes a tape: nothing after it is read.
bool PulseRun::read_motions(const io::InputFile& input, std::string_view text, bool& started) {
  if (options_.canon) {
    canon_.execute(text, input.line_number(), motions_);
    return true;
  }
  const GcodeLine line = lex_gcode_line(text);
  // '%' opens a tape; the next '%' (or one after any block) ends it.
  if (line.percent) {
    if (started) return false;
    started = true;
    return true;
  }
  if (!line.words.empty()) started = true;
  interpreter_.execute(line, input.line_number(), motions_);
  return true;
}

// The stepper's counters hold any point of the path: the end, and for an
// arc the whole circle's box. Checked here, where the line is known.
void PulseRun::check_counter_range(const Motion& motion) const {
  if (motion.kind == MotionKind::dwell) return;
  stepper_.quantise(motion.end);
  if (motion.kind == MotionKind::arc) {
    const ArcGeometry g = arc_geometry(motion);
    const double r = std::max(g.r_start, g.r_end);
    Vec3 corner = motion.center;
    corner[g.a0] = std::fabs(g.c0) + r;
    corner[g.a1] = std::fabs(g.c1) + r;
    stepper_.quantise(corner);
  }
}

// A G33 cannot be slowed to what the machine can do as a feed is: the tool
// would leave the thread the spindle cuts. LinuxCNC refuses a spindle speed
// that asks too much of the axes; so does this, at the G33's line.
void PulseRun::check_synchronised_speed(const Motion& motion) const {
  if (!motion.spindle_synchronised) return;
  const double cap = machine_speed_cap(options_.limits, motion);
  if (motion.feed > cap * (1 + 1e-12))
    throw Error(
        fmt::format("G33 needs {:.6g} mm/min along its line (K times S), more than the machine allows there "
                    "({:.6g} mm/min)",
                    motion.feed * 60, cap * 60));
}

// Before the block is planned: a move of a kilometre at fine steps implies
// 10^11 pulses, hours of stepping and terabytes of records.
void PulseRun::check_implied_pulses(const Motion& motion) {
  implied_pulses_ += implied_pulses(motion, options_.steps_per_mm);
  if (implied_pulses_ > options_.max_pulses)
    throw Error(
        fmt::format("the program implies {:.4g} step pulses up to this block, more than --max-pulses {:g} allows",
                    implied_pulses_, options_.max_pulses));
}

void PulseRun::finish() { planner_.finish(ready_); }

ProgramScan PulseRun::scan(const std::string& path, const PulseOptions& options) {
  PulseRun reader(options, {}, {});
  reader.scanning_ = true;
  ProgramScan out;
  try {
    reader.run_lines(path);
  } catch (const Error&) {
    out.fails = true;
  }
  out.implied_pulses = reader.implied_pulses_;
  out.end = options.canon ? reader.canon_.position() : reader.interpreter_.position();
  return out;
}

void PulseRun::on_block(const PlannedBlock& block) {
  if (block.motion.kind == MotionKind::dwell) {
    clock_ += block.duration;
    summary_.dwell_s += block.duration;
    return;
  }
  if (block.feed_capped) ++summary_.feed_capped;
  if (svg_) svg_->add_motion(block.motion);
  const double start = clock_;
  const bool want_pulses = static_cast<bool>(on_pulses_);
  summary_.path_mm += stepper_.run(block.motion, [&](std::span<const StepEvent> events) {
    if (want_pulses) pulses_.clear();
    for (const StepEvent& event : events) {
      const double t = start + block.time_at(event.along_mm);
      for (int axis = 0; axis < 3; ++axis) {
        if (event.delta[axis] == 0) continue;
        ++summary_.pulses[axis];
        if (last_step_time_[axis] >= 0) {
          const double interval = t - last_step_time_[axis];
          if (interval > 0) shortest_interval_[axis] = std::min(shortest_interval_[axis], interval);
          else ++summary_.coincident_steps;
        }
        last_step_time_[axis] = t;
      }
      summary_.max_deviation_mm = std::max(summary_.max_deviation_mm, event.deviation_sq);  // squared until summary()
      summary_.deviation_sq_sum += event.deviation_sq;
      if (want_pulses) pulses_.push_back(Pulse{t, event.delta});
    }
    summary_.events += events.size();
    if (svg_)
      for (const StepEvent& event : events) {
        for (int axis = 0; axis < 3; ++axis) lattice_[axis] += event.delta[axis];
        svg_->add_point(static_cast<double>(lattice_[0]) / options_.steps_per_mm[0],
                        static_cast<double>(lattice_[1]) / options_.steps_per_mm[1]);
      }
    if (want_pulses) on_pulses_(std::span<const Pulse>(pulses_.data(), pulses_.size()));
  });
  clock_ = start + block.duration;
}

PulseSummary PulseRun::summary() const {
  PulseSummary out = summary_;
  out.max_deviation_mm = std::sqrt(summary_.max_deviation_mm);
  out.duration_s = clock_;
  for (int axis = 0; axis < 3; ++axis) {
    out.final_mm[axis] = static_cast<double>(stepper_.position()[axis]) / options_.steps_per_mm[axis];
    // Over positive intervals; two steps of one axis at one instant are
    // counted in coincident_steps instead.
    out.peak_rate[axis] =
        std::isfinite(shortest_interval_[axis]) && shortest_interval_[axis] > 0 ? 1.0 / shortest_interval_[axis] : 0.0;
  }
  out.blocks = options_.canon ? canon_.blocks() : interpreter_.blocks();
  out.unused_words = options_.canon ? canon_.unused_words() : interpreter_.unused_words();
  return out;
}

}  // namespace tk::motion
