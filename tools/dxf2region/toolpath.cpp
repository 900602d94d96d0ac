/// @file toolpath.cpp
/// @brief dxf2region --toolpath: the finishing contour as G-code.
#include <fmt/format.h>

#include <cstdio>

#include "cad/toolpath.hpp"
#include "io/error.hpp"
#include "modes.hpp"

namespace dxf2region {

void write_toolpath(const Settings& s, const Job& job, tk::io::RecordWriter& writer, tk::cli::ToolApp& tool) {
  if (tool.common().csv) throw tk::UsageError("--toolpath writes G-code: --csv does not apply");
  tk::cad::ToolpathOptions options;
  options.feed = s.feed;
  options.plunge_feed = s.plunge_feed;
  options.cut_z = s.cut_z;
  options.safe_z = s.safe_z;
  options.climb = s.direction == "climb";
  options.title =
      fmt::format("dxf2region {}, tool radius {:g} mm, {}, {}", job.name, s.tool_radius, s.side, s.direction);
  const std::string gcode = tk::cad::toolpath_gcode(job.region.loops, options);
  if (std::fwrite(gcode.data(), 1, gcode.size(), stdout) != gcode.size())
    throw tk::Error("write error on standard output");
  writer.flush();
}

}  // namespace dxf2region
