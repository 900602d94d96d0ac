/// @file time_panels_svg.hpp
/// @brief Signals of a simulation against time as SVG: panels stacked over
/// one shared time axis, each with its own y-axis, polylines with a legend
/// and horizontal reference lines or bands. A long series is reduced to its
/// minimum and maximum per pixel column, so the envelope of a fast
/// oscillation stays visible in a file of modest size.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "sim/svg_marks.hpp"

namespace tk::sim {

/// Sample i of a signal (or of the time). The owner keeps its own sample
/// records and hands out accessors, so a run of millions of samples is not
/// copied once per series.
using SampleValue = std::function<double(std::size_t)>;

/// The accessor of one field of the owner's records (read at drawing time).
template <class Record>
SampleValue field_of(const std::vector<Record>& records, double Record::*field) {
  return [&records, field](std::size_t i) { return records[i].*field; };
}

// Every member has an initialiser (`= {}` too), so designated initialisers
// may leave any out without -Wmissing-field-initializers.

struct PlotSeries {
  SampleValue value = {};
  std::string colour = "#1b1b1b";
  double width = 1.2;
  std::string label = {};  ///< its entry in the panel's legend; empty: none
};

/// A dashed line at `low` when high == low, else a shaded band from low to high.
struct PlotLevel {
  double low = 0, high = 0;
  std::string colour = "#c8281e";
  std::string label = {};  ///< written above the right end; empty: none
};

struct TimePanel {
  std::string y_label = {};
  std::vector<PlotSeries> series = {};  ///< drawn in order, later ones on top
  std::vector<PlotLevel> levels = {};   ///< drawn under the series
  /// from_data: the data's extent (and the levels') widened to whole ticks;
  /// symmetric: the same, made symmetric round zero; fixed: y_min..y_max,
  /// values outside drawn at the edge.
  enum class Range { from_data, symmetric, fixed } range = Range::from_data;
  double y_min = 0, y_max = 1;
  double y_step = 0;  ///< between ticks; 0: a 1-2-5 step giving about six
};

struct TimePanelsPlot {
  std::string title = {};
  std::size_t samples = 0;
  SampleValue time_s = {};  ///< non-decreasing; the axis runs from min(0, first) to the last
  std::vector<TimePanel> panels = {};
  double panel_height = 250;  ///< pixels
  std::string time_label = "time t, s";
};

/// The drawing as SVG text.
std::string time_panels_svg(const TimePanelsPlot& plot);

/// Writes the drawing to `path` atomically; throws tk::Error naming `path`
/// when it cannot.
void write_time_panels_svg(const std::string& path, const TimePanelsPlot& plot);

}  // namespace tk::sim
