/// @file part.hpp
/// @brief A part as dxf2region works on it: the drawing read, the chosen
/// layers kept, scaled to millimetres, chained into loops and indexed.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "cad/drawing.hpp"
#include "cad/loops.hpp"
#include "cad/region_distance.hpp"

namespace tk::cad {

struct PartOptions {
  std::vector<std::string> layers;  ///< keep only these (all when empty)
  std::string units;                ///< the drawing's unit when $INSUNITS is 0 or absent ("mm", "in", ...)
  double join_tolerance = 1e-3;     ///< mm: ends closer than this meet
  double chord_tolerance = 1e-3;    ///< drawing units: ELLIPSE and SPLINE flattening
};

/// Coordinates (drawing and tool positions) beyond ±1e9 mm, 1000 km, are
/// not a part: bad data. The bound keeps the offset's integer polygon stage
/// and every distance far inside double and 64-bit range.
inline constexpr double kMaxCoordinateMm = 1e9;

struct Part {
  Drawing drawing;  ///< in mm, only the chosen layers' segments
  double millimetres_per_unit = 1;
  std::string units_source;  ///< "$INSUNITS", "--units" or "assumed"
  LoopSet loops;
  std::unique_ptr<RegionIndex> index;  ///< over loops.loops
};

/// Millimetres per unit for a unit name (mm, cm, m, in, ft, um, ...);
/// Error listing the names otherwise.
double millimetres_per_named_unit(const std::string& name);

/// Reads and prepares `path`; `warn` receives what the user should know
/// (units assumed, layers missing from the selection ...). Error when a
/// chosen layer does not exist.
Part load_part(const std::string& path, const PartOptions& options,
               const std::function<void(const std::string&)>& warn);

}  // namespace tk::cad
