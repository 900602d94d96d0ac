/// @file toolpath.cpp
/// @brief G-code for the finishing contour.
#include "cad/toolpath.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <numbers>

#include "cad/segment_geometry.hpp"
#include "io/error.hpp"
#include "motion/gcode_comment.hpp"

namespace tk::cad {
namespace {

/// Six decimals, without "-0.000000".
std::string mm(double value) {
  std::string text = fmt::format("{:.6f}", value);
  if (text == "-0.000000") text = "0.000000";
  return text;
}

/// A coordinate as written and as a control reads it back.
struct Printed {
  std::string text;
  double value;
};

Printed printed(double value) {
  std::string text = mm(value);
  const double read_back = std::strtod(text.c_str(), nullptr);
  return {std::move(text), read_back};
}

/// Half of the printed micrometre: an arc whose chord stays this close to it
/// is as well served by a line.
constexpr double kHalfResolutionMm = 0.5e-6;
/// LinuxCNC 2.8 cuts a whole circle for an arc under 1e-6 rad; ten times
/// that leaves room for the reader's own rounding.
constexpr double kShortestSweepRad = 1e-5;

/// Whether the arc `s`, written from `from` (the printed position) to
/// `to` around `centre` (both as printed), goes out as a G1 to its end:
/// when its sagitta is within half the printed resolution, or when its
/// sweep as the printed numbers give it is under kShortestSweepRad.
bool write_as_line(const Segment& s, Point from, Point to, Point centre) {
  const ArcShape arc = arc_shape(s);
  const double sweep = std::abs(arc.sweep);
  if (arc.radius * (1 - std::cos(std::min(sweep, std::numbers::pi) / 2)) <= kHalfResolutionMm) return true;
  // Rounding moves the ends by a micrometre at most: it can only make an arc
  // of a few microradians look shorter (or reversed), never a larger one.
  if (sweep >= std::numbers::pi / 2) return false;
  const double ux = from.x - centre.x, uy = from.y - centre.y, vx = to.x - centre.x, vy = to.y - centre.y;
  const double printed_sweep = std::atan2(ux * vy - uy * vx, ux * vx + uy * vy);  // counter-clockwise, near 0
  return (arc.sweep > 0 ? printed_sweep : -printed_sweep) < kShortestSweepRad;
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
  if (!options.title.empty()) out += motion::gcode_comment(options.title) + "\n";
  out += "G21 G90 G91.1 G17 G94 " + motion::gcode_comment("mm, absolute, incremental arc centres, XY plane, feed per minute") + "\n";
  out += "G0 Z" + mm(options.safe_z) + "\n";
  for (std::size_t i = 0; i < loops.size(); ++i) {
    std::vector<Segment> path = loops[i].segments;
    if (path.empty()) continue;
    // The loops have the region (material) on their left: climb milling goes the other way round.
    if (options.climb) reverse_chain(path);
    out += motion::gcode_comment(fmt::format("loop {}{}", i, loops[i].is_hole() ? ", a hole" : "")) + "\n";
    Printed x = printed(path.front().start.x), y = printed(path.front().start.y);
    out += "G0 X" + x.text + " Y" + y.text + "\n";
    out += "G1 Z" + mm(options.cut_z) + " F" + mm(options.plunge_feed) + "\n";
    bool feed_set = false;
    for (const Segment& s : path) {
      // Everything from the position as printed, so that each piece starts
      // where the control stands.
      const Point from{x.value, y.value};
      const Printed end_x = printed(s.end.x), end_y = printed(s.end.y);
      if (end_x.text == x.text && end_y.text == y.text) continue;  // no motion at the printed resolution
      std::string line;
      if (is_arc(s)) {
        const ArcShape arc = arc_shape(s);
        const Printed i_word = printed(arc.centre.x - from.x), j_word = printed(arc.centre.y - from.y);
        const Point centre{from.x + i_word.value, from.y + j_word.value};
        if (!write_as_line(s, from, {end_x.value, end_y.value}, centre))
          line = (arc.sweep > 0 ? "G3 X" : "G2 X") + end_x.text + " Y" + end_y.text + " I" + i_word.text + " J" + j_word.text;
      }
      if (line.empty()) line = "G1 X" + end_x.text + " Y" + end_y.text;
      if (!feed_set) line += " F" + mm(options.feed);
      feed_set = true;
      out += line + "\n";
      x = end_x;
      y = end_y;
    }
    out += "G0 Z" + mm(options.safe_z) + "\n";
  }
  out += "M2\n";
  return out;
}

}  // namespace tk::cad
