/// @file number.hpp
/// @brief A number to test: its value and, when known, its k*b^n+c shape.
#pragma once

#include <gmpxx.h>

#include <cstdint>
#include <optional>
#include <string>

namespace tk::primes {

/// N = k * b^n + c.
struct KbncForm {
  mpz_class k = 1;
  std::uint64_t b = 2;
  std::uint64_t n = 0;
  std::int64_t c = 0;
};

struct Number {
  mpz_class value;
  std::optional<KbncForm> form;
};

/// k*b^n+c as a value; Error if it would exceed `max_bits`.
mpz_class evaluate_kbnc(const KbncForm& form, std::size_t max_bits);

/// The size check of evaluate_kbnc alone, without computing the number.
void evaluate_kbnc_bits_check(const KbncForm& form, std::size_t max_bits);

/// k*2^n = (k/2^t)*2^(n+t): the same number with every factor 2 of k moved
/// into the exponent, so that k is odd, as LLR, Proth's theorem and the
/// published prime lists take it. Base 2 and k > 0 only; returns t.
std::uint64_t make_k_odd(KbncForm& form);

/// "k*b^n+c" text for a form (b^n when k = 1, no c when c = 0).
std::string kbnc_text(const KbncForm& form);

}  // namespace tk::primes
