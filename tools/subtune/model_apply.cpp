/// @file model_apply.cpp
/// @brief subtune feed and correct: the force-error model applied per workpiece.
#include <fmt/format.h>

#include <cmath>
#include <optional>

#include "cli/tool_app.hpp"
#include "io/error.hpp"
#include "io/number_column.hpp"
#include "io/record_fields.hpp"
#include "io/record_reader.hpp"
#include "io/record_writer.hpp"
#include "machining/force_error_report.hpp"
#include "modes.hpp"

namespace subtune {

void apply_model(const std::vector<std::string>& inputs, const ForceErrorModel& m, std::optional<FeedRange> feed_range,
                 double fixed_feed, const tk::cli::ToolApp& tool) {
  tk::io::RecordReader reader(inputs, tk::io::number_column_probe("a"));
  tk::io::RecordWriter writer(tool.output_format());
  writer.declare_fields(feed_range ? tk::machining::feed_choice_fields() : tk::machining::correction_fields());
  std::uint64_t unsolved = 0;
  tk::Record record;
  while (reader.next(record)) {
    const tk::Location where = reader.where();
    const double a = length_field(record, "a", where);
    if (a < 0) throw tk::Error(fmt::format("allowance a = {} mm is negative", a), where);
    if (feed_range) {
      const tk::machining::FeedChoice choice =
          tk::machining::feed_for_error(m, a, feed_range->target, feed_range->f_min, feed_range->f_max);
      tk::machining::add_feed_choice(record, choice);
      if (choice.status == tk::machining::FeedStatus::none) ++unsolved;
    } else {
      const std::optional<double> record_feed = tk::io::optional_number_field(record, "f", where);
      if (!record_feed && std::isnan(fixed_feed))
        throw tk::Error("no feed: give --feed or an f field in the record", where);
      const double f = record_feed.value_or(fixed_feed);
      if (!(f > 0)) throw tk::Error(fmt::format("feed f = {} mm/rev must be positive", f), where);
      tk::machining::add_correction(record, m, a, f);
    }
    writer.write(record);
  }
  writer.flush();
  if (unsolved > 0)
    tool.warn(
        fmt::format("{} workpiece(s) have no feed in [{:g}, {:g}] mm/rev giving y = {:g} mm (feed_status none; "
                    "error_min and error_max give the reachable range)",
                    unsolved, feed_range->f_min, feed_range->f_max, feed_range->target));
}

}  // namespace subtune
