/// @file canon.hpp
/// @brief LinuxCNC's canonical machining commands, one per line as its
/// standalone interpreter prints them (`rs274 -g prog.ngc`), turned into
/// the same Motions the G-code interpreter makes: so that whatever LinuxCNC
/// can interpret (subroutines, parameters, expressions, canned cycles, G76,
/// cutter compensation...) can be stepped, without a second interpreter.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "motion/gcode.hpp"

namespace tk::motion {

/// Reads the stream a line at a time. A line is `[COUNT N-FIELD] NAME(ARGS)`
/// ("   43 N0090  STRAIGHT_TRAVERSE(1.0000, 1.0000, 0.0000, ...)"), the
/// counter and N field optional; blank lines are skipped.
///
/// Positions are LinuxCNC's: the canonical coordinates are the program's
/// (current units, work offsets removed), and the machine moves to
/// R(θ)·(p + G92 offset) + G5x offset + tool length offset, as LinuxCNC's
/// motion layer does (θ the XY rotation of G10 L2 R). Motions come out in
/// those machine coordinates, in mm, like GcodeInterpreter's.
///
/// Acting commands: STRAIGHT_TRAVERSE, STRAIGHT_FEED, STRAIGHT_PROBE (the
/// move to the probe's target: rs274 has no probe to touch), ARC_FEED,
/// RIGID_TAP (G33.1: in following the spindle and back out),
/// DWELL, SET_FEED_RATE, SET_FEED_MODE (1: per spindle revolution),
/// START_SPEED_FEED_SYNC / STOP_SPEED_FEED_SYNCH (G33, G76: moves follow
/// the spindle), SET_SPINDLE_SPEED, SET_SPINDLE_MODE (constant surface
/// speed), START_SPINDLE_*, STOP_SPINDLE_TURNING, SELECT_PLANE,
/// USE_LENGTH_UNITS, SET_G5X_OFFSET, SET_G92_OFFSET, SET_XY_ROTATION,
/// USE_TOOL_LENGTH_OFFSET, PROGRAM_END. Commands that move or time nothing
/// (comments, coolant, tool changes, stops, outputs...) are counted in
/// unused_words() by name. Throws tk::Error (no location; the caller adds
/// it) on a line that is no canonical command, a wrong number of
/// arguments, a bad number, a command unknown here, NURBS_FEED (rs274 -g
/// does not print the spline), motion of A, B, C, U, V or W, an arc out of
/// the XY plane under an XY rotation, a move at feed rate 0, a move that
/// follows a stopped spindle, or an arc whose ends lie on circles of
/// different radii (LinuxCNC's tolerance). options.lenient skips the extra
/// axes and unknown commands with a warning instead.
class CanonInterpreter {
 public:
  explicit CanonInterpreter(InterpreterOptions options = {});

  void execute(std::string_view text, std::size_t line_number, std::vector<Motion>& out);

  void on_warning(std::function<void(const std::string&)> warn) { warn_ = std::move(warn); }
  const Vec3& position() const { return position_; }
  const std::map<std::string, std::uint64_t>& unused_words() const { return unused_; }
  std::uint64_t blocks() const { return commands_; }  ///< canonical commands read
  bool program_ended() const { return ended_; }       ///< PROGRAM_END() seen

 private:
  struct Command;
  void straight(const Command& command, MotionKind kind, std::vector<Motion>& out);
  void arc_feed(const Command& command, std::vector<Motion>& out);
  void rigid_tap(const Command& command, std::vector<Motion>& out);
  void check_extra_axes(const Command& command, std::size_t first);
  double feed_speed(bool arc, bool& synchronised) const;
  Vec3 to_machine(double x, double y, double z) const;
  Vec3 checked(Vec3 point) const;

  InterpreterOptions options_;
  std::function<void(const std::string&)> warn_;
  Vec3 position_;                     ///< machine, mm
  double unit_ = 1;                   ///< mm per program unit (USE_LENGTH_UNITS)
  Vec3 g5x_, g92_, tool_;             ///< mm
  double rotation_deg_ = 0;           ///< SET_XY_ROTATION
  int plane_ = 17;                    ///< 17 XY, 18 XZ, 19 YZ
  double feed_ = 0;                   ///< SET_FEED_RATE: mm/min, or mm per revolution
  bool feed_per_revolution_ = false;  ///< SET_FEED_MODE(_, 1), G95
  bool synchronised_ = false;         ///< between START_SPEED_FEED_SYNC and STOP_SPEED_FEED_SYNCH
  double sync_per_revolution_ = 0;    ///< mm per spindle revolution
  bool sync_velocity_only_ = false;   ///< its second argument: speed follows, position does not
  double spindle_rpm_ = 0;
  bool spindle_turning_ = false;
  bool constant_surface_speed_ = false;
  std::vector<double> extra_axes_;  ///< the last A B C (U V W) seen, program units
  std::map<std::string, std::uint64_t> unused_;
  std::uint64_t commands_ = 0;
  bool ended_ = false;
};

}  // namespace tk::motion
