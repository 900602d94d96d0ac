/// @file test_gerbicz_check.cpp
/// @brief Gerbicz's check of the Proth squarings and the Jacobi check of
/// LLR's Lucas sequence on the FFT, by injected errors: a value altered at
/// a block's end (or in the tail, or before a Jacobi check, to one whose
/// u - 2 is a square) must be caught, the proof redone from the last
/// verified state, and the verdict and res64 must equal GMP's; an error
/// that recurs every time must stop the proof with an error, never give a
/// verdict.
#include <gtest/gtest.h>

#include "io/error.hpp"
#include "primes/gerbicz_check.hpp"
#include "primes/jacobi_check.hpp"
#include "primes/riesel_proof.hpp"

namespace {

using namespace tk::primes;

ProofOptions with(Arithmetic arithmetic) {
  ProofOptions options;
  options.arithmetic = arithmetic;
  return options;
}

// Flips a low bit of the value the first time the iteration is `at`.
std::function<bool(std::uint64_t, mpz_class&)> flip_once_at(std::uint64_t at) {
  auto done = std::make_shared<bool>(false);
  return [at, done](std::uint64_t iteration, mpz_class& value) {
    if (*done || iteration != at) return false;
    *done = true;
    mpz_combit(value.get_mpz_t(), 5);
    return true;
  };
}

TEST(GerbiczCheck, PlanGrowsWithTheProof) {
  EXPECT_EQ(gerbicz_plan(100).block, 32u);
  EXPECT_EQ(gerbicz_plan(4501).block, 67u);
  EXPECT_EQ(gerbicz_plan(171959).block, 414u);
  EXPECT_EQ(gerbicz_plan(100000000).block, 1000u);
}

TEST(GerbiczCheck, AnErrorInABlockIsCaughtAndTheProofRedone) {
  // n = 4502: B = 67, 67 blocks and a tail of 12. Prime and composites.
  for (std::uint64_t n : {4502ull, 4503ull, 5000ull}) {
    const auto by_gmp = proth_prove(1327691127, n, with(Arithmetic::gmp));
    const std::uint64_t block = gerbicz_plan(n - 1).block;
    for (std::uint64_t at : {block, 10 * block, (block - 1) * block}) {
      ProofOptions fft = with(Arithmetic::fft);
      fft.corrupt_for_tests = flip_once_at(at);
      const auto checked = proth_prove(1327691127, n, fft);
      EXPECT_EQ(checked.check_restarts, 1u) << n << " at " << at;
      EXPECT_EQ(checked.verdict, by_gmp.verdict) << n << " at " << at;
      EXPECT_EQ(checked.res64, by_gmp.res64) << n << " at " << at;
    }
  }
  EXPECT_EQ(proth_prove(1327691127, 4502, with(Arithmetic::gmp)).verdict, Verdict::prime);
}

TEST(GerbiczCheck, AnErrorInTheTailIsCaughtByItsSecondRun) {
  ProofOptions fft = with(Arithmetic::fft);
  fft.corrupt_for_tests = flip_once_at(4501);  // the last iteration: in the tail
  const auto checked = proth_prove(1327691127, 4502, fft);
  EXPECT_EQ(checked.check_restarts, 1u);
  EXPECT_EQ(checked.verdict, Verdict::prime);
}

TEST(GerbiczCheck, WithoutErrorsNothingIsRedone) {
  const auto checked = proth_prove(1327691127, 4502, with(Arithmetic::fft));
  EXPECT_EQ(checked.check_restarts, 0u);
  EXPECT_EQ(checked.verdict, Verdict::prime);
  EXPECT_GT(checked.fft_length, 0u);
}

TEST(GerbiczCheck, AnErrorThatAlwaysRecursStopsTheProof) {
  ProofOptions fft = with(Arithmetic::fft);
  fft.corrupt_for_tests = [](std::uint64_t iteration, mpz_class& value) {
    if (iteration != 670) return false;
    mpz_combit(value.get_mpz_t(), 5);
    return true;
  };
  EXPECT_THROW(proth_prove(1327691127, 4502, fft), tk::Error);
}

// Sets u to 3 (u - 2 = 1, a square: Jacobi +1, never -1) the first time
// the iteration is `at`.
std::function<bool(std::uint64_t, mpz_class&)> three_once_at(std::uint64_t at) {
  auto done = std::make_shared<bool>(false);
  return [at, done](std::uint64_t iteration, mpz_class& value) {
    if (*done || iteration != at) return false;
    *done = true;
    value = 3;
    return true;
  };
}

TEST(JacobiCheck, AnErrorBeforeACheckIsCaughtAndTheProofRedone) {
  // n = 12000: checks at 5000, 10000 and the end (11998); n = 4502 (a
  // prime): only at the end, so the restart goes back to u_0.
  const std::pair<std::uint64_t, std::uint64_t> cases[] = {{12000, 5000}, {12000, 10000}, {12000, 11998}, {4502, 4500}};
  for (const auto& [n, at] : cases) {
    const auto by_gmp = llr_prove(1327691127, n, LlrStart::llr, with(Arithmetic::gmp));
    ProofOptions fft = with(Arithmetic::fft);
    fft.corrupt_for_tests = three_once_at(at);
    const auto checked = llr_prove(1327691127, n, LlrStart::llr, fft);
    EXPECT_EQ(checked.check_restarts, 1u) << n << " at " << at;
    EXPECT_EQ(checked.verdict, by_gmp.verdict) << n << " at " << at;
    EXPECT_EQ(checked.res64, by_gmp.res64) << n << " at " << at;
  }
  EXPECT_EQ(llr_prove(1327691127, 4502, LlrStart::llr, with(Arithmetic::gmp)).verdict, Verdict::prime);
}

TEST(JacobiCheck, TheIdentityHoldsForBothStartsWithoutErrors) {
  // (P^2 - 4 / N) = -1 for LLR's P and for the seed's P = 11 (D = 13), on
  // the Riesel prime 3*2^12676 - 1 (OEIS A002235; (13/N) = -1, PARI): two
  // checks on the way and one at the end, a ninth of the seed's squaring
  // time (the seed's proofs took 16.7 s of the sanitized unit tests).
  for (const LlrStart start : {LlrStart::llr, LlrStart::d13}) {
    const auto checked = llr_prove(3, 12676, start, with(Arithmetic::fft));
    EXPECT_EQ(checked.check_restarts, 0u);
    EXPECT_EQ(checked.verdict, Verdict::prime);
  }
  const auto composite = llr_prove(3, 12001, LlrStart::llr, with(Arithmetic::fft));  // P = 5 (3 divides k)
  EXPECT_EQ(composite.check_restarts, 0u);
}

TEST(JacobiCheck, AnErrorThatAlwaysRecursStopsTheProof) {
  ProofOptions fft = with(Arithmetic::fft);
  fft.corrupt_for_tests = [](std::uint64_t iteration, mpz_class& value) {
    if (iteration != 5000) return false;
    value = 3;
    return true;
  };
  EXPECT_THROW(llr_prove(1327691127, 12000, LlrStart::llr, fft), tk::Error);
}

}  // namespace
