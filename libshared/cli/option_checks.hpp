/// @file option_checks.hpp
/// @brief CLI11 checks for real and count options, so a bad value is a usage
/// error naming the option ("--mass: must be ..."), found before anything runs;
/// and the check of the size a run implies, made before the run starts.
#pragma once

#include <CLI/CLI.hpp>

#include <cstdint>
#include <string>
#include <string_view>

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

/// Whether 0 is allowed besides [low, high] ("0: none" settings).
enum class ZeroAllowed { no, yes };
/// What is wrong with `v` for [low, high] ("must be a number from L to H"),
/// empty when nothing; NaN and infinities are outside every range.
std::string out_of_range(double v, double low, double high, ZeroAllowed zero = ZeroAllowed::no);
/// A number from `low` to `high` (or 0, with ZeroAllowed::yes): the range a
/// man page's OPTIONS gives, physical or computational.
CLI::Validator range_check(double low, double high, ZeroAllowed zero = ZeroAllowed::no);
/// The same for a value set after parsing (a default, a library's
/// parameters): throws UsageError "OPTION must be a number from L to H, not V".
void require_range(double v, double low, double high, std::string_view option, ZeroAllowed zero = ZeroAllowed::no);

/// The size a run implies (cycles, samples, vertices, bytes), checked before
/// the run: throws UsageError "OPTIONS imply N WHAT, more than the CAP this
/// tool allows" when `implied` exceeds `cap` (or is NaN).
void require_run_size(double implied, double cap, std::string_view what, std::string_view options);

}  // namespace tk::cli
