/// @file pulse_report.hpp
/// @brief A run's summary (PulseSummary) as gcode-pulse's --summary record.
#pragma once

#include <string_view>

#include "io/record.hpp"
#include "motion/pulse_run.hpp"

namespace tk::motion {

/// The summary's fields after `method` (the stepping method's name), in
/// output order; unused_words is an object of word -> count.
Record pulse_summary_record(const PulseSummary& summary, std::string_view method);

}  // namespace tk::motion
