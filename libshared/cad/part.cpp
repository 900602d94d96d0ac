/// @file part.cpp
/// @brief Reading a part: layers, units, loops, index.
#include "cad/part.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "cad/dxf_reader.hpp"
#include "cad/segment_geometry.hpp"
#include "io/error.hpp"

namespace tk::cad {
namespace {

/// Unit names for --units, as their $INSUNITS codes (one table of lengths: units.cpp).
const std::pair<const char*, int> kUnits[] = {
    {"mm", 4}, {"cm", 5}, {"dm", 14}, {"m", 6}, {"um", 13}, {"in", 1}, {"inch", 1}, {"ft", 2}, {"mil", 9},
};

}  // namespace

double millimetres_per_named_unit(const std::string& name) {
  std::string known;
  for (const auto& [unit, code] : kUnits) {
    if (name == unit) return millimetres_per_unit(code);
    known += known.empty() ? unit : std::string(", ") + unit;
  }
  throw Error("unknown unit '" + name + "' (known: " + known + ")");
}

namespace {
/// An entity all of whose segments are shorter than the join tolerance
/// vanishes from the loops (a closed polyline too): say so, once per entity.
void warn_vanishing_entities(const std::vector<Segment>& segments, double join_tolerance, const std::string& name,
                             const std::function<void(const std::string&)>& warn) {
  std::map<std::uint32_t, std::pair<std::size_t, bool>> entities;  // entity -> line, every segment short
  for (const Segment& s : segments) {
    auto [it, fresh] = entities.try_emplace(s.entity, s.source_line, true);
    if (!(segment_length(s) < join_tolerance)) it->second.second = false;
  }
  for (const auto& [entity, state] : entities)
    if (state.second && warn)
      warn(fmt::format("{}:{}: entity {} vanishes: every segment of it is shorter than --join-tol {:g} mm", name,
                       state.first, entity, join_tolerance));
}
}  // namespace

Part load_part(const std::string& path, const PartOptions& options,
               const std::function<void(const std::string&)>& warn) {
  Part part;
  const double given = options.units.empty() ? 0 : millimetres_per_named_unit(options.units);
  DxfReadOptions read_options;
  read_options.chord_tolerance = options.chord_tolerance;  // in the drawing's units: they are not known before reading
  part.drawing = read_dxf_file(path, read_options);
  Drawing& d = part.drawing;
  const std::string name = path == "-" ? "<stdin>" : path;
  const double declared = millimetres_per_unit(d.insunits);
  if (declared > 0) {
    part.millimetres_per_unit = declared;
    part.units_source = "$INSUNITS";
    if (given > 0 && given != declared)
      warn(name + ": $INSUNITS says " + std::to_string(declared) + " mm per unit: --units " + options.units +
           " is not used");
  } else if (given > 0) {
    part.millimetres_per_unit = given;
    part.units_source = "--units";
  } else {
    part.units_source = "assumed";
    warn(name + ": the drawing does not say its unit ($INSUNITS " + std::to_string(d.insunits) +
         "): taking millimetres (--units to say otherwise)");
  }
  // The chosen layers only.
  if (!options.layers.empty()) {
    std::vector<bool> keep(d.layers.size(), false);
    for (const std::string& layer : options.layers) {
      const auto found = std::find(d.layers.begin(), d.layers.end(), layer);
      if (found == d.layers.end()) {
        std::string list;
        for (const std::string& l : d.layers) list += (list.empty() ? "" : ", ") + l;
        throw Error("no layer '" + layer + "' with supported entities (layers: " + (list.empty() ? "none" : list) + ")",
                    {name, 0});
      }
      keep[found - d.layers.begin()] = true;
    }
    std::erase_if(d.segments, [&](const Segment& s) { return !keep[s.layer]; });
  }
  const double k = part.millimetres_per_unit;
  if (k != 1) {
    for (Segment& s : d.segments) {
      s.start = {s.start.x * k, s.start.y * k};
      s.end = {s.end.x * k, s.end.y * k};
    }
  }
  for (const Segment& s : d.segments) {
    if (!std::isfinite(s.start.x) || !std::isfinite(s.start.y) || !std::isfinite(s.end.x) || !std::isfinite(s.end.y))
      throw Error("coordinates overflow when scaled to millimetres", {name, s.source_line});
    for (const double v : {s.start.x, s.start.y, s.end.x, s.end.y})
      if (std::abs(v) > kMaxCoordinateMm)
        throw Error(fmt::format("coordinate {:g} mm is beyond ±{:g} mm (entity {}): not a part drawing", v,
                                kMaxCoordinateMm, s.entity),
                    {name, s.source_line});
  }
  warn_vanishing_entities(d.segments, options.join_tolerance, name, warn);
  part.loops = build_loops(d.segments, options.join_tolerance);
  part.index = std::make_unique<RegionIndex>(part.loops.loops);
  return part;
}

}  // namespace tk::cad
