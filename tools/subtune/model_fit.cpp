/// @file model_fit.cpp
/// @brief subtune model: the force-error model fitted to calibration records.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "cli/number_option.hpp"
#include "cli/option_checks.hpp"
#include "cli/tool_app.hpp"
#include "io/error.hpp"
#include "io/number_column.hpp"
#include "io/record_fields.hpp"
#include "io/record_reader.hpp"
#include "io/record_writer.hpp"
#include "machining/force_error_model.hpp"
#include "quality/lathe_sim.hpp"
#include "quality/size_plot.hpp"
#include "modes.hpp"

namespace subtune {

const std::array<const char*, 6> kCoefficientNames{"b0", "b1", "b2", "b12", "b11", "b22"};

std::array<double*, 6> coefficients(ForceErrorModel& m) { return {&m.b0, &m.b1, &m.b2, &m.b12, &m.b11, &m.b22}; }

void fit_model(const std::vector<std::string>& inputs, bool residuals, tk::io::OutputFormat format) {
  std::vector<tk::machining::CalibrationPoint> points;
  std::vector<tk::Record> records;
  tk::io::RecordReader reader(inputs);
  reader.expect_columns({{"a", "f", "y"}});
  tk::Record record;
  while (reader.next(record)) {
    const tk::Location where = reader.where();
    points.push_back({length_field(record, "a", where), length_field(record, "f", where), length_field(record, "y", where)});
    if (residuals) records.push_back(std::move(record));
  }
  if (points.empty()) throw tk::Error("no calibration records (a, f, y) in the input");
  const tk::machining::ForceErrorFit fit = tk::machining::fit_force_error_model(points);
  tk::io::RecordWriter writer(format);
  std::vector<std::string> columns{"record"};
  tk::Record model{{"record", "model"}};
  ForceErrorModel m = fit.model;
  for (std::size_t k = 0; k < 6; ++k) model[kCoefficientNames[k]] = *coefficients(m)[k];
  model["points"] = fit.points, model["r2"] = fit.r2, model["adjusted_r2"] = fit.adjusted_r2;
  model["residual_sd"] = fit.residual_sd, model["condition"] = fit.condition;
  if (residuals) {
    for (const auto& [key, value] : records.front().items()) columns.push_back(key);
    columns.insert(columns.end(), {"fitted", "residual"});
  }
  for (const auto& [key, value] : model.items())
    if (key != "record") columns.push_back(key);
  writer.declare_fields(columns);  // CSV: one header for both kinds of record
  for (std::size_t i = 0; i < records.size(); ++i) {
    tk::Record r{{"record", "point"}};
    for (auto& [key, value] : records[i].items()) r[key] = value;
    r["fitted"] = fit.fitted[i], r["residual"] = fit.residuals[i];
    writer.write(r);
  }
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
      *coefficients(m)[k] = values[k];
    }
    return m;
  }
  tk::io::RecordReader reader({path});
  tk::Record record;
  bool found = false;
  while (reader.next(record)) {
    bool complete = true;
    for (const char* name : kCoefficientNames) complete = complete && record.contains(name);
    if (!complete) continue;
    for (std::size_t k = 0; k < 6; ++k) *coefficients(m)[k] = tk::io::number_field(record, kCoefficientNames[k], reader.where());
    found = true;
  }
  if (!found) throw tk::Error(fmt::format("{}: no model record (b0, b1, b2, b12, b11, b22); make one with 'subtune model'", path));
  return m;
}

}  // namespace subtune
