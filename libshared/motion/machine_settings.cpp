/// @file machine_settings.cpp
#include "motion/machine_settings.hpp"

#include <cmath>
#include <fstream>
#include <iterator>

#include <fmt/format.h>

#include "cli/option_checks.hpp"
#include "io/error.hpp"
#include "io/record.hpp"

namespace tk::motion {

namespace {

template <typename T>
void take(std::optional<T>& mine, const std::optional<T>& theirs) {
  if (theirs) mine = theirs;
}

/// "NAME: must be a number from L to H, not V": gcode-pulse names the
/// option from NAME, a machine file's error names the file.
void check_range(double value, SettingRange range, const char* name) {
  const std::string problem = cli::out_of_range(value, range.low, range.high);
  if (!problem.empty()) throw Error(fmt::format("{}: {}, not {:g}", name, problem, value));
}

void check_range(const std::array<double, 3>& values, SettingRange range, const char* name) {
  for (double value : values) check_range(value, range, name);
}

std::array<double, 3> triple(const Record& value, const std::string& key) {
  if (!value.is_array() || value.size() != 3) throw Error(key + " must be a list of three numbers [X, Y, Z]");
  std::array<double, 3> out{};
  for (int axis = 0; axis < 3; ++axis) {
    if (!value[axis].is_number()) throw Error(key + " must be a list of three numbers [X, Y, Z]");
    out[axis] = value[axis].get<double>();
  }
  return out;
}

double number(const Record& value, const std::string& key) {
  if (!value.is_number()) throw Error(key + " must be a number");
  return value.get<double>();
}

}  // namespace

void MachineSettings::override_with(const MachineSettings& over) {
  take(steps_per_mm, over.steps_per_mm);
  take(axis_max_feed, over.axis_max_feed);
  take(axis_accel, over.axis_accel);
  take(start, over.start);
  take(rapid, over.rapid);
  take(max_feed, over.max_feed);
  take(accel, over.accel);
  take(junction_deviation, over.junction_deviation);
  take(lookahead, over.lookahead);
}

void MachineSettings::apply_to(PulseOptions& options) const {
  MachineLimits& limits = options.limits;
  if (steps_per_mm) {
    check_range(*steps_per_mm, kStepsPerMmRange, "steps_per_mm");
    options.steps_per_mm = *steps_per_mm;
  }
  if (accel) {
    check_range(*accel, kAccelRange, "accel");
    limits.acceleration = *accel;
  }
  if (rapid) {
    check_range(*rapid, kFeedRange, "rapid");
    limits.rapid_speed = *rapid / 60;
  }
  // The feed cap defaults to the rapid speed.
  limits.max_speed = limits.rapid_speed;
  if (max_feed) {
    check_range(*max_feed, kFeedRange, "max_feed");
    limits.max_speed = *max_feed / 60;
  }
  if (axis_max_feed) {
    check_range(*axis_max_feed, kFeedRange, "axis_max_feed");
    for (int axis = 0; axis < 3; ++axis) limits.axis_speed[axis] = (*axis_max_feed)[axis] / 60;
  }
  if (axis_accel) {
    check_range(*axis_accel, kAccelRange, "axis_accel");
    limits.axis_acceleration = *axis_accel;
  }
  if (junction_deviation) {
    check_range(*junction_deviation, kJunctionDeviationRange, "junction_deviation");
    limits.junction_deviation = *junction_deviation;
  }
  if (lookahead) {
    check_range(static_cast<double>(*lookahead), kLookaheadRange, "lookahead");
    limits.lookahead = *lookahead;
  }
  if (start) {
    for (int axis = 0; axis < 3; ++axis)
      if (!(std::fabs((*start)[axis]) <= options.interpreter.max_coordinate_mm))
        throw Error(fmt::format("start: must be three numbers from {0:g} to {1:g}, the coordinate range",
                                -options.interpreter.max_coordinate_mm, options.interpreter.max_coordinate_mm));
    options.interpreter.start = Vec3{(*start)[0], (*start)[1], (*start)[2]};
  }
}

MachineSettings read_machine_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error("cannot open the machine file", Location{path, 0});
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  Record root = Record::parse(text, nullptr, false);
  if (root.is_discarded()) throw Error("the machine file is not valid JSON", Location{path, 0});
  if (!root.is_object()) throw Error("the machine file must hold one JSON object", Location{path, 0});
  MachineSettings settings;
  try {
    for (const auto& [key, value] : root.items()) {
      if (key == "steps_per_mm") settings.steps_per_mm = triple(value, key);
      else if (key == "axis_max_feed") settings.axis_max_feed = triple(value, key);
      else if (key == "axis_accel") settings.axis_accel = triple(value, key);
      else if (key == "start") settings.start = triple(value, key);
      else if (key == "rapid") settings.rapid = number(value, key);
      else if (key == "max_feed") settings.max_feed = number(value, key);
      else if (key == "accel") settings.accel = number(value, key);
      else if (key == "junction_deviation") settings.junction_deviation = number(value, key);
      else if (key == "lookahead") {
        if (!value.is_number_unsigned()) throw Error("lookahead must be a positive whole number");
        settings.lookahead = value.get<std::size_t>();
      } else if (key != "name" && !key.starts_with('#')) {
        throw Error("unknown key '" + key + "'");
      }
    }
    // Values are checked here too, so a bad file is named as the culprit.
    PulseOptions scratch;
    settings.apply_to(scratch);
  } catch (const Error& e) {
    throw Error(e.what(), Location{path, 0});
  }
  return settings;
}

}  // namespace tk::motion
