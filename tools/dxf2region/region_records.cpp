/// @file region_records.cpp
/// @brief dxf2region's default mode: the prohibited region as records.
#include "cad/region_output.hpp"
#include "modes.hpp"

namespace dxf2region {

void write_region(const Settings& s, const Job& job, tk::io::RecordWriter& writer, tk::cli::ToolApp& tool) {
  for (std::size_t i = 0; i < job.region.loops.size(); ++i)
    writer.write(tk::cad::loop_record(job.region.loops[i], i, s.flatten_tolerance, s.tool_radius == 0));
  write_findings(s, job, job.region, writer, tool);
  writer.flush();
}

}  // namespace dxf2region
