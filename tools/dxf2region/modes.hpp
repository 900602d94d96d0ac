/// @file modes.hpp
/// @brief dxf2region's modes, one file each (region records, --toolpath,
/// --simulate, --check), and the part and region they all start from;
/// main.cpp wires the options to them.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "cad/invasion_sim.hpp"
#include "cad/part.hpp"
#include "cad/region_offset.hpp"
#include "cli/tool_app.hpp"
#include "io/record_writer.hpp"

namespace dxf2region {

/// The options, as given (main.cpp checks their ranges).
struct Settings {
  std::string part_path, units, side = "outside", svg_path, check_path, direction = "climb";
  std::string invasion_check = "exact";
  std::vector<std::string> layers;
  double tool_radius = 0, join_tolerance = 1e-3, flatten_tolerance = 0.01, offset_tolerance = 1e-4;
  double latency = 0.09, margin = 0.02, feed = 600, plunge_feed = 100, cut_z = -1, safe_z = 5;
  double period = 0.001, latency_mm = 0, period_mm = 0;
  bool travel_latency = false, travel_period = false;  ///< --latency-mm, --period-mm given
  std::uint32_t strokes = 1000;
  std::uint64_t seed = 1;
  bool summary = false;
  bool checking = false;  ///< --check given: the contour's index gets its grid (many barrier points)
  std::vector<double> speeds, tolerances;

  tk::cad::MachiningSide machining() const {
    return side == "inside" ? tk::cad::MachiningSide::inside : tk::cad::MachiningSide::outside;
  }
  /// The seed's experiment at joystick speed `v`, mm/s.
  tk::cad::InvasionSimOptions experiment_at(double v) const;
};

/// The part read, its name for messages, and the prohibited region.
struct Job {
  tk::cad::Part part;
  std::string name;  ///< the file, or <stdin>
  std::size_t doubled_edges = 0;
  tk::cad::RegionOffset region;
};

/// Reads the part and offsets it, warning of what the drawing leaves out,
/// and draws --svg. In the region mode (`region_mode`) the writer gets the
/// region's fields, and a drawing with no closed loop still gets what was
/// found in it before the error.
Job prepare(const Settings& settings, tk::io::RecordWriter& writer, bool region_mode, tk::cli::ToolApp& tool);

/// The default mode: the region's loops, then what was found in the drawing.
void write_region(const Settings& settings, const Job& job, tk::io::RecordWriter& writer, tk::cli::ToolApp& tool);
/// What was found in the drawing (loose ends, T-junctions, uncut spans) and its totals.
void write_findings(const Settings& settings, const Job& job, const tk::cad::RegionOffset& region,
                    tk::io::RecordWriter& writer, tk::cli::ToolApp& tool);

/// --toolpath: the finishing contour as G-code.
void write_toolpath(const Settings& settings, const Job& job, tk::io::RecordWriter& writer, tk::cli::ToolApp& tool);

/// --simulate: the seed's invasion experiment per joystick speed.
void simulate(const Settings& settings, const Job& job, tk::io::RecordWriter& writer);

/// --check: the guard over a stream of tool positions.
void check_positions(const Settings& settings, const Job& job, tk::io::RecordWriter& writer);

}  // namespace dxf2region
