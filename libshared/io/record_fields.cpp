/// @file record_fields.cpp
/// @brief Typed record fields.
#include "io/record_fields.hpp"

#include <charconv>
#include <cmath>
#include <string>

namespace tk::io {

std::optional<double> optional_number_field(const Record& record, std::string_view key, const Location& where) {
  const auto found = record.find(std::string(key));
  if (found == record.end() || found->is_null()) return std::nullopt;
  double value = 0;
  if (found->is_number()) {
    value = found->get<double>();
  } else if (found->is_string()) {
    const std::string& text = found->get_ref<const std::string&>();
    if (text.empty()) return std::nullopt;
    std::string_view digits = text;
    if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (error == std::errc::result_out_of_range) throw Error("field '" + std::string(key) + "' is out of range: '" + text + "'", where);
    if (error != std::errc() || end != digits.data() + digits.size())
      throw Error("field '" + std::string(key) + "' is not a number: '" + text + "'", where);
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
