/// @file record_fields.cpp
/// @brief Typed record fields.
#include "io/record_fields.hpp"

#include <charconv>
#include <cmath>
#include <string>

namespace tk::io {

NumberText parse_number_text(std::string_view text, double& value) {
  if (!text.empty() && text.front() == '+') {
    text.remove_prefix(1);
    if (!text.empty() && (text.front() == '-' || text.front() == '+')) return NumberText::not_a_number;  // "+-40"
  }
  double parsed = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), parsed);
  if (error == std::errc::result_out_of_range) return NumberText::out_of_range;
  if (error != std::errc() || end != text.data() + text.size()) return NumberText::not_a_number;
  if (!std::isfinite(parsed)) return NumberText::not_finite;
  value = parsed;
  return NumberText::ok;
}

std::optional<double> optional_number_field(const Record& record, std::string_view key, const Location& where) {
  const auto found = record.find(std::string(key));
  if (found == record.end() || found->is_null()) return std::nullopt;
  double value = 0;
  if (found->is_number()) {
    value = found->get<double>();
  } else if (found->is_string()) {
    const std::string& text = found->get_ref<const std::string&>();
    if (text.empty()) return std::nullopt;
    switch (parse_number_text(text, value)) {
      case NumberText::ok: break;
      case NumberText::out_of_range:
        throw Error("field '" + std::string(key) + "' is out of range: '" + text + "'", where);
      case NumberText::not_a_number:
        throw Error("field '" + std::string(key) + "' is not a number: '" + text + "'", where);
      case NumberText::not_finite: throw Error("field '" + std::string(key) + "' is not finite", where);
    }
  } else {
    throw Error("field '" + std::string(key) + "' is not a number", where);
  }
  if (!std::isfinite(value)) throw Error("field '" + std::string(key) + "' is not finite", where);
  return value;
}

double number_field(const Record& record, std::string_view key, const Location& where) {
  const std::optional<double> value = optional_number_field(record, key, where);
  if (!value) throw Error("missing field '" + std::string(key) + "'", where);
  return *value;
}

}  // namespace tk::io
