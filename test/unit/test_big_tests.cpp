// Unit tests for the GMP tests and the special-form reduction, checked
// against GMP's own mpz_mod / mpz_powm / mpz_probab_prime_p.
#include <gtest/gtest.h>

#include <random>

#include "primes/big_tests.hpp"
#include "primes/modulus.hpp"
#include "primes/primality.hpp"
#include "test_volume.hpp"

using namespace tk::primes;

namespace {

mpz_class kbnc(std::uint64_t k, std::uint64_t n, std::int64_t c) {
  mpz_class v = mpz_class(static_cast<unsigned long>(k)) << static_cast<mp_bitcnt_t>(n);
  return v + c;
}

}  // namespace

TEST(Modulus, DetectsRieselAndProthShapes) {
  auto form = detect_special_form(kbnc(778965587811, 36627, -1));
  ASSERT_TRUE(form);
  EXPECT_EQ(form->k, 778965587811u);
  EXPECT_EQ(form->n, 36627u);
  EXPECT_EQ(form->c, -1);
  form = detect_special_form(kbnc(3, 1000, 1));
  ASSERT_TRUE(form);
  EXPECT_EQ(form->c, 1);
  EXPECT_FALSE(detect_special_form(kbnc(3, 1000, 5)));  // c = 5 only when hinted
  EXPECT_TRUE(detect_special_form(kbnc(3, 1000, 5), 5));
  EXPECT_FALSE(detect_special_form(mpz_class("123456789012345678901234567890")));
}

TEST(Modulus, SpecialReductionMatchesMpzMod) {
  gmp_randclass random(gmp_randinit_mt);
  random.seed(42);
  for (std::int64_t c : {-1LL, 1LL, -7LL, 12345LL, -2147483647LL}) {
    for (std::uint64_t k : {1ULL, 3ULL, 778965587811ULL, 18446744073709551557ULL}) {
      for (std::uint64_t n : {70ULL, 129ULL, 1000ULL, 4097ULL}) {
        const mpz_class N = kbnc(k, n, c);
        const auto form = detect_special_form(N, c);
        ASSERT_TRUE(form) << k << " " << n << " " << c;
        const Modulus special(N, *form), generic(N);
        for (int i = 0; i < 30; ++i) {
          mpz_class x = random.get_z_bits(2 * mpz_sizeinbase(N.get_mpz_t(), 2) + (i % 5) * 20);
          if (i % 3 == 0) x = -x;
          mpz_class expected;
          mpz_mod(expected.get_mpz_t(), x.get_mpz_t(), N.get_mpz_t());
          mpz_class got = x;
          special.reduce(got.get_mpz_t());
          ASSERT_EQ(got, expected) << "k=" << k << " n=" << n << " c=" << c;
          got = x;
          generic.reduce(got.get_mpz_t());
          ASSERT_EQ(got, expected);
        }
      }
    }
  }
}

TEST(BigTests, StrongProbablePrimeAgreesWithDefinitionViaPowm) {
  gmp_randclass random(gmp_randinit_mt);
  random.seed(7);
  for (int i = 0; i < 200; ++i) {
    mpz_class n = random.get_z_bits(100 + i * 3) | 1;
    if (n < 5) continue;
    const unsigned long base = 2 + i % 11;
    // Independent definition of the strong test with mpz_powm.
    mpz_class d = n - 1, x;
    const mp_bitcnt_t s = mpz_scan1(d.get_mpz_t(), 0);
    d >>= s;
    mpz_powm(x.get_mpz_t(), mpz_class(base).get_mpz_t(), d.get_mpz_t(), n.get_mpz_t());
    bool expected = x == 1 || x == n - 1;
    for (mp_bitcnt_t r = 1; r < s && !expected; ++r) {
      mpz_powm_ui(x.get_mpz_t(), x.get_mpz_t(), 2, n.get_mpz_t());
      if (x == n - 1) expected = true;
    }
    EXPECT_EQ(strong_probable_prime(Modulus(n), mpz_class(base)), expected) << n;
  }
}

TEST(BigTests, FermatWithSpecialAndGenericModulusAgree) {
  for (std::uint64_t n = 64; n < 400; n += 7) {
    const mpz_class N = kbnc(15, n, -1);
    const auto form = detect_special_form(N);
    ASSERT_TRUE(form);
    for (unsigned long base : {2UL, 3UL, 10UL}) {
      mpz_class r;
      mpz_powm(r.get_mpz_t(), mpz_class(base).get_mpz_t(), mpz_class(N - 1).get_mpz_t(), N.get_mpz_t());
      EXPECT_EQ(fermat_probable_prime(Modulus(N, *form), mpz_class(base)), r == 1) << n;
      EXPECT_EQ(fermat_probable_prime(Modulus(N), mpz_class(base)), r == 1) << n;
    }
  }
}

// BPSW agrees with GMP's mpz_probab_prime_p (itself BPSW plus extra
// Miller-Rabin rounds here) on random numbers and on k*2^n+-1 forms.
TEST(BigTests, BpswAgreesWithGmpOnRandomAndSpecialNumbers) {
  gmp_randclass random(gmp_randinit_mt);
  random.seed(99);
  TestPlan plan;
  for (int i = 0; i < 400; ++i) {
    mpz_class n = random.get_z_bits(65 + (i * 7) % 600) | 1;
    if (i % 4 == 0) mpz_nextprime(n.get_mpz_t(), n.get_mpz_t());
    const bool expected = mpz_probab_prime_p(n.get_mpz_t(), 30) != 0;
    const TestOutcome got = test_number(Number{n, std::nullopt}, plan);
    EXPECT_EQ(got.verdict == Verdict::probable_prime, expected) << n;
    EXPECT_EQ(got.verdict == Verdict::composite, !expected) << n;
  }
  for (std::uint64_t k = 1; k < 60; k += 2) {
    for (std::int64_t c : {-1LL, 1LL}) {
      const std::uint64_t n = 100 + k * 3;
      const mpz_class N = kbnc(k, n, c);
      const bool expected = mpz_probab_prime_p(N.get_mpz_t(), 30) != 0;
      const TestOutcome got = test_number(Number{N, KbncForm{k, 2, n, c}}, plan);
      EXPECT_EQ(got.verdict == Verdict::probable_prime, expected) << k << "*2^" << n << c;
    }
  }
}

// Mersenne numbers 2^p - 1: prime exactly for the known exponents.
TEST(BigTests, MersenneExponentsBelow700) {
  const std::vector<std::uint64_t> mersenne = {89, 107, 127, 521, 607};
  TestPlan plan;
  for (std::uint64_t p = 67; p < 700; p += 2) {
    const mpz_class N = kbnc(1, p, -1);
    const bool expected = std::find(mersenne.begin(), mersenne.end(), p) != mersenne.end();
    const TestOutcome got = test_number(Number{N, KbncForm{1, 2, p, -1}}, plan);
    EXPECT_EQ(got.verdict == Verdict::probable_prime, expected) << p;
  }
}

TEST(BigTests, WitnessesNameTheDecidingTest) {
  TestPlan plan;
  // A product of two 40-bit primes has no small factor: base 2 decides.
  const mpz_class semiprime = mpz_class("1099511627791") * mpz_class("1099511627689");
  EXPECT_EQ(test_number(Number{semiprime, std::nullopt}, plan).witness, "base 2");
  EXPECT_EQ(test_number(Number{semiprime * 3, std::nullopt}, plan).witness, "factor 3");
  const mpz_class square = mpz_class("18446744073709551557") * mpz_class("18446744073709551557");
  plan.trial_bound = 0;
  EXPECT_EQ(test_number(Number{square, std::nullopt}, plan).verdict, Verdict::composite);
}

TEST(Primality, VerdictsBelowAndAbove2To64) {
  TestPlan plan;
  EXPECT_EQ(test_number(Number{mpz_class("18446744073709551557"), {}}, plan).verdict, Verdict::prime);
  EXPECT_EQ(test_number(Number{mpz_class("18446744073709551629"), {}}, plan).verdict, Verdict::probable_prime);
  EXPECT_EQ(test_number(Number{mpz_class(1), {}}, plan).verdict, Verdict::composite);
  EXPECT_EQ(test_number(Number{mpz_class(-7), {}}, plan).verdict, Verdict::composite);
  EXPECT_EQ(test_number(Number{mpz_class(2), {}}, plan).verdict, Verdict::prime);
  plan.kind = TestKind::trial;
  plan.trial_bound = 1000;
  EXPECT_EQ(test_number(Number{mpz_class(999983), {}}, plan).verdict, Verdict::prime);  // 1000^2 > n
  EXPECT_EQ(test_number(Number{mpz_class("1000000007"), {}}, plan).verdict, Verdict::unknown);
}

TEST(Primality, RandomBasesAreReproducible) {
  TestPlan plan;
  plan.kind = TestKind::miller_rabin;
  plan.random_bases = 5;
  plan.seed = 11;
  const mpz_class carmichael("9585921133193329");
  const auto first = test_number(Number{carmichael * mpz_class("1000000007"), {}}, plan);
  const auto second = test_number(Number{carmichael * mpz_class("1000000007"), {}}, plan);
  EXPECT_EQ(first.witness, second.witness);
  EXPECT_EQ(first.verdict, Verdict::composite);
}

// Splitting BPSW over two threads must not change any verdict or witness.
TEST(Primality, SplitBpswGivesTheSequentialVerdictsAndWitnesses) {
  TestPlan sequential, split;
  split.split_bits = 100;
  sequential.trial_bound = split.trial_bound = 0;  // let the big tests decide
  gmp_randclass random(gmp_randinit_mt);
  random.seed(5);
  for (int i = 0; i < 40; ++i) {
    mpz_class n = random.get_z_bits(200 + 10 * i) | 1;
    if (i % 3 == 0) mpz_nextprime(n.get_mpz_t(), n.get_mpz_t());
    const Number number{n, std::nullopt};
    const TestOutcome a = test_number(number, sequential), b = test_number(number, split);
    EXPECT_EQ(a.verdict, b.verdict) << n;
    EXPECT_EQ(a.witness, b.witness) << n;
  }
  // 2^521 - 1 is a Mersenne prime.
  const Number mersenne{(mpz_class(1) << 521) - 1, KbncForm{1, 2, 521, -1}};
  EXPECT_EQ(test_number(mersenne, split).verdict, Verdict::probable_prime);
}

// test_number is what mrtest runs: its 64-bit path against a sieve, and
// against GMP at the top of the 64-bit range.
TEST(Primality, TestNumberAgreesWithASieveAndWithGmpNear2To64) {
  std::vector<bool> composite(300001);
  for (std::size_t i = 2; i * i <= 300000; ++i)
    if (!composite[i])
      for (std::size_t j = i * i; j <= 300000; j += i) composite[j] = true;
  TestPlan plan;
  for (unsigned long n = 2; n <= 300000; ++n) {
    const Verdict v = test_number(Number{mpz_class(n), std::nullopt}, plan).verdict;
    ASSERT_EQ(v, composite[n] ? Verdict::composite : Verdict::prime) << n;
  }
  for (unsigned long n = ~0UL - 60001; n < ~0UL - 1; n += 2) {
    const mpz_class z(n);
    const Verdict v = test_number(Number{z, std::nullopt}, plan).verdict;
    ASSERT_EQ(v == Verdict::prime, mpz_probab_prime_p(z.get_mpz_t(), 40) != 0) << n;
  }
}

// k*2^n - 1 runs Lucas first and skips Miller-Rabin when Rodseth's criterion
// proves primality: verdicts must still match GMP, with one or two threads,
// and the witnesses of both must agree.
TEST(Primality, RieselShapesMatchGmpSequentialAndSplit) {
  TestPlan sequential, split;
  split.split_bits = 64;
  sequential.trial_bound = split.trial_bound = 0;
  int primes = 0;
  const std::uint64_t k_end = test_volume(1500, 300);
  for (std::uint64_t k = 1; k < k_end; k += 2) {
    for (std::uint64_t n : {64ULL, 89ULL, 127ULL, 200ULL}) {
      const mpz_class N = kbnc(k, n, -1);
      const Number number{N, KbncForm{k, 2, n, -1}};
      const TestOutcome a = test_number(number, sequential), b = test_number(number, split);
      const bool expected = mpz_probab_prime_p(N.get_mpz_t(), 40) != 0;
      ASSERT_EQ(a.verdict == Verdict::probable_prime, expected) << k << "*2^" << n << "-1";
      ASSERT_EQ(a.verdict, b.verdict) << k << "*2^" << n << "-1";
      ASSERT_EQ(a.witness, b.witness) << k << "*2^" << n << "-1";
      primes += expected;
    }
  }
  EXPECT_GT(primes, k_end / 40);
}
