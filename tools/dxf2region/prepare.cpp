/// @file prepare.cpp
/// @brief dxf2region: the part read and offset, as every mode starts.
#include <fmt/format.h>

#include "cad/region_output.hpp"
#include "cad/region_svg.hpp"
#include "cad/segment_geometry.hpp"
#include "io/error.hpp"
#include "modes.hpp"

namespace dxf2region {

tk::cad::InvasionSimOptions Settings::experiment_at(double v) const {
  tk::cad::InvasionSimOptions options;
  options.feed_mm_s = v;
  options.latency_s = travel_latency ? latency_mm / v : latency;
  options.period_s = travel_period ? period_mm / v : period;
  options.margin_mm = margin;
  options.strokes = strokes;
  options.seed = seed;
  return options;
}

void write_findings(const Settings& s, const Job& job, const tk::cad::RegionOffset& region,
                    tk::io::RecordWriter& writer, tk::cli::ToolApp& tool) {
  const tk::cad::LoopSet& found = job.part.loops;
  for (const tk::cad::LooseEnd& end : found.loose_ends) writer.write(tk::cad::loose_end_record(end));
  for (const tk::cad::TJunction& junction : found.t_junctions) writer.write(tk::cad::t_junction_record(junction));
  for (const tk::cad::UncutSpan& span : region.uncut) writer.write(tk::cad::uncut_record(span));
  tk::Record totals = tk::cad::drawing_record(job.part, region);
  totals["file"] = job.name;
  totals["tool_radius"] = s.tool_radius;
  totals["side"] = s.side;
  totals["doubled_edges"] = job.doubled_edges;
  if (tool.common().csv) {  // nested objects as JSON text in one cell
    totals["entities_read"] = totals["entities_read"].dump();
    totals["entities_skipped"] = totals["entities_skipped"].dump();
  }
  writer.write(totals);
}

Job prepare(const Settings& s, tk::io::RecordWriter& writer, bool region_mode, tk::cli::ToolApp& tool) {
  auto warn = [&](const std::string& message) { tool.warn(message); };
  tk::cad::PartOptions part_options;
  part_options.layers = s.layers;
  part_options.units = s.units;
  part_options.join_tolerance = s.join_tolerance;
  Job job{tk::cad::load_part(s.part_path, part_options, warn), s.part_path == "-" ? "<stdin>" : s.part_path, 0, {}};
  const std::string& name = job.name;
  const tk::cad::LoopSet& found = job.part.loops;
  for (const auto& [type, count] : job.part.drawing.entities_skipped)
    warn(name + ": " + std::to_string(count) + " " + type + (count == 1 ? " entity" : " entities") + " not used");
  if (!found.loose_ends.empty())
    warn(fmt::format("{}: {} loose ends (first at {:g}, {:g}, line {}): open chains are not part of the region", name,
                     found.loose_ends.size(), found.loose_ends[0].at.x, found.loose_ends[0].at.y,
                     found.loose_ends[0].source_line));
  const std::vector<tk::cad::Point> doubled = tk::cad::doubled_edges(found.loops);
  job.doubled_edges = doubled.size();
  if (!doubled.empty())
    warn(fmt::format("{}: {} edges drawn twice (first about {:g}, {:g}): the region there may not be what was meant",
                     name, doubled.size(), doubled[0].x, doubled[0].y));
  if (region_mode) writer.declare_fields(tk::cad::region_record_fields());
  if (found.loops.empty()) {
    if (region_mode) write_findings(s, job, {}, writer, tool);  // what was found helps to mend the drawing
    throw tk::Error("no closed loop in the drawing" + std::string(s.layers.empty() ? "" : " on the chosen layers"),
                    {name, 0});
  }

  tk::cad::OffsetOptions offset_options;
  offset_options.tool_radius = s.tool_radius;
  offset_options.side = s.machining();
  offset_options.tolerance = s.offset_tolerance;
  offset_options.contour_grid = s.checking;
  try {
    job.region = tk::cad::offset_region(found.loops, *job.part.index, offset_options);
  } catch (const tk::UsageError&) {
    throw;  // the offset's size, named by its options
  } catch (const tk::Error& e) {
    throw tk::Error(e.what(), {name, e.where().line});  // the library knows the DXF line, not the file
  }
  const tk::cad::RegionOffset& region = job.region;
  if (region.polygon_loops > 0)
    warn(std::to_string(region.polygon_loops) +
         " offset loops stay as polygons (the exact lines and arcs did not check out)");
  if (region.loops.empty())
    warn("the tool fits nowhere in the pocket: every position is prohibited, and there is no contour");
  if (!region.uncut.empty())
    warn(std::to_string(region.uncut.size()) +
         " stretches of the drawing are out of the tool's reach (records \"uncut\")");

  if (!s.svg_path.empty()) {
    tk::cad::SvgLayers layers_to_draw;
    layers_to_draw.drawn = &found.loops;
    layers_to_draw.open = &found.open_segments;
    layers_to_draw.region = &region.loops;
    layers_to_draw.loose_ends = &found.loose_ends;
    layers_to_draw.uncut = &region.uncut;
    layers_to_draw.title = fmt::format(
        "dxf2region {}: drawing (black), prohibited region for tool radius {:g} mm (red, its contour blue), "
        "out of reach (orange)",
        name, s.tool_radius);
    tk::cad::write_region_svg(s.svg_path, layers_to_draw);
  }
  return job;
}

}  // namespace dxf2region
