/// @file test_transform_bpsw.cpp
/// @brief BPSW and its two halves on generic N where the transform loops
/// switch on (kTransformPowerFromBits, kTransformLucasFromBits), against
/// GMP: primes from mpz_nextprime and products of two of them, with GMP's
/// mpz_probab_prime_p (BPSW in GMP >= 6.2) and the strong test by
/// mpz_powm as oracles; and Mersenne numbers 2^p - 1 taken as generic
/// (no special form): a composite one with p prime is a strong base-2
/// pseudoprime, which the Lucas half must catch, as the special-form code
/// (weighted transform) does on the same number.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include "primes/big_tests.hpp"
#include "primes/primality.hpp"
#include "primes/transform_tests.hpp"

namespace transform_bpsw_test {

using namespace tk::primes;

// The strong test to base 2 by its definition, with mpz_powm.
bool strong_base2_by_powm(const mpz_class& n) {
  mpz_class d = n - 1, x;
  const mp_bitcnt_t s = mpz_scan1(d.get_mpz_t(), 0);
  d >>= s;
  mpz_powm(x.get_mpz_t(), mpz_class(2).get_mpz_t(), d.get_mpz_t(), n.get_mpz_t());
  if (x == 1 || x == n - 1) return true;
  for (mp_bitcnt_t r = 1; r < s; ++r) {
    mpz_powm_ui(x.get_mpz_t(), x.get_mpz_t(), 2, n.get_mpz_t());
    if (x == n - 1) return true;
  }
  return false;
}

bool lucas_generic(const mpz_class& n) {
  const SelfridgeChoice choice = selfridge_d(n);
  mpz_class factor;
  return strong_lucas_probable_prime(Modulus(n), choice.d, factor);
}

mpz_class prime_of(unsigned long bits, gmp_randclass& random) {
  mpz_class p = random.get_z_bits(bits);
  mpz_setbit(p.get_mpz_t(), bits - 1);
  mpz_nextprime(p.get_mpz_t(), p.get_mpz_t());
  return p;
}

TEST(TransformBpsw, PrimesAndSemiprimesAtTheCrossoversAgreeWithGmp) {
  gmp_randclass random(gmp_randinit_mt);
  random.seed(2307);
  const mpz_class m61 = (mpz_class(1) << 61) - 1;  // a known prime
  for (unsigned long bits :
       {kTransformLucasFromBits - 1, kTransformLucasFromBits, kTransformPowerFromBits - 1, kTransformPowerFromBits}) {
    const mpz_class p = prime_of(bits, random);
    // the one below the crossover is prime times 2^61 - 1 above it
    const mpz_class semiprime = bits % 2 ? p * m61 : prime_of(bits / 2, random) * prime_of(bits - bits / 2, random);
    for (const mpz_class& n : {p, semiprime}) {
      const bool gmp = mpz_probab_prime_p(n.get_mpz_t(), 0) != 0;
      EXPECT_EQ(strong_probable_prime(Modulus(n), 2), strong_base2_by_powm(n)) << bits;
      EXPECT_EQ(lucas_generic(n), gmp) << bits;  // GMP's BPSW: a semiprime fails both halves here
      const TestOutcome got = test_number(Number{n, std::nullopt}, TestPlan{});
      EXPECT_EQ(got.verdict == Verdict::probable_prime, gmp) << bits;
      EXPECT_EQ(got.verdict == Verdict::composite, !gmp) << bits;
    }
    EXPECT_TRUE(mpz_probab_prime_p(p.get_mpz_t(), 0));
  }
}

TEST(TransformBpsw, MersenneNumbersAsGenericModuli) {
  // 2203, 2281, 3217, 4253: Mersenne primes; 2003, 2011, 3001, 3011, 4001
  // prime exponents of composite 2^p - 1 (strong base-2 pseudoprimes).
  for (unsigned long p : {2003ul, 2011ul, 2203ul, 2281ul, 3001ul, 3011ul, 3217ul, 4001ul, 4253ul}) {
    mpz_class n;
    mpz_ui_pow_ui(n.get_mpz_t(), 2, p);
    n -= 1;
    const bool prime = p == 2203 || p == 2281 || p == 3217 || p == 4253;
    EXPECT_TRUE(strong_probable_prime(Modulus(n), 2)) << p;
    EXPECT_TRUE(strong_base2_by_powm(n)) << p;
    const SelfridgeChoice choice = selfridge_d(n);
    mpz_class factor;
    const bool special = strong_lucas_probable_prime(Modulus(n, SpecialForm{1, p, -1}), choice.d, factor);
    EXPECT_EQ(lucas_generic(n), special) << p;
    EXPECT_EQ(lucas_generic(n), prime) << p;
    EXPECT_EQ(mpz_probab_prime_p(n.get_mpz_t(), 0) != 0, prime) << p;
  }
}

}  // namespace transform_bpsw_test
