/// @file simulate.cpp
/// @brief dxf2region --simulate: the seed's invasion experiment against the region.
#include "cad/invasion_check.hpp"
#include "cad/region_report.hpp"
#include "cad/segment_geometry.hpp"
#include "modes.hpp"

namespace dxf2region {

void simulate(const Settings& s, const Job& job, tk::io::RecordWriter& writer) {
  const tk::cad::MachiningSide machining = s.machining();
  const auto guard = [&](tk::cad::Point p) {
    return tk::cad::guard_query(*job.part.index, p, s.tool_radius, machining).distance;
  };
  std::vector<std::vector<tk::cad::Point>> boundary;  // the region on the left of each
  for (const tk::cad::Loop& loop : job.region.loops)
    boundary.push_back(tk::cad::flatten_loop(loop, s.offset_tolerance * 10));
  const tk::cad::SignedDistance printed = [&](tk::cad::Point p) {
    return tk::cad::interval_line_distance(boundary, p);
  };
  for (double v : s.speeds) {
    const tk::cad::InvasionSimOptions options = s.experiment_at(v);
    const auto results = tk::cad::simulate_invasions(guard, boundary, s.tolerances, options,
                                                     s.invasion_check == "printed" ? &printed : nullptr);
    for (const tk::cad::InvasionSimResult& r : results)
      writer.write(tk::cad::invasion_sim_record(r, s.invasion_check, options));
  }
  writer.flush();
}

}  // namespace dxf2region
