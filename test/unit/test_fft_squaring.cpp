/// @file test_fft_squaring.cpp
/// @brief The FFT squaring against GMP's mpz arithmetic (x^2 - m mod N
/// computed directly): random values, chains of squarings, the edge values
/// 0, 1, 2 and N-1, both forms k*2^n-1 and k*2^n+1, limb-aligned n. The
/// safety net is in test_squaring_safety.cpp.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <random>

#include "primes/fft_squaring.hpp"
#include "primes/riesel_proof.hpp"
#include "squaring_chain.hpp"

namespace {

using namespace tk::primes;

using squaring_test::value_of;

void expect_chain_matches(FftSquaring& fft, const SpecialForm& form, mpz_class x, unsigned long minus, int rounds) {
  squaring_test::expect_chain_matches(fft, form, x, minus, rounds);
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
    for (const mpz_class& x :
         {mpz_class(0), mpz_class(1), mpz_class(2), mpz_class(N - 1), mpz_class(N - 2), mpz_class(N / 2)})
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

TEST(FftSquaring, ProofsAgreeAcrossArithmetics) {
  // Primes, composites with their res64, LLR and Proth: identical results
  // whether GMP or the FFT squares (n from 64 up so the FFT takes them).
  for (std::uint64_t n : {4502ull, 4503ull, 4504ull, 5000ull}) {
    ProofOptions gmp, fft;
    gmp.arithmetic = Arithmetic::gmp;
    fft.arithmetic = Arithmetic::fft;
    const auto llr_gmp = llr_prove(1327691127, n, LlrStart::llr, gmp),
               llr_fft = llr_prove(1327691127, n, LlrStart::llr, fft);
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
