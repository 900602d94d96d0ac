/// @file feed_drive_run.hpp
/// @brief Every sample of one feed-drive simulation, for the controller tests.
#pragma once

#include <vector>

#include "control/feed_drive_sim.hpp"

namespace tk::test {

inline std::vector<tk::control::FeedDriveSample> run_feed_drive(const tk::control::FeedDriveConfig& config) {
  std::vector<tk::control::FeedDriveSample> out;
  tk::control::simulate_feed_drive(config, [&](const tk::control::FeedDriveSample& s) { out.push_back(s); });
  return out;
}

}  // namespace tk::test
