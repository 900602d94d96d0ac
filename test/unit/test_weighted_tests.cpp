/// @file test_weighted_tests.cpp
/// @brief Miller-Rabin and Fermat on the weighted squaring against the same
/// tests by GMP (mpz_powm, the modulus taken without its form), on the
/// primes 3*2^n - 1 (OEIS A002235) and 3*2^n + 1 (A002253), composites of
/// both forms with k up to 56 bits, bases that are squares (whose Proth
/// chains reach -1 early) and a base sharing a factor with N; the Lucas
/// test's W^2 - 2 tail against GMP's.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include "primes/big_tests.hpp"
#include "primes/weighted_tests.hpp"
#include "squaring_chain.hpp"

namespace {

using namespace tk::primes;
using squaring_test::name_of;
using squaring_test::value_of;

// The weighted tests' verdicts against the GMP tests (the modulus taken
// without its form, so GMP's mpz_powm): both must give one, the same.
void expect_same_verdicts(const SpecialForm& form, std::initializer_list<unsigned long> bases) {
  const mpz_class value = value_of(form);
  const Modulus with_form(value, form), plain(value);
  for (unsigned long base : bases) {
    const mpz_class b = base;
    const auto strong = weighted_strong_probable_prime(with_form, b, nullptr, 0);
    const auto fermat = weighted_fermat_probable_prime(with_form, b, 0);
    ASSERT_TRUE(strong.has_value() && fermat.has_value()) << name_of(form) << " base " << base;
    EXPECT_EQ(*strong, strong_probable_prime(plain, b)) << name_of(form) << " base " << base;
    EXPECT_EQ(*fermat, fermat_probable_prime(plain, b)) << name_of(form) << " base " << base;
  }
}

TEST(WeightedTests, PrimesOfTheOeisPassEveryBase) {
  for (std::uint64_t n : {76, 94, 103, 143, 206, 216, 306, 324, 391, 458, 470, 827, 1274})
    expect_same_verdicts({3, n, -1}, {2, 3, 4, 5, 9, 10});
  for (std::uint64_t n : {66, 189, 201, 209, 276, 353, 408, 438, 534})
    expect_same_verdicts({3, n, 1}, {2, 3, 4, 5, 9, 10});
}

// A base that shares a factor with N: b^d is then never +-1, whatever the
// chain gives (N = 3*2^100 - 1 = 313*q, b = 0 mod 313 and 1 mod q).
TEST(WeightedTests, ABaseSharingAFactorFails) {
  const SpecialForm form{3, 100, -1};
  const mpz_class N = value_of(form), q = N / 313;
  ASSERT_EQ(N % 313, 0);
  mpz_class inverse;
  mpz_invert(inverse.get_mpz_t(), mpz_class(313).get_mpz_t(), q.get_mpz_t());
  const mpz_class b = 313 * inverse % N;  // 0 mod 313, 1 mod q
  const Modulus modulus(N, form);
  EXPECT_EQ(weighted_strong_probable_prime(modulus, b, nullptr, 0), false);
  EXPECT_EQ(weighted_fermat_probable_prime(modulus, b, 0), false);
  EXPECT_FALSE(strong_probable_prime(Modulus(N), b));
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

// The Lucas test's tail: the first W_r = 0, against GMP's loop. The
// Lucas-Lehmer chain of the Mersenne prime 2^1279 - 1 from 4 reaches 0 at
// r = 1278, the last step; from sqrt(2) = 2^640 it does at r = 2 (W goes
// on -2, 2, 2, ...); a random start of a composite never does.
TEST(WeightedTests, LucasTailsFindTheirFirstZero) {
  const SpecialForm mersenne{1, 1279, -1};
  const mpz_class M = value_of(mersenne);
  const Modulus modulus(M, mersenne);
  auto first_zero = [&](const mpz_class& w) {
    const auto tail = weighted_lucas_tail(modulus, w, 1278, nullptr, 0);
    EXPECT_TRUE(tail.has_value());
    return tail ? tail->zero_at : 0;
  };
  EXPECT_EQ(first_zero(4), 1278u);
  mpz_class root = 1;
  root <<= 640;
  EXPECT_EQ(first_zero(root), 2u);
  EXPECT_EQ(first_zero(0), 1u);
  const SpecialForm composite{778965587811ull, 3001, -1};
  gmp_randclass random(gmp_randinit_default);
  random.seed(5);
  const mpz_class N = value_of(composite);
  mpz_class w = random.get_z_range(N);
  const auto tail = weighted_lucas_tail(Modulus(N, composite), w, 500, nullptr, 0);
  ASSERT_TRUE(tail.has_value());
  bool zero = false;
  for (int r = 1; r <= 500 && !zero; ++r, w = (w * w - 2) % N) zero = w == 0;
  EXPECT_FALSE(zero);
  EXPECT_EQ(tail->zero_at, 0u);
}

TEST(WeightedTests, BelowTheirSizeOrOutsideTheFormTheyStepAside) {
  const SpecialForm form{3, 1274, -1};
  EXPECT_FALSE(weighted_strong_probable_prime(Modulus(value_of(form), form), 2).has_value());  // below 24,000 bits
  EXPECT_FALSE(weighted_fermat_probable_prime(Modulus(value_of(form)), 2, 0).has_value());     // no form
  EXPECT_FALSE(weighted_lucas_tail(Modulus(value_of(form), form), 4, 10).has_value());
}

}  // namespace
