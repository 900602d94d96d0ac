/// @file feed_drive_report.hpp
/// @brief A feed-drive run's summary as a record: smcsim's --summary and
/// its sweep's rows.
#pragma once

#include <string>
#include <vector>

#include "control/feed_drive_sim.hpp"
#include "io/record.hpp"

namespace tk::control {

/// The summary record's fields, in order.
extern const std::vector<std::string> kSummaryFields;

/// The summary of the run of `config`: the controller and its switching
/// gains, then the figures (the tracking ones null when the run diverged).
Record summary_record(const FeedDriveConfig& config, const FeedDriveSummary& summary);

}  // namespace tk::control
