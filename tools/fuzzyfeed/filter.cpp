/// @file filter.cpp
/// @brief fuzzyfeed's stream mode: the override law's answer added to each
/// spindle-load record.
#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <optional>

#include "io/error.hpp"
#include "io/record_fields.hpp"
#include "io/record_reader.hpp"
#include "modes.hpp"

namespace fuzzyfeed {

void filter_records(const std::vector<std::string>& inputs, const FeedOverrideParams& law_params,
                    tk::io::OutputFormat format) {
  FeedOverride law(law_params);
  tk::io::RecordWriter writer(format);
  writer.declare_fields({"wk", "override", "feed_out"});
  tk::io::RecordReader reader(inputs.empty() ? std::vector<std::string>{"-"} : inputs);
  reader.expect_columns({{"t", "load"}});
  tk::Record record;
  double previous_t = -std::numeric_limits<double>::infinity();
  while (reader.next(record)) {
    const tk::Location where = reader.where();
    const double t = tk::io::number_field(record, "t", where);
    if (!(t > previous_t)) throw tk::Error(fmt::format("t must increase strictly: {} after {}", t, previous_t), where);
    previous_t = t;
    const double load = tk::io::number_field(record, "load", where);
    if (!(load >= 0 && load <= 100)) throw tk::Error(fmt::format("load {} is outside 0-100 % of rated", load), where);
    const std::optional<double> feed = tk::io::optional_number_field(record, "feed", where);
    if (feed && *feed < 0) throw tk::Error(fmt::format("feed {} is negative", *feed), where);
    const OverrideStep step = law.step(load);
    record["wk"] = step.wk;
    record["override"] = step.override_pct;
    if (feed) {
      const double feed_out = *feed * step.override_pct / 100;
      if (!std::isfinite(feed_out)) throw tk::Error(fmt::format("feed {} times the override overflows", *feed), where);
      record["feed_out"] = feed_out;
    }
    writer.write(record);
  }
  writer.flush();
}

}  // namespace fuzzyfeed
