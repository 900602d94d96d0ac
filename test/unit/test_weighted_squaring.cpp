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
  const std::uint64_t ks[] = {1,
                              3,
                              5,
                              1023,
                              65537,
                              778965587811ull,
                              16869987339975ull,
                              (1ull << 44) - 1,
                              (1ull << 56) - 1,
                              72057594037927935ull - 2};
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
    for (const mpz_class& x :
         {mpz_class(0), mpz_class(1), mpz_class(2), mpz_class(N - 1), mpz_class(N - 2), mpz_class(N / 2)})
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

// Each transform (ours at AVX-512 and AVX2 width, FFTW's) at lengths ours
// plans with radix-3, radix-2 and radix-4 passes, with the digits create()
// would choose there: chains against GMP, no square redone.
TEST(WeightedSquaring, EveryTransformMatchesGmp) {
  gmp_randclass random(gmp_randinit_default);
  random.seed(20261126);
  struct Case {
    SpecialForm form;
    std::size_t length;
    int digit_bits;
  };
  const Case cases[] = {
      {{778965587811ull, 36627, -1}, 4096, 21}, {{3, 36627, 1}, 6144, 14},  {{16869987339975ull, 60000, -1}, 6144, 21},
      {{(1ull << 56) - 5, 90001, 1}, 9216, 21}, {{1, 20000, -1}, 2304, 19}, {{65537, 4503, 1}, 576, 19}};
  using Transform = WeightedSquaring::Transform;
  int own = 0;
  for (Transform transform : {Transform::widest, Transform::avx2, Transform::fftw})
    for (const Case& c : cases) {
      auto squarer = WeightedSquaring::create_with(c.form, c.length, c.digit_bits, transform);
      ASSERT_NE(squarer, nullptr) << name_of(c.form) << " at " << c.length;
      if (transform == Transform::fftw) {
        EXPECT_EQ(squarer->transform_name(), "FFTW");
      }
      if (transform == Transform::avx2 && __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) {
        EXPECT_EQ(squarer->transform_name(), "right-angle, 4 lanes");
      }
      own += squarer->transform_name() != "FFTW";
      const mpz_class N = value_of(c.form);
      expect_chain_matches(*squarer, c.form, random.get_z_range(N), c.form.c < 0 ? 2 : 0, 6);
      EXPECT_EQ(squarer->fallbacks(), 0u) << name_of(c.form) << " by " << squarer->transform_name();
      EXPECT_LT(squarer->worst_roundoff(), 0.3) << name_of(c.form) << " by " << squarer->transform_name();
    }
  if (!__builtin_cpu_supports("avx2")) GTEST_SKIP() << "no AVX2: only FFTW's transform ran";
  EXPECT_EQ(own, 12);  // both of ours, on every case
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
