/// @file turning_svg.cpp
/// @brief The two panels drawn by sim::write_time_panels_svg.
#include "machining/turning_svg.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "sim/time_panels_svg.hpp"

namespace tk::machining {

void TurningSvg::add(double t_s, double load_pct, double load_true_pct, double override_pct, double depth_mm) {
  if (samples_.size() >= kMaxSamples) {
    truncated_ = true;
    return;
  }
  samples_.push_back({t_s, load_pct, load_true_pct, override_pct, depth_mm});
}

void TurningSvg::write(const std::string& path, const TurningPlotInfo& info) const {
  using sim::TimePanel, sim::field_of;
  double load_max = 100, depth_max = 0;
  for (const Sample& s : samples_) load_max = std::max(load_max, s.load_true), depth_max = std::max(depth_max, s.depth);

  TimePanel load{.y_label = "spindle load M_a, % of rated",
                 .range = TimePanel::Range::fixed,
                 .y_min = 0,
                 .y_max = std::ceil(load_max / 20) * 20,
                 .y_step = 20};
  load.levels.push_back({info.mz_pct, info.mz_pct, "#c8281e", fmt::format("M_z = {:g} %", info.mz_pct)});
  load.series = {{field_of(samples_, &Sample::load), "#9aa7b8", 1, "measured M_a (smoothed, noise)"},
                 {field_of(samples_, &Sample::load_true), "#1b1b1b", 1.5, "true load"}};

  TimePanel feed{.y_label = "feed override O, %", .range = TimePanel::Range::fixed, .y_min = 0, .y_max = 200};
  if (depth_max > 0)  // the allowance as a step under the override, its top at a quarter of the axis
    feed.series.push_back({[this, depth_max](std::size_t i) { return samples_[i].depth / depth_max * 50; }, "#e0a030",
                           2, fmt::format("allowance a_p (top of the orange step = {:g} mm)", depth_max)});
  feed.series.push_back({field_of(samples_, &Sample::override_pct), "#1f5fbf", 1.2, "override O_n"});

  sim::write_time_panels_svg(path, {.title = info.title,
                                    .samples = samples_.size(),
                                    .time_s = field_of(samples_, &Sample::t),
                                    .panels = {std::move(load), std::move(feed)}});
}

}  // namespace tk::machining
