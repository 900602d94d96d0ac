/// @file lap_svg.cpp
/// @brief The lap drawing.
#include "vehicle/lap_svg.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "io/atomic_file.hpp"
#include "sim/time_panels_svg.hpp"

namespace tk::vehicle {

namespace {

// Distinct on white and against the grey tape (Tableau 10, without grey).
constexpr std::array<const char*, 9> kColours{"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd",
                                              "#8c564b", "#e377c2", "#17becf", "#bcbd22"};

struct Box {
  double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
  void add(double x, double y) {
    x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x), y1 = std::max(y1, y);
  }
};

}  // namespace

void write_lap_svg(const std::string& path, const Track& track, const std::vector<LapRun>& runs) {
  Box box;
  for (const Point& p : track.vertices()) box.add(p.x, p.y);
  for (const auto& run : runs)
    for (const TracePoint& p : run.second) box.add(p.x, p.y);
  const double size = std::max({box.x1 - box.x0, box.y1 - box.y0, 1.0});
  const double margin = 0.05 * size, legend_row = size / 30;
  // Room above the drawing for the legend; SVG's y grows downward, so y is mirrored by hand (text stays upright).
  const double left = box.x0 - margin, top = box.y1 + margin + legend_row * (static_cast<double>(runs.size()) + 0.5);
  const double width = box.x1 - box.x0 + 2 * margin, height = top - (box.y0 - margin);
  const auto sx = [&](double x) { return x - left; };
  const auto sy = [&](double y) { return top - y; };

  std::string svg = fmt::format(
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"1000\" height=\"{:.0f}\" viewBox=\"0 0 {:.6g} {:.6g}\">\n"
      "<title>line follower laps: track {:.0f} mm, line {:.3g} mm wide</title>\n"
      "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n",
      1000 * height / width, width, height, track.length_mm(), track.line_width_mm());
  std::string d;
  for (std::size_t i = 0; i < track.vertices().size(); ++i)
    d += fmt::format("{}{:.6g} {:.6g}", i ? " L" : "M", sx(track.vertices()[i].x), sy(track.vertices()[i].y));
  svg += fmt::format("<path d=\"{} Z\" fill=\"none\" stroke=\"#b0b0b0\" stroke-width=\"{:.6g}\" stroke-linejoin=\"round\"/>\n", d,
                     track.line_width_mm());
  const double stroke = std::max(size / 1000, 0.5);
  svg += fmt::format("<circle cx=\"{:.6g}\" cy=\"{:.6g}\" r=\"{:.6g}\" fill=\"black\"><title>start</title></circle>\n",
                     sx(track.start().x), sy(track.start().y), 3 * stroke);

  for (std::size_t r = 0; r < runs.size(); ++r) {
    const char* colour = kColours[r % kColours.size()];
    const auto& points = runs[r].second;
    if (!points.empty()) {
      d.clear();
      for (std::size_t i = 0; i < points.size(); ++i) d += fmt::format("{}{:.6g} {:.6g}", i ? " L" : "M", sx(points[i].x), sy(points[i].y));
      svg += fmt::format("<path d=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"{:.6g}\" stroke-opacity=\"0.8\"/>\n", d, colour, stroke);
      svg += fmt::format("<circle cx=\"{:.6g}\" cy=\"{:.6g}\" r=\"{:.6g}\" fill=\"{}\"/>\n", sx(points.back().x),
                         sy(points.back().y), 4 * stroke, colour);
    }
    const double y = legend_row * (static_cast<double>(r) + 1);
    svg += fmt::format("<line x1=\"{:.6g}\" y1=\"{:.6g}\" x2=\"{:.6g}\" y2=\"{:.6g}\" stroke=\"{}\" stroke-width=\"{:.6g}\"/>\n",
                       margin, y - legend_row / 3, margin + 2 * legend_row, y - legend_row / 3, colour, 3 * stroke);
    svg += fmt::format("<text x=\"{:.6g}\" y=\"{:.6g}\" font-family=\"sans-serif\" font-size=\"{:.6g}\">{}</text>\n",
                       margin + 2.5 * legend_row, y, 0.7 * legend_row, sim::xml_escape(runs[r].first));
  }
  svg += "</svg>\n";
  io::write_file_atomically(path, svg);
}

}  // namespace tk::vehicle
