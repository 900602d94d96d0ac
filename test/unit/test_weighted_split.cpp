/// @file test_weighted_split.cpp
/// @brief A squaring split over threads (WeightedSquaring::use_threads)
/// leaves digit for digit what the one-thread squaring leaves, after
/// every square, and GMP's x^2 - m mod N: k = 1, 3, 44 and 56 bits, both
/// signs, small and large n (one to three outer passes), both SIMD widths
/// (AVX2 also carries by the scalar chains), 2 and 3 threads. And the
/// threads' barrier orders what they write.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <atomic>
#include <vector>

#include "primes/proof_threads.hpp"
#include "primes/riesel_proof.hpp"
#include "primes/right_angle_transform.hpp"
#include "primes/weighted_squaring.hpp"
#include "squaring_chain.hpp"

namespace {

using namespace tk::primes;
using squaring_test::name_of;
using squaring_test::value_of;
using SplitTransform = WeightedSquaring::Transform;

// One squarer on one thread and one on `threads`, the same transform,
// length and digits, squared side by side from the same x; GMP's chain
// alongside. `own_length`: create() chose this length (no square redone).
void expect_pair_matches(const SpecialForm& form, std::size_t length, double bits, SplitTransform transform,
                         unsigned threads, unsigned long minus, int rounds, gmp_randclass& random, bool own_length) {
  auto one = WeightedSquaring::create_with(form, length, bits, transform);
  auto split = WeightedSquaring::create_with(form, length, bits, transform);
  ASSERT_NE(one, nullptr) << name_of(form);
  ASSERT_NE(split, nullptr) << name_of(form);
  ASSERT_TRUE(split->use_threads(threads)) << name_of(form) << " on " << split->transform_name();
  ASSERT_EQ(split->threads(), threads);
  const std::string what = name_of(form) + " on " + split->transform_name() + ", length " + std::to_string(length) +
                           ", " + std::to_string(threads) + " threads, minus " + std::to_string(minus);
  const mpz_class N = value_of(form);
  mpz_class x = random.get_z_range(N);
  one->load(x);
  split->load(x);
  for (int round = 0; round < rounds; ++round) {
    one->square_minus(minus);
    split->square_minus(minus);
    x = x * x - minus;
    mpz_mod(x.get_mpz_t(), x.get_mpz_t(), N.get_mpz_t());
    ASSERT_EQ(split->held_digits(), one->held_digits()) << what << " round " << round;
    ASSERT_EQ(split->held_mod_p61(), one->held_mod_p61()) << what << " round " << round;
    if (round % 4 == 3 || round + 1 == rounds) {
      mpz_class got;
      one->store(got);
      ASSERT_EQ(got, x) << what << " round " << round;
      split->store(got);
      ASSERT_EQ(got, x) << what << " round " << round;
    }
  }
  // The same squares redone by GMP (none at create()'s own lengths; a
  // rare one at the next plannable length), most went the split way.
  EXPECT_EQ(split->fallbacks(), one->fallbacks()) << what;
  EXPECT_LE(4 * split->fallbacks(), static_cast<std::uint64_t>(rounds)) << what;
  if (own_length) {
    EXPECT_EQ(split->fallbacks(), 0u) << what;
  }
  EXPECT_EQ(split->worst_roundoff(), one->worst_roundoff()) << what;
}

void expect_split_matches(const SpecialForm& form, SplitTransform transform, unsigned threads, unsigned long minus,
                          int rounds, gmp_randclass& random) {
  auto widest = WeightedSquaring::create(form);
  ASSERT_NE(widest, nullptr) << name_of(form);
  // create() times a few lengths and may keep one only FFTW plans (under
  // the sanitizers FFTW, not instrumented, often wins): the next one ours plans.
  std::size_t length = widest->transform_length();
  while (!RightAngleSquarer::supports(length)) length += 16;
  // create()'s low digits m exactly: n / (m - 1/2) bits round up to m.
  const double bits = static_cast<double>(form.n) / (static_cast<double>(widest->low_digits()) - 0.5);
  expect_pair_matches(form, length, bits, transform, threads, minus, rounds, random,
                      length == widest->transform_length());
}

TEST(WeightedSplit, DigitForDigitTheOneThreadSquaringAndGmps) {
  gmp_randclass random(gmp_randinit_default);
  random.seed(2323);
  for (SplitTransform transform : {SplitTransform::widest, SplitTransform::avx2})
    for (std::uint64_t k : {1ull, 3ull, 16869987339975ull, (1ull << 56) - 1})
      for (std::uint64_t n : {64ull, 127ull, 4503ull, 36627ull, 171960ull})
        for (std::int64_t c : {-1, 1})
          expect_split_matches(SpecialForm{k, n, c}, transform, 2, c < 0 ? 2 : 0, 12, random);
}

// Where AVX-512 squares on one thread, the rounding carries the two
// ranges of digits, [0, m) and [m, 2(m + t) - 1), in the pass that rounds
// them, and the multiplication by k carries its product (the split square
// carries in passes of their own): m at every offset within a vector of
// eight, the square's last coefficient at offsets past the middle of the
// transform and below it (a length four times too long), and k of 56
// bits, whose digits take a second carry pass before the multiplication.
TEST(WeightedSplit, FusedCarriesAtEveryEdgeOfTheirVectors) {
  gmp_randclass random(gmp_randinit_default);
  random.seed(2325);
  for (std::uint64_t k : {3ull, 16869987339975ull, (1ull << 56) - 1})
    for (std::uint64_t n : {4000ull, 4001ull, 4003ull, 4007ull})
      for (std::size_t m = 200; m < 208; ++m) {
        const SpecialForm form{k, n, n % 2 ? -1 : 1};
        const double bits = static_cast<double>(n) / (static_cast<double>(m) - 0.5);
        for (std::size_t length : {std::size_t{512}, std::size_t{2048}})
          expect_pair_matches(form, length, bits, SplitTransform::widest, 2, n % 2 ? 2 : 0, 6, random, false);
      }
}

// Lengths with three outer passes, and three threads (uneven shares).
TEST(WeightedSplit, LargeLengthsAndThreeThreads) {
  gmp_randclass random(gmp_randinit_default);
  random.seed(2324);
  for (SplitTransform transform : {SplitTransform::widest, SplitTransform::avx2}) {
    expect_split_matches(SpecialForm{16869987339975ull, 600011, -1}, transform, 2, 2, 6, random);
    expect_split_matches(SpecialForm{3, 1200007, 1}, transform, 2, 0, 4, random);
    expect_split_matches(SpecialForm{16869987339975ull, 171960, -1}, transform, 3, 2, 8, random);
    expect_split_matches(SpecialForm{1, 4503, 1}, transform, 3, 0, 8, random);
  }
}

// Digits far too large for the length: every split square fails its
// checks (the held digits untouched) and GMP redoes it; the chain stays
// GMP's and the split squaring goes on after each.
TEST(WeightedSplit, FailedChecksFallBackToGmp) {
  for (SplitTransform transform : {SplitTransform::widest, SplitTransform::avx2}) {
    const SpecialForm form{16869987339975ull, 60000, -1};
    auto squarer = WeightedSquaring::create_with(form, 6144, 28, transform);
    ASSERT_NE(squarer, nullptr);
    ASSERT_TRUE(squarer->use_threads(2));
    squaring_test::expect_chain_matches(*squarer, form, value_of(form) / 3, 2, 5);
    EXPECT_EQ(squarer->fallbacks(), 5u) << squarer->transform_name();
  }
}

// Back to one thread mid-chain: the digits the split left unweighted are
// weighted before the next square.
TEST(WeightedSplit, ThreadsChangeMidChain) {
  const SpecialForm form{16869987339975ull, 36627, -1};
  auto squarer = WeightedSquaring::create(form);
  ASSERT_NE(squarer, nullptr);
  const mpz_class N = value_of(form);
  mpz_class x = 123456789;
  squarer->load(x);
  for (unsigned threads : {2u, 1u, 3u, 2u}) {
    squarer->use_threads(threads);
    for (int round = 0; round < 3; ++round) {
      squarer->square_minus(2);
      x = x * x - 2;
      mpz_mod(x.get_mpz_t(), x.get_mpz_t(), N.get_mpz_t());
    }
    mpz_class got;
    squarer->store(got);
    ASSERT_EQ(got, x) << threads << " threads";
  }
  EXPECT_EQ(squarer->fallbacks(), 0u);
}

// Paced: trials and stretches switch between split and one-thread
// squaring (whichever wins here); the digits stay the one-thread ones
// through every switch, over two trials at least (the second stretch is
// 2048 or, after a lost trial, 4096 squarings).
TEST(WeightedSplit, PacedSwitchesKeepTheDigits) {
  const SpecialForm form{16869987339975ull, 4503, -1};
  auto one = WeightedSquaring::create(form);
  auto paced = WeightedSquaring::create(form);
  ASSERT_TRUE(paced->use_threads(2, true));
  const mpz_class N = value_of(form);
  mpz_class x = 987654321;
  one->load(x);
  paced->load(x);
  int split = 0;
  for (int round = 0; round < 5300; ++round) {
    split += paced->splitting();
    one->square_minus(2);
    paced->square_minus(2);
    x = x * x - 2;
    mpz_mod(x.get_mpz_t(), x.get_mpz_t(), N.get_mpz_t());
    ASSERT_EQ(paced->held_digits(), one->held_digits()) << "round " << round;
  }
  mpz_class got;
  paced->store(got);
  EXPECT_EQ(got, x);
  EXPECT_GE(split, 2 * 32);  // at least the two split trials
  EXPECT_EQ(paced->fallbacks(), 0u);
}

// A whole proof with its squarings split from any length, against GMP's.
TEST(WeightedSplit, ProofsOnTwoThreadsMatchGmp) {
  ProofOptions gmp, split;
  gmp.arithmetic = Arithmetic::gmp;
  split.arithmetic = Arithmetic::fft;
  split.threads = 2;
  split.split_from_length = 1;
  split.paced_split = false;  // every square split
  for (const auto& [k, n] : {std::pair{3ull, 4423ull}, std::pair{5ull, 4001ull}, std::pair{1095ull, 2992ull}}) {
    const ProofResult a = llr_prove(k, n, LlrStart::llr, gmp), b = llr_prove(k, n, LlrStart::llr, split);
    EXPECT_EQ(b.verdict, a.verdict) << k << "*2^" << n << "-1";
    EXPECT_EQ(b.res64, a.res64) << k << "*2^" << n << "-1";
    const ProofResult p = proth_prove(k, n, gmp), q = proth_prove(k, n, split);
    EXPECT_EQ(q.verdict, p.verdict) << k << "*2^" << n << "+1";
    EXPECT_EQ(q.res64, p.res64) << k << "*2^" << n << "+1";
    EXPECT_EQ(b.fft_fallbacks + q.fft_fallbacks, 0u);
  }
}

// Each round, every thread writes its slot, passes the barrier, then reads
// every other thread's: a barrier that let one through early fails this.
TEST(ProofThreads, BarrierOrdersWritesAcrossRounds) {
  for (unsigned count : {1u, 2u, 3u}) {
    ProofThreads threads(count);
    ASSERT_EQ(threads.count(), count);
    std::vector<std::atomic<long>> slot(count);
    std::atomic<long> wrong{0};
    for (long round = 1; round <= 500; ++round)
      threads.run([&](unsigned index) {
        slot[index].store(round * 10 + index, std::memory_order_relaxed);
        threads.barrier();
        for (unsigned other = 0; other < count; ++other)
          if (slot[other].load(std::memory_order_relaxed) != round * 10 + other) ++wrong;
        threads.barrier();
      });
    EXPECT_EQ(wrong.load(), 0) << count << " threads";
  }
}

}  // namespace
