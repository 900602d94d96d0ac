/// @file time_panels_svg.cpp
#include "sim/time_panels_svg.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "io/atomic_file.hpp"
#include "io/error.hpp"

namespace tk::sim {

namespace {

constexpr double kLeft = 90, kWidth = 880, kCanvasWidth = 1000, kTop = 50, kGap = 30, kBottom = 50;
constexpr int kColumns = static_cast<int>(kWidth);  // one per pixel
constexpr int kYTicks = 6, kTimeTicks = 10;
/// A white outline under the letters keeps labels readable over the data.
constexpr const char* kHalo = " stroke=\"white\" stroke-width=\"3\" paint-order=\"stroke\"";

/// Where one panel stands and the values it spans: maps data to pixels.
struct Frame {
  double top, height, t_min, t_max, y_min, y_max, y_step;
  double x(double t) const { return kLeft + kWidth * (t - t_min) / (t_max - t_min); }
  double y(double v) const { return top + height * (y_max - std::clamp(v, y_min, y_max)) / (y_max - y_min); }
};

/// The panel's y extent and tick step, per its Range.
void fit_y(const TimePanelsPlot& plot, const TimePanel& panel, Frame& frame) {
  if (panel.range == TimePanel::Range::fixed) {
    frame.y_min = panel.y_min, frame.y_max = panel.y_max;
    frame.y_step = panel.y_step > 0 ? panel.y_step : nice_step(panel.y_max - panel.y_min, kYTicks);
    return;
  }
  double low = std::numeric_limits<double>::infinity(), high = -low;
  for (const PlotSeries& series : panel.series)
    for (std::size_t i = 0; i < plot.samples; ++i)
      if (const double v = series.value(i); std::isfinite(v)) low = std::min(low, v), high = std::max(high, v);
  for (const PlotLevel& level : panel.levels) low = std::min(low, level.low), high = std::max(high, level.high);
  if (low > high) low = -1, high = 1;  // nothing to show
  if (panel.range == TimePanel::Range::symmetric) high = std::max(-low, high), low = -high;
  if (high - low <= std::abs(high) * 1e-12) {  // a constant: give it room
    const double room = high != 0 ? std::abs(high) * 0.1 : 1;
    low -= room, high += room;
  }
  // Widened to whole ticks; the slack keeps rounding noise from adding a tick.
  frame.y_step = panel.y_step > 0 ? panel.y_step : nice_step(high - low, kYTicks);
  frame.y_min = std::floor(low / frame.y_step + 1e-9) * frame.y_step;
  frame.y_max = std::ceil(high / frame.y_step - 1e-9) * frame.y_step;
}

/// A polyline of one series. Beyond three samples per pixel column it keeps
/// each column's minimum and maximum, in the order they came.
std::string polyline(const TimePanelsPlot& plot, const Frame& frame, const PlotSeries& series) {
  std::string points;
  const auto point = [&](std::size_t i) {
    points += fmt::format("{:.1f},{:.1f} ", frame.x(plot.time_s(i)), frame.y(series.value(i)));
  };
  if (plot.samples <= 3 * static_cast<std::size_t>(kColumns)) {
    for (std::size_t i = 0; i < plot.samples; ++i)
      if (std::isfinite(series.value(i))) point(i);
  } else {
    int column = -1;
    std::size_t low_i = 0, high_i = 0;
    double low = 0, high = 0;
    const auto flush = [&] {
      if (column < 0) return;
      point(std::min(low_i, high_i));
      if (low_i != high_i) point(std::max(low_i, high_i));
    };
    for (std::size_t i = 0; i < plot.samples; ++i) {
      const double v = series.value(i);
      if (!std::isfinite(v)) continue;
      const double share = (plot.time_s(i) - frame.t_min) / (frame.t_max - frame.t_min);
      const int c = std::clamp(static_cast<int>(share * kColumns), 0, kColumns - 1);
      if (c != column) {
        flush();
        column = c, low_i = high_i = i, low = high = v;
      } else if (v < low) {
        low = v, low_i = i;
      } else if (v > high) {
        high = v, high_i = i;
      }
    }
    flush();
  }
  if (!points.empty()) points.pop_back();
  return fmt::format(
      "<polyline fill=\"none\" stroke=\"{}\" stroke-width=\"{:g}\" stroke-linejoin=\"round\" points=\"{}\"/>\n",
      xml_escape(series.colour), series.width, points);
}

/// Frame, grid, tick labels, y-label, and the time labels under the last panel.
std::string axes(const Frame& frame, const std::string& y_label, double t_step, bool time_labels) {
  const double bottom = frame.top + frame.height;
  std::string svg;
  for (int k = 0;; ++k) {
    double v = frame.y_min + k * frame.y_step;
    if (v > frame.y_max + frame.y_step * 1e-9) break;
    if (std::abs(v) < frame.y_step * 1e-9) v = 0;  // not 5.55e-17
    svg += fmt::format(
        "<line x1=\"{0}\" x2=\"{1}\" y1=\"{2:.1f}\" y2=\"{2:.1f}\" stroke=\"{3}\"/>"
        "<text class=\"tick\" x=\"{4}\" y=\"{5:.1f}\" text-anchor=\"end\">{6}</text>\n",
        kLeft, kLeft + kWidth, frame.y(v), v == 0 ? "#999" : "#ddd", kLeft - 6, frame.y(v) + 4,
        plain_number(v, frame.y_step));
  }
  for (int k = 0;; ++k) {
    const double t = frame.t_min + k * t_step;
    if (t > frame.t_max + t_step * 1e-9) break;
    svg += fmt::format("<line x1=\"{0:.1f}\" x2=\"{0:.1f}\" y1=\"{1}\" y2=\"{2}\" stroke=\"#ddd\"/>\n", frame.x(t),
                       frame.top, bottom);
    if (time_labels)
      svg += fmt::format("<text class=\"tick\" x=\"{:.1f}\" y=\"{}\" text-anchor=\"middle\">{}</text>\n", frame.x(t),
                         bottom + 16, plain_number(t, t_step));
  }
  svg += fmt::format(
      "<rect class=\"panel\" x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"#444\"/>\n", kLeft,
      frame.top, kWidth, frame.height);
  svg += fmt::format(
      "<text x=\"16\" y=\"{0:.1f}\" transform=\"rotate(-90 16 {0:.1f})\" text-anchor=\"middle\">{1}</text>\n",
      frame.top + frame.height / 2, xml_escape(y_label));
  return svg;
}

std::string level_mark(const Frame& frame, const PlotLevel& level) {
  const std::string colour = xml_escape(level.colour);
  std::string svg =
      level.high == level.low
          ? fmt::format(
                "<line x1=\"{0}\" x2=\"{1}\" y1=\"{2:.1f}\" y2=\"{2:.1f}\" stroke=\"{3}\" stroke-dasharray=\"6 4\"/>\n",
                kLeft, kLeft + kWidth, frame.y(level.low), colour)
          : fmt::format(
                "<rect x=\"{}\" y=\"{:.1f}\" width=\"{}\" height=\"{:.1f}\" fill=\"{}\" fill-opacity=\"0.12\"/>\n",
                kLeft, frame.y(level.high), kWidth, frame.y(level.low) - frame.y(level.high), colour);
  if (!level.label.empty())
    svg += fmt::format("<text x=\"{}\" y=\"{:.1f}\" text-anchor=\"end\" fill=\"{}\"{}>{}</text>\n", kLeft + kWidth - 6,
                       frame.y(level.high) - 5, colour, kHalo, xml_escape(level.label));
  return svg;
}

std::string legend(const Frame& frame, const TimePanel& panel) {
  std::string entries;
  for (const PlotSeries& series : panel.series)
    if (!series.label.empty())
      entries += fmt::format("<tspan dx=\"{}\" fill=\"{}\">{}</tspan>", entries.empty() ? 0 : 14,
                             xml_escape(series.colour), xml_escape(series.label));
  return entries.empty()
             ? ""
             : fmt::format("<text x=\"{}\" y=\"{}\"{}>{}</text>\n", kLeft + 8, frame.top + 16, kHalo, entries);
}

}  // namespace

std::string time_panels_svg(const TimePanelsPlot& plot) {
  const double t_first = plot.samples ? plot.time_s(0) : 0, t_last = plot.samples ? plot.time_s(plot.samples - 1) : 1;
  const double t_min = std::min(0.0, t_first);
  double t_max = std::max(t_last, t_min + 1e-3);
  const double t_step = nice_step(t_max - t_min, kTimeTicks);
  // A run whose last sample falls one period short of a tick (3 s sampled at 1e-4 ends at 2.9999) ends on that tick.
  const double next_tick = t_min + std::ceil((t_max - t_min) / t_step - 1e-9) * t_step;
  if (next_tick - t_max < 0.01 * (t_max - t_min)) t_max = next_tick;
  const std::size_t count = plot.panels.size();
  const double height = kTop + count * plot.panel_height + (count ? count - 1 : 0) * kGap + kBottom;
  std::string svg = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1:g}\" font-family=\"sans-serif\" "
      "font-size=\"12\">\n"
      "<title>{2}</title>\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      "<text x=\"{3}\" y=\"24\" font-size=\"12.5\">{2}</text>\n",
      kCanvasWidth, height, xml_escape(plot.title), kLeft);
  for (std::size_t p = 0; p < count; ++p) {
    const TimePanel& panel = plot.panels[p];
    Frame frame{kTop + p * (plot.panel_height + kGap), plot.panel_height, t_min, t_max, 0, 1, 1};
    fit_y(plot, panel, frame);
    svg += axes(frame, panel.y_label, t_step, p + 1 == count);
    for (const PlotLevel& level : panel.levels) svg += level_mark(frame, level);
    for (const PlotSeries& series : panel.series) svg += polyline(plot, frame, series);
    svg += legend(frame, panel);
  }
  svg += fmt::format("<text x=\"{}\" y=\"{:g}\" text-anchor=\"middle\">{}</text>\n</svg>\n", kLeft + kWidth / 2,
                     height - kBottom + 36, xml_escape(plot.time_label));
  return svg;
}

void write_time_panels_svg(const std::string& path, const TimePanelsPlot& plot) {
  io::write_file_atomically(path, time_panels_svg(plot));
}

}  // namespace tk::sim
