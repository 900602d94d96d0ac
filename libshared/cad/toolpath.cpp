/// @file toolpath.cpp
/// @brief G-code for the finishing contour.
#include "cad/toolpath.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "cad/segment_geometry.hpp"
#include "io/error.hpp"
#include "motion/gcode_writer.hpp"

namespace tk::cad {
namespace {

using motion::PrintedNumber;

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
  if (!(options.feed > 0) || !(options.plunge_feed > 0) || !std::isfinite(options.feed) ||
      !std::isfinite(options.plunge_feed))
    throw Error("toolpath: feeds must be positive and finite");
  if (!(options.safe_z > options.cut_z)) throw Error("toolpath: the safe height must be above the cut depth");
  motion::GcodeWriter out(motion::kFixedMicrons);
  const auto mm = [&](double value) { return out.number(value); };
  if (!options.title.empty()) out.comment(options.title);
  out.line("G21 G90 G91.1 G17 G94", "mm, absolute, incremental arc centres, XY plane, feed per minute");
  out.line("G0 Z" + mm(options.safe_z));
  for (std::size_t i = 0; i < loops.size(); ++i) {
    std::vector<Segment> path = loops[i].segments;
    if (path.empty()) continue;
    // The loops have the region (material) on their left: climb milling goes the other way round.
    if (options.climb) reverse_chain(path);
    out.comment(fmt::format("loop {}{}", i, loops[i].is_hole() ? ", a hole" : ""));
    PrintedNumber x = out.printed(path.front().start.x), y = out.printed(path.front().start.y);
    out.line("G0 X" + x.text + " Y" + y.text);
    out.line("G1 Z" + mm(options.cut_z) + " F" + mm(options.plunge_feed));
    bool feed_set = false;
    for (const Segment& s : path) {
      // Everything from the position as printed, so that each piece starts
      // where the control stands.
      const Point from{x.value, y.value};
      const PrintedNumber end_x = out.printed(s.end.x), end_y = out.printed(s.end.y);
      if (end_x.text == x.text && end_y.text == y.text) continue;  // no motion at the printed resolution
      std::string line;
      if (is_arc(s)) {
        const ArcShape arc = arc_shape(s);
        const PrintedNumber i_word = out.printed(arc.centre.x - from.x), j_word = out.printed(arc.centre.y - from.y);
        const Point centre{from.x + i_word.value, from.y + j_word.value};
        if (!write_as_line(s, from, {end_x.value, end_y.value}, centre))
          line = (arc.sweep > 0 ? "G3 X" : "G2 X") + end_x.text + " Y" + end_y.text + " I" + i_word.text + " J" +
                 j_word.text;
      }
      if (line.empty()) line = "G1 X" + end_x.text + " Y" + end_y.text;
      if (!feed_set) line += " F" + mm(options.feed);
      feed_set = true;
      out.line(line);
      x = end_x;
      y = end_y;
    }
    out.line("G0 Z" + mm(options.safe_z));
  }
  out.line("M2");
  return out.text();
}

}  // namespace tk::cad
