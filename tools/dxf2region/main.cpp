/// @file main.cpp
/// @brief dxf2region: a DXF part profile to the prohibited region for a
/// round tool, its finishing contour as G-code, the invasion check of a
/// stream of tool positions, and the seed's latency experiment.
#include <fmt/format.h>

#include <algorithm>

#include "cad/invasion_sim.hpp"
#include "cad/part.hpp"
#include "cli/number_option.hpp"
#include "cli/option_checks.hpp"
#include "cli/tool_app.hpp"
#include "io/error.hpp"
#include "modes.hpp"

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
  dxf2region::Settings s;
  std::string tolerances_text = "1,2,3,4,4.5,5", speeds_text = "12,18";
  bool toolpath = false, simulate = false;
  CLI::App& app = tool.app();
  app.add_option("part", s.part_path, "the DXF file ('-' for standard input)")->required()->type_name("PART.dxf");
  app.add_option("--layer", s.layers, "use only this layer (again for more)")->type_name("L");
  app.add_option("--units", s.units, "the drawing's unit when $INSUNITS is 0 or absent: mm, cm, m, in, ft, ...")
      ->type_name("U");
  app.add_option("--join-tol", s.join_tolerance, "ends closer than this meet, mm")
      ->capture_default_str()
      ->type_name("MM");
  app.add_option("--tool-radius", s.tool_radius, "grow the part (or shrink the pocket) by the tool's radius, mm")
      ->capture_default_str()
      ->type_name("R");
  app.add_option("--side", s.side, "outside: the tool works around the part; inside: in a pocket")
      ->check(CLI::IsMember({"outside", "inside"}))
      ->capture_default_str();
  app.add_option("--svg", s.svg_path, "draw the drawing, the region and what was found in it")->type_name("FILE");
  app.add_option("--flatten-tol", s.flatten_tolerance, "chord tolerance of the loops' polylines in the records, mm")
      ->capture_default_str()
      ->type_name("MM");
  app.add_option("--offset-tol", s.offset_tolerance, "tolerance of the offset's polygon stage, mm")
      ->capture_default_str()
      ->type_name("MM");
  auto* check = app.add_option("--check", s.check_path,
                               "check tool positions (records with x, y and optionally t); standard input when no file")
                    ->expected(0, 1)
                    ->type_name("[POSITIONS]");
  app.add_flag("--summary", s.summary, "with --check: a final record (positions, invasions, deepest invasion)");
  auto* latency_option =
      app.add_option("--latency", s.latency,
                     "with --check and times, --simulate: seconds from a sample to a stop taking effect")
          ->capture_default_str()
          ->type_name("S");
  app.add_option("--margin", s.margin, "the latency-aware guard's aim, mm")->capture_default_str()->type_name("MM");
  app.add_flag("--toolpath", toolpath, "write the finishing contour as G-code");
  app.add_option("--feed", s.feed, "contour feed, mm/min")->capture_default_str()->type_name("F");
  app.add_option("--plunge-feed", s.plunge_feed, "feed going down, mm/min")->capture_default_str()->type_name("F");
  app.add_option("--cut-z", s.cut_z, "Z of the cut, mm")->capture_default_str()->type_name("Z");
  app.add_option("--safe-z", s.safe_z, "Z of rapid moves, mm")->capture_default_str()->type_name("Z");
  app.add_option("--direction", s.direction, "climb (material on the right) or conventional")
      ->check(CLI::IsMember({"climb", "conventional"}))
      ->capture_default_str();
  app.add_flag("--simulate", simulate, "run the seed's invasion experiment against the region");
  app.add_option("--tolerances", tolerances_text,
                 "with --simulate: the fixed guard's tolerances, mm (the seed's Tables 2-3)")
      ->capture_default_str()
      ->type_name("T,...");
  app.add_option("--joystick-speed", speeds_text, "with --simulate: the operator's feeds, mm/s (the seed's Table 2)")
      ->capture_default_str()
      ->type_name("V,...");
  auto* period_option =
      app.add_option("--period", s.period, "with --simulate: control period, s")->capture_default_str()->type_name("S");
  auto* latency_mm_option =
      app.add_option("--latency-mm", s.latency_mm,
                     "with --simulate: the latency as travel at each feed, mm (instead of --latency)")
          ->type_name("MM")
          ->excludes(latency_option);
  auto* period_mm_option =
      app.add_option("--period-mm", s.period_mm,
                     "with --simulate: the control period as travel at each feed, mm (instead of --period)")
          ->type_name("MM")
          ->excludes(period_option);
  app.add_option(
         "--invasion-check", s.invasion_check,
         "with --simulate: what the fixed guard compares with T: the exact distance, or the seed's eq. (2) (printed)")
      ->check(CLI::IsMember({"exact", "printed"}))
      ->capture_default_str();
  app.add_option("--strokes", s.strokes, "with --simulate: approaches per guard")
      ->capture_default_str()
      ->type_name("N");
  app.add_option("--seed", s.seed, "with --simulate: random seed of the strokes")
      ->capture_default_str()
      ->type_name("N");

  return tool.run(argc, argv, [&] {
    const bool checking = s.checking = check->count() > 0;
    if (checking + toolpath + simulate > 1)
      throw tk::UsageError("--check, --toolpath and --simulate exclude each other");
    if (s.summary && !checking) throw tk::UsageError("--summary goes with --check");
    // The ranges dxf2region(1) gives under OPTIONS: a metre-radius tool is
    // past the largest face mill; an offset tolerance finer than 0.1 um is
    // below any machine's resolution and slows the offset without bound.
    using tk::cli::require_range;
    require_range(s.tool_radius, 0, 1000, "--tool-radius");
    require_range(s.join_tolerance, 1e-6, 10, "--join-tol");
    require_range(s.flatten_tolerance, 1e-6, 10, "--flatten-tol");
    require_range(s.offset_tolerance, 1e-4, 1, "--offset-tol");
    require_range(s.latency, 0, 10, "--latency");
    require_range(s.margin, 0, 100, "--margin");
    require_range(s.period, 1e-6, 1, "--period");
    require_range(s.feed, 0.1, 1e5, "--feed");
    require_range(s.plunge_feed, 0.1, 1e5, "--plunge-feed");
    require_range(s.cut_z, -1e4, 1e4, "--cut-z");
    require_range(s.safe_z, -1e4, 1e4, "--safe-z");
    require_range(s.strokes, 1, 1e6, "--strokes");
    s.travel_latency = latency_mm_option->count() > 0, s.travel_period = period_mm_option->count() > 0;
    if (!simulate && (s.travel_latency || s.travel_period || s.invasion_check != "exact"))
      throw tk::UsageError("--latency-mm, --period-mm and --invasion-check go with --simulate");
    if (s.travel_latency) require_range(s.latency_mm, 0, 1000, "--latency-mm");
    if (s.travel_period) require_range(s.period_mm, 1e-4, 1000, "--period-mm");
    s.speeds = number_list(speeds_text, "--joystick-speed");
    s.tolerances = number_list(tolerances_text, "--tolerances");
    for (const double tolerance : s.tolerances) require_range(tolerance, 0, 1000, "--tolerances");
    if (simulate)
      for (double v : s.speeds) {
        require_range(v, 0.01, 1e4, "--joystick-speed");
        try {
          tk::cad::check_invasion_sim(s.tolerances, s.experiment_at(v));
        } catch (const tk::Error& e) {
          throw tk::UsageError(std::string("--simulate: ") + e.what());
        }
      }
    if (!s.units.empty()) {
      try {
        tk::cad::millimetres_per_named_unit(s.units);
      } catch (const tk::Error& e) {
        throw tk::UsageError(std::string("--units: ") + e.what());
      }
    }
    tk::io::RecordWriter writer(tool.output_format());
    const bool region_mode = !checking && !toolpath && !simulate;
    const dxf2region::Job job = dxf2region::prepare(s, writer, region_mode, tool);
    if (toolpath) dxf2region::write_toolpath(s, job, writer, tool);
    else if (simulate) dxf2region::simulate(s, job, writer);
    else if (checking) dxf2region::check_positions(s, job, writer);
    else dxf2region::write_region(s, job, writer, tool);
  });
}
