/// @file main.cpp
/// @brief dxf2region: a DXF part profile to the prohibited region for a
/// round tool, its finishing contour as G-code, the invasion check of a
/// stream of tool positions, and the seed's latency experiment.
#include <fmt/format.h>

#include <cmath>
#include <cstdio>

#include "cad/invasion_check.hpp"
#include "cad/invasion_sim.hpp"
#include "cad/part.hpp"
#include "cad/region_offset.hpp"
#include "cad/region_output.hpp"
#include "cad/region_svg.hpp"
#include "cad/segment_geometry.hpp"
#include "cad/toolpath.hpp"
#include "cli/number_option.hpp"
#include "cli/option_checks.hpp"
#include "cli/tool_app.hpp"
#include "io/error.hpp"
#include "io/record_fields.hpp"
#include "io/record_reader.hpp"
#include "io/record_writer.hpp"

namespace {

/// "1,2,3" as numbers; a usage error naming the option otherwise.
std::vector<double> number_list(const std::string& text, const char* option) {
  return tk::cli::parse_numbers(text, option, std::count(text.begin(), text.end(), ',') + 1);
}


}  // namespace

int main(int argc, char** argv) {
  tk::cli::ToolApp tool("dxf2region",
                        "Turn a DXF part profile into the prohibited region for a round tool: as records and SVG, as "
                        "the finishing contour in G-code (--toolpath), as a guard over tool positions (--check), or "
                        "in a simulation of a joystick operator under control latency (--simulate).",
                        "See dxf2region(1).");
  std::string part_path, units, side = "outside", svg_path, check_path, direction = "climb";
  std::string tolerances_text = "1,2,3,4,4.5,5", speeds_text = "12,18", invasion_check = "exact";
  std::vector<std::string> layers;
  double tool_radius = 0, join_tolerance = 1e-3, flatten_tolerance = 0.01, offset_tolerance = 1e-4;
  double latency = 0.09, margin = 0.02, feed = 600, plunge_feed = 100, cut_z = -1, safe_z = 5;
  double period = 0.001, latency_mm = 0, period_mm = 0;
  std::uint32_t strokes = 1000;
  std::uint64_t seed = 1;
  bool toolpath = false, summary = false, simulate = false;
  CLI::App& app = tool.app();
  app.add_option("part", part_path, "the DXF file ('-' for standard input)")->required()->type_name("PART.dxf");
  app.add_option("--layer", layers, "use only this layer (again for more)")->type_name("L");
  app.add_option("--units", units, "the drawing's unit when $INSUNITS is 0 or absent: mm, cm, m, in, ft, ...")->type_name("U");
  app.add_option("--join-tol", join_tolerance, "ends closer than this meet, mm")->capture_default_str()->type_name("MM");
  app.add_option("--tool-radius", tool_radius, "grow the part (or shrink the pocket) by the tool's radius, mm")
      ->capture_default_str()
      ->type_name("R");
  app.add_option("--side", side, "outside: the tool works around the part; inside: in a pocket")
      ->check(CLI::IsMember({"outside", "inside"}))
      ->capture_default_str();
  app.add_option("--svg", svg_path, "draw the drawing, the region and what was found in it")->type_name("FILE");
  app.add_option("--flatten-tol", flatten_tolerance, "chord tolerance of the loops' polylines in the records, mm")
      ->capture_default_str()
      ->type_name("MM");
  app.add_option("--offset-tol", offset_tolerance, "tolerance of the offset's polygon stage, mm")
      ->capture_default_str()
      ->type_name("MM");
  auto* check = app.add_option("--check", check_path, "check tool positions (records with x, y and optionally t); standard input when no file")
                    ->expected(0, 1)
                    ->type_name("[POSITIONS]");
  app.add_flag("--summary", summary, "with --check: a final record (positions, invasions, deepest invasion)");
  auto* latency_option =
      app.add_option("--latency", latency, "with --check and times, --simulate: seconds from a sample to a stop taking effect")
          ->capture_default_str()
          ->type_name("S");
  app.add_option("--margin", margin, "the latency-aware guard's aim, mm")->capture_default_str()->type_name("MM");
  app.add_flag("--toolpath", toolpath, "write the finishing contour as G-code");
  app.add_option("--feed", feed, "contour feed, mm/min")->capture_default_str()->type_name("F");
  app.add_option("--plunge-feed", plunge_feed, "feed going down, mm/min")->capture_default_str()->type_name("F");
  app.add_option("--cut-z", cut_z, "Z of the cut, mm")->capture_default_str()->type_name("Z");
  app.add_option("--safe-z", safe_z, "Z of rapid moves, mm")->capture_default_str()->type_name("Z");
  app.add_option("--direction", direction, "climb (material on the right) or conventional")
      ->check(CLI::IsMember({"climb", "conventional"}))
      ->capture_default_str();
  app.add_flag("--simulate", simulate, "run the seed's invasion experiment against the region");
  app.add_option("--tolerances", tolerances_text, "with --simulate: the fixed guard's tolerances, mm (the seed's Tables 2-3)")
      ->capture_default_str()
      ->type_name("T,...");
  app.add_option("--joystick-speed", speeds_text, "with --simulate: the operator's feeds, mm/s (the seed's Table 2)")
      ->capture_default_str()
      ->type_name("V,...");
  auto* period_option = app.add_option("--period", period, "with --simulate: control period, s")->capture_default_str()->type_name("S");
  auto* latency_mm_option =
      app.add_option("--latency-mm", latency_mm, "with --simulate: the latency as travel at each feed, mm (instead of --latency)")
          ->type_name("MM")
          ->excludes(latency_option);
  auto* period_mm_option =
      app.add_option("--period-mm", period_mm, "with --simulate: the control period as travel at each feed, mm (instead of --period)")
          ->type_name("MM")
          ->excludes(period_option);
  app.add_option("--invasion-check", invasion_check,
                 "with --simulate: what the fixed guard compares with T: the exact distance, or the seed's eq. (2) (printed)")
      ->check(CLI::IsMember({"exact", "printed"}))
      ->capture_default_str();
  app.add_option("--strokes", strokes, "with --simulate: approaches per guard")->capture_default_str()->type_name("N");
  app.add_option("--seed", seed, "with --simulate: random seed of the strokes")->capture_default_str()->type_name("N");

  return tool.run(argc, argv, [&] {
    const bool checking = check->count() > 0;
    if (checking + toolpath + simulate > 1) throw tk::UsageError("--check, --toolpath and --simulate exclude each other");
    if (summary && !checking) throw tk::UsageError("--summary goes with --check");
    // The ranges dxf2region(1) gives under OPTIONS: a metre-radius tool is
    // past the largest face mill; an offset tolerance finer than 0.1 um is
    // below any machine's resolution and slows the offset without bound.
    using tk::cli::require_range;
    require_range(tool_radius, 0, 1000, "--tool-radius");
    require_range(join_tolerance, 1e-6, 10, "--join-tol");
    require_range(flatten_tolerance, 1e-6, 10, "--flatten-tol");
    require_range(offset_tolerance, 1e-4, 1, "--offset-tol");
    require_range(latency, 0, 10, "--latency");
    require_range(margin, 0, 100, "--margin");
    require_range(period, 1e-6, 1, "--period");
    require_range(feed, 0.1, 1e5, "--feed");
    require_range(plunge_feed, 0.1, 1e5, "--plunge-feed");
    require_range(cut_z, -1e4, 1e4, "--cut-z");
    require_range(safe_z, -1e4, 1e4, "--safe-z");
    require_range(strokes, 1, 1e6, "--strokes");
    const bool travel_latency = latency_mm_option->count() > 0, travel_period = period_mm_option->count() > 0;
    if (!simulate && (travel_latency || travel_period || invasion_check != "exact"))
      throw tk::UsageError("--latency-mm, --period-mm and --invasion-check go with --simulate");
    if (travel_latency) require_range(latency_mm, 0, 1000, "--latency-mm");
    if (travel_period) require_range(period_mm, 1e-4, 1000, "--period-mm");
    const std::vector<double> speeds = number_list(speeds_text, "--joystick-speed");
    const std::vector<double> tolerances = number_list(tolerances_text, "--tolerances");
    for (const double tolerance : tolerances) require_range(tolerance, 0, 1000, "--tolerances");
    auto experiment_at = [&](double v) {
      tk::cad::InvasionSimOptions options;
      options.feed_mm_s = v;
      options.latency_s = travel_latency ? latency_mm / v : latency;
      options.period_s = travel_period ? period_mm / v : period;
      options.margin_mm = margin;
      options.strokes = strokes;
      options.seed = seed;
      return options;
    };
    if (simulate)
      for (double v : speeds) {
        require_range(v, 0.01, 1e4, "--joystick-speed");
        try {
          tk::cad::check_invasion_sim(tolerances, experiment_at(v));
        } catch (const tk::Error& e) {
          throw tk::UsageError(std::string("--simulate: ") + e.what());
        }
      }
    if (!units.empty()) {
      try {
        tk::cad::millimetres_per_named_unit(units);
      } catch (const tk::Error& e) {
        throw tk::UsageError(std::string("--units: ") + e.what());
      }
    }
    const tk::cad::MachiningSide machining = side == "inside" ? tk::cad::MachiningSide::inside : tk::cad::MachiningSide::outside;
    auto warn = [&](const std::string& message) { tool.warn(message); };

    tk::cad::PartOptions part_options;
    part_options.layers = layers;
    part_options.units = units;
    part_options.join_tolerance = join_tolerance;
    const tk::cad::Part part = tk::cad::load_part(part_path, part_options, warn);
    const std::string name = part_path == "-" ? "<stdin>" : part_path;
    const tk::cad::LoopSet& found = part.loops;
    for (const auto& [type, count] : part.drawing.entities_skipped)
      warn(name + ": " + std::to_string(count) + " " + type + (count == 1 ? " entity" : " entities") + " not used");
    if (!found.loose_ends.empty())
      warn(fmt::format("{}: {} loose ends (first at {:g}, {:g}, line {}): open chains are not part of the region", name,
                       found.loose_ends.size(), found.loose_ends[0].at.x, found.loose_ends[0].at.y, found.loose_ends[0].source_line));
    const std::vector<tk::cad::Point> doubled = tk::cad::doubled_edges(found.loops);
    if (!doubled.empty())
      warn(fmt::format("{}: {} edges drawn twice (first about {:g}, {:g}): the region there may not be what was meant", name,
                       doubled.size(), doubled[0].x, doubled[0].y));
    tk::io::RecordWriter writer(tool.output_format());
    auto write_findings = [&](const tk::cad::RegionOffset& region) {
      for (const tk::cad::LooseEnd& end : found.loose_ends) writer.write(tk::cad::loose_end_record(end));
      for (const tk::cad::TJunction& junction : found.t_junctions) writer.write(tk::cad::t_junction_record(junction));
      for (const tk::cad::UncutSpan& span : region.uncut) writer.write(tk::cad::uncut_record(span));
      tk::Record totals = tk::cad::drawing_record(part, region);
      totals["file"] = name;
      totals["tool_radius"] = tool_radius;
      totals["side"] = side;
      totals["doubled_edges"] = doubled.size();
      if (tool.common().csv) {  // nested objects as JSON text in one cell
        totals["entities_read"] = totals["entities_read"].dump();
        totals["entities_skipped"] = totals["entities_skipped"].dump();
      }
      writer.write(totals);
    };
    const bool region_mode = !checking && !toolpath && !simulate;
    if (region_mode) writer.declare_fields(tk::cad::region_record_fields());
    if (found.loops.empty()) {
      if (region_mode) write_findings({});  // what was found helps to mend the drawing
      throw tk::Error("no closed loop in the drawing" + std::string(layers.empty() ? "" : " on the chosen layers"), {name, 0});
    }

    tk::cad::OffsetOptions offset_options;
    offset_options.tool_radius = tool_radius;
    offset_options.side = machining;
    offset_options.tolerance = offset_tolerance;
    tk::cad::RegionOffset region;
    try {
      region = tk::cad::offset_region(found.loops, *part.index, offset_options);
    } catch (const tk::UsageError&) {
      throw;  // the offset's size, named by its options
    } catch (const tk::Error& e) {
      throw tk::Error(e.what(), {name, e.where().line});  // the library knows the DXF line, not the file
    }
    if (region.polygon_loops > 0)
      warn(std::to_string(region.polygon_loops) + " offset loops stay as polygons (the exact lines and arcs did not check out)");
    if (region.loops.empty())
      warn("the tool fits nowhere in the pocket: every position is prohibited, and there is no contour");
    if (!region.uncut.empty())
      warn(std::to_string(region.uncut.size()) + " stretches of the drawing are out of the tool's reach (records \"uncut\")");

    if (!svg_path.empty()) {
      tk::cad::SvgLayers layers_to_draw;
      layers_to_draw.drawn = &found.loops;
      layers_to_draw.open = &found.open_segments;
      layers_to_draw.region = &region.loops;
      layers_to_draw.loose_ends = &found.loose_ends;
      layers_to_draw.uncut = &region.uncut;
      layers_to_draw.title = fmt::format("dxf2region {}: drawing (black), prohibited region for tool radius {:g} mm (red, its contour blue), "
                                         "out of reach (orange)", name, tool_radius);
      tk::cad::write_region_svg(svg_path, layers_to_draw);
    }

    if (toolpath) {
      if (tool.common().csv) throw tk::UsageError("--toolpath writes G-code: --csv does not apply");
      tk::cad::ToolpathOptions options;
      options.feed = feed;
      options.plunge_feed = plunge_feed;
      options.cut_z = cut_z;
      options.safe_z = safe_z;
      options.climb = direction == "climb";
      options.title = fmt::format("dxf2region {}, tool radius {:g} mm, {}, {}", name, tool_radius, side, direction);
      const std::string gcode = tk::cad::toolpath_gcode(region.loops, options);
      if (std::fwrite(gcode.data(), 1, gcode.size(), stdout) != gcode.size()) throw tk::Error("write error on standard output");
      writer.flush();
      return;
    }
    if (simulate) {
      const auto guard = [&](tk::cad::Point p) { return tk::cad::guard_query(*part.index, p, tool_radius, machining).distance; };
      std::vector<std::vector<tk::cad::Point>> boundary;  // the region on the left of each
      for (const tk::cad::Loop& loop : region.loops) boundary.push_back(tk::cad::flatten_loop(loop, offset_tolerance * 10));
      const tk::cad::SignedDistance printed = [&](tk::cad::Point p) { return tk::cad::interval_line_distance(boundary, p); };
      for (double v : speeds) {
        const tk::cad::InvasionSimOptions options = experiment_at(v);
        const auto results =
            tk::cad::simulate_invasions(guard, boundary, tolerances, options, invasion_check == "printed" ? &printed : nullptr);
        for (const tk::cad::InvasionSimResult& r : results) {
          writer.write(tk::Record{{"guard", r.guard},
                                  {"invasion_check", r.guard == "fixed-tolerance" ? invasion_check : "exact"},
                                  {"tolerance_mm", r.tolerance_mm},
                                  {"strokes", r.strokes},
                                  {"invasions", r.invasions},
                                  {"success_rate", r.success_rate},
                                  {"mean_undercut_mm", r.mean_undercut_mm},
                                  {"max_undercut_mm", r.max_undercut_mm},
                                  {"mean_invasion_mm", r.mean_invasion_mm},
                                  {"max_invasion_mm", r.max_invasion_mm},
                                  {"latency_s", options.latency_s},
                                  {"period_s", options.period_s},
                                  {"joystick_speed_mm_s", v}});
        }
      }
      writer.flush();
      return;
    }
    if (checking) {
      tk::cad::GuardOptions options{tool_radius, machining, latency, margin};
      tk::cad::InvasionGuard guard(*part.index, options, region.contour.get());
      std::vector<std::string> fields{"inside", "distance", "clamped_x", "clamped_y", "element", "entity", "dxf_line", "approach_mm_s", "stop"};
      if (summary)  // CSV: the summary's columns too, empty in the positions' rows
        fields.insert(fields.end(), {"summary", "positions", "invasions", "deepest_invasion_mm", "deepest_x", "deepest_y", "closest_mm", "stops"});
      writer.declare_fields(fields);
      tk::io::RecordReader reader({check_path.empty() ? std::string("-") : check_path});
      reader.expect_columns({{"x", "y"}});
      tk::Record record;
      const auto& elements = part.index->elements();
      while (reader.next(record)) {
        const tk::Location where = reader.where();
        const tk::cad::Point p{tk::io::number_field(record, "x", where), tk::io::number_field(record, "y", where)};
        for (const double v : {p.x, p.y})  // a distance that far out would be all rounding: bad data
          if (!(std::abs(v) <= tk::cad::kMaxCoordinateMm))
            throw tk::Error(fmt::format("position {:g} mm is beyond ±{:g} mm", v, tk::cad::kMaxCoordinateMm), where);
        const std::optional<double> t = tk::io::optional_number_field(record, "t", where);
        tk::cad::PositionCheck c;
        try {
          c = guard.check(p, t);
        } catch (const tk::Error& e) {
          throw tk::Error(e.what(), where);
        }
        record["inside"] = c.answer.distance < 0;
        record["distance"] = c.answer.distance;
        record["clamped_x"] = c.answer.clamped.x;
        record["clamped_y"] = c.answer.clamped.y;
        record["element"] = c.answer.element;
        record["entity"] = elements[c.answer.element].entity;
        record["dxf_line"] = elements[c.answer.element].source_line;
        if (c.approach_mm_s) record["approach_mm_s"] = *c.approach_mm_s;
        if (c.stop) record["stop"] = *c.stop;
        writer.write(record);
      }
      if (summary) {
        const tk::cad::GuardSummary& s = guard.summary();
        tk::Record last{{"summary", true},
                        {"positions", s.positions},
                        {"invasions", s.invasions},
                        {"deepest_invasion_mm", s.deepest_mm}};
        if (s.invasions > 0) {
          last["deepest_x"] = s.deepest_at.x;
          last["deepest_y"] = s.deepest_at.y;
        }
        if (s.positions > 0) last["closest_mm"] = s.closest_mm;
        last["stops"] = s.stops;
        writer.write(last);
      }
      writer.flush();
      return;
    }
    // The region itself.
    for (std::size_t i = 0; i < region.loops.size(); ++i)
      writer.write(tk::cad::loop_record(region.loops[i], i, flatten_tolerance, tool_radius == 0));
    write_findings(region);
    writer.flush();
  });
}
