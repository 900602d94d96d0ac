/// @file drawing.hpp
/// @brief A 2D drawing as the CAD side of the toolkit sees it: every
/// supported DXF entity reduced to lines and circular arcs in the XY plane
/// of the world coordinate system, in the drawing's own units, each piece
/// remembering where it came from.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace tk::cad {

struct Point {
  double x = 0, y = 0;
};

/// A line (bulge 0) or a circular arc from `start` to `end`. The bulge is
/// tan(sweep / 4), positive counter-clockwise, as in a DXF LWPOLYLINE: 1 is
/// a half circle, and |bulge| < 1 less than one. A full circle is two arcs.
struct Segment {
  Point start, end;
  double bulge = 0;
  std::uint32_t layer = 0;      ///< index into Drawing::layers
  std::uint32_t entity = 0;     ///< 0-based index of the source entity in the file
  std::size_t source_line = 0;  ///< line of the file where that entity starts (0 for binary DXF)
  bool flattened = false;       ///< a chord of an ELLIPSE or SPLINE
};

/// Everything read from one file.
struct Drawing {
  std::vector<Segment> segments;
  std::vector<std::string> layers;                      ///< names as written, in order of first use
  std::map<std::string, std::size_t> entities_read;     ///< supported entity type -> how many
  std::map<std::string, std::size_t> entities_skipped;  ///< other entity types (TEXT, INSERT, ...) -> how many
  std::string version;                                  ///< $ACADVER, e.g. "AC1015"; empty when absent
  int insunits = 0;                                     ///< $INSUNITS, 0 when absent
  bool binary = false;                                  ///< read from binary DXF
};

/// Millimetres per drawing unit for a $INSUNITS code (1 inch, 2 feet, 4 mm,
/// 5 cm, 6 m, ...), or 0 for 0 (unitless) and codes that name no length.
double millimetres_per_unit(int insunits);

}  // namespace tk::cad
