/// @file feed_drive_plot.hpp
/// @brief The seed's four panels for one run as SVG: position and
/// reference, position error, velocity error, control signal (and the
/// cutting force) against time.
#pragma once

#include <string>
#include <vector>

#include "control/feed_drive_sim.hpp"

namespace tk::control {

class FeedDrivePlot {
 public:
  /// Samples kept; a longer run is drawn up to here.
  static constexpr std::size_t kMaxSamples = 2000000;
  void add(const FeedDriveSample& sample);
  /// Writes the drawing atomically; throws tk::Error naming the file when it cannot.
  void write(const std::string& path, const std::string& title) const;

 private:
  std::vector<FeedDriveSample> samples_;
};

}  // namespace tk::control
