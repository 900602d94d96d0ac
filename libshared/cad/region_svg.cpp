/// @file region_svg.cpp
/// @brief The SVG drawing of the region.
#include "cad/region_svg.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "cad/segment_geometry.hpp"
#include "io/atomic_file.hpp"
#include "sim/svg_marks.hpp"

namespace tk::cad {

namespace {

/// SVG path data of a loop or a segment chain (model coordinates, y up:
/// the whole drawing is flipped by a transform).
void append_path(std::string& d, const std::vector<Segment>& segments, bool close) {
  if (segments.empty()) return;
  d += fmt::format("M{:.6g} {:.6g}", segments.front().start.x, segments.front().start.y);
  for (const Segment& s : segments) {
    if (is_arc(s)) {
      const ArcShape arc = arc_shape(s);
      d += fmt::format(" A{:.6g} {:.6g} 0 {} {} {:.6g} {:.6g}", arc.radius, arc.radius,
                       std::abs(arc.sweep) > M_PI ? 1 : 0, arc.sweep > 0 ? 1 : 0, s.end.x, s.end.y);
    } else {
      d += fmt::format(" L{:.6g} {:.6g}", s.end.x, s.end.y);
    }
  }
  if (close) d += " Z";
  d += ' ';
}

struct Extent {
  double min_x = std::numeric_limits<double>::infinity(), min_y = min_x, max_x = -min_x, max_y = -min_x;
  void add(const Segment& s) {
    const Box b = bounding_box(s);
    min_x = std::min(min_x, b.min_x);
    min_y = std::min(min_y, b.min_y);
    max_x = std::max(max_x, b.max_x);
    max_y = std::max(max_y, b.max_y);
  }
};

template <class T>
bool has(const std::vector<T>* items) {
  return items && !items->empty();
}

/// Each layer's look, shared by the drawing and its legend entry.
struct Styles {
  std::string part, region_fill, contour, open, uncut, loose_end;
  explicit Styles(double stroke)
      : part(fmt::format("fill=\"none\" stroke=\"black\" stroke-width=\"{:.3g}\"", stroke)),
        region_fill("fill=\"#e8a0a0\" fill-opacity=\"0.5\""),
        contour(fmt::format("stroke=\"#2050c0\" stroke-width=\"{:.3g}\"", stroke)),
        open(fmt::format("fill=\"none\" stroke=\"#808080\" stroke-dasharray=\"{:.3g}\" stroke-width=\"{:.3g}\"",
                         4 * stroke, stroke)),
        uncut(fmt::format("fill=\"none\" stroke=\"#f08000\" stroke-width=\"{:.3g}\" stroke-linecap=\"round\"",
                          4 * stroke)),
        loose_end(fmt::format("fill=\"none\" stroke=\"red\" stroke-width=\"{:.3g}\"", stroke)) {}
};

std::vector<sim::LegendEntry> legend_entries(const SvgLayers& layers, const Styles& style) {
  using Mark = sim::LegendEntry::Mark;
  std::vector<sim::LegendEntry> entries;
  if (has(layers.drawn)) entries.push_back({Mark::line, style.part, "part as drawn"});
  if (has(layers.region)) {
    entries.push_back({Mark::area, style.region_fill, "prohibited region for the tool centre"});
    entries.push_back({Mark::line, style.contour, "region contour: the tool centre's limit"});
  }
  if (has(layers.open)) entries.push_back({Mark::line, style.open, "open segments (not in the region)"});
  if (has(layers.uncut)) entries.push_back({Mark::line, style.uncut, "uncut: out of the tool's reach"});
  if (has(layers.loose_ends)) entries.push_back({Mark::dot, style.loose_end, "loose ends"});
  return entries;
}

}  // namespace

void write_region_svg(const std::string& path, const SvgLayers& layers) {
  Extent extent;
  auto add_loops = [&](const std::vector<Loop>* loops) {
    if (loops)
      for (const Loop& loop : *loops)
        for (const Segment& s : loop.segments) extent.add(s);
  };
  add_loops(layers.drawn);
  add_loops(layers.region);
  if (layers.open)
    for (const Segment& s : *layers.open) extent.add(s);
  if (!(extent.max_x >= extent.min_x)) extent = {0, 0, 1, 1};
  const double size = std::max({extent.max_x - extent.min_x, extent.max_y - extent.min_y, 1e-6});
  const double margin = 0.05 * size, stroke = size / 800, font = size / 32;
  const Styles style(stroke);
  const std::vector<sim::LegendEntry> legend = legend_entries(layers, style);

  // Below the drawing (SVG's y grows downward, the drawing is flipped): the legend, then the scale bar.
  const double x0 = extent.min_x - margin, y0 = extent.min_y - margin;
  const double h = extent.max_y - extent.min_y + 2 * margin;
  double w = extent.max_x - extent.min_x + 2 * margin;
  for (const sim::LegendEntry& entry : legend)
    w = std::max(w, sim::text_width(entry.label, font) + 3.1 * font + 2 * margin);
  const double legend_top = -y0, bar_y = legend_top + sim::legend_height(legend.size(), font) + 1.8 * font;
  const double band = bar_y - legend_top + margin;
  std::string svg = fmt::format(
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"{:.6g} {:.6g} {:.6g} {:.6g}\" width=\"{:.0f}mm\" "
      "height=\"{:.0f}mm\">\n",
      x0, -(y0 + h), w, h + band, std::max(w, 1.0), std::max(h + band, 1.0));
  std::string title = layers.title;
  std::erase_if(title, [](char c) { return c == '<' || c == '>' || c == '&'; });
  svg += "<title>" + title + "</title>\n";
  svg += fmt::format("<rect x=\"{:.6g}\" y=\"{:.6g}\" width=\"{:.6g}\" height=\"{:.6g}\" fill=\"white\"/>\n", x0,
                     -(y0 + h), w, h + band);
  svg += "<g transform=\"scale(1,-1)\">\n";
  auto loops_path = [&](const std::vector<Loop>* loops, const std::string& css_class, const std::string& look) {
    if (!has(loops)) return;
    std::string d;
    for (const Loop& loop : *loops) append_path(d, loop.segments, true);
    svg += "<path class=\"" + css_class + "\" " + look + " d=\"" + d + "\"/>\n";
  };
  loops_path(layers.region, "region", style.region_fill + " fill-rule=\"evenodd\" " + style.contour);
  loops_path(layers.drawn, "part", style.part);
  if (has(layers.open)) {
    std::string d;
    for (const Segment& s : *layers.open) append_path(d, {s}, false);
    svg += fmt::format("<path class=\"open\" {} d=\"{}\"/>\n", style.open, d);
  }
  if (layers.uncut)
    for (const UncutSpan& span : *layers.uncut)
      svg += fmt::format("<path class=\"uncut\" {} d=\"M{:.6g} {:.6g} L{:.6g} {:.6g}\"/>\n", style.uncut, span.from.x,
                         span.from.y, span.to.x, span.to.y);
  if (layers.loose_ends)
    for (const LooseEnd& end : *layers.loose_ends)
      svg += fmt::format("<circle class=\"loose-end\" cx=\"{:.6g}\" cy=\"{:.6g}\" r=\"{:.3g}\" {}/>\n", end.at.x,
                         end.at.y, 6 * stroke, style.loose_end);
  svg += "</g>\n";
  svg += sim::svg_legend(legend, x0 + margin, legend_top, font);
  svg += sim::svg_scale_bar(sim::nearest_125(std::max(extent.max_x - extent.min_x, size / 4) / 5), 1, x0 + margin,
                            bar_y, font, stroke);
  svg += "</svg>\n";
  io::write_file_atomically(path, svg);
}

}  // namespace tk::cad
