/// @file pulse_report.cpp
#include "motion/pulse_report.hpp"

#include <string>

namespace tk::motion {

Record pulse_summary_record(const PulseSummary& s, std::string_view method) {
  Record record;
  record["method"] = std::string(method);
  static const char* const kAxes[3] = {"x", "y", "z"};
  for (int axis = 0; axis < 3; ++axis) record[std::string("pulses_") + kAxes[axis]] = s.pulses[axis];
  for (int axis = 0; axis < 3; ++axis) record[std::string("final_") + kAxes[axis]] = s.final_mm[axis];
  record["duration_s"] = s.duration_s;
  record["dwell_s"] = s.dwell_s;
  record["path_mm"] = s.path_mm;
  record["max_deviation_mm"] = s.max_deviation_mm;
  record["rms_deviation_mm"] = s.rms_deviation_mm();
  for (int axis = 0; axis < 3; ++axis) record[std::string("peak_rate_") + kAxes[axis]] = s.peak_rate[axis];
  record["coincident_steps"] = s.coincident_steps;
  record["events"] = s.events;
  record["blocks"] = s.blocks;
  record["motions"] = s.motions;
  record["feed_capped_blocks"] = s.feed_capped;
  Record unused = Record::object();
  for (const auto& [word, count] : s.unused_words) unused[word] = count;
  record["unused_words"] = unused;
  return record;
}

}  // namespace tk::motion
