/// @file region_output.cpp
/// @brief Region records.
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
  return {"record",
          "loop",
          "depth",
          "hole",
          "area_mm2",
          "length_mm",
          "elements",
          "polyline",
          "x",
          "y",
          "x0",
          "y0",
          "x1",
          "y1",
          "depth_mm",
          "entity",
          "dxf_line",
          "touched_entity",
          "touched_dxf_line",
          "file",
          "version",
          "units",
          "mm_per_unit",
          "entities_read",
          "entities_skipped",
          "loops",
          "holes",
          "open_segments",
          "loose_ends",
          "t_junctions",
          "uncut",
          "polygon_loops",
          "tool_radius",
          "side",
          "doubled_edges"};
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
  return Record{
      {"record", "loose_end"}, {"x", end.at.x}, {"y", end.at.y}, {"entity", end.entity}, {"dxf_line", end.source_line}};
}

Record t_junction_record(const TJunction& junction) {
  return Record{{"record", "t_junction"},
                {"x", junction.at.x},
                {"y", junction.at.y},
                {"entity", junction.entity},
                {"dxf_line", junction.source_line},
                {"touched_entity", junction.touched_entity},
                {"touched_dxf_line", junction.touched_source_line}};
}

Record uncut_record(const UncutSpan& span) {
  return Record{{"record", "uncut"}, {"x0", span.from.x},      {"y0", span.from.y},     {"x1", span.to.x},
                {"y1", span.to.y},   {"depth_mm", span.depth}, {"entity", span.entity}, {"dxf_line", span.source_line}};
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

}  // namespace tk::cad
