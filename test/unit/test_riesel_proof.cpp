/// @file test_riesel_proof.cpp
/// @brief LLR and Proth proofs against published tables (OEIS A002235,
/// A002253, A002254), GMP's own test on random k and n, and each other (LLR's
/// P against the seed's D = 13), plus resuming from a saved state.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "io/error.hpp"
#include "primes/riesel_proof.hpp"

namespace {

using namespace tk::primes;

std::vector<std::uint64_t> llr_primes(std::uint64_t k, std::uint64_t n_max) {
  std::vector<std::uint64_t> ns;
  for (std::uint64_t n = 2; n <= n_max; ++n)
    if ((n >= 64 || k < (std::uint64_t(1) << n)) && llr_prove(k, n, LlrStart::llr).verdict == Verdict::prime)
      ns.push_back(n);
  return ns;
}

std::vector<std::uint64_t> proth_primes(std::uint64_t k, std::uint64_t n_max) {
  std::vector<std::uint64_t> ns;
  for (std::uint64_t n = 1; n <= n_max; ++n)
    if ((n >= 64 || k < (std::uint64_t(1) << n)) && proth_prove(k, n).verdict == Verdict::prime) ns.push_back(n);
  return ns;
}

TEST(RieselProof, OeisA002235ThreeTimesPowerMinusOne) {
  // n with 3*2^n - 1 prime (OEIS A002235), n >= 2 (k < 2^n)
  EXPECT_EQ(llr_primes(3, 1300),
            (std::vector<std::uint64_t>{2,  3,   4,   6,   7,   11,  18,  34,  38,  43,  55,  64,  76,
                                        94, 103, 143, 206, 216, 306, 324, 391, 458, 470, 827, 1274}));
}

TEST(RieselProof, OeisA002253ThreeTimesPowerPlusOne) {
  // n with 3*2^n + 1 prime (OEIS A002253), n >= 2 (k < 2^n)
  EXPECT_EQ(proth_primes(3, 1300),
            (std::vector<std::uint64_t>{2, 5, 6, 8, 12, 18, 30, 36, 41, 66, 189, 201, 209, 276, 353, 408, 438, 534}));
}

TEST(RieselProof, OeisA002254FiveTimesPowerPlusOne) {
  // n with 5*2^n + 1 prime (OEIS A002254), n >= 3 (k < 2^n)
  EXPECT_EQ(proth_primes(5, 1000), (std::vector<std::uint64_t>{3, 7, 13, 15, 25, 39, 55, 75, 85, 127}));
}

TEST(RieselProof, AgreesWithGmpAndTheSeedsStart) {
  std::mt19937_64 random(11);
  int primes = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const std::uint64_t n = 20 + random() % 300;
    const std::uint64_t k = (random() % 100000) | 1;
    mpz_class N = k;
    N <<= n;
    const bool gmp_minus = mpz_probab_prime_p(mpz_class(N - 1).get_mpz_t(), 30) > 0;
    const bool gmp_plus = mpz_probab_prime_p(mpz_class(N + 1).get_mpz_t(), 30) > 0;
    const ProofResult minus = llr_prove(k, n, LlrStart::llr);
    EXPECT_EQ(minus.verdict == Verdict::prime, gmp_minus) << k << "*2^" << n << "-1";
    EXPECT_EQ(proth_prove(k, n).verdict == Verdict::prime, gmp_plus) << k << "*2^" << n << "+1";
    if (llr_parameter(k, n, LlrStart::d13)) {
      const ProofResult seed = llr_prove(k, n, LlrStart::d13);
      EXPECT_EQ(seed.verdict, minus.verdict) << k << "*2^" << n << "-1";
      EXPECT_EQ(seed.parameter, 11u);
    }
    primes += gmp_minus + gmp_plus;
  }
  EXPECT_GT(primes, 10);  // the comparison saw primes, not only composites
}

TEST(RieselProof, ParameterChoices) {
  EXPECT_EQ(llr_parameter(1, 7, LlrStart::llr), 4u);  // Lucas-Lehmer: 2^7 - 1
  EXPECT_EQ(llr_parameter(5, 10, LlrStart::llr), 4u);
  // 3 | k: the first P with (P-2 / N) = 1 and (P+2 / N) = -1.
  const std::uint64_t p = *llr_parameter(3, 11, LlrStart::llr);
  const mpz_class N = mpz_class(3) * (mpz_class(1) << 11) - 1;
  EXPECT_EQ(mpz_jacobi(mpz_class(p - 2).get_mpz_t(), N.get_mpz_t()), 1);
  EXPECT_EQ(mpz_jacobi(mpz_class(p + 2).get_mpz_t(), N.get_mpz_t()), -1);
  for (std::uint64_t q = 3; q < p; ++q)
    EXPECT_FALSE(mpz_jacobi(mpz_class(q - 2).get_mpz_t(), N.get_mpz_t()) == 1 &&
                 mpz_jacobi(mpz_class(q + 2).get_mpz_t(), N.get_mpz_t()) == -1);
  const std::uint64_t a = *proth_base(3, 12);
  const mpz_class M = mpz_class(3) * (mpz_class(1) << 12) + 1;
  EXPECT_EQ(mpz_jacobi(mpz_class(a).get_mpz_t(), M.get_mpz_t()), -1);
}

TEST(RieselProof, ResumingFromAStateGivesTheSameResult) {
  const std::uint64_t k = 1035, n = 2000;  // composite or prime, the residues must match
  const ProofResult straight = llr_prove(k, n, LlrStart::llr);
  std::vector<ProofState> states;
  ProofOptions saving;
  saving.report_every = 300;
  saving.progress = [&](const ProofState& state) {
    states.push_back(state);
    return states.size() < 3;  // stop after the third report
  };
  EXPECT_EQ(llr_prove(k, n, LlrStart::llr, saving).verdict, Verdict::unknown);
  ASSERT_EQ(states.size(), 3u);
  ProofOptions resume;
  resume.resume_from = states.back();
  const ProofResult resumed = llr_prove(k, n, LlrStart::llr, resume);
  EXPECT_EQ(resumed.verdict, straight.verdict);
  EXPECT_EQ(resumed.res64, straight.res64);
}

TEST(RieselProof, BadFormsAreErrors) {
  EXPECT_THROW(llr_prove(4, 10, LlrStart::llr), tk::Error);     // even k
  EXPECT_THROW(llr_prove(2049, 11, LlrStart::llr), tk::Error);  // k >= 2^n
  EXPECT_THROW(llr_prove(1, 1, LlrStart::llr), tk::Error);      // n < 2
  EXPECT_THROW(proth_prove(3, 1), tk::Error);                   // k >= 2^n
}

}  // namespace

namespace {

/// The proof of k*2^n+-1 resumed from `state`: its verdict, and why the state was refused (empty if used).
std::pair<Verdict, std::string> resumed_from(std::uint64_t k, std::uint64_t n, int c, const ProofState& state) {
  ProofOptions options;
  options.resume_from = state;
  std::string why;
  options.resume_rejected = [&](const std::string& reason) { why = reason; };
  const ProofResult result = c < 0 ? llr_prove(k, n, LlrStart::llr, options) : proth_prove(k, n, options);
  return {result.verdict, why};
}

TEST(RieselProof, AStateOutsideTheProofIsRefusedAndTheProofStartsOver) {
  // 3*2^391-1 and 3*2^353+1 are prime (A002235, A002253): 389 and 352 squarings.
  const mpz_class llr_N = mpz_class(3) * (mpz_class(1) << 391) - 1, proth_N = mpz_class(3) * (mpz_class(1) << 353) + 1;
  const std::vector<std::pair<std::uint64_t, mpz_class>> bad_llr = {
      {99999999, 5}, {389, 5}, {0, 5}, {100, llr_N}, {100, llr_N + 5}, {100, -5}, {~std::uint64_t(0) - 4, 5}};
  for (const auto& [iteration, value] : bad_llr) {
    const auto [verdict, why] = resumed_from(3, 391, -1, ProofState{iteration, value});
    EXPECT_EQ(verdict, Verdict::prime) << iteration << " " << value;
    EXPECT_FALSE(why.empty()) << iteration << " " << value;
  }
  for (const auto& [iteration, value] : std::vector<std::pair<std::uint64_t, mpz_class>>{{352, 5}, {7, proth_N}}) {
    const auto [verdict, why] = resumed_from(3, 353, +1, ProofState{iteration, value});
    EXPECT_EQ(verdict, Verdict::prime) << iteration;
    EXPECT_FALSE(why.empty()) << iteration;
  }
  EXPECT_EQ(resumed_from(3, 391, -1, ProofState{99999999, 5}).second,
            "iteration 99999999 is outside this proof (389 squarings)");
  EXPECT_EQ(resumed_from(3, 391, -1, ProofState{100, llr_N}).second, "residue is not below N");
  // A state inside the proof is used (here a wrong one: the verdict follows it).
  EXPECT_EQ(resumed_from(3, 391, -1, ProofState{100, 5}), (std::pair<Verdict, std::string>{Verdict::composite, ""}));
}

}  // namespace
