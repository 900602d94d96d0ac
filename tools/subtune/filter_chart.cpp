/// @file filter_chart.cpp
/// @brief subtune --policy shewhart|ewma|cusum: the filter under a chart.
#include <fmt/format.h>

#include <cmath>

#include "cli/tool_app.hpp"
#include "io/number_column.hpp"
#include "io/record_reader.hpp"
#include "io/record_writer.hpp"
#include "modes.hpp"
#include "quality/subtune_report.hpp"

namespace subtune {

/// The filter under a chart instead of sub-tuning: per part the chart's
/// statistic and limit, its level, and whether to adjust.
void filter_chart(const std::vector<std::string>& inputs, AdjustmentPolicy& chart, const std::string& field,
                  const Limits& limits, const std::string& svg_path, const tk::cli::ToolApp& tool) {
  tk::io::RecordReader reader(inputs, tk::io::number_column_probe(field));
  tk::io::RecordWriter writer(tool.output_format());
  std::vector<std::string> fields = chart_step_fields();
  const bool csv = tool.output_format() == tk::io::OutputFormat::csv;
  if (csv || limits.lower || limits.upper) fields.push_back("in_tolerance");
  SizePlot plot;
  std::uint64_t parts = 0, since_adjustment = 0;
  double offset = 0;
  tk::Record record;
  while (reader.next(record)) {
    const tk::Location where = reader.where();
    const double size = length_field(record, field, where);
    if (parts++ == 0) {
      if (record.size() == 1) fields.insert(fields.begin(), field);
      writer.declare_fields(fields);
    }
    const PolicyStep step = chart.observe(size);
    ++since_adjustment;
    if (step.alarm) offset += step.correction;
    add_chart_step(record, step, since_adjustment, offset);
    if (const Limits l = limits_of(record, limits, where); l.lower || l.upper) record["in_tolerance"] = within(size, l);
    writer.write(record);
    if (step.alarm) since_adjustment = 0;
    if (!svg_path.empty()) plot.add(static_cast<double>(parts), size, step.level, offset);
  }
  writer.flush();
  if (!svg_path.empty()) {
    const std::string name(policy_name(chart.kind()));
    write_plot(plot, svg_path,
               {.title = fmt::format("subtune --policy {}: {} parts", name, parts),
                .level_label = level_label(chart.kind()),
                .lower = limits.lower.value_or(NAN),
                .upper = limits.upper.value_or(NAN)},
               tool);
  }
}

}  // namespace subtune
