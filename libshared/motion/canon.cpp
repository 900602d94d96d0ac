/// @file canon.cpp
/// @brief The canonical command stream of `rs274 -g` to Motions.
#include "motion/canon.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <numbers>
#include <set>

#include <fmt/format.h>

#include "io/error.hpp"
#include "motion/arc_geometry.hpp"

namespace tk::motion {

namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r'; }

/// Commands that neither move nor time anything here: counted, not run.
const std::set<std::string, std::less<>>& passive_commands() {
  static const std::set<std::string, std::less<>> names = {"CHANGE_TOOL",
                                                           "CHANGE_TOOL_NUMBER",
                                                           "CLAMP_AXIS",
                                                           "CLEAR_AUX_OUTPUT_BIT",
                                                           "CLEAR_MOTION_OUTPUT_BIT",
                                                           "COMMENT",
                                                           "DISABLE_ADAPTIVE_FEED",
                                                           "DISABLE_FEED_HOLD",
                                                           "DISABLE_FEED_OVERRIDE",
                                                           "DISABLE_SPEED_OVERRIDE",
                                                           "ENABLE_ADAPTIVE_FEED",
                                                           "ENABLE_FEED_HOLD",
                                                           "ENABLE_FEED_OVERRIDE",
                                                           "ENABLE_SPEED_OVERRIDE",
                                                           "FINISH",
                                                           "FLOOD_OFF",
                                                           "FLOOD_ON",
                                                           "LOG",
                                                           "LOGAPPEND",
                                                           "LOGCLOSE",
                                                           "LOGOPEN",
                                                           "MESSAGE",
                                                           "MIST_OFF",
                                                           "MIST_ON",
                                                           "ON_RESET",
                                                           "OPTIONAL_PROGRAM_STOP",
                                                           "ORIENT_SPINDLE",
                                                           "PALLET_SHUTTLE",
                                                           "PROGRAM_STOP",
                                                           "SELECT_TOOL",
                                                           "SET_AUX_OUTPUT_BIT",
                                                           "SET_AUX_OUTPUT_VALUE",
                                                           "SET_CUTTER_RADIUS_COMPENSATION",
                                                           "SET_FEED_REFERENCE",
                                                           "SET_MOTION_CONTROL_MODE",
                                                           "SET_MOTION_OUTPUT_BIT",
                                                           "SET_MOTION_OUTPUT_VALUE",
                                                           "SET_NAIVECAM_TOLERANCE",
                                                           "SET_TOOL_TABLE_ENTRY",
                                                           "START_CHANGE",
                                                           "START_CUTTER_RADIUS_COMPENSATION",
                                                           "STOP_CUTTER_RADIUS_COMPENSATION",
                                                           "TURN_PROBE_OFF",
                                                           "TURN_PROBE_ON",
                                                           "UNCLAMP_AXIS",
                                                           "USE_NO_SPINDLE_FORCE",
                                                           "USE_SPINDLE_FORCE",
                                                           "WAIT_SPINDLE_ORIENT_COMPLETE"};
  return names;
}

/// The text for a message, bytes that are no printable ASCII as '?'.
std::string printable(std::string_view text) {
  std::string out(text);
  for (char& c : out)
    if (c < 0x20 || c > 0x7e) c = '?';
  return out;
}

double parse_number(std::string_view token) {
  double value = 0;
  const char* first = token.data();
  if (!token.empty() && token.front() == '+') ++first;
  const auto [end, error] = std::from_chars(first, token.data() + token.size(), value);
  if (error != std::errc() || end != token.data() + token.size() || !std::isfinite(value))
    throw Error(fmt::format("bad number '{}'", printable(token.substr(0, 32))));
  return value;
}

}  // namespace

/// One command: its name, its arguments as written, and those split at
/// commas and blanks (rs274 separates USE_TOOL_LENGTH_OFFSET's by both).
struct CanonInterpreter::Command {
  std::string_view name, arguments;
  std::vector<std::string_view> tokens;

  double number(std::size_t i) const { return parse_number(tokens[i]); }
  void expect(std::initializer_list<std::size_t> counts) const {
    if (std::find(counts.begin(), counts.end(), tokens.size()) != counts.end()) return;
    std::string allowed;
    for (const std::size_t n : counts) allowed += (allowed.empty() ? "" : " or ") + std::to_string(n);
    throw Error(fmt::format("{} takes {} arguments, not {}", name, allowed, tokens.size()));
  }
};

CanonInterpreter::CanonInterpreter(InterpreterOptions options) : options_(options), position_(options.start) {}

void CanonInterpreter::execute(std::string_view text, std::size_t line_number, std::vector<Motion>& out) {
  if (ended_) return;
  std::size_t i = 0;
  while (i < text.size() && is_space(text[i])) ++i;
  if (i == text.size()) return;
  // rs274's counter and N field ("   43 N0090  "), when present.
  if (std::isdigit(static_cast<unsigned char>(text[i]))) {
    while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i]))) ++i;
    const std::size_t field = i;
    while (i < text.size() && is_space(text[i])) ++i;
    if (i == field || i == text.size() || text[i] != 'N')
      throw Error("not a canonical command: a counter without an N field (rs274 -g prints 'COUNT N.....  NAME(...)')");
    while (i < text.size() && !is_space(text[i])) ++i;
    while (i < text.size() && is_space(text[i])) ++i;
  }
  const std::size_t name_start = i;
  while (i < text.size() && (std::isupper(static_cast<unsigned char>(text[i])) ||
                             std::isdigit(static_cast<unsigned char>(text[i])) || text[i] == '_'))
    ++i;
  std::size_t close = text.size();
  while (close > i && is_space(text[close - 1])) --close;
  if (i == name_start || i >= close || text[i] != '(' || text[close - 1] != ')')
    throw Error(fmt::format("not a canonical command (rs274 -g prints one per line, as NAME(ARGUMENTS)): '{}'",
                            printable(text.substr(name_start, 40))));
  Command command;
  command.name = text.substr(name_start, i - name_start);
  command.arguments = text.substr(i + 1, close - i - 2);
  ++commands_;

  const std::string_view name = command.name;
  if (passive_commands().contains(name)) {
    ++unused_[std::string(name)];
    return;
  }
  for (std::size_t j = 0; j < command.arguments.size();) {
    const char c = command.arguments[j];
    if (c == ',' || is_space(c)) {
      ++j;
      continue;
    }
    const std::size_t start = j;
    while (j < command.arguments.size() && command.arguments[j] != ',' && !is_space(command.arguments[j])) ++j;
    command.tokens.push_back(command.arguments.substr(start, j - start));
  }
  const std::size_t first_new = out.size();
  if (name == "STRAIGHT_TRAVERSE") {
    straight(command, MotionKind::rapid, out);
  } else if (name == "STRAIGHT_FEED" || name == "STRAIGHT_PROBE") {
    straight(command, MotionKind::linear, out);
  } else if (name == "ARC_FEED") {
    arc_feed(command, out);
  } else if (name == "RIGID_TAP") {
    rigid_tap(command, out);
  } else if (name == "DWELL") {
    command.expect({1});
    const double seconds = command.number(0);
    if (seconds < 0) throw Error(fmt::format("negative dwell time {:g}", seconds));
    if (seconds > 0) out.push_back(dwell_at(position_, seconds, line_number));
  } else if (name == "SET_FEED_RATE") {
    command.expect({1});
    feed_ = command.number(0) * unit_;
    if (feed_ < 0) throw Error(fmt::format("negative feed rate {:g}", command.number(0)));
  } else if (name == "SET_FEED_MODE") {
    command.expect({1, 2});
    const double mode = command.number(command.tokens.size() - 1);
    if (mode != 0 && mode != 1) throw Error(fmt::format("SET_FEED_MODE: unknown mode {:g}", mode));
    feed_per_revolution_ = mode == 1;
  } else if (name == "START_SPEED_FEED_SYNC" || name == "START_SPEED_FEED_SYNCH") {
    command.expect({2, 3});
    const std::size_t n = command.tokens.size();
    sync_per_revolution_ = command.number(n - 2) * unit_;
    const std::string_view mode = command.tokens[n - 1];
    sync_velocity_only_ = !(mode == "0" || mode == "false");
    synchronised_ = true;
  } else if (name == "STOP_SPEED_FEED_SYNCH" || name == "STOP_SPEED_FEED_SYNC") {
    synchronised_ = false;
  } else if (name == "SET_SPINDLE_SPEED") {
    command.expect({1, 2});
    spindle_rpm_ = command.number(command.tokens.size() - 1);
    if (spindle_rpm_ < 0) throw Error(fmt::format("negative spindle speed {:g}", spindle_rpm_));
  } else if (name == "SET_SPINDLE_MODE") {
    command.expect({1, 2});
    constant_surface_speed_ = command.number(command.tokens.size() - 1) != 0;
  } else if (name == "START_SPINDLE_CLOCKWISE" || name == "START_SPINDLE_COUNTERCLOCKWISE") {
    spindle_turning_ = true;
  } else if (name == "STOP_SPINDLE_TURNING") {
    spindle_turning_ = false;
  } else if (name == "SELECT_PLANE") {
    const std::string_view plane = command.arguments;
    if (plane == "CANON_PLANE_XY") plane_ = 17;
    else if (plane == "CANON_PLANE_XZ") plane_ = 18;
    else if (plane == "CANON_PLANE_YZ") plane_ = 19;
    else
      throw Error(
          fmt::format("SELECT_PLANE({}): only the XY, XZ and YZ planes are supported", printable(plane.substr(0, 40))));
  } else if (name == "USE_LENGTH_UNITS") {
    const std::string_view units = command.arguments;
    if (units == "CANON_UNITS_MM") unit_ = 1;
    else if (units == "CANON_UNITS_INCHES") unit_ = kMmPerInch;
    else if (units == "CANON_UNITS_CM") unit_ = 10;
    else throw Error(fmt::format("USE_LENGTH_UNITS({}): unknown units", printable(units.substr(0, 40))));
  } else if (name == "SET_G5X_OFFSET") {
    command.expect({7, 10});
    g5x_ = {command.number(1) * unit_, command.number(2) * unit_, command.number(3) * unit_};
  } else if (name == "SET_G92_OFFSET") {
    command.expect({6, 9});
    g92_ = {command.number(0) * unit_, command.number(1) * unit_, command.number(2) * unit_};
  } else if (name == "SET_XY_ROTATION") {
    command.expect({1});
    rotation_deg_ = command.number(0);
  } else if (name == "USE_TOOL_LENGTH_OFFSET") {
    command.expect({3, 6, 9});
    tool_ = {command.number(0) * unit_, command.number(1) * unit_, command.number(2) * unit_};
  } else if (name == "PROGRAM_END") {
    ended_ = true;
  } else if (name == "NURBS_FEED") {
    throw Error(
        "NURBS_FEED (G5.1, G5.2 splines): rs274 -g does not print the spline's points, so it cannot be stepped");
  } else {
    const std::string message = fmt::format("canonical command {} is not supported", name);
    if (!options_.lenient) throw Error(message);
    if (warn_) warn_("skipped " + message);
  }
  for (std::size_t m = first_new; m < out.size(); ++m) out[m].source_line = line_number;
}

/// Program coordinates (mm) to the machine's, as LinuxCNC's motion layer
/// maps them: G92 offset, then the XY rotation, then the G5x and tool offsets.
Vec3 CanonInterpreter::to_machine(double x, double y, double z) const {
  x += g92_.x;
  y += g92_.y;
  z += g92_.z;
  if (rotation_deg_ != 0) {
    const double theta = rotation_deg_ * std::numbers::pi / 180;
    const double c = std::cos(theta), s = std::sin(theta);
    const double rx = x * c - y * s;
    y = x * s + y * c;
    x = rx;
  }
  return checked({x + g5x_.x + tool_.x, y + g5x_.y + tool_.y, z + g5x_.z + tool_.z});
}

Vec3 CanonInterpreter::checked(Vec3 point) const {
  for (int axis = 0; axis < 3; ++axis)
    if (!(std::abs(point[axis]) <= options_.max_coordinate_mm))
      throw Error(fmt::format("machine coordinate {}{:.10g} beyond ±{:.10g} mm", "XYZ"[axis], point[axis],
                              options_.max_coordinate_mm));
  return point;
}

/// The A B C (U V W) after X Y Z: this machine has none, so they must stay put.
void CanonInterpreter::check_extra_axes(const Command& command, std::size_t first) {
  extra_axes_.resize(command.tokens.size() - first, 0.0);
  for (std::size_t i = first; i < command.tokens.size(); ++i) {
    const double value = command.number(i);
    if (value == extra_axes_[i - first]) continue;
    const char axis = "ABCUVW"[i - first];
    const std::string message =
        fmt::format("{} moves the {} axis to {:g}: gcode-pulse steps X, Y and Z only", command.name, axis, value);
    if (!options_.lenient) throw Error(message);
    if (warn_) warn_("ignored: " + message);
    extra_axes_[i - first] = value;
  }
}

/// The speed of a feed move in mm/s; `synchronised` tells whether the tool
/// must follow the spindle (G33, G76), when the move cannot be slowed.
double CanonInterpreter::feed_speed(bool arc, bool& synchronised) const {
  synchronised = false;
  double per_revolution = 0;
  if (synchronised_) {
    per_revolution = sync_per_revolution_;
    synchronised = !sync_velocity_only_;
    if (synchronised && arc) throw Error("ARC_FEED while the motion follows the spindle: not supported");
  } else if (feed_per_revolution_) {
    per_revolution = feed_;
  } else {
    if (!(feed_ > 0)) throw Error("a feed move at feed rate 0");
    return feed_ / 60;
  }
  if (!spindle_turning_) throw Error("a move that follows the spindle, with the spindle stopped");
  if (constant_surface_speed_)
    throw Error("a move that follows the spindle in constant surface speed mode: the spindle's rpm is unknown");
  if (!(spindle_rpm_ > 0) || !(per_revolution > 0))
    throw Error(fmt::format("a move that follows the spindle at {:g} mm per revolution and {:g} rpm", per_revolution,
                            spindle_rpm_));
  return per_revolution * spindle_rpm_ / 60;
}

void CanonInterpreter::straight(const Command& command, MotionKind kind, std::vector<Motion>& out) {
  command.expect({6, 9});
  check_extra_axes(command, 3);
  Motion motion;
  motion.kind = kind;
  motion.start = position_;
  motion.end = to_machine(command.number(0) * unit_, command.number(1) * unit_, command.number(2) * unit_);
  if (kind == MotionKind::linear) motion.feed = feed_speed(false, motion.spindle_synchronised);
  if (motion.end.x == position_.x && motion.end.y == position_.y && motion.end.z == position_.z) return;
  position_ = motion.end;
  out.push_back(motion);
}

/// RIGID_TAP(x, y, z[, retract scale]), G33.1: into the hole following the
/// spindle, and back out to where it started once the spindle reverses
/// (the scale times as fast). The overrun while the spindle reverses is
/// the machine's and is not modelled.
void CanonInterpreter::rigid_tap(const Command& command, std::vector<Motion>& out) {
  command.expect({3, 4});
  const double scale = command.tokens.size() == 4 ? command.number(3) : 1.0;
  if (!(scale > 0)) throw Error(fmt::format("RIGID_TAP retract scale {:g}: must be positive", scale));
  Motion in;
  in.kind = MotionKind::linear;
  in.start = position_;
  in.end = to_machine(command.number(0) * unit_, command.number(1) * unit_, command.number(2) * unit_);
  in.feed = feed_speed(false, in.spindle_synchronised);
  if (in.end.x == position_.x && in.end.y == position_.y && in.end.z == position_.z) return;
  Motion out_again = in;
  std::swap(out_again.start, out_again.end);
  out_again.feed *= scale;
  out.push_back(in);
  out.push_back(out_again);
}

/// ARC_FEED(first_end, second_end, first_axis, second_axis, rotation,
/// axis_end_point, A, B, C[, U, V, W]): "first" and "second" are the
/// plane's axes in the order X Y, Z X, Y Z (G17, G18, G19), the centre is
/// (first_axis, second_axis), the sign of rotation its direction
/// (negative: clockwise) and |rotation| - 1 the extra full turns.
void CanonInterpreter::arc_feed(const Command& command, std::vector<Motion>& out) {
  command.expect({9, 12});
  check_extra_axes(command, 6);
  static constexpr int kPlaneAxes[3][3] = {{0, 1, 2}, {2, 0, 1}, {1, 2, 0}};
  const int* axes = kPlaneAxes[plane_ - 17];
  if (plane_ != 17 && rotation_deg_ != 0)
    throw Error("ARC_FEED out of the XY plane under an XY rotation (G10 L2 R): not supported");
  const double rotation = command.number(4);
  if (rotation == 0 || rotation != std::floor(rotation) || std::abs(rotation) > 1e6)
    throw Error(fmt::format("ARC_FEED rotation {:g}: a non-zero whole number of turns", rotation));
  Vec3 end, centre;
  end[axes[0]] = command.number(0) * unit_;
  end[axes[1]] = command.number(1) * unit_;
  end[axes[2]] = command.number(5) * unit_;
  centre[axes[0]] = command.number(2) * unit_;
  centre[axes[1]] = command.number(3) * unit_;
  Motion motion;
  motion.kind = MotionKind::arc;
  motion.start = position_;
  motion.end = to_machine(end.x, end.y, end.z);
  motion.center = to_machine(centre.x, centre.y, centre.z);
  motion.center[axes[2]] = position_[axes[2]];
  motion.axis0 = axes[0];
  motion.axis1 = axes[1];
  motion.axis2 = axes[2];
  motion.clockwise = rotation < 0;
  motion.turns = static_cast<std::uint64_t>(std::abs(rotation)) - 1;
  const auto radius = [&](const Vec3& p) {
    return std::hypot(p[axes[0]] - motion.center[axes[0]], p[axes[1]] - motion.center[axes[1]]);
  };
  motion.feed = feed_speed(true, motion.spindle_synchronised);
  // Cutter compensation can shrink a helix to its axis (a tool as wide as
  // the hole): a circle smaller than LinuxCNC's tolerance is the line along
  // the normal axis, within less than a step.
  const bool inches = unit_ == kMmPerInch;
  if (std::max(radius(motion.start), radius(motion.end)) < (inches ? 0.0005 * kMmPerInch : 0.005)) {
    motion.kind = MotionKind::linear;
    if (motion.end.x == position_.x && motion.end.y == position_.y && motion.end.z == position_.z) return;
  } else {
    check_arc_radii(radius(motion.start), radius(motion.end), inches);
  }
  position_ = motion.end;
  out.push_back(motion);
}

}  // namespace tk::motion
