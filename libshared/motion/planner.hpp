/// @file planner.hpp
/// @brief Feed-rate planning: each motion gets a trapezoidal speed profile
/// (accelerate at a constant rate, cruise, decelerate) whose entry and exit
/// speeds join the neighbouring blocks, as a CNC control's look-ahead does.
///
/// Junction speeds follow grbl's junction-deviation model: the corner is
/// rounded by an arc that stays within `junction_deviation` of the sharp
/// corner, and the speed is the one at which that arc's centripetal
/// acceleration equals the machine's. Arcs are also limited to the speed
/// whose centripetal acceleration v^2/R equals it. Look-ahead runs over a
/// window of blocks: the last block in the window must be able to stop, so
/// a longer window only ever raises speeds. A full window is planned once
/// and its first half goes out, so every block is planned with at least
/// half a window after it. A dwell stops the machine, and so does the start
/// of a spindle-synchronised (G33) motion after one that is not.
#pragma once

#include <array>
#include <cstddef>
#include <deque>
#include <functional>

#include "motion/gcode.hpp"

namespace tk::motion {

/// Per-axis limits work as grbl's do: a block's speed and acceleration
/// along its path are capped so that no axis' share of them exceeds its
/// own limit (a line: limit / |direction component|; an arc or helix: the
/// largest share any of its tangents gives an axis, cos of its slope for
/// the plane's axes and sin for the normal axis).
struct MachineLimits {
  double acceleration = 500;                                       ///< mm/s^2 along the path
  double rapid_speed = 5000.0 / 60;                                ///< mm/s for G0
  double max_speed = 5000.0 / 60;                                  ///< mm/s: programmed feeds above it are capped
  double junction_deviation = 0.01;                                ///< mm
  std::size_t lookahead = 256;                                     ///< blocks planned together
  std::array<double, 3> axis_speed{kNoLimit, kNoLimit, kNoLimit};  ///< mm/s per axis
  std::array<double, 3> axis_acceleration{kNoLimit, kNoLimit, kNoLimit};  ///< mm/s^2 per axis

  static constexpr double kNoLimit = 1e300;
};

/// A motion with its planned speeds (mm/s); dwells have only a duration.
struct PlannedBlock {
  Motion motion;
  double length = 0;  ///< mm along the path
  double entry_speed = 0, cruise_speed = 0, exit_speed = 0;
  double acceleration = 0;
  double duration = 0;       ///< s
  bool feed_capped = false;  ///< the programmed feed exceeded max_speed or an axis' speed
  /// Where the cruise starts and ends (mm) and when (s): set with the profile.
  double cruise_from = 0, cruise_to = 0, cruise_starts = 0, cruise_ends = 0;

  /// Seconds from the block's start until the tool is `along` mm into it.
  double time_at(double along) const;
};

class Planner {
 public:
  using Sink = std::function<void(const PlannedBlock&)>;

  explicit Planner(MachineLimits limits);

  /// Adds a motion; blocks whose profiles are final go to `ready`, in order.
  void add(const Motion& motion, const Sink& ready);
  /// Ends the program: the machine stops after the last block.
  void finish(const Sink& ready);

 private:
  struct Pending {
    PlannedBlock block;
    double max_entry = 0;  ///< junction and nominal limits on the entry speed
    double nominal = 0;
    Vec3 entry_direction, exit_direction;
  };
  void plan();
  void emit_front(const Sink& ready);

  MachineLimits limits_;
  std::deque<Pending> pending_;
  bool have_previous_ = false;
  bool previous_synchronised_ = false;  ///< the previous motion was a G33
  Vec3 previous_exit_direction_;
  double previous_nominal_ = 0, previous_acceleration_ = 0;
  double locked_entry_ = 0;  ///< the entry speed of the front block, fixed by the block before it
};

/// The feed cap along a motion in mm/s: the rapid speed for G0, max_speed
/// for the others, lowered so that no axis' share of it exceeds the axis'
/// own limit (as the planner caps a programmed feed; arcs' centripetal
/// limit aside).
double machine_speed_cap(const MachineLimits& limits, const Motion& motion);

/// The finished profile of one block: cruise speed and duration from its
/// entry, nominal and exit speeds, length and acceleration.
void complete_profile(PlannedBlock& block, double nominal);

}  // namespace tk::motion
