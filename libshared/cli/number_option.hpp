/// @file number_option.hpp
/// @brief Integer option values as prime hunters write them: 1000000000,
/// 1e9, 2^40, and inclusive ranges A:B of those. A value that does not
/// parse is a usage error (tk::UsageError, exit 2) naming the option, so a
/// tool calls these where it reads its options and catches nothing.
#pragma once

#include <cstdint>
#include <string_view>
#include <utility>
#include <vector>

namespace tk::cli {

/// A non-negative integer below 2^64: digits, "AeB" (A times 10^B) or
/// "A^B". Throws UsageError naming `option` for anything else or an overflow.
std::uint64_t parse_count(std::string_view text, std::string_view option);

/// "A:B" with A <= B, each as parse_count reads it.
std::pair<std::uint64_t, std::uint64_t> parse_range(std::string_view text, std::string_view option);

/// "K/N" with 1 <= K <= N <= 1000000, as --shard takes it: {K - 1, N}.
std::pair<unsigned, unsigned> parse_shard(std::string_view text, std::string_view option);

/// "A,B,C": exactly `count` finite decimal numbers separated by commas (as
/// --steps-per-mm X,Y,Z or --window X0,Y0,X1,Y1 take them). Throws UsageError
/// naming `option` for anything else.
std::vector<double> parse_numbers(std::string_view text, std::string_view option, std::size_t count);

/// A number, or "FROM:TO:STEP" for FROM, FROM+STEP, ... up to TO (included
/// when a step lands on it), as a sweep's grids take them. Throws UsageError
/// naming `option` for anything else or more than `max_values` values.
std::vector<double> parse_grid(std::string_view text, std::string_view option, std::size_t max_values = 1000000);

}  // namespace tk::cli
