/// @file option_checks.hpp
/// @brief CLI11 checks for real and count options, so a bad value is a usage
/// error naming the option ("--mass: must be ..."), found before anything runs.
#pragma once

#include <CLI/CLI.hpp>

#include <cstdint>
#include <string>

namespace tk::cli {

/// Real options lie within ±kMaxOptionMagnitude and positive ones at or above
/// kMinPositiveOption: far beyond any physical setting, and it keeps a
/// simulation's products and sums of squares inside double range.
inline constexpr double kMaxOptionMagnitude = 1e12, kMinPositiveOption = 1e-12;

enum class NumberDomain { finite, non_negative, positive, fraction };

/// What is wrong with `v` for the domain ("must be ..."), empty when nothing.
std::string out_of_domain(double v, NumberDomain domain);
/// A finite number in the domain (non_negative: 0 or positive; fraction: 0 to 1).
CLI::Validator number_check(NumberDomain domain);
/// A whole number from `low` to `high` (CLI11 itself would wrap "-1" round to 2^64 − 1).
CLI::Validator count_check(std::uint64_t low, std::uint64_t high);

}  // namespace tk::cli
