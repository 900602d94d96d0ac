/// @file check_positions.cpp
/// @brief dxf2region --check: the invasion guard over a stream of tool positions.
#include <fmt/format.h>

#include <cmath>

#include "cad/invasion_check.hpp"
#include "cad/region_report.hpp"
#include "io/error.hpp"
#include "io/record_fields.hpp"
#include "io/record_reader.hpp"
#include "modes.hpp"

namespace dxf2region {

void check_positions(const Settings& s, const Job& job, tk::io::RecordWriter& writer) {
  tk::cad::GuardOptions options{s.tool_radius, s.machining(), s.latency, s.margin};
  tk::cad::InvasionGuard guard(*job.part.index, options, job.region.contour.get());
  writer.declare_fields(tk::cad::position_check_fields(s.summary));
  tk::io::RecordReader reader({s.check_path.empty() ? std::string("-") : s.check_path});
  reader.expect_columns({{"x", "y"}});
  tk::Record record;
  const auto& elements = job.part.index->elements();
  while (reader.next(record)) {
    const tk::Location where = reader.where();
    const tk::cad::Point p{tk::io::number_field(record, "x", where), tk::io::number_field(record, "y", where)};
    for (const double v : {p.x, p.y})  // a distance that far out would be all rounding: bad data
      if (!(std::abs(v) <= tk::cad::kMaxCoordinateMm))
        throw tk::Error(fmt::format("position {:g} mm is beyond ±{:g} mm", v, tk::cad::kMaxCoordinateMm), where);
    const std::optional<double> t = tk::io::optional_number_field(record, "t", where);
    tk::cad::PositionCheck c;
    try {
      c = guard.check(p, t);
    } catch (const tk::Error& e) {
      throw tk::Error(e.what(), where);
    }
    tk::cad::add_position_fields(record, c, elements);
    writer.write(record);
  }
  if (s.summary) writer.write(tk::cad::guard_summary_record(guard.summary()));
  writer.flush();
}

}  // namespace dxf2region
