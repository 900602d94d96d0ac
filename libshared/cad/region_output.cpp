/// @file region_output.cpp
/// @brief Region records and the SVG drawing.
#include "cad/region_output.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "cad/segment_geometry.hpp"
#include "io/atomic_file.hpp"
#include "io/error.hpp"

namespace tk::cad {

std::vector<std::string> region_record_fields() {
  return {"record", "loop",      "depth",    "hole",  "area_mm2", "length_mm", "elements", "polyline", "x",
          "y",      "x0",        "y0",       "x1",    "y1",       "depth_mm",  "entity",   "dxf_line", "touched_entity",
          "touched_dxf_line", "file", "version", "units", "mm_per_unit", "entities_read", "entities_skipped", "loops",
          "holes", "open_segments", "loose_ends", "t_junctions", "uncut", "polygon_loops", "tool_radius", "side", "doubled_edges"};
}

Record loop_record(const Loop& loop, std::size_t number, double flatten_tolerance, bool with_sources) {
  Record record;
  record["record"] = "loop";
  record["loop"] = number;
  record["depth"] = loop.depth;
  record["hole"] = loop.is_hole();
  record["area_mm2"] = loop.area;
  double length = 0;
  Record elements = Record::array();
  for (const Segment& s : loop.segments) {
    length += segment_length(s);
    Record e;
    e["type"] = is_arc(s) ? "arc" : "line";
    e["x0"] = s.start.x;
    e["y0"] = s.start.y;
    e["x1"] = s.end.x;
    e["y1"] = s.end.y;
    if (is_arc(s)) {
      const ArcShape arc = arc_shape(s);
      e["cx"] = arc.centre.x;
      e["cy"] = arc.centre.y;
      e["r"] = arc.radius;
      e["bulge"] = s.bulge;
    }
    if (with_sources) {
      e["entity"] = s.entity;
      e["dxf_line"] = s.source_line;
    }
    elements.push_back(std::move(e));
  }
  record["length_mm"] = length;
  record["elements"] = std::move(elements);
  Record points = Record::array();
  for (const Point& p : flatten_loop(loop, flatten_tolerance)) points.push_back(Record::array({p.x, p.y}));
  record["polyline"] = std::move(points);
  return record;
}

Record loose_end_record(const LooseEnd& end) {
  return Record{{"record", "loose_end"}, {"x", end.at.x}, {"y", end.at.y}, {"entity", end.entity}, {"dxf_line", end.source_line}};
}

Record t_junction_record(const TJunction& junction) {
  return Record{{"record", "t_junction"},        {"x", junction.at.x},
                {"y", junction.at.y},            {"entity", junction.entity},
                {"dxf_line", junction.source_line}, {"touched_entity", junction.touched_entity},
                {"touched_dxf_line", junction.touched_source_line}};
}

Record uncut_record(const UncutSpan& span) {
  return Record{{"record", "uncut"},       {"x0", span.from.x},        {"y0", span.from.y}, {"x1", span.to.x},
                {"y1", span.to.y},         {"depth_mm", span.depth},   {"entity", span.entity},
                {"dxf_line", span.source_line}};
}

Record drawing_record(const Part& part, const RegionOffset& region) {
  Record record;
  record["record"] = "drawing";
  record["version"] = part.drawing.version;
  record["units"] = part.units_source;
  record["mm_per_unit"] = part.millimetres_per_unit;
  Record read = Record::object(), skipped = Record::object();
  for (const auto& [type, count] : part.drawing.entities_read) read[type] = count;
  for (const auto& [type, count] : part.drawing.entities_skipped) skipped[type] = count;
  record["entities_read"] = std::move(read);
  record["entities_skipped"] = std::move(skipped);
  std::size_t holes = 0;
  for (const Loop& loop : part.loops.loops) holes += loop.is_hole();
  record["loops"] = part.loops.loops.size();
  record["holes"] = holes;
  record["open_segments"] = part.loops.open_segments.size();
  record["loose_ends"] = part.loops.loose_ends.size();
  record["t_junctions"] = part.loops.t_junctions.size();
  record["uncut"] = region.uncut.size();
  record["polygon_loops"] = region.polygon_loops;
  return record;
}

namespace {

/// SVG path data of a loop or a segment chain (model coordinates, y up:
/// the whole drawing is flipped by a transform).
void append_path(std::string& d, const std::vector<Segment>& segments, bool close) {
  if (segments.empty()) return;
  d += fmt::format("M{:.6g} {:.6g}", segments.front().start.x, segments.front().start.y);
  for (const Segment& s : segments) {
    if (is_arc(s)) {
      const ArcShape arc = arc_shape(s);
      d += fmt::format(" A{:.6g} {:.6g} 0 {} {} {:.6g} {:.6g}", arc.radius, arc.radius, std::abs(arc.sweep) > M_PI ? 1 : 0,
                       arc.sweep > 0 ? 1 : 0, s.end.x, s.end.y);
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
  const double margin = 0.05 * size, stroke = size / 800;
  const double x0 = extent.min_x - margin, y0 = extent.min_y - margin;
  const double w = extent.max_x - extent.min_x + 2 * margin, h = extent.max_y - extent.min_y + 2 * margin;
  std::string svg = fmt::format(
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"{:.6g} {:.6g} {:.6g} {:.6g}\" width=\"{:.0f}mm\" height=\"{:.0f}mm\">\n",
      x0, -(y0 + h), w, h, std::max(w, 1.0), std::max(h, 1.0));
  std::string title = layers.title;
  std::erase_if(title, [](char c) { return c == '<' || c == '>' || c == '&'; });
  svg += "<title>" + title + "</title>\n<g transform=\"scale(1,-1)\">\n";
  auto loops_path = [&](const std::vector<Loop>* loops, const std::string& style) {
    if (!loops || loops->empty()) return;
    std::string d;
    for (const Loop& loop : *loops) append_path(d, loop.segments, true);
    svg += "<path " + style + " d=\"" + d + "\"/>\n";
  };
  loops_path(layers.region, fmt::format("fill=\"#e8a0a0\" fill-opacity=\"0.5\" fill-rule=\"evenodd\" stroke=\"#2050c0\" stroke-width=\"{:.3g}\"", stroke));
  loops_path(layers.drawn, fmt::format("fill=\"none\" stroke=\"black\" stroke-width=\"{:.3g}\"", stroke));
  if (layers.open && !layers.open->empty()) {
    std::string d;
    for (const Segment& s : *layers.open) append_path(d, {s}, false);
    svg += fmt::format("<path fill=\"none\" stroke=\"#808080\" stroke-dasharray=\"{:.3g}\" stroke-width=\"{:.3g}\" d=\"{}\"/>\n",
                       4 * stroke, stroke, d);
  }
  if (layers.uncut)
    for (const UncutSpan& span : *layers.uncut)
      svg += fmt::format("<path fill=\"none\" stroke=\"#f08000\" stroke-width=\"{:.3g}\" stroke-linecap=\"round\" d=\"M{:.6g} {:.6g} L{:.6g} {:.6g}\"/>\n",
                         4 * stroke, span.from.x, span.from.y, span.to.x, span.to.y);
  if (layers.loose_ends)
    for (const LooseEnd& end : *layers.loose_ends)
      svg += fmt::format("<circle cx=\"{:.6g}\" cy=\"{:.6g}\" r=\"{:.3g}\" fill=\"none\" stroke=\"red\" stroke-width=\"{:.3g}\"/>\n",
                         end.at.x, end.at.y, 6 * stroke, stroke);
  svg += "</g>\n</svg>\n";
  io::write_file_atomically(path, svg);
}

}  // namespace tk::cad
