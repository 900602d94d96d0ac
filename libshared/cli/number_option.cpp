/// @file number_option.cpp
#include "cli/number_option.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>
#include <string>

#include "io/error.hpp"

namespace tk::cli {

namespace {

bool digits(std::string_view text, std::uint64_t& value) {
  if (text.empty() || text.find_first_not_of("0123456789") != std::string_view::npos) return false;
  return std::from_chars(text.data(), text.data() + text.size(), value).ec == std::errc();
}

}  // namespace

std::uint64_t parse_count(std::string_view text, std::string_view option) {
  auto bad = [&](const std::string& why) {
    return UsageError(std::string(option) + " '" + std::string(text.substr(0, 40)) + "' " + why);
  };
  const auto not_integer = [&] { return bad("is not a non-negative integer (digits, 1e9, 1.1e9 or 2^40)"); };
  const auto overflow = [&] { return bad("does not fit in 64 bits"); };
  if (text.starts_with('-')) throw bad("is negative");
  const std::size_t operator_at = text.find_first_of("eE^");
  std::uint64_t value = 0, exponent = 0;
  if (operator_at == std::string_view::npos) {
    if (digits(text, value)) return value;
    const bool only_digits = !text.empty() && text.find_first_not_of("0123456789") == std::string_view::npos;
    throw only_digits ? overflow() : not_integer();
  }
  if (!digits(text.substr(operator_at + 1), exponent)) throw not_integer();
  std::string_view mantissa = text.substr(0, operator_at);
  if (text[operator_at] == '^') {
    std::uint64_t base = 0;
    if (!digits(mantissa, base)) throw not_integer();
    value = 1;
    for (std::uint64_t i = 0; i < exponent && value != 0 && base != 1; ++i) {
      if (base > 1 && value > UINT64_MAX / base) throw overflow();
      value *= base;
    }
    return value;
  }
  // A decimal mantissa: 1.1e9 is an integer, 1.25e1 is not.
  std::string whole(mantissa.substr(0, mantissa.find('.')));
  std::string fraction(mantissa.find('.') == std::string_view::npos ? "" : mantissa.substr(mantissa.find('.') + 1));
  while (!fraction.empty() && fraction.back() == '0') fraction.pop_back();
  if (whole.empty() || !digits(whole, value) ||
      (!fraction.empty() && fraction.find_first_not_of("0123456789") != std::string::npos))
    throw not_integer();
  if (fraction.size() > exponent) throw bad("is not a whole number");
  std::string all = whole + fraction + std::string(exponent - fraction.size(), '0');
  if (exponent > 40 && value != 0) throw overflow();
  if (!digits(all.substr(std::min(all.find_first_not_of('0'), all.size() - 1)), value)) throw overflow();
  return value;
}

std::pair<std::uint64_t, std::uint64_t> parse_range(std::string_view text, std::string_view option) {
  const std::size_t colon = text.find(':');
  if (colon == std::string_view::npos)
    throw UsageError(std::string(option) + " '" + std::string(text.substr(0, 40)) + "' is not a range A:B");
  const std::uint64_t low = parse_count(text.substr(0, colon), option);
  const std::uint64_t high = parse_count(text.substr(colon + 1), option);
  if (high < low)
    throw UsageError(std::string(option) + " range " + std::string(text.substr(0, 80)) +
                     " is empty: its end is below its start");
  return {low, high};
}

std::pair<unsigned, unsigned> parse_shard(std::string_view text, std::string_view option) {
  const std::size_t slash = text.find('/');
  const std::string quoted = std::string(option) + " '" + std::string(text.substr(0, 40)) + "'";
  if (slash == std::string_view::npos) throw UsageError(quoted + " is not K/N");
  const std::uint64_t index = parse_count(text.substr(0, slash), option);
  const std::uint64_t count = parse_count(text.substr(slash + 1), option);
  if (count == 0 || count > 1000000 || index == 0 || index > count)
    throw UsageError(quoted + " needs 1 <= K <= N <= 1000000");
  return {static_cast<unsigned>(index - 1), static_cast<unsigned>(count)};
}

namespace {
/// One finite decimal number (a leading '+' allowed), or nullopt.
std::optional<double> finite_number(std::string_view part) {
  if (part.starts_with('+')) part.remove_prefix(1);
  double value = 0;
  const auto [end, ec] = std::from_chars(part.data(), part.data() + part.size(), value);
  if (part.empty() || ec != std::errc() || end != part.data() + part.size() || !std::isfinite(value))
    return std::nullopt;
  return value;
}
}  // namespace

std::vector<double> parse_numbers(std::string_view text, std::string_view option, std::size_t count) {
  const auto bad = [&] {
    return UsageError(std::string(option) + " '" + std::string(text.substr(0, 60)) + "' is not " +
                      std::to_string(count) + " finite numbers separated by commas");
  };
  std::vector<double> values;
  for (std::size_t at = 0; at <= text.size();) {
    const std::size_t comma = std::min(text.find(',', at), text.size());
    const std::optional<double> value = finite_number(text.substr(at, comma - at));
    if (!value) throw bad();
    values.push_back(*value);
    at = comma + 1;
  }
  if (values.size() != count) throw bad();
  return values;
}

std::vector<double> parse_grid(std::string_view text, std::string_view option, std::size_t max_values) {
  const auto bad = [&](const std::string& why) {
    return UsageError(std::string(option) + " '" + std::string(text.substr(0, 60)) + "' " + why);
  };
  std::vector<std::optional<double>> parts;
  for (std::size_t at = 0; at <= text.size();) {
    const std::size_t colon = std::min(text.find(':', at), text.size());
    parts.push_back(finite_number(text.substr(at, colon - at)));
    at = colon + 1;
  }
  if ((parts.size() != 1 && parts.size() != 3) || std::find(parts.begin(), parts.end(), std::nullopt) != parts.end())
    throw bad("is not a number or FROM:TO:STEP");
  if (parts.size() == 1) return {*parts[0]};
  const double from = *parts[0], to = *parts[1], step = *parts[2];
  if (!(step > 0) || to < from) throw bad("needs FROM <= TO and a positive STEP");
  const double count = std::floor((to - from) / step * (1 + 1e-12)) + 1;  // TO itself when the steps land on it
  if (count > static_cast<double>(max_values)) throw bad("has more than " + std::to_string(max_values) + " values");
  std::vector<double> values;
  for (std::size_t i = 0; i < static_cast<std::size_t>(count); ++i)
    values.push_back(from + static_cast<double>(i) * step);
  return values;
}

}  // namespace tk::cli
