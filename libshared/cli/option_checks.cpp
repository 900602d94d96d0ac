/// @file option_checks.cpp
#include "cli/option_checks.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>

#include "io/error.hpp"

namespace tk::cli {

std::string out_of_domain(double v, NumberDomain domain) {
  const bool finite = std::isfinite(v);
  const bool positive = finite && v >= kMinPositiveOption && v <= kMaxOptionMagnitude;
  switch (domain) {
    case NumberDomain::finite:
      if (!finite || std::abs(v) > kMaxOptionMagnitude) return "must be a number from -1e12 to 1e12";
      break;
    case NumberDomain::non_negative:
      if (!(v == 0 || positive)) return "must be 0 or a number from 1e-12 to 1e12";
      break;
    case NumberDomain::positive:
      if (!positive) return "must be a positive number from 1e-12 to 1e12";
      break;
    case NumberDomain::fraction:
      if (!finite || !(v >= 0 && v <= 1)) return "must be a number from 0 to 1";
      break;
  }
  return {};
}

CLI::Validator number_check(NumberDomain domain) {
  return CLI::Validator(
      [domain](std::string& text) -> std::string {
        errno = 0;
        char* end = nullptr;
        double v = std::strtod(text.c_str(), &end);
        if (text.empty() || end != text.c_str() + text.size()) return fmt::format("'{}' is not a number", text);
        if (errno == ERANGE)
          v = std::numeric_limits<double>::quiet_NaN();  // overflow or underflow: out of every domain
        const std::string problem = out_of_domain(v, domain);
        return problem.empty() ? problem : fmt::format("{}, not {}", problem, text);
      },
      "");
}

CLI::Validator count_check(std::uint64_t low, std::uint64_t high) {
  return CLI::Validator(
      [low, high](std::string& text) -> std::string {
        std::uint64_t v = 0;
        const bool digits = !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
        if (!digits || text.size() > 19 || (v = std::stoull(text)) < low || v > high)
          return fmt::format("must be a whole number from {} to {}, not {}", low, high, text);
        return {};
      },
      "");
}

std::string out_of_range(double v, double low, double high, ZeroAllowed zero) {
  if ((zero == ZeroAllowed::yes && v == 0) || (v >= low && v <= high)) return {};  // NaN fails both
  return fmt::format("must be {}a number from {:g} to {:g}", zero == ZeroAllowed::yes ? "0 or " : "", low, high);
}

CLI::Validator range_check(double low, double high, ZeroAllowed zero) {
  return CLI::Validator(
      [low, high, zero](std::string& text) -> std::string {
        errno = 0;
        char* end = nullptr;
        double v = std::strtod(text.c_str(), &end);
        if (text.empty() || end != text.c_str() + text.size()) return fmt::format("'{}' is not a number", text);
        if (errno == ERANGE && std::abs(v) > 1)
          v = std::numeric_limits<double>::quiet_NaN();  // overflow: out of every range
        const std::string problem = out_of_range(v, low, high, zero);
        return problem.empty() ? problem : fmt::format("{}, not {}", problem, text);
      },
      "");
}

void require_range(double v, double low, double high, std::string_view option, ZeroAllowed zero) {
  const std::string problem = out_of_range(v, low, high, zero);
  if (!problem.empty()) throw UsageError(fmt::format("{}: {}, not {:g}", option, problem, v));
}

void require_run_size(double implied, double cap, std::string_view what, std::string_view options) {
  if (!(implied <= cap))
    throw UsageError(
        fmt::format("{} imply {:.3g} {}, more than the {:g} this tool allows", options, implied, what, cap));
}

}  // namespace tk::cli
