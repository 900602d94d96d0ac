/// @file feed_drive_plot.cpp
#include "control/feed_drive_plot.hpp"

#include "io/error.hpp"

namespace tk::control {

void FeedDrivePlot::add(const FeedDriveSample& sample) {
  if (samples_.size() < kMaxSamples) samples_.push_back(sample);
}

void FeedDrivePlot::write(const std::string& path, const std::string&) const { throw Error(path + ": plotting is not written yet"); }

}  // namespace tk::control
