/// @file svg_marks.cpp
#include "sim/svg_marks.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace tk::sim {

std::string xml_escape(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

double nice_step(double span, int ticks) {
  const double raw = span / ticks, power = std::pow(10, std::floor(std::log10(raw)));
  for (const double m : {1.0, 2.0, 5.0})
    if (m * power >= raw) return m * power;
  return 10 * power;
}

double nearest_125(double length) {
  const double power = std::pow(10, std::floor(std::log10(length)));
  double best = power;
  for (const double m : {2.0, 5.0, 10.0})
    if (std::abs(std::log(m * power / length)) < std::abs(std::log(best / length))) best = m * power;
  return best;
}

std::string plain_number(double value, double step) {
  // The fewest decimals that write the step exactly (to 1e-6 of it); at most 12.
  int decimals = 0;
  for (double scaled = std::abs(step); decimals < 12 && std::abs(scaled - std::round(scaled)) > 1e-6 * std::abs(scaled);
       scaled *= 10)
    ++decimals;
  if (std::abs(value) < std::abs(step) * 1e-9) value = 0;  // not -0.000 from rounding noise
  return fmt::format("{:.{}f}", value, decimals);
}

double legend_height(std::size_t rows, double font_size) { return static_cast<double>(rows) * 1.6 * font_size; }

double text_width(const std::string& text, double font_size) {
  return 0.6 * font_size * static_cast<double>(text.size());
}

std::string svg_legend(const std::vector<LegendEntry>& entries, double x, double y, double font_size) {
  const double row = 1.6 * font_size, swatch = 2.5 * font_size;
  std::string svg = fmt::format("<g class=\"legend\" font-family=\"sans-serif\" font-size=\"{:.4g}\">\n", font_size);
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const LegendEntry& entry = entries[i];
    const double middle = y + (static_cast<double>(i) + 0.5) * row;
    switch (entry.mark) {
      case LegendEntry::Mark::line:
        svg += fmt::format("<line x1=\"{:.6g}\" y1=\"{:.6g}\" x2=\"{:.6g}\" y2=\"{:.6g}\" {}/>", x, middle, x + swatch,
                           middle, entry.style);
        break;
      case LegendEntry::Mark::area:
        svg += fmt::format("<rect x=\"{:.6g}\" y=\"{:.6g}\" width=\"{:.6g}\" height=\"{:.6g}\" {}/>", x,
                           middle - 0.45 * font_size, swatch, 0.9 * font_size, entry.style);
        break;
      case LegendEntry::Mark::dot:
        svg += fmt::format("<circle cx=\"{:.6g}\" cy=\"{:.6g}\" r=\"{:.6g}\" {}/>", x + swatch / 2, middle,
                           0.35 * font_size, entry.style);
        break;
    }
    svg += fmt::format("<text x=\"{:.6g}\" y=\"{:.6g}\">{}</text>\n", x + swatch + 0.6 * font_size,
                       middle + 0.35 * font_size, xml_escape(entry.label));
  }
  return svg + "</g>\n";
}

std::string svg_scale_bar(double length_mm, double units_per_mm, double x, double y, double font_size, double stroke) {
  const double x1 = x + length_mm * units_per_mm, tick = 0.4 * font_size;
  return fmt::format(
      "<g class=\"scale-bar\" stroke=\"black\" stroke-width=\"{4:.4g}\">"
      "<line x1=\"{0:.6g}\" y1=\"{2:.6g}\" x2=\"{1:.6g}\" y2=\"{2:.6g}\"/>"
      "<line x1=\"{0:.6g}\" y1=\"{5:.6g}\" x2=\"{0:.6g}\" y2=\"{6:.6g}\"/><line x1=\"{1:.6g}\" y1=\"{5:.6g}\" "
      "x2=\"{1:.6g}\" y2=\"{6:.6g}\"/>"
      "<text x=\"{7:.6g}\" y=\"{8:.6g}\" stroke=\"none\" text-anchor=\"middle\" font-family=\"sans-serif\" "
      "font-size=\"{3:.4g}\">{9} mm</text>"
      "</g>\n",
      x, x1, y, font_size, stroke, y - tick, y + tick, (x + x1) / 2, y - 0.6 * font_size,
      plain_number(length_mm, length_mm));
}

}  // namespace tk::sim
