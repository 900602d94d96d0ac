/// @file test_weighted_tests.cpp
/// @brief Miller-Rabin and Fermat on the weighted squaring against the same
/// tests by GMP (mpz_powm, the modulus taken without its form), on the
/// primes 3*2^n - 1 (OEIS A002235) and 3*2^n + 1 (A002253), composites of
/// both forms with k up to 56 bits, and bases that are squares (whose
/// Proth chains reach 1 early, left to the GMP test); the Lucas test's
/// W^2 - 2 chain against GMP's.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include "primes/big_tests.hpp"
#include "primes/weighted_tests.hpp"
#include "squaring_chain.hpp"

namespace {

using namespace tk::primes;
using squaring_test::name_of;
using squaring_test::value_of;

// The weighted tests' verdict where they give one, else the GMP test's
// (as big_tests does), against the GMP test alone.
void expect_same_verdicts(const SpecialForm& form, std::initializer_list<unsigned long> bases) {
  const mpz_class value = value_of(form);
  const Modulus with_form(value, form), plain(value);
  for (unsigned long base : bases) {
    const mpz_class b = base;
    const bool gmp_strong = strong_probable_prime(plain, b), gmp_fermat = fermat_probable_prime(plain, b);
    const auto strong = weighted_strong_probable_prime(with_form, b, nullptr, 0);
    const auto fermat = weighted_fermat_probable_prime(with_form, b, 0);
    ASSERT_TRUE(fermat.has_value()) << name_of(form);
    EXPECT_EQ(*fermat, gmp_fermat) << name_of(form) << " base " << base;
    if (strong) {
      EXPECT_EQ(*strong, gmp_strong) << name_of(form) << " base " << base;
    }
    EXPECT_EQ(strong_probable_prime(with_form, b), gmp_strong) << name_of(form) << " base " << base;
    // Proth: undecided only when the chain reached 1 before its last step.
    if (!strong) {
      EXPECT_EQ(form.c, 1) << name_of(form);
    }
  }
}

TEST(WeightedTests, PrimesOfTheOeisPassEveryBase) {
  for (std::uint64_t n : {76, 94, 103, 143, 206, 216, 306, 324, 391, 458, 470, 827, 1274})
    expect_same_verdicts({3, n, -1}, {2, 3, 4, 5, 9, 10});
  for (std::uint64_t n : {66, 189, 201, 209, 276, 353, 408, 438, 534})
    expect_same_verdicts({3, n, 1}, {2, 3, 4, 5, 9, 10});
  const SpecialForm prime{3, 534, 1};
  EXPECT_FALSE(weighted_strong_probable_prime(Modulus(value_of(prime), prime), 4, nullptr, 0).has_value())
      << "4 is a square: its Proth chain reaches 1 before the last step";
  EXPECT_EQ(weighted_strong_probable_prime(Modulus(value_of(prime), prime), 5, nullptr, 0), true);
}

TEST(WeightedTests, CompositesOfBothFormsFailAsByGmp) {
  gmp_randclass random(gmp_randinit_default);
  random.seed(2611);
  int composites = 0;
  for (int trial = 0; trial < 24; ++trial) {
    const unsigned kbits = 1 + static_cast<unsigned>(mpz_class(random.get_z_range(56)).get_ui());
    const std::uint64_t k = mpz_class(random.get_z_bits(kbits) | 1).get_ui() | (1ull << (kbits - 1));
    const std::uint64_t n = 64 + mpz_class(random.get_z_range(3000)).get_ui();
    const SpecialForm form{k, n, trial % 2 ? 1 : -1};
    expect_same_verdicts(form, {2, 7});
    composites += mpz_probab_prime_p(value_of(form).get_mpz_t(), 25) == 0;
  }
  EXPECT_GE(composites, 18);
}

// The Lucas test's tail W -> W^2 - 2 against GMP's, and the Lucas-Lehmer
// chain of the Mersenne prime 2^1279 - 1 (from 4, 0 after 1277 steps).
TEST(WeightedTests, MinusTwoChainsAreGmps) {
  gmp_randclass random(gmp_randinit_default);
  random.seed(5);
  for (const SpecialForm form : {SpecialForm{3, 1274, -1}, SpecialForm{778965587811ull, 3001, -1}, SpecialForm{(1ull << 55) + 3, 777, -1}}) {
    const mpz_class N = value_of(form);
    const Modulus modulus(N, form);
    mpz_class w = random.get_z_range(N);
    const auto got = weighted_minus_two_chain(modulus, w, 100, nullptr, 0);
    ASSERT_TRUE(got.has_value());
    for (int i = 0; i < 100; ++i) w = (w * w - 2) % N;
    if (w < 0) w += N;
    EXPECT_EQ(*got, w) << name_of(form);
  }
  const SpecialForm mersenne{1, 1279, -1};
  EXPECT_EQ(weighted_minus_two_chain(Modulus(value_of(mersenne), mersenne), 4, 1277, nullptr, 0), mpz_class(0));
  EXPECT_NE(weighted_minus_two_chain(Modulus(value_of(mersenne), mersenne), 4, 1276, nullptr, 0), mpz_class(0));
}

TEST(WeightedTests, BelowTheirSizeOrOutsideTheFormTheyStepAside) {
  const SpecialForm form{3, 1274, -1};
  EXPECT_FALSE(weighted_strong_probable_prime(Modulus(value_of(form), form), 2).has_value());  // below 24,000 bits
  EXPECT_FALSE(weighted_fermat_probable_prime(Modulus(value_of(form)), 2, 0).has_value());     // no form
  EXPECT_FALSE(weighted_minus_two_chain(Modulus(value_of(form), form), 4, 10).has_value());
}

}  // namespace
