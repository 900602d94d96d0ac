/// @file number_expression.hpp
/// @brief Numbers as prime hunters write them: decimal, 0x hex, and
/// expressions such as 778965587811*2^36627-1, (2^127+1)/3, 10**100+267,
/// 1000!+1 or 997#-1, with the size bounded before anything is computed.
#pragma once

#include <cstddef>
#include <string_view>

#include "primes/number.hpp"

namespace tk::primes {

/// Default bound on the size of a number: 2^26 bits (about 20 million digits).
inline constexpr std::size_t kDefaultMaxBits = std::size_t{1} << 26;

/// Parses and evaluates `text`. Grammar: + - * / (exact) % ^ ** (right
/// associative), unary minus, parentheses, n! and p# (primorial). The
/// result's k*b^n+c shape is kept when the text is written that way.
/// Throws Error (without location) for malformed text, inexact division,
/// division by zero, or a result (or intermediate) above `max_bits`.
Number parse_number(std::string_view text, std::size_t max_bits = kDefaultMaxBits);

/// True when `text` looks like a number or expression (digits, operators,
/// parentheses, spaces) rather than, say, a CSV header. Cheap check only.
bool looks_like_number(std::string_view text);

}  // namespace tk::primes
