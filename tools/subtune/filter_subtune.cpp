/// @file filter_subtune.cpp
/// @brief subtune's filter: sub-tuning's decision per measured size.
#include <fmt/format.h>

#include "cli/tool_app.hpp"
#include "io/number_column.hpp"
#include "io/record_reader.hpp"
#include "io/record_writer.hpp"
#include "modes.hpp"
#include "quality/subtune_report.hpp"

namespace subtune {

void filter_sizes(const std::vector<std::string>& inputs, const SubTuneSettings& settings, const std::string& field,
                  const Limits& limits, const std::string& svg_path, const tk::cli::ToolApp& tool) {
  SubTuner tuner(settings);
  tk::io::RecordReader reader(inputs, tk::io::number_column_probe(field));
  tk::io::RecordWriter writer(tool.output_format());
  // CSV always has an in_tolerance column (empty where no limits apply), since
  // any record may bring limits of its own; JSON has the field only where one does.
  const bool tolerance_column = tool.output_format() == tk::io::OutputFormat::csv || limits.lower || limits.upper;
  const std::vector<std::string>& own = subtune_step_fields();
  std::vector<std::string> fields = own;
  if (tolerance_column) fields.push_back("in_tolerance");
  SizePlot plot;
  SizePlotInfo info;
  info.lower = limits.lower.value_or(info.lower), info.upper = limits.upper.value_or(info.upper);
  std::uint64_t parts = 0;
  std::vector<tk::io::Cell> row;
  bool fast = false;
  tk::Record record;
  while (reader.next(record)) {
    const tk::Location where = reader.where();
    const double size = length_field(record, field, where);
    if (parts == 0) {
      // A stream that starts with bare sizes (a number column) takes the
      // writer's fast path, no record built, and the size is a field the
      // writer must be told of; other inputs carry it in place.
      fast = record.size() == 1;
      if (fast) fields.insert(fields.begin(), field);
      writer.declare_fields(fields);
    }
    const SubTuneStep step = tuner.observe(size);
    ++parts;
    const Limits l = limits_of(record, limits, where);
    const bool judged = l.lower || l.upper, in_tolerance = within(size, l);
    using tk::io::Cell;
    subtune_step_cells(step, row);
    if (fast && record.size() == 1) {
      row.insert(row.begin(), Cell::real(size));
      if (tolerance_column) row.push_back(judged ? Cell::boolean(in_tolerance) : Cell::real(NAN));
      writer.write_row(row);
    } else {
      for (std::size_t i = 0; i < own.size(); ++i) record[own[i]] = tk::io::cell_value(row[i]);
      if (judged) record["in_tolerance"] = in_tolerance;
      writer.write(record);
    }
    if (!svg_path.empty())
      plot.add(static_cast<double>(parts), size, step.a + step.b * static_cast<double>(step.n), step.offset);
  }
  writer.flush();
  if (!svg_path.empty()) {
    info.title = fmt::format("subtune: {} parts, alpha {:g}", parts, settings.alpha);
    write_plot(plot, svg_path, info, tool);
  }
}

}  // namespace subtune
