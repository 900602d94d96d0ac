/// @file toolpath.cpp
/// @brief G-code for the finishing contour.
#include "cad/toolpath.hpp"

#include <fmt/format.h>

#include <cmath>

#include "cad/segment_geometry.hpp"
#include "io/error.hpp"

namespace tk::cad {
namespace {

/// Six decimals, without "-0.000000".
std::string mm(double value) {
  std::string text = fmt::format("{:.6f}", value);
  if (text == "-0.000000") text = "0.000000";
  return text;
}

void check(double value, const char* what) {
  if (!std::isfinite(value)) throw Error(std::string("toolpath: ") + what + " must be finite");
}

}  // namespace

std::string toolpath_gcode(const std::vector<Loop>& loops, const ToolpathOptions& options) {
  check(options.cut_z, "the cut depth");
  check(options.safe_z, "the safe height");
  if (!(options.feed > 0) || !(options.plunge_feed > 0) || !std::isfinite(options.feed) || !std::isfinite(options.plunge_feed))
    throw Error("toolpath: feeds must be positive and finite");
  if (!(options.safe_z > options.cut_z)) throw Error("toolpath: the safe height must be above the cut depth");
  std::string out;
  if (!options.title.empty()) out += "(" + options.title + ")\n";
  out += "G21 G90 G91.1 G17 G94 (mm, absolute, incremental arc centres, XY plane, feed per minute)\n";
  out += "G0 Z" + mm(options.safe_z) + "\n";
  for (std::size_t i = 0; i < loops.size(); ++i) {
    std::vector<Segment> path = loops[i].segments;
    if (path.empty()) continue;
    // The loops have the region (material) on their left: climb milling goes the other way round.
    if (options.climb) reverse_chain(path);
    out += fmt::format("(loop {}{})\n", i, loops[i].is_hole() ? ", a hole" : "");
    out += "G0 X" + mm(path.front().start.x) + " Y" + mm(path.front().start.y) + "\n";
    out += "G1 Z" + mm(options.cut_z) + " F" + mm(options.plunge_feed) + "\n";
    bool feed_set = false;
    for (const Segment& s : path) {
      std::string line;
      if (is_arc(s)) {
        const ArcShape arc = arc_shape(s);
        line = (arc.sweep > 0 ? "G3 X" : "G2 X") + mm(s.end.x) + " Y" + mm(s.end.y) + " I" + mm(arc.centre.x - s.start.x) +
               " J" + mm(arc.centre.y - s.start.y);
      } else {
        line = "G1 X" + mm(s.end.x) + " Y" + mm(s.end.y);
      }
      if (!feed_set) line += " F" + mm(options.feed);
      feed_set = true;
      out += line + "\n";
    }
    out += "G0 Z" + mm(options.safe_z) + "\n";
  }
  out += "M2\n";
  return out;
}

}  // namespace tk::cad
