/// @file lap_svg.cpp
/// @brief The lap drawing.
#include "vehicle/lap_svg.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "io/atomic_file.hpp"
#include "sim/svg_marks.hpp"

namespace tk::vehicle {

namespace {

// Distinct on white and against the grey tape (Tableau 10, without grey).
constexpr std::array<const char*, 9> kColours{"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd",
                                              "#8c564b", "#e377c2", "#17becf", "#bcbd22"};
constexpr const char* kTapeStyle = "stroke=\"#b0b0b0\"";
constexpr const char* kStopStyle = "fill=\"#c00000\" stroke=\"white\"";
/// A white outline under the letters keeps a label readable over the tape.
constexpr const char* kHalo = "stroke=\"white\" stroke-width=\"{:.3g}\" paint-order=\"stroke\"";

struct Box {
  double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
  void add(double x, double y) {
    x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x), y1 = std::max(y1, y);
  }
};

std::string caption(const LapRun& run) {
  const LapResult& r = run.result;
  if (r.completed) return fmt::format("{}: {} laps in {:.2f} s", run.label, r.lap_times_s.size(), r.total_s);
  return fmt::format("{}: did not finish ({})", run.label, r.stop_reason.empty() ? "ended" : r.stop_reason);
}

/// Where a panel's model coordinates land: its left edge and the top of its
/// drawing area; y is mirrored by hand so text stays upright.
struct Panel {
  double left, top, width, height;  // the frame
  double origin_x, origin_y;        // where (box.x0, box.y1) lands
  double sx(double x, const Box& box) const { return origin_x + (x - box.x0); }
  double sy(double y, const Box& box) const { return origin_y + (box.y1 - y); }
};

}  // namespace

void write_lap_svg(const std::string& path, const Track& track, const std::vector<LapRun>& runs) {
  Box box;
  for (const Point& p : track.vertices()) box.add(p.x, p.y);
  for (const auto& run : runs)
    for (const TracePoint& p : run.trace) box.add(p.x, p.y);
  const double size = std::max({box.x1 - box.x0, box.y1 - box.y0, 1.0});
  const double margin = 0.05 * size, font = size / 24, stroke = std::max(size / 400, 0.5);
  const std::size_t columns = runs.size() <= 1 ? 1 : runs.size() <= 4 ? 2 : 3;
  const std::size_t rows = std::max<std::size_t>(1, (runs.size() + columns - 1) / columns);
  const double header = 2 * font, gap = margin;
  const double panel_width = box.x1 - box.x0 + 2 * margin, panel_height = header + box.y1 - box.y0 + 2 * margin;
  const std::vector<sim::LegendEntry> legend{
      {sim::LegendEntry::Mark::line, fmt::format("{} stroke-width=\"{:.6g}\"", kTapeStyle, track.line_width_mm()),
       fmt::format("the line ({:.3g} mm tape)", track.line_width_mm())},
      {sim::LegendEntry::Mark::dot, "fill=\"black\"", "start"},
      {sim::LegendEntry::Mark::line, fmt::format("stroke=\"{}\" stroke-width=\"{:.6g}\"", kColours[0], stroke),
       "the axle centre's path"},
      {sim::LegendEntry::Mark::dot, kStopStyle, "where a car that did not finish ended"}};
  const double legend_top = margin, panels_top = legend_top + sim::legend_height(legend.size(), font) + margin;
  const double width = 2 * margin + static_cast<double>(columns) * panel_width + static_cast<double>(columns - 1) * gap;
  const double height =
      panels_top + static_cast<double>(rows) * panel_height + static_cast<double>(rows - 1) * gap + margin;

  std::string svg = fmt::format(
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{:.0f}\" height=\"{:.0f}\" viewBox=\"0 0 {:.6g} {:.6g}\" "
      "font-family=\"sans-serif\">\n"
      "<title>line follower laps: track {:.0f} mm, line {:.3g} mm wide, one panel per run</title>\n"
      "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n",
      520.0 * static_cast<double>(columns), 520.0 * static_cast<double>(columns) * height / width, width, height,
      track.length_mm(), track.line_width_mm());
  svg += sim::svg_legend(legend, margin, legend_top, font);
  const std::string halo = fmt::format(kHalo, font / 5);

  for (std::size_t r = 0; r < runs.size(); ++r) {
    const LapRun& run = runs[r];
    const double left = margin + static_cast<double>(r % columns) * (panel_width + gap);
    const double top = panels_top + static_cast<double>(r / columns) * (panel_height + gap);
    const Panel panel{left, top, panel_width, panel_height, left + margin, top + header + margin};
    const char* colour = kColours[r % kColours.size()];
    svg += fmt::format("<g class=\"run\" id=\"run-{}\">\n", r);
    svg += fmt::format(
        "<rect class=\"panel\" x=\"{:.6g}\" y=\"{:.6g}\" width=\"{:.6g}\" height=\"{:.6g}\" fill=\"none\" "
        "stroke=\"#444\" "
        "stroke-width=\"{:.3g}\"/>\n",
        panel.left, panel.top, panel.width, panel.height, stroke / 2);
    svg += fmt::format("<text x=\"{:.6g}\" y=\"{:.6g}\" font-size=\"{:.4g}\" fill=\"{}\">{}</text>\n",
                       panel.left + margin / 2, panel.top + 1.4 * font, font, colour, sim::xml_escape(caption(run)));
    std::string d;
    for (std::size_t i = 0; i < track.vertices().size(); ++i)
      d += fmt::format("{}{:.6g} {:.6g}", i ? " L" : "M", panel.sx(track.vertices()[i].x, box),
                       panel.sy(track.vertices()[i].y, box));
    svg += fmt::format(
        "<path class=\"track\" d=\"{} Z\" fill=\"none\" {} stroke-width=\"{:.6g}\" stroke-linejoin=\"round\"/>\n", d,
        kTapeStyle, track.line_width_mm());
    svg +=
        fmt::format("<circle cx=\"{:.6g}\" cy=\"{:.6g}\" r=\"{:.6g}\" fill=\"black\"><title>start</title></circle>\n",
                    panel.sx(track.start().x, box), panel.sy(track.start().y, box), 0.35 * font);
    const auto& points = run.trace;
    if (!points.empty()) {
      d.clear();
      for (std::size_t i = 0; i < points.size(); ++i)
        d += fmt::format("{}{:.6g} {:.6g}", i ? " L" : "M", panel.sx(points[i].x, box), panel.sy(points[i].y, box));
      svg += fmt::format("<path class=\"path\" d=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"{:.6g}\"/>\n", d,
                         colour, stroke);
    }
    if (!run.result.completed && !points.empty()) {
      const double x = panel.sx(points.back().x, box), y = panel.sy(points.back().y, box);
      const std::string label =
          fmt::format("{} after {:.1f} s, {:.0f} mm", run.result.stop_reason.empty() ? "ended" : run.result.stop_reason,
                      run.result.total_s, run.result.distance_mm);
      // The label towards the panel's middle, kept inside the frame.
      const double half = sim::text_width(label, font) / 2;
      const double label_x =
          std::clamp(x, panel.left + margin / 2 + half, panel.left + panel.width - margin / 2 - half);
      const double label_y = y > panel.origin_y + (box.y1 - box.y0) / 2 ? y - 1.3 * font : y + 1.9 * font;
      svg +=
          fmt::format("<circle class=\"stop\" cx=\"{:.6g}\" cy=\"{:.6g}\" r=\"{:.6g}\" {} stroke-width=\"{:.3g}\"/>\n",
                      x, y, 0.5 * font, kStopStyle, font / 8);
      svg += fmt::format(
          "<text class=\"stop-label\" x=\"{:.6g}\" y=\"{:.6g}\" font-size=\"{:.4g}\" text-anchor=\"middle\" "
          "fill=\"#c00000\" {}>{}</text>\n",
          label_x, label_y, font, halo, sim::xml_escape(label));
    }
    svg += "</g>\n";
  }
  svg += "</svg>\n";
  io::write_file_atomically(path, svg);
}

}  // namespace tk::vehicle
