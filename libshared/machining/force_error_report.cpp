#include "machining/force_error_report.hpp"

#include "io/record_fields.hpp"

namespace tk::machining {

const std::array<const char*, 6> kCoefficientNames{"b0", "b1", "b2", "b12", "b11", "b22"};

std::array<double*, 6> coefficients(ForceErrorModel& m) { return {&m.b0, &m.b1, &m.b2, &m.b12, &m.b11, &m.b22}; }

Record model_record(const ForceErrorFit& fit) {
  Record model{{"record", "model"}};
  ForceErrorModel m = fit.model;
  for (std::size_t k = 0; k < kCoefficientNames.size(); ++k) model[kCoefficientNames[k]] = *coefficients(m)[k];
  model["points"] = fit.points, model["r2"] = fit.r2, model["adjusted_r2"] = fit.adjusted_r2;
  model["residual_sd"] = fit.residual_sd, model["condition"] = fit.condition;
  return model;
}

Record point_record(const Record& calibration, double fitted, double residual) {
  Record r{{"record", "point"}};
  for (const auto& [key, value] : calibration.items()) r[key] = value;
  r["fitted"] = fitted, r["residual"] = residual;
  return r;
}

std::optional<ForceErrorModel> model_from_record(const Record& record, const Location& where) {
  for (const char* name : kCoefficientNames)
    if (!record.contains(name)) return std::nullopt;
  ForceErrorModel m;
  for (std::size_t k = 0; k < kCoefficientNames.size(); ++k)
    *coefficients(m)[k] = io::number_field(record, kCoefficientNames[k], where);
  return m;
}

std::vector<std::string> feed_choice_fields() {
  return {"feed", "predicted_error", "feed_status", "error_min", "error_max"};
}

std::vector<std::string> correction_fields() { return {"predicted_error", "correction"}; }

void add_feed_choice(Record& record, const FeedChoice& choice) {
  record["feed"] = choice.feed, record["predicted_error"] = choice.error;
  record["feed_status"] = feed_status_name(choice.status);
  record["error_min"] = choice.error_min, record["error_max"] = choice.error_max;
}

void add_correction(Record& record, const ForceErrorModel& m, double a, double f) {
  record["predicted_error"] = m.error_at(a, f), record["correction"] = setup_correction(m, a, f);
}

}  // namespace tk::machining
