/// @file gcode_interpreter.cpp
/// @brief The modal RS274/NGC interpreter: modal state, units, distance and
/// lathe diameter modes, the spindle, straight moves, spindle-synchronised
/// moves (G33), dwells, and arcs in centre (I/J/K) and radius (R) format.
#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "io/error.hpp"
#include "motion/arc_geometry.hpp"
#include "motion/gcode.hpp"
#include "motion/gcode_block.hpp"

namespace tk::motion {

Motion dwell_at(const Vec3& position, double seconds, std::size_t source_line) {
  Motion dwell;
  dwell.kind = MotionKind::dwell;
  dwell.start = dwell.end = position;
  dwell.duration = seconds;
  dwell.source_line = source_line;
  return dwell;
}

GcodeInterpreter::GcodeInterpreter(InterpreterOptions options) : options_(options), position_(options.start) {}

void GcodeInterpreter::warn(const std::string& message) const {
  if (warn_) warn_(message);
}

void GcodeInterpreter::execute(const GcodeLine& line, std::size_t line_number, std::vector<Motion>& out) {
  // LinuxCNC stops reading at M2/M30, so whatever follows is ignored; '/'
  // lines are skipped as with the block delete switch on.
  if (ended_ || line.block_delete) return;
  GcodeBlock block;
  for (const GcodeWord& word : line.words) block.add(word);
  if (block.empty()) return;
  ++blocks_;

  const bool skip_motion = skip_unsupported(block);
  set_tool_offset(block);
  record_unused(block);
  // The rest in LinuxCNC's order of execution (feed mode, F, S, spindle,
  // dwell, plane, units, lathe and distance modes, motion, program end),
  // except that units come before F so that "G20 F10" means 10 in/min.
  set_modes(block);
  set_spindle(block);
  if (block.has_g(40)) {
    if (!block.has('P')) throw Error("G4 (dwell) without a P word");
    const double seconds = block.take('P');
    if (seconds < 0) throw Error(fmt::format("negative dwell time P{:g}", seconds));
    if (seconds > 0) out.push_back(dwell_at(position_, seconds, line_number));
  }
  move(block, skip_motion, line_number, out);
  for (char letter = 'A'; letter <= 'Z'; ++letter)
    if (block.has(letter) && !block.used[GcodeBlock::index(letter)])
      throw Error(fmt::format("{}{:g}: nothing on the line uses the {} word", letter,
                              block.value[GcodeBlock::index(letter)], letter));
  if (block.has_m(2) || block.has_m(30)) ended_ = true;
}

/// Fails on the codes and axes this interpreter cannot honour or, when
/// lenient, drops them with a warning. True when a dropped code owned the
/// line's axis words, so that the line must not move.
bool GcodeInterpreter::skip_unsupported(GcodeBlock& block) {
  bool skip_motion = false;
  for (auto it = block.gcodes.begin(); it != block.gcodes.end();) {
    const GcodeInfo& info = **it;
    if (info.use != GcodeUse::unsupported) {
      ++it;
      continue;
    }
    const std::string name = fmt::format("{} ({})", gcode_name(info.code), info.what);
    if (!options_.lenient) throw Error(name + " is not supported");
    warn("skipped " + name);
    if (info.group == GcodeGroup::motion) {
      motion_mode_ = -2;
      skipped_mode_ = name;
    }
    skip_motion = skip_motion || info.group == GcodeGroup::motion || info.takes_axis_words;
    block.used.set();  // its argument words (R, Q, L, P...) go with it
    it = block.gcodes.erase(it);
  }
  for (const char letter : {'A', 'B', 'C', 'U', 'V', 'W'}) {
    if (!block.has(letter)) continue;
    const std::string word = fmt::format("{}{:g}", letter, block.take(letter));
    if (!options_.lenient) throw Error(fmt::format("axis word {} is not supported (3 axes only: X, Y, Z)", word));
    warn(fmt::format("skipped {} (3 axes only: X, Y, Z)", word));
  }
  return skip_motion;
}

void GcodeInterpreter::record_unused(GcodeBlock& block) {
  for (const GcodeInfo* info : block.gcodes)
    if (info->use == GcodeUse::record) ++unused_[gcode_name(info->code)];
  if (block.ignored_g80) ++unused_["G80"];
  if (block.has_g(640)) {  // G64 P (tolerance) Q (naive CAM tolerance)
    block.consume('P');
    block.consume('Q');
  }
  for (const int m : block.mcodes) {
    if (m == 2 || m == 30) continue;  // they end the program
    ++unused_[fmt::format("M{}", m)];
    for (const char letter : mcode_arguments(m)) block.consume(letter);
  }
  for (const char letter : {'T', 'H', 'D'}) {
    if (!block.has(letter)) continue;
    block.take(letter);
    ++unused_[std::string(1, letter)];
  }
}

/// T selects, M6 loads the selected tool, M61 Q loads tool Q; then G43
/// (the table's offsets of tool H, or of the loaded tool), G43.1 (the
/// line's X Y Z are the offsets) or G49 (none), in LinuxCNC's order. The
/// machine does not move: later absolute coordinates shift by the offset.
void GcodeInterpreter::set_tool_offset(GcodeBlock& block) {
  const auto tool_number = [&](char letter) {
    const double value = block.value[GcodeBlock::index(letter)];
    if (value < 0 || value != std::floor(value) || value > 1e9)
      throw Error(fmt::format("{}{:g}: a tool number is a whole number, 0 or more", letter, value));
    return static_cast<int>(value);
  };
  if (block.has('T')) selected_tool_ = tool_number('T');
  if (block.has_m(6)) loaded_tool_ = selected_tool_;
  if (block.has_m(61) && block.has('Q')) loaded_tool_ = tool_number('Q');
  const GcodeInfo* mode = block.in_group(GcodeGroup::tool_length);
  if (!mode) return;
  if (mode->code == 490) {
    tool_offset_ = {};
  } else if (mode->code == 431) {
    for (int axis = 0; axis < 3; ++axis) {
      const char letter = "XYZ"[axis];
      if (!block.has(letter)) continue;
      tool_offset_[axis] = block.take(letter) * unit();
      block.present.reset(GcodeBlock::index(letter));  // an offset, not a move
    }
  } else {
    int tool = loaded_tool_;
    if (block.has('H')) {
      tool = tool_number('H');
      block.take('H');
    }
    if (tool == 0) {
      tool_offset_ = {};
      return;
    }
    if (!options_.has_tool_table) {
      const std::string message = fmt::format(
          "G43 (tool length offset) of tool {}: its length is unknown without a tool table "
          "(--tool-table FILE)",
          tool);
      if (!options_.lenient) throw Error(message);
      warn("skipped " + message);
      return;
    }
    const auto found = options_.tool_table.find(tool);
    if (found == options_.tool_table.end()) throw Error(fmt::format("G43: tool {} is not in the tool table", tool));
    tool_offset_ = found->second;
  }
}

void GcodeInterpreter::set_modes(GcodeBlock& block) {
  if (const GcodeInfo* mode = block.in_group(GcodeGroup::feed_mode)) {
    const bool inverse = mode->code == 930;
    if (inverse_time_ && !inverse) feed_ = 0;  // a G93 F is a time: G94 needs a new F
    inverse_time_ = inverse;
  }
  // Units before F, so that "G20 F10" is 10 in/min.
  if (const GcodeInfo* units = block.in_group(GcodeGroup::units)) inches_ = units->code == 200 || units->code == 700;
  if (block.has('F')) {
    const double feed = block.take('F');
    if (feed < 0) throw Error(fmt::format("negative feed rate F{:g}", feed));
    if (!inverse_time_) feed_ = feed * unit();  // in G93 each move reads its own F
  }
  if (const GcodeInfo* plane = block.in_group(GcodeGroup::plane)) plane_ = plane->code / 10;
  if (const GcodeInfo* lathe = block.in_group(GcodeGroup::lathe_mode)) diameter_mode_ = lathe->code == 70;
  if (const GcodeInfo* distance = block.in_group(GcodeGroup::distance)) incremental_ = distance->code == 910;
  if (const GcodeInfo* distance = block.in_group(GcodeGroup::arc_distance)) arc_incremental_ = distance->code == 911;
}

/// The spindle matters only to G33, which follows it: S is kept (rpm, or a
/// surface speed under G96), M3/M4 start it and M5 stops it. M3-M5 and G96
/// G97 still count as unused words: they do not move or time anything.
void GcodeInterpreter::set_spindle(GcodeBlock& block) {
  if (block.has('S')) {
    const double speed = block.take('S');
    if (speed < 0) throw Error(fmt::format("negative spindle speed S{:g}", speed));
    spindle_speed_ = speed;
  }
  if (const GcodeInfo* mode = block.in_group(GcodeGroup::spindle_mode)) constant_surface_speed_ = mode->code == 960;
  if (block.has_m(3) || block.has_m(4)) spindle_turning_ = true;
  if (block.has_m(5)) spindle_turning_ = false;
}

void GcodeInterpreter::move(GcodeBlock& block, bool skip_motion, std::size_t line_number, std::vector<Motion>& out) {
  if (const GcodeInfo* mode = block.in_group(GcodeGroup::motion)) {  // unsupported ones are gone
    motion_mode_ = mode->code == 800 ? -1 : mode->code / 10;
    skipped_mode_.clear();
  }
  const bool axis_words = block.has('X') || block.has('Y') || block.has('Z');
  const bool arc_mode = motion_mode_ == 2 || motion_mode_ == 3;
  const bool arc_words = block.has('I') || block.has('J') || block.has('K') || block.has('R');
  // LinuxCNC refuses a G33 with no end point rather than wait for the
  // spindle to go nowhere.
  if (block.has_g(330) && !axis_words && !skip_motion)
    throw Error("G33 without X, Y or Z words (it needs an end point)");
  // G2/G3 with only centre words and no end point: a full circle.
  if (skip_motion || !(axis_words || (arc_mode && arc_words))) return;
  if (motion_mode_ == -2) {
    warn(fmt::format("skipped this line's motion: {} mode", skipped_mode_));
    block.used.set();
    return;
  }
  if (motion_mode_ == -1) throw Error("axis words with no motion mode (after G80)");

  // G53: this line's coordinates are the machine's, with no offset.
  const bool machine_coordinates = block.has_g(530);
  if (machine_coordinates && incremental_) throw Error("G53 in incremental distance mode (G91)");
  if (machine_coordinates && motion_mode_ != 0 && motion_mode_ != 1) throw Error("G53 needs G0 or G1 motion");
  // G43 moves nothing (LinuxCNC's G43: "The next time a compensated axis
  // is moved, that axis's endpoint is the compensated location"): an axis
  // without a word stays where the machine is.
  Vec3 target = position_;
  for (int axis = 0; axis < 3; ++axis) {
    const char letter = "XYZ"[axis];
    if (!block.has(letter)) continue;
    double value = block.take(letter) * unit();
    // G7: the word is a diameter, the machine's X a radius. LinuxCNC halves
    // the number as it reads it, so G91 increments are halved too.
    if (letter == 'X' && diameter_mode_) value /= 2;
    target[axis] = incremental_ ? position_[axis] + value : value + (machine_coordinates ? 0 : tool_offset_[axis]);
    if (!(std::abs(target[axis]) <= options_.max_coordinate_mm))
      throw Error(
          fmt::format("coordinate {}{:.10g} beyond ±{:.10g} mm", letter, target[axis], options_.max_coordinate_mm));
  }
  const bool moves = target.x != position_.x || target.y != position_.y || target.z != position_.z;
  Motion motion;
  motion.kind = MotionKind::rapid;
  motion.start = position_;
  motion.end = target;
  motion.source_line = line_number;
  if (motion_mode_ == 0) {
    if (!moves) return;
  } else if (motion_mode_ == 33) {
    motion.kind = MotionKind::linear;
    motion.spindle_synchronised = true;
    motion.feed = synchronised_speed(block);  // checked even when the line goes nowhere, as LinuxCNC does
    if (!moves) return;
  } else {
    const std::string g = fmt::format("G{}", motion_mode_);
    if (inverse_time_ && !block.has('F')) throw Error(g + " in inverse time mode (G93) without an F word");
    const double feed = inverse_time_ ? block.value[GcodeBlock::index('F')] : feed_;
    if (arc_mode) {
      motion.kind = MotionKind::arc;
      motion.clockwise = motion_mode_ == 2;
      arc(block, motion);
    } else if (!moves) {
      return;
    } else {
      motion.kind = MotionKind::linear;
    }
    if (feed <= 0) throw Error(fmt::format("feed rate is zero (cannot do {} with zero feed rate)", g));
    double length = std::hypot(target.x - position_.x, target.y - position_.y, target.z - position_.z);
    if (arc_mode) {
      const auto radius = [&motion](const Vec3& point) {
        return std::hypot(point[motion.axis0] - motion.center[motion.axis0],
                          point[motion.axis1] - motion.center[motion.axis1]);
      };
      const double mean_radius = (radius(motion.start) + radius(motion.end)) / 2;
      length = std::hypot(mean_radius * arc_sweep(motion), target[motion.axis2] - position_[motion.axis2]);
    }
    if (inverse_time_) {
      motion.inverse_time = true;
      motion.duration = 60 / feed;
      motion.feed = length / motion.duration;
    } else {
      motion.feed = feed / 60;
    }
  }
  position_ = target;
  out.push_back(motion);
}

/// G33's speed along its line in mm/s. LinuxCNC keeps the tool K along the
/// line the axis words draw for each spindle revolution (its "drive line":
/// the path, not the Z axis alone), so the speed is K times the spindle's
/// rpm. F has no part in it. LinuxCNC's checks come first: K on the block
/// (it is not modal), no F, the spindle turning; then what this needs to
/// know the rpm: a positive S outside G96.
double GcodeInterpreter::synchronised_speed(GcodeBlock& block) const {
  if (!block.has('K')) throw Error("G33 without a K word (distance per spindle revolution)");
  const double per_revolution = block.take('K');
  if (!(per_revolution > 0))
    throw Error(fmt::format("G33 K{:g}: the distance per spindle revolution must be positive", per_revolution));
  if (block.has('F'))
    throw Error(fmt::format("F{:g} with G33: its speed follows the spindle (K per revolution), not a feed rate",
                            block.value[GcodeBlock::index('F')]));
  if (!spindle_turning_) throw Error("G33 with the spindle stopped (M3 or M4 starts it)");
  if (constant_surface_speed_)
    throw Error("G33 in constant surface speed mode (G96): S is no spindle speed in rpm (G97 selects rpm)");
  if (!(spindle_speed_ > 0)) throw Error("G33 without a spindle speed (S0, or no S word yet)");
  return per_revolution * unit() * spindle_speed_ / 60;
}

/// Fills in an arc's plane, centre and turns; start, end and direction are set.
void GcodeInterpreter::arc(GcodeBlock& block, Motion& motion) const {
  // The plane's axes in the order that makes G2 clockwise seen from the
  // positive normal: XY; ZX for G18 (K is the first centre word); YZ.
  static constexpr int kPlaneAxes[3][3] = {{0, 1, 2}, {2, 0, 1}, {1, 2, 0}};
  const int* axes = kPlaneAxes[plane_ - 17];
  motion.axis0 = axes[0];
  motion.axis1 = axes[1];
  motion.axis2 = axes[2];
  const std::string g = fmt::format("G{}", motion_mode_);
  const char first = "IJK"[axes[0]], second = "IJK"[axes[1]], normal = "IJK"[axes[2]];
  const std::string centre_words = fmt::format("{}/{}", std::min(first, second), std::max(first, second));
  if (block.has(normal))
    throw Error(
        fmt::format("{} word with {} in the G{} plane: its centre words are {}", normal, g, plane_, centre_words));
  const bool radius_format = block.has('R');
  if (radius_format && (block.has(first) || block.has(second)))
    throw Error(fmt::format("{} with both R and {} words", g, centre_words));
  if (!radius_format && !block.has(first) && !block.has(second))
    throw Error(fmt::format("{} without R or {} words", g, centre_words));
  if (block.has('P') && !block.m_takes_p) {
    const double p = block.take('P');
    if (p < 1 || p != std::floor(p) || p > 1e6)
      throw Error(fmt::format("{} P{:g}: the number of turns must be a positive whole number", g, p));
    motion.turns = static_cast<std::uint64_t>(p) - 1;
  }

  // LinuxCNC's tolerances, in the program's units.
  const double tolerance = inches_ ? 0.0005 * kMmPerInch : 0.005;
  const double start0 = motion.start[axes[0]], start1 = motion.start[axes[1]];
  const double end0 = motion.end[axes[0]], end1 = motion.end[axes[1]];
  double centre0 = 0, centre1 = 0;
  if (radius_format) {
    const double radius = block.take('R') * unit();
    const double half_chord = std::hypot(end0 - start0, end1 - start1) / 2;
    if (half_chord == 0)
      throw Error(fmt::format("{} with R: the end point equals the start point (a full circle needs {} words)", g,
                              centre_words));
    if (std::abs(radius) < tolerance) throw Error(fmt::format("zero-radius arc (R{:g})", radius / unit()));
    if (half_chord - std::abs(radius) > tolerance)
      throw Error(fmt::format("arc radius too small to reach the end point (radius {:g} mm, half the chord {:g} mm)",
                              std::abs(radius), half_chord));
    const double half = std::min(half_chord, std::abs(radius));  // a chord within tolerance of 2R: a half circle
    // The centre lies right of the chord (from start to end) for G2 with
    // R > 0 and G3 with R < 0, which makes the arc 180 degrees or less.
    const double side = motion.clockwise == (radius > 0) ? -std::numbers::pi / 2 : std::numbers::pi / 2;
    const double direction = std::atan2(end1 - start1, end0 - start0) + side;
    const double distance = std::sqrt(radius * radius - half * half);
    centre0 = (start0 + end0) / 2 + distance * std::cos(direction);
    centre1 = (start1 + end1) / 2 + distance * std::sin(direction);
  } else {
    const double offset0 = block.has(first) ? block.take(first) * unit() : 0;
    const double offset1 = block.has(second) ? block.take(second) * unit() : 0;
    centre0 = arc_incremental_ ? start0 + offset0 : offset0 + tool_offset_[axes[0]];
    centre1 = arc_incremental_ ? start1 + offset1 : offset1 + tool_offset_[axes[1]];
    check_arc_radii(std::hypot(start0 - centre0, start1 - centre1), std::hypot(end0 - centre0, end1 - centre1),
                    inches_);
  }
  motion.center = motion.start;
  motion.center[axes[0]] = centre0;
  motion.center[axes[1]] = centre1;
}

}  // namespace tk::motion
