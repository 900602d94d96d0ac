/// @file svg_marks.hpp
/// @brief What the toolkit's SVG writers share: escaped text, steps on a
/// 1-2-5 series and numbers written plainly (1000, 0.002, never 1e+03),
/// a legend of swatches and labels, and a labelled scale bar.
#pragma once

#include <string>
#include <vector>

namespace tk::sim {

/// `text` with &, <, > and " escaped, for SVG text and attribute values.
std::string xml_escape(const std::string& text);

/// A step of 1, 2 or 5 times a power of ten giving about `ticks` ticks over `span` (> 0).
double nice_step(double span, int ticks);

/// The 1, 2 or 5 times a power of ten nearest to `length` (> 0) by ratio:
/// a round length for a scale bar.
double nearest_125(double length);

/// `value` in fixed notation with as many decimals as `step` needs (0.25
/// two, 1000 none): tick labels on a grid of that step read as plain numbers.
std::string plain_number(double value, double step);

/// One row of a legend: a mark drawn with `style` (SVG presentation
/// attributes, e.g. `stroke="red" stroke-width="2"`) and its label.
struct LegendEntry {
  enum class Mark { line, area, dot } mark = Mark::line;
  std::string style = {};
  std::string label = {};
};

/// The legend as an SVG group of class "legend", one row per entry, `font_size`
/// high (in the drawing's units), its top left corner at (x, y).
std::string svg_legend(const std::vector<LegendEntry>& entries, double x, double y, double font_size);

/// The height svg_legend takes for `rows` entries.
double legend_height(std::size_t rows, double font_size);

/// A rough width of `text` at `font_size` in a sans-serif face, for making room.
double text_width(const std::string& text, double font_size);

/// A scale bar of class "scale-bar": a line `length_mm` long drawn at
/// `units_per_mm` drawing units per mm, ticks at its ends and "N mm" above
/// it; (x, y) is its left end, the label takes `font_size` above that.
std::string svg_scale_bar(double length_mm, double units_per_mm, double x, double y, double font_size, double stroke);

}  // namespace tk::sim
