/// @file squaring_chain.hpp
/// @brief What the squarers' tests share: N of a form, and a chain of
/// squarings checked against GMP's x^2 - m mod N after every step.
#pragma once

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <string>

#include "primes/modulus.hpp"

namespace squaring_test {

inline mpz_class value_of(const tk::primes::SpecialForm& form) {
  mpz_class N = form.k;
  N <<= static_cast<mp_bitcnt_t>(form.n);
  return N + form.c;
}

inline std::string name_of(const tk::primes::SpecialForm& form) {
  return std::to_string(form.k) + "*2^" + std::to_string(form.n) + (form.c > 0 ? "+1" : "-1");
}

template <class Squarer>
void expect_chain_matches(Squarer& squarer, const tk::primes::SpecialForm& form, mpz_class x, unsigned long minus,
                          int rounds) {
  const mpz_class N = value_of(form);
  squarer.load(x);
  for (int round = 0; round < rounds; ++round) {
    squarer.square_minus(minus);
    x = x * x - minus;
    mpz_mod(x.get_mpz_t(), x.get_mpz_t(), N.get_mpz_t());
    mpz_class got;
    squarer.store(got);
    ASSERT_EQ(got, x) << name_of(form) << " round " << round;
  }
}

}  // namespace squaring_test
