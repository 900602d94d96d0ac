/// @file stepper.hpp
/// @brief Turns lines and arcs into unit moves on the step lattice (every
/// axis -1, 0 or +1 per event: one of the 26 neighbours), by four methods:
///
/// - direct (Panayotov & Goranov's single-impulse calculation, as printed):
///   the line from the current lattice point to the end pierces the box of
///   one step around the point; move to the neighbour nearest that
///   puncture, re-origin there (a new line to the end) and repeat. The
///   paper gives no rule for arcs: they are walked as by `nearest`.
/// - nearest: of the neighbours that make progress toward the target, the
///   one whose new position lies closest to the programmed path (the line
///   stays the programmed one, it is not recomputed after each step).
/// - bresenham: the classic integer line algorithm (the major axis steps
///   every event, minor axes when their error term crosses) and its
///   midpoint generalisation for arcs.
/// - dda: the digital differential analyser, sampling the ideal path at a
///   fixed rate fine enough that no axis moves more than one step per
///   sample, and stepping when a quantised coordinate changes.
///
/// Counters are integers, so a block always ends exactly on its commanded
/// end quantised to steps, and a million blocks accumulate no drift.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <string_view>
#include <vector>

#include "motion/gcode.hpp"

namespace tk::motion {

enum class StepMethod : std::uint8_t { direct, nearest, bresenham, dda };

/// The methods' command-line names, in the enum's order.
inline constexpr std::array<const char*, 4> kStepMethodNames{"direct", "nearest", "bresenham", "dda"};
/// The method of that name; an Error for any other name.
StepMethod step_method_named(std::string_view name);

/// One event: the unit move of each axis, how far along the block's ideal
/// path (mm from its start) the new lattice point lies, and the square of
/// its distance from the ideal path (mm^2).
struct StepEvent {
  std::array<std::int8_t, 3> delta{};
  double along_mm = 0;
  double deviation_sq = 0;
};

class Stepper {
 public:
  /// Steps per mm of each axis, each positive and finite.
  Stepper(StepMethod method, std::array<double, 3> steps_per_mm);

  /// Steps one line, rapid or arc from the current lattice point to the
  /// motion's end, handing the events to `sink` in chunks (at most a few
  /// thousand at a time). Dwells do nothing. Returns the ideal path length
  /// in mm (the helix length for arcs).
  double run(const Motion& motion, const std::function<void(std::span<const StepEvent>)>& sink);

  const std::array<std::int64_t, 3>& position() const { return position_; }
  /// Puts the machine at a lattice point (the start of a program).
  void set_position(const std::array<std::int64_t, 3>& lattice) { position_ = lattice; }
  /// The lattice point nearest to `mm` (rounding half away from zero).
  std::array<std::int64_t, 3> quantise(const Vec3& mm) const;
  double step_mm(int axis) const { return step_mm_[axis]; }

 private:
  /// Collects events and hands them to the sink a chunk at a time (a
  /// fixed array on the stack: one store and one compare per event).
  class Chunk {
   public:
    static constexpr std::size_t kEvents = 1024;
    explicit Chunk(const std::function<void(std::span<const StepEvent>)>& sink) : sink_(sink) {}
    void push(const StepEvent& event) {
      events_[count_++] = event;
      if (count_ == kEvents) flush();
    }
    void flush() {
      if (count_ != 0) sink_(std::span<const StepEvent>(events_.data(), count_));
      count_ = 0;
    }

   private:
    std::array<StepEvent, kEvents> events_;
    std::size_t count_ = 0;
    const std::function<void(std::span<const StepEvent>)>& sink_;  ///< outlives the chunk
  };

  /// A walk's state, and one function per stepping method: lines in
  /// stepper_line.cpp, arcs in stepper_arc.cpp.
  class LineWalk;
  class ArcWalk;

  double run_line(const Motion& motion, Chunk& out);
  double run_arc(const Motion& motion, Chunk& out);

  StepMethod method_;
  std::array<double, 3> steps_per_mm_, step_mm_;
  std::array<std::int64_t, 3> position_{};
};

}  // namespace tk::motion
