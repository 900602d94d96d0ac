/// @file model_fit.cpp
/// @brief subtune model: the force-error model fitted to calibration records.
#include <fmt/format.h>

#include <optional>

#include "cli/number_option.hpp"
#include "cli/option_checks.hpp"
#include "io/error.hpp"
#include "io/record_reader.hpp"
#include "io/record_writer.hpp"
#include "machining/force_error_report.hpp"
#include "modes.hpp"

namespace subtune {

void fit_model(const std::vector<std::string>& inputs, bool residuals, tk::io::OutputFormat format) {
  std::vector<tk::machining::CalibrationPoint> points;
  std::vector<tk::Record> records;
  tk::io::RecordReader reader(inputs);
  reader.expect_columns({{"a", "f", "y"}});
  tk::Record record;
  while (reader.next(record)) {
    const tk::Location where = reader.where();
    points.push_back(
        {length_field(record, "a", where), length_field(record, "f", where), length_field(record, "y", where)});
    if (residuals) records.push_back(std::move(record));
  }
  if (points.empty()) throw tk::Error("no calibration records (a, f, y) in the input");
  const tk::machining::ForceErrorFit fit = tk::machining::fit_force_error_model(points);
  tk::io::RecordWriter writer(format);
  std::vector<std::string> columns{"record"};
  const tk::Record model = tk::machining::model_record(fit);
  if (residuals) {
    for (const auto& [key, value] : records.front().items()) columns.push_back(key);
    columns.insert(columns.end(), {"fitted", "residual"});
  }
  for (const auto& [key, value] : model.items())
    if (key != "record") columns.push_back(key);
  writer.declare_fields(columns);  // CSV: one header for both kinds of record
  for (std::size_t i = 0; i < records.size(); ++i)
    writer.write(tk::machining::point_record(records[i], fit.fitted[i], fit.residuals[i]));
  writer.write(model);
  writer.flush();
}

/// The model from --coefficients, or from the last record of FILE that has all six.
ForceErrorModel load_model(const std::string& path, const std::string& coefficient_text) {
  ForceErrorModel m;
  if (!coefficient_text.empty()) {
    const std::vector<double> values = tk::cli::parse_numbers(coefficient_text, "--coefficients", 6);
    for (std::size_t k = 0; k < 6; ++k) {
      // Millimetres per unit of a, f and their products: ±1e6 keeps y finite
      // for every allowance and feed the tool takes.
      tk::cli::require_range(values[k], -kMaxCoefficient, kMaxCoefficient, "--coefficients");
      *tk::machining::coefficients(m)[k] = values[k];
    }
    return m;
  }
  tk::io::RecordReader reader({path});
  tk::Record record;
  bool found = false;
  while (reader.next(record)) {
    if (const std::optional<ForceErrorModel> read = tk::machining::model_from_record(record, reader.where())) {
      m = *read;
      found = true;
    }
  }
  if (!found)
    throw tk::Error(
        fmt::format("{}: no model record (b0, b1, b2, b12, b11, b22); make one with 'subtune model'", path));
  return m;
}

}  // namespace subtune
