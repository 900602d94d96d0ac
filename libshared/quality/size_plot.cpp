/// @file size_plot.cpp
#include "quality/size_plot.hpp"

#include <cmath>

#include "sim/time_panels_svg.hpp"

namespace tk::quality {

void SizePlot::add(double part, double measured, double fitted, double offset, double made) {
  if (parts_.size() >= kMaxParts) {
    truncated_ = true;
    return;
  }
  if (std::isfinite(made)) has_made_ = true;
  parts_.push_back({part, measured, fitted, offset, made});
}

void SizePlot::write(const std::string& path, const SizePlotInfo& info) const {
  using sim::field_of, sim::TimePanel;
  TimePanel sizes{.y_label = "size, mm"};
  if (std::isfinite(info.lower) && std::isfinite(info.upper))
    sizes.levels.push_back({info.lower, info.upper, "#2a9d3a", "tolerance"});
  if (std::isfinite(info.nominal)) sizes.levels.push_back({info.nominal, info.nominal, "#c8281e", "nominal"});
  sizes.series.push_back({field_of(parts_, &Part::measured), "#9aa7b8", 1, "measured"});
  if (has_made_) sizes.series.push_back({field_of(parts_, &Part::made), "#1b1b1b", 1, "as made"});
  sizes.series.push_back({field_of(parts_, &Part::fitted), "#1f5fbf", 1.6, info.level_label});
  TimePanel offset{.y_label = "set-up offset, mm",
                   .series = {{field_of(parts_, &Part::offset), "#c8281e", 1.6, "sum of corrections"}},
                   .range = TimePanel::Range::symmetric};
  sim::write_time_panels_svg(path, {.title = info.title,
                                    .samples = parts_.size(),
                                    .time_s = field_of(parts_, &Part::part),
                                    .panels = {std::move(sizes), std::move(offset)},
                                    .time_label = "part number"});
}

}  // namespace tk::quality
