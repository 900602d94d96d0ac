// Theorem 2.3 of "Prime Hunting" (Farkas et al.) as mrtest's --test mr-grh:
// Miller-Rabin with every base a < 2 (ln n)^2. Checked against hand values
// of the bound (60-digit decimal logarithms, Python's decimal module),
// brute-force factoring and published strong pseudoprimes.
#include <gtest/gtest.h>

#include <vector>

#include <gmpxx.h>

#include "brute_force_prime.hpp"
#include "primes/number.hpp"
#include "primes/primality.hpp"

using namespace tk::primes;

using tk::test::brute_force_prime;

namespace {

TestOutcome grh_test(const mpz_class& n) {
  TestPlan plan;
  plan.kind = TestKind::mr_grh;
  plan.trial_bound = 0;  // the bases alone decide
  return test_number(Number{n, std::nullopt}, plan);
}

}  // namespace

TEST(GrhMillerRabin, LastBaseIsTheFloorOfTwiceLnSquared) {
  // floor(2 (ln n)^2) from 60-digit logarithms; capped at n - 2.
  const std::vector<std::pair<const char*, std::uint64_t>> hand = {
      {"3", 1},  // 2.41: capped at n - 2
      {"5", 3},  // 5.18: capped
      {"9", 7},  // 9.66: capped
      {"97", 41},
      {"1000003", 381},
      {"2305843009213693951", 3575},   // 2^61 - 1
      {"18446744073709551557", 3935},  // 2^64 - 59
      {"3825123056546413051", 3661},
      {"318665857834031151167461", 5857},
      {"1000000000000000000000000000057", 9543},
  };
  for (const auto& [digits, last] : hand) EXPECT_EQ(grh_last_base(mpz_class(digits)), last) << digits;
  // Big numbers: never below the floor, at most one base above it.
  auto near = [](const mpz_class& n, std::uint64_t floor_value) {
    const std::uint64_t got = grh_last_base(n);
    return got == floor_value || got == floor_value + 1;
  };
  mpz_class riesel = 3;
  riesel <<= 100000;
  riesel -= 1;
  EXPECT_TRUE(near(riesel, 9609364880));  // 9609364880.78
  mpz_class power = 1;
  power <<= std::uint64_t{1} << 20;
  EXPECT_TRUE(near(power, 1056527350806));  // 2^(2^20): ...806.17
  power <<= (std::uint64_t{1} << 26) - (std::uint64_t{1} << 20);
  EXPECT_TRUE(near(power, 4327536028902087));  // 2^(2^26), the default --max-bits: ...087.33
}

TEST(GrhMillerRabin, DecidesEveryOddNumberBelow100000LikeTrialDivision) {
  // Theorem 2.3 holds unconditionally wherever it has been checked; here by
  // brute force: every odd composite has a witness below 2 (ln n)^2, and
  // every prime passes all those bases.
  for (std::uint64_t n = 3; n < 100000; n += 2) {
    const TestOutcome outcome = grh_test(mpz_class(static_cast<unsigned long>(n)));
    if (!brute_force_prime(n)) {
      ASSERT_EQ(outcome.verdict, Verdict::composite) << n;
      continue;
    }
    // Every base up to n - 2 tried (n <= 19 here) is a proof without GRH.
    const bool all_bases = grh_last_base(mpz_class(static_cast<unsigned long>(n))) >= n - 2;
    ASSERT_EQ(outcome.verdict, all_bases ? Verdict::prime : Verdict::prime_if_grh) << n;
    ASSERT_EQ(all_bases, n <= 19) << n;
  }
}

TEST(GrhMillerRabin, PrimePowersAndStrongPseudoprimesToManyBases) {
  // The theorem leaves prime powers out: they are caught first. 1093^2 is a
  // strong pseudoprime to base 2 (1093 is a Wieferich prime).
  EXPECT_EQ(grh_test(mpz_class(1093 * 1093)).witness, "perfect power");
  EXPECT_EQ(grh_test(mpz_class(243)).witness, "perfect power");
  // Strong pseudoprimes to every prime base up to 31 (psi_9, below 2^64)
  // and up to 37 (psi_12, above). Their least witnesses, 37 and 14, are
  // PARI/GP's (Miller-Rabin written in GP from the paper's text, base by
  // base), far below the bounds 3661 and 5857.
  EXPECT_EQ(grh_test(mpz_class("3825123056546413051")).witness, "base 37");
  EXPECT_EQ(grh_test(mpz_class("318665857834031151167461")).witness, "base 14");
  // Primes just below and above 2^64 pass every base: prime if GRH holds.
  EXPECT_EQ(grh_test(mpz_class("18446744073709551557")).verdict, Verdict::prime_if_grh);
  EXPECT_EQ(grh_test(mpz_class("18446744073709551629")).verdict, Verdict::prime_if_grh);
  EXPECT_EQ(verdict_name(Verdict::prime_if_grh), "prime-if-grh");
  EXPECT_EQ(parse_test_kind("mr-grh"), TestKind::mr_grh);
}

TEST(NormalisedK, EvenKMovesItsTwosIntoTheExponent) {
  // k*2^n = (k/2^t)*2^(n+t): the paper's h0 = 0, c = 30030 at x = 1 and 4.
  KbncForm form{30030, 2, 256000, 1};
  EXPECT_EQ(make_k_odd(form), 1u);
  EXPECT_EQ(form.k, 15015);
  EXPECT_EQ(form.n, 256001u);
  form = KbncForm{120120, 2, 256000, -1};
  EXPECT_EQ(make_k_odd(form), 3u);
  EXPECT_EQ(form.k, 15015);
  EXPECT_EQ(form.n, 256003u);
  form = KbncForm{440682, 2, 3300, -1};  // riesel(1)'s example
  make_k_odd(form);
  EXPECT_EQ(kbnc_text(form), "220341*2^3301-1");
  form = KbncForm{778965587811, 2, 36627, -1};  // odd: unchanged
  EXPECT_EQ(make_k_odd(form), 0u);
  EXPECT_EQ(form.n, 36627u);
}
