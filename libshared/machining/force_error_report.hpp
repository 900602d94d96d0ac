/// @file force_error_report.hpp
/// @brief The force-error model as records: the fitted model and its
/// calibration points, a model read back from such a record, and the feed
/// or set-up correction it gives a workpiece.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "io/error.hpp"
#include "io/record.hpp"
#include "machining/force_error_model.hpp"

namespace tk::machining {

/// b0, b1, b2, b12, b11, b22: the model's fields.
extern const std::array<const char*, 6> kCoefficientNames;
/// The coefficients in kCoefficientNames' order.
std::array<double*, 6> coefficients(ForceErrorModel& m);

/// {"record": "model", b0..b22, points, r2, adjusted_r2, residual_sd, condition}.
Record model_record(const ForceErrorFit& fit);
/// {"record": "point"}, the calibration record's fields, fitted and residual.
Record point_record(const Record& calibration, double fitted, double residual);
/// The model of a record holding all six coefficients; nullopt when one is
/// missing, tk::Error at `where` when one is not a number.
std::optional<ForceErrorModel> model_from_record(const Record& record, const Location& where);

/// The fields add_feed_choice and add_correction write.
std::vector<std::string> feed_choice_fields();
std::vector<std::string> correction_fields();
void add_feed_choice(Record& record, const FeedChoice& choice);
/// The predicted error y(a, f) and the set-up correction that cancels it.
void add_correction(Record& record, const ForceErrorModel& m, double a, double f);

}  // namespace tk::machining
