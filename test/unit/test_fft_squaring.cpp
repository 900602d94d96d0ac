/// @file test_fft_squaring.cpp
/// @brief The FFT squaring against GMP's mpz arithmetic (x^2 - m mod N
/// computed directly): random values, chains of squarings, the edge values
/// 0, 1, 2 and N-1, both forms k*2^n-1 and k*2^n+1, limb-aligned n; and
/// the safety net: digits too wide to round correctly must be caught and
/// redone, never give a wrong square.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <random>

#include "primes/fft_squaring.hpp"
#include "primes/riesel_proof.hpp"

namespace {

using namespace tk::primes;

mpz_class value_of(const SpecialForm& form) {
  mpz_class N = form.k;
  N <<= static_cast<mp_bitcnt_t>(form.n);
  return N + form.c;
}

mpz_class square_minus_directly(const mpz_class& x, unsigned long minus, const mpz_class& N) {
  mpz_class r = x * x - minus;
  mpz_mod(r.get_mpz_t(), r.get_mpz_t(), N.get_mpz_t());
  return r;
}

void expect_chain_matches(FftSquaring& fft, const SpecialForm& form, mpz_class x, unsigned long minus, int rounds) {
  const mpz_class N = value_of(form);
  fft.load(x);
  for (int round = 0; round < rounds; ++round) {
    fft.square_minus(minus);
    x = square_minus_directly(x, minus, N);
    mpz_class got;
    fft.store(got);
    ASSERT_EQ(got, x) << form.k << "*2^" << form.n << (form.c > 0 ? "+1" : "-1") << " round " << round;
  }
}

TEST(FftSquaring, MatchesGmpOnRandomValuesOfBothForms) {
  gmp_randclass random(gmp_randinit_default);
  random.seed(20261122);
  const std::uint64_t ks[] = {1, 3, 778965587811ull, 16869987339975ull, 0xFFFFFFFFFFFFFFFFull};
  const std::uint64_t ns[] = {64, 127, 128, 1000, 4503, 36627};
  for (std::uint64_t k : ks)
    for (std::uint64_t n : ns)
      for (std::int64_t c : {-1, 1}) {
        const SpecialForm form{k, n, c};
        auto fft = FftSquaring::create(form);
        ASSERT_NE(fft, nullptr);
        const mpz_class N = value_of(form);
        expect_chain_matches(*fft, form, random.get_z_range(N), c < 0 ? 2 : 0, 20);
        EXPECT_EQ(fft->fallbacks(), 0u);
        EXPECT_LT(fft->worst_roundoff(), 0.1);
      }
}

TEST(FftSquaring, EdgeValuesIncludingANegativeSquareMinusTwo) {
  for (std::int64_t c : {-1, 1}) {
    const SpecialForm form{778965587811ull, 3000, c};
    const mpz_class N = value_of(form);
    auto fft = FftSquaring::create(form);
    ASSERT_NE(fft, nullptr);
    for (const mpz_class& x : {mpz_class(0), mpz_class(1), mpz_class(2), mpz_class(N - 1), mpz_class(N - 2), mpz_class(N / 2)})
      for (unsigned long minus : {0ul, 2ul}) expect_chain_matches(*fft, form, x, minus, 3);
  }
}

TEST(FftSquaring, LargeNumberPicksALengthAndDigitsThatRoundSafely) {
  const SpecialForm form{16869987339975ull, 171960, -1};
  auto fft = FftSquaring::create(form);
  ASSERT_NE(fft, nullptr);
  // The square must not wrap: twice the digits fit the transform.
  EXPECT_GE(fft->transform_length() * static_cast<std::size_t>(fft->digit_bits()), 2 * (171960 + 44));
  EXPECT_LE(fft->digit_bits(), 20);
  gmp_randclass random(gmp_randinit_default);
  random.seed(7);
  expect_chain_matches(*fft, form, random.get_z_range(value_of(form)), 2, 4);
  EXPECT_EQ(fft->fallbacks(), 0u);
}

TEST(FftSquaring, DigitsTooWideAreCaughtAndRedoneByGmp) {
  // 30-bit digits at length 4096: coefficients near 2^67, far past a
  // double's 53 bits, so nearly every square rounds wrongly. Every one must
  // be caught and redone, and the chain must still equal GMP's.
  const SpecialForm form{778965587811ull, 40000, -1};
  auto fft = FftSquaring::create_with(form, 4096, 30);
  ASSERT_NE(fft, nullptr);
  gmp_randclass random(gmp_randinit_default);
  random.seed(11);
  expect_chain_matches(*fft, form, random.get_z_range(value_of(form)), 2, 10);
  EXPECT_EQ(fft->fallbacks(), 10u);
}

TEST(FftSquaring, BorderlineDigitsStillNeverGiveAWrongSquare) {
  // 23-bit digits at length 8192: errors near 0.5, some squares caught and
  // some (correctly) kept; whatever the split, the values must be GMP's.
  const SpecialForm form{3, 90000, 1};
  auto fft = FftSquaring::create_with(form, 8192, 23);
  ASSERT_NE(fft, nullptr);
  gmp_randclass random(gmp_randinit_default);
  random.seed(12);
  expect_chain_matches(*fft, form, random.get_z_range(value_of(form)), 0, 30);
}

TEST(FftSquaring, RefusesFormsItCannotReduce) {
  EXPECT_EQ(FftSquaring::create(SpecialForm{3, 63, -1}), nullptr);  // n < 64: GMP's job
  EXPECT_EQ(FftSquaring::create(SpecialForm{4, 1000, -1}), nullptr);  // even k
  EXPECT_EQ(FftSquaring::create(SpecialForm{3, 1000, 5}), nullptr);   // c other than +-1
  EXPECT_EQ(FftSquaring::create_with(SpecialForm{3, 10000, -1}, 512, 16), nullptr);  // would wrap
}

TEST(FftSquaring, ProofsAgreeAcrossArithmetics) {
  // Primes, composites with their res64, LLR and Proth: identical results
  // whether GMP or the FFT squares (n from 64 up so the FFT takes them).
  for (std::uint64_t n : {4502ull, 4503ull, 4504ull, 5000ull}) {
    ProofOptions gmp, fft;
    gmp.arithmetic = Arithmetic::gmp;
    fft.arithmetic = Arithmetic::fft;
    const auto llr_gmp = llr_prove(1327691127, n, LlrStart::llr, gmp), llr_fft = llr_prove(1327691127, n, LlrStart::llr, fft);
    EXPECT_EQ(llr_gmp.verdict, llr_fft.verdict) << n;
    EXPECT_EQ(llr_gmp.res64, llr_fft.res64) << n;
    EXPECT_GT(llr_fft.fft_length, 0u);
    EXPECT_EQ(llr_gmp.fft_length, 0u);
    const auto proth_gmp = proth_prove(1327691127, n, gmp), proth_fft = proth_prove(1327691127, n, fft);
    EXPECT_EQ(proth_gmp.verdict, proth_fft.verdict) << n;
    EXPECT_EQ(proth_gmp.res64, proth_fft.res64) << n;
  }
  ProofOptions fft;
  fft.arithmetic = Arithmetic::fft;
  EXPECT_EQ(llr_prove(1327691127, 4502, LlrStart::llr, fft).verdict, Verdict::prime);  // OpenPFGW's twin
  EXPECT_EQ(proth_prove(1327691127, 4502, fft).verdict, Verdict::prime);
}

}  // namespace
