/// @file turning_svg.cpp
/// @brief Two panels of polylines with axes; long runs are reduced to the
/// minimum and maximum per pixel column, so the envelope of a fast
/// oscillation stays visible.
#include "machining/turning_svg.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "io/atomic_file.hpp"

namespace tk::machining {

namespace {

constexpr double kLeft = 70, kWidth = 880, kPanelHeight = 250, kTop1 = 50, kTop2 = 360;

/// A step of 1, 2 or 5 times a power of ten giving about `ticks` ticks.
double nice_step(double span, int ticks) {
  const double raw = span / ticks, power = std::pow(10, std::floor(std::log10(raw)));
  for (const double m : {1.0, 2.0, 5.0})
    if (m * power >= raw) return m * power;
  return 10 * power;
}

/// Maps data to one panel's pixels.
struct Panel {
  double top, y_max, t_max;
  double x(double t) const { return kLeft + kWidth * t / t_max; }
  double y(double v) const { return top + kPanelHeight * (1 - std::clamp(v, 0.0, y_max) / y_max); }
};

/// A polyline of `value(sample)`, at most two points per pixel column.
template <class Samples, class Value>
std::string polyline(const Samples& samples, const Panel& panel, Value value, const char* colour, double width) {
  std::string points;
  const auto point = [&](double t, double v) { points += fmt::format("{:.1f},{:.1f} ", panel.x(t), panel.y(v)); };
  if (samples.size() <= 3 * kWidth) {
    for (const auto& s : samples) point(s.t, value(s));
  } else {
    std::size_t i = 0;
    for (int column = 0; column < kWidth && i < samples.size(); ++column) {
      const double column_end = panel.t_max * (column + 1) / kWidth;
      double low = value(samples[i]), high = low, t = samples[i].t;
      for (; i < samples.size() && samples[i].t <= column_end; ++i) low = std::min(low, value(samples[i])), high = std::max(high, value(samples[i]));
      point(t, low);
      if (high != low) point(t, high);
    }
  }
  return fmt::format("<polyline fill=\"none\" stroke=\"{}\" stroke-width=\"{}\" points=\"{}\"/>\n", colour, width, points);
}

std::string axes(const Panel& panel, double y_step, const std::string& label, double t_step, bool time_labels) {
  std::string svg = fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"#444\"/>\n", kLeft,
                                panel.top, kWidth, kPanelHeight);
  for (double v = 0; v <= panel.y_max + 1e-9; v += y_step)
    svg += fmt::format("<line x1=\"{0}\" x2=\"{1}\" y1=\"{2:.1f}\" y2=\"{2:.1f}\" stroke=\"#ddd\"/>"
                       "<text x=\"{3}\" y=\"{4:.1f}\" text-anchor=\"end\">{5:g}</text>\n",
                       kLeft, kLeft + kWidth, panel.y(v), kLeft - 6, panel.y(v) + 4, v);
  for (double t = 0; t <= panel.t_max + 1e-9; t += t_step) {
    svg += fmt::format("<line x1=\"{0:.1f}\" x2=\"{0:.1f}\" y1=\"{1}\" y2=\"{2}\" stroke=\"#ddd\"/>\n", panel.x(t), panel.top,
                       panel.top + kPanelHeight);
    if (time_labels)
      svg += fmt::format("<text x=\"{:.1f}\" y=\"{}\" text-anchor=\"middle\">{:g}</text>\n", panel.x(t), panel.top + kPanelHeight + 16, t);
  }
  svg += fmt::format("<text x=\"16\" y=\"{0:.1f}\" transform=\"rotate(-90 16 {0:.1f})\" text-anchor=\"middle\">{1}</text>\n",
                     panel.top + kPanelHeight / 2, label);
  return svg;
}

std::string escape(const std::string& text) {
  std::string out;
  for (const char c : text) out += c == '<' ? "&lt;" : c == '>' ? "&gt;" : c == '&' ? "&amp;" : std::string(1, c);
  return out;
}

}  // namespace

void TurningSvg::add(double t_s, double load_pct, double load_true_pct, double override_pct, double depth_mm) {
  if (samples_.size() >= kMaxSamples) {
    truncated_ = true;
    return;
  }
  samples_.push_back({t_s, load_pct, load_true_pct, override_pct, depth_mm});
}

void TurningSvg::write(const std::string& path, const TurningPlotInfo& info) const {
  const double t_max = samples_.empty() ? 1 : std::max(samples_.back().t, 1e-3);
  double load_max = 100, depth_max = 0;
  for (const Sample& s : samples_) load_max = std::max(load_max, s.load_true), depth_max = std::max(depth_max, s.depth);
  load_max = std::ceil(load_max / 20) * 20;
  const Panel load{kTop1, load_max, t_max}, override_panel{kTop2, 200, t_max};
  const double t_step = nice_step(t_max, 10);
  std::string svg = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"1000\" height=\"680\" font-family=\"sans-serif\" font-size=\"12\">\n"
      "<title>{0}</title>\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      "<text x=\"{1}\" y=\"24\" font-size=\"12.5\">{0}</text>\n",
      escape(info.title), kLeft);
  svg += axes(load, 20, "spindle load M_a, % of rated", t_step, false);
  if (info.dead_band_pct > 0)
    svg += fmt::format("<rect x=\"{}\" y=\"{:.1f}\" width=\"{}\" height=\"{:.1f}\" fill=\"#2a9d3a\" fill-opacity=\"0.12\"/>\n", kLeft,
                       load.y(info.mz_pct + info.dead_band_pct), kWidth,
                       load.y(info.mz_pct - info.dead_band_pct) - load.y(info.mz_pct + info.dead_band_pct));
  svg += polyline(samples_, load, [](const Sample& s) { return s.load; }, "#9aa7b8", 1);
  svg += polyline(samples_, load, [](const Sample& s) { return s.load_true; }, "#1b1b1b", 1.5);
  svg += fmt::format("<line x1=\"{0}\" x2=\"{1}\" y1=\"{2:.1f}\" y2=\"{2:.1f}\" stroke=\"#c8281e\" stroke-dasharray=\"6 4\"/>"
                     "<text x=\"{3}\" y=\"{4:.1f}\" fill=\"#c8281e\">M_z = {5:g} %</text>\n",
                     kLeft, kLeft + kWidth, load.y(info.mz_pct), kLeft + kWidth - 90, load.y(info.mz_pct) - 5, info.mz_pct);
  svg += fmt::format("<text x=\"{}\" y=\"{}\"><tspan fill=\"#1b1b1b\">true load</tspan>  <tspan fill=\"#9aa7b8\">measured (lag, noise)</tspan></text>\n",
                     kLeft + 8, kTop1 + 16);

  svg += axes(override_panel, 50, "feed override O, %", t_step, true);
  if (depth_max > 0) {  // the allowance as a shaded step under the override, on its own scale
    const Panel depth{kTop2, depth_max * 4, t_max};
    svg += polyline(samples_, depth, [](const Sample& s) { return s.depth; }, "#e0a030", 2);
    svg += fmt::format("<text x=\"{}\" y=\"{:.1f}\" fill=\"#b07010\">allowance a_p (top of the orange step = {:g} mm)</text>\n",
                       kLeft + 8, kTop2 + kPanelHeight - 8, depth_max);
  }
  svg += polyline(samples_, override_panel, [](const Sample& s) { return s.override_pct; }, "#1f5fbf", 1.2);
  svg += fmt::format("<text x=\"{}\" y=\"{}\" fill=\"#1f5fbf\">override O_n</text>\n", kLeft + 8, kTop2 + 16);
  svg += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">time t, s</text>\n", kLeft + kWidth / 2, kTop2 + kPanelHeight + 36);
  svg += "</svg>\n";
  io::write_file_atomically(path, svg, path + ".tmp");
}

}  // namespace tk::machining
