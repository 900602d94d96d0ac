/// @file test_weighted_squaring.cpp
/// @brief The weighted squaring against GMP (x^2 - m mod N computed
/// directly): random values and chains of squarings, k from 1 to 56 bits
/// (the 44-bit k of the twin records among them), both forms, n around
/// limb and digit boundaries, the edge values, and whole proofs. The
/// safety net is in test_squaring_safety.cpp.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include "primes/riesel_proof.hpp"
#include "primes/weighted_squaring.hpp"
#include "squaring_chain.hpp"

namespace {

using namespace tk::primes;

using squaring_test::expect_chain_matches;
using squaring_test::name_of;
using squaring_test::value_of;

TEST(WeightedSquaring, MatchesGmpForManyKOfBothSigns) {
  gmp_randclass random(gmp_randinit_default);
  random.seed(20261123);
  const std::uint64_t ks[] = {1, 3, 5, 1023, 65537, 778965587811ull, 16869987339975ull, (1ull << 44) - 1,
                              (1ull << 56) - 1, 72057594037927935ull - 2};
  const std::uint64_t ns[] = {64, 65, 127, 128, 1000, 4503, 36627};
  for (std::uint64_t k : ks)
    for (std::uint64_t n : ns)
      for (std::int64_t c : {-1, 1}) {
        const SpecialForm form{k, n, c};
        auto squarer = WeightedSquaring::create(form);
        ASSERT_NE(squarer, nullptr) << name_of(form);
        const mpz_class N = value_of(form);
        expect_chain_matches(*squarer, form, random.get_z_range(N), c < 0 ? 2 : 0, 12);
        EXPECT_EQ(squarer->fallbacks(), 0u) << name_of(form);
        EXPECT_LT(squarer->worst_roundoff(), 0.25) << name_of(form);
      }
}

TEST(WeightedSquaring, RandomKAndNAgainstGmp) {
  gmp_randclass random(gmp_randinit_default);
  random.seed(99);
  for (int trial = 0; trial < 60; ++trial) {
    const unsigned kbits = 1 + static_cast<unsigned>(mpz_class(random.get_z_range(56)).get_ui());
    const std::uint64_t k = mpz_class(random.get_z_bits(kbits) | 1).get_ui() | (1ull << (kbits - 1));
    const std::uint64_t n = 64 + mpz_class(random.get_z_range(20000)).get_ui();
    const SpecialForm form{k, n, trial % 2 ? 1 : -1};
    auto squarer = WeightedSquaring::create(form);
    ASSERT_NE(squarer, nullptr) << name_of(form);
    expect_chain_matches(*squarer, form, random.get_z_range(value_of(form)), trial % 3, 5);
    EXPECT_EQ(squarer->fallbacks(), 0u) << name_of(form);
  }
}

TEST(WeightedSquaring, EdgeValuesIncludingANegativeSquareMinusTwo) {
  for (std::int64_t c : {-1, 1}) {
    const SpecialForm form{778965587811ull, 3000, c};
    const mpz_class N = value_of(form);
    auto squarer = WeightedSquaring::create(form);
    ASSERT_NE(squarer, nullptr);
    for (const mpz_class& x : {mpz_class(0), mpz_class(1), mpz_class(2), mpz_class(N - 1), mpz_class(N - 2), mpz_class(N / 2)})
      for (unsigned long minus : {0ul, 2ul}) expect_chain_matches(*squarer, form, x, minus, 3);
  }
}

TEST(WeightedSquaring, LargeTwinNumberRoundsSafely) {
  const SpecialForm form{16869987339975ull, 171960, -1};
  auto squarer = WeightedSquaring::create(form);
  ASSERT_NE(squarer, nullptr);
  gmp_randclass random(gmp_randinit_default);
  random.seed(7);
  expect_chain_matches(*squarer, form, random.get_z_range(value_of(form)), 2, 4);
  EXPECT_EQ(squarer->fallbacks(), 0u);
  EXPECT_LT(squarer->worst_roundoff(), 0.25);
}

TEST(WeightedSquaring, RefusesKPast56Bits) {
  EXPECT_EQ(WeightedSquaring::create(SpecialForm{1ull << 57 | 1, 1000, -1}), nullptr);  // the padded FFT's case
}

}  // namespace

namespace {

TEST(WeightedSquaring, ProofsOnTheFftGiveGmpsVerdictsAndResidues) {
  // k small, 44-bit (the twin records' size), and past 56 bits (the padded
  // FFT's case); LLR and Proth, composites and whatever primes fall in.
  using namespace tk::primes;
  ProofOptions gmp, fft;
  gmp.arithmetic = Arithmetic::gmp;
  fft.arithmetic = Arithmetic::fft;
  for (std::uint64_t k : {3ull, 16869987339975ull, (1ull << 44) - 1, (1ull << 60) + 1})
    for (std::uint64_t n : {2000ull, 3001ull}) {
      const auto llr_gmp = llr_prove(k, n, LlrStart::llr, gmp), llr_fft = llr_prove(k, n, LlrStart::llr, fft);
      EXPECT_EQ(llr_gmp.verdict, llr_fft.verdict) << k << " " << n;
      EXPECT_EQ(llr_gmp.res64, llr_fft.res64) << k << " " << n;
      EXPECT_GT(llr_fft.fft_length, 0u);
      const auto proth_gmp = proth_prove(k, n, gmp), proth_fft = proth_prove(k, n, fft);
      EXPECT_EQ(proth_gmp.verdict, proth_fft.verdict) << k << " " << n;
      EXPECT_EQ(proth_gmp.res64, proth_fft.res64) << k << " " << n;
      EXPECT_EQ(proth_fft.check_restarts, 0u);
    }
}

}  // namespace
