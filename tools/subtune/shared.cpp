/// @file shared.cpp
/// @brief subtune: what the modes share (length fields, tolerance limits, plots).
#include <fmt/format.h>

#include <cmath>

#include "cli/tool_app.hpp"
#include "io/error.hpp"
#include "io/record_fields.hpp"
#include "modes.hpp"

namespace subtune {

double length_field(const tk::Record& record, const std::string& key, const tk::Location& where) {
  const double v = tk::io::number_field(record, key, where);
  if (std::abs(v) > kMaxLengthMm)
    throw tk::Error(fmt::format("{} = {} mm is beyond ±{:g} mm", key, v, kMaxLengthMm), where);
  if (v != 0 && std::abs(v) < kMinLengthMm)
    throw tk::Error(fmt::format("{} = {} mm is below {:g} mm in magnitude (and not 0)", key, v, kMinLengthMm), where);
  return v;
}

/// The legend of the policy's level line in the plots.
std::string level_label(PolicyKind kind) {
  switch (kind) {
    case PolicyKind::subtune: return "regression A_T at the part";
    case PolicyKind::ewma: return "EWMA level (target + z)";
    case PolicyKind::cusum: return "CUSUM estimate of the mean";
    case PolicyKind::shewhart: return "the point (Shewhart)";
    case PolicyKind::none: break;
  }
  return "level";
}

/// Writes the plot, saying so when it holds only the first parts.
void write_plot(const SizePlot& plot, const std::string& path, const SizePlotInfo& info, const tk::cli::ToolApp& tool) {
  if (plot.truncated()) tool.warn(fmt::format("the plot shows the first {} parts only", SizePlot::kMaxParts));
  plot.write(path, info);
}

/// The record's own limits, else the options'.
Limits limits_of(const tk::Record& record, const Limits& options, const tk::Location& where) {
  Limits l{tk::io::optional_number_field(record, "lower", where),
           tk::io::optional_number_field(record, "upper", where)};
  if (!l.lower) l.lower = options.lower;
  if (!l.upper) l.upper = options.upper;
  return l;
}

bool within(double size, const Limits& l) { return (!l.lower || size >= *l.lower) && (!l.upper || size <= *l.upper); }

}  // namespace subtune
