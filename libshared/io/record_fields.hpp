/// @file record_fields.hpp
/// @brief Reading typed fields from records: a JSON number, or the text of
/// a CSV cell that holds one.
#pragma once

#include <optional>
#include <string_view>

#include "io/error.hpp"
#include "io/record.hpp"

namespace tk::io {

enum class NumberText { ok, not_a_number, out_of_range, not_finite };

/// Parses all of `text` as a decimal number (one optional leading '+');
/// `value` is set only when the result is ok.
NumberText parse_number_text(std::string_view text, double& value);

/// The finite number in `record[key]`; Error at `where` when the field is
/// missing, not a number, or NaN/infinite.
double number_field(const Record& record, std::string_view key, const Location& where);

/// As number_field, but nullopt when the field is missing or empty (a CSV null).
std::optional<double> optional_number_field(const Record& record, std::string_view key, const Location& where);

}  // namespace tk::io
