/// @file feed_drive_plot.cpp
/// @brief The four panels drawn by sim::write_time_panels_svg.
#include "control/feed_drive_plot.hpp"

#include "sim/time_panels_svg.hpp"

namespace tk::control {

void FeedDrivePlot::add(const FeedDriveSample& sample) {
  if (samples_.size() < kMaxSamples) samples_.push_back(sample);
}

void FeedDrivePlot::write(const std::string& path, const std::string& title) const {
  using sim::TimePanel;
  const auto value = [this](double FeedDriveSample::*field) { return sim::field_of(samples_, field); };
  // x over a wider, lighter x_ref: both stay visible where they coincide.
  TimePanel position{.y_label = "position x, mm",
                     .series = {{value(&FeedDriveSample::x_ref_mm), "#f08070", 3, "reference x_ref"},
                                {value(&FeedDriveSample::x_mm), "#1f5fbf", 1.2, "position x"}}};
  TimePanel error{.y_label = "position error e, mm",
                  .series = {{value(&FeedDriveSample::error_mm), "#1b1b1b", 1.2, ""}},
                  .range = TimePanel::Range::symmetric};
  TimePanel error_rate{.y_label = "velocity error e_dot, mm/s",
                       .series = {{value(&FeedDriveSample::error_rate_mm_s), "#1b1b1b", 1.2, ""}},
                       .range = TimePanel::Range::symmetric};
  // The cutting force drawn after F, thin and light, so a chattering F does not hide it.
  TimePanel force{.y_label = "force, N",
                  .series = {{value(&FeedDriveSample::force_n), "#1f5fbf", 1.2, "control force F"},
                             {value(&FeedDriveSample::disturbance_n), "#e0a030", 1, "cutting force F_d"}},
                  .range = TimePanel::Range::symmetric};
  sim::write_time_panels_svg(
      path, {.title = title,
             .samples = samples_.size(),
             .time_s = value(&FeedDriveSample::t_s),
             .panels = {std::move(position), std::move(error), std::move(error_rate), std::move(force)},
             .panel_height = 180});
}

}  // namespace tk::control
