/// @file region_output.hpp
/// @brief The region as records (loops of lines and arcs with a flattened
/// polyline, and what the chaining and the offset found); its drawing is
/// in region_svg.hpp.
#pragma once

#include <string>
#include <vector>

#include "cad/loops.hpp"
#include "cad/part.hpp"
#include "cad/region_offset.hpp"
#include "io/record.hpp"

namespace tk::cad {

/// Every field a region record may have, in output order (for CSV).
std::vector<std::string> region_record_fields();

/// One record per loop: {"record":"loop", "loop", "depth", "hole",
/// "area_mm2", "length_mm", "elements": [{"type":"line"|"arc", "x0", "y0",
/// "x1", "y1", arcs also "cx", "cy", "r", "bulge"; drawn elements "entity",
/// "dxf_line"}], "polyline": [[x, y], ...]} with the polyline's chords
/// within `flatten_tolerance` of the curve.
Record loop_record(const Loop& loop, std::size_t number, double flatten_tolerance, bool with_sources);
Record loose_end_record(const LooseEnd& end);
Record t_junction_record(const TJunction& junction);
Record uncut_record(const UncutSpan& span);
/// The last record: {"record":"drawing", "version", "units", "mm_per_unit",
/// "entities_read": {type: n}, "entities_skipped": {type: n}, "loops",
/// "holes", "open_segments", "loose_ends", "t_junctions", "uncut",
/// "polygon_loops"}.
Record drawing_record(const Part& part, const RegionOffset& region);

}  // namespace tk::cad
