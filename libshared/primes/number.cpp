/// @file number.cpp
#include "primes/number.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "io/error.hpp"

namespace tk::primes {

void evaluate_kbnc_bits_check(const KbncForm& form, std::size_t max_bits) {
  if (form.b < 2) throw Error("base b must be at least 2");
  const double bits = static_cast<double>(form.n) * std::log2(static_cast<double>(form.b)) +
                      static_cast<double>(mpz_sizeinbase(form.k.get_mpz_t(), 2));
  if (bits > static_cast<double>(max_bits) + 1)
    throw Error("number has about " + std::to_string(static_cast<std::uint64_t>(std::min(bits, 1e18))) +
                " bits, more than --max-bits " + std::to_string(max_bits));
}

mpz_class evaluate_kbnc(const KbncForm& form, std::size_t max_bits) {
  evaluate_kbnc_bits_check(form, max_bits);
  mpz_class value;
  if (form.b == 2) {
    mpz_mul_2exp(value.get_mpz_t(), form.k.get_mpz_t(), form.n);
  } else {
    mpz_ui_pow_ui(value.get_mpz_t(), form.b, form.n);
    value *= form.k;
  }
  if (form.c >= 0) value += static_cast<unsigned long>(form.c);
  else value -= static_cast<unsigned long>(-(form.c + 1)) + 1UL;
  return value;
}

std::uint64_t make_k_odd(KbncForm& form) {
  if (form.b != 2 || form.k <= 0) throw Error("only k*2^n+c with k > 0 has an odd-k form");
  const mp_bitcnt_t twos = mpz_scan1(form.k.get_mpz_t(), 0);
  mpz_tdiv_q_2exp(form.k.get_mpz_t(), form.k.get_mpz_t(), twos);
  form.n += twos;
  return twos;
}

std::string kbnc_text(const KbncForm& form) {
  const std::string k = form.k == 1 ? std::string() : form.k.get_str() + "*";
  if (form.c == 0) return fmt::format("{}{}^{}", k, form.b, form.n);
  return fmt::format("{}{}^{}{:+d}", k, form.b, form.n, form.c);
}

}  // namespace tk::primes
