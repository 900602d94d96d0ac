/// @file machine_settings.hpp
/// @brief The machine gcode-pulse drives: steps per mm, speeds and
/// accelerations (along the path and per axis), start position. Settings
/// come from a JSON machine file and from options; an option given on the
/// command line wins over the file, the file over the defaults.
///
/// A machine file is one JSON object whose keys are the option names
/// without their dashes, '-' written '_', in the options' units:
///
///     {"steps_per_mm": [200, 200, 400], "rapid": 6000, "max_feed": 4000,
///      "axis_max_feed": [6000, 6000, 1500], "accel": 800,
///      "axis_accel": [800, 800, 200], "junction_deviation": 0.02,
///      "lookahead": 256, "start": [0, 0, 5], "name": "router"}
///
/// Lists are X, Y, Z; feeds in mm/min, accelerations in mm/s^2, lengths in
/// mm. "name" and keys starting with '#' are comments. Any other key is an
/// error (a misspelt limit must not pass silently).
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>

#include "motion/pulse_run.hpp"

namespace tk::motion {

/// The range a setting takes (gcode-pulse(1), OPTIONS), the same from the
/// command line and from a machine file.
struct SettingRange {
  double low, high;
};
/// A step per mm to a step per nanometre.
inline constexpr SettingRange kStepsPerMmRange{1, 1e6};
/// Feeds and speeds, mm/min; 1e12 stands for no limit (ideal timing).
inline constexpr SettingRange kFeedRange{0.01, 1e12};
/// Accelerations, mm/s^2; 1e12 stands for instant.
inline constexpr SettingRange kAccelRange{0.01, 1e12};
/// Corner rounding, mm: up to the coordinate range (none at all).
inline constexpr SettingRange kJunctionDeviationRange{0, 1e6};
/// Blocks planned together: the planner holds that many.
inline constexpr SettingRange kLookaheadRange{1, 1e5};
/// Where the machine starts, each axis in mm: the interpreter's coordinate range.
inline SettingRange start_range() {
  return {-InterpreterOptions{}.max_coordinate_mm, InterpreterOptions{}.max_coordinate_mm};
}

struct MachineSettings {
  std::optional<std::array<double, 3>> steps_per_mm, axis_max_feed, axis_accel, start;
  std::optional<double> rapid, max_feed, accel, junction_deviation;
  std::optional<std::size_t> lookahead;

  /// Every setting `over` holds replaces this one's.
  void override_with(const MachineSettings& over);
  /// Checks every value (throws Error naming the setting, e.g. "accel must
  /// be a positive number") and fills PulseOptions, defaults for the rest.
  void apply_to(PulseOptions& options) const;
};

/// Reads a machine file; errors name the file.
MachineSettings read_machine_file(const std::string& path);

}  // namespace tk::motion
