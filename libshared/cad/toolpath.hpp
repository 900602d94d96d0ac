/// @file toolpath.hpp
/// @brief The finishing contour as G-code: a G0 approach above each loop,
/// a plunge, the loop in G1/G2/G3 at the feed, a retract. RS274/NGC as
/// LinuxCNC and grbl read it, and as gcode-pulse runs it.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "cad/loops.hpp"

namespace tk::cad {

struct ToolpathOptions {
  double feed = 600;         ///< mm/min along the contour
  double plunge_feed = 100;  ///< mm/min going down
  double cut_z = -1;         ///< mm
  double safe_z = 5;         ///< mm, for G0 moves
  bool climb = true;         ///< material on the right of the travel (clockwise spindle)
  std::string title;         ///< written as a comment at the top (any text)
};

/// `loops` have the prohibited region on their left (RegionOffset::loops).
/// Coordinates in mm, six decimals; arcs with incremental centres (I, J)
/// from the position as printed. An arc whose sagitta is at most half a
/// printed micrometre, or whose sweep from the printed numbers is under
/// 1e-5 rad (LinuxCNC cuts a whole circle under 1e-6), is written as a G1 to
/// its end; a piece that does not move at the printed resolution is left
/// out. Written through motion::GcodeWriter (kFixedMicrons).
std::string toolpath_gcode(const std::vector<Loop>& loops, const ToolpathOptions& options);

}  // namespace tk::cad
