// Unit tests for the 64-bit fast path, checked against brute force and
// published pseudoprime facts.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include <gmpxx.h>

#include "brute_force_prime.hpp"
#include "primes/montgomery64.hpp"
#include "primes/prime64.hpp"

using namespace tk::primes;

using tk::test::brute_force_prime;

namespace {

std::vector<bool> sieve(std::size_t limit) {
  std::vector<bool> prime(limit + 1, true);
  prime[0] = prime[1] = false;
  for (std::size_t i = 2; i * i <= limit; ++i)
    if (prime[i])
      for (std::size_t j = i * i; j <= limit; j += i) prime[j] = false;
  return prime;
}

u64 naive_powmod(u64 b, u64 e, u64 m) {
  u64 r = 1 % m;
  b %= m;
  while (e) {
    if (e & 1) r = static_cast<u64>(static_cast<u128>(r) * b % m);
    b = static_cast<u64>(static_cast<u128>(b) * b % m);
    e >>= 1;
  }
  return r;
}

}  // namespace

TEST(Prime64, AgreesWithSieveBelowTwoMillion) {
  const auto prime = sieve(2'000'000);
  for (u64 n = 0; n <= 2'000'000; ++n) ASSERT_EQ(is_prime_u64(n), prime[n]) << n;
}

TEST(Prime64, AgreesWithTrialDivisionOnRandomNumbersNear2To40) {
  std::mt19937_64 random(12345);
  for (int i = 0; i < 3000; ++i) {
    const u64 n = (u64{1} << 40) + (random() >> 25);
    ASSERT_EQ(is_prime_u64(n), brute_force_prime(n)) << n;
  }
}

TEST(Prime64, KnownLargePrimesAndComposites) {
  EXPECT_TRUE(is_prime_u64(18446744073709551557ULL));   // largest 64-bit prime
  EXPECT_FALSE(is_prime_u64(18446744073709551615ULL));  // 2^64 - 1
  EXPECT_FALSE(is_prime_u64(18446744073709551613ULL));
  EXPECT_TRUE(is_prime_u64(9223372036854775783ULL));  // largest prime below 2^63
  EXPECT_TRUE(is_prime_u64(4294967291ULL));           // largest 32-bit prime
  EXPECT_FALSE(is_prime_u64(4294967291ULL * 4294967279ULL));
  EXPECT_FALSE(is_prime_u64(4294967291ULL * 4294967291ULL));  // a perfect square
}

// Strong pseudoprimes to base 2 fool Miller-Rabin base 2 but not BPSW.
TEST(Prime64, StrongPseudoprimesToBase2AreCaught) {
  for (u64 n : {2047ULL, 3277ULL, 4033ULL, 4681ULL, 8321ULL, 3215031751ULL, 2152302898747ULL, 3474749660383ULL,
                341550071728321ULL, 3825123056546413051ULL}) {
    EXPECT_TRUE(strong_probable_prime_u64(n, 2)) << n;
    EXPECT_FALSE(is_prime_u64(n)) << n;
  }
}

TEST(Prime64, CarmichaelNumbersPassFermatButNotBpsw) {
  for (u64 n : {561ULL, 1105ULL, 1729ULL, 2465ULL, 2821ULL, 6601ULL, 8911ULL, 41041ULL, 825265ULL, 321197185ULL,
                9585921133193329ULL}) {
    EXPECT_TRUE(fermat_probable_prime_u64(n, 2)) << n;
    EXPECT_FALSE(is_prime_u64(n)) << n;
  }
}

TEST(Prime64, FermatMatchesNaivePowmod) {
  std::mt19937_64 random(7);
  for (int i = 0; i < 2000; ++i) {
    const u64 n = random() | 1 | (u64{1} << 63);
    const u64 base = 2 + random() % 1000;
    EXPECT_EQ(fermat_probable_prime_u64(n, base), naive_powmod(base, n - 1, n) == 1) << n;
  }
}

// Lucas pseudoprimes (Selfridge method A, strong): OEIS A217255 begins 5459, 5777, 10877.
TEST(Prime64, StrongLucasPseudoprimesPassLucasButFailBase2) {
  for (u64 n : {5459ULL, 5777ULL, 10877ULL, 16109ULL, 18971ULL, 22499ULL, 24569ULL, 25199ULL}) {
    u64 factor = 0;
    const std::int64_t d = selfridge_d_u64(n, factor);
    ASSERT_NE(d, 0);
    EXPECT_EQ(factor, 0u);
    EXPECT_TRUE(strong_lucas_probable_prime_u64(n, d)) << n;
    EXPECT_FALSE(strong_probable_prime_u64(n, 2)) << n;
    EXPECT_FALSE(is_prime_u64(n));
  }
}

TEST(Prime64, StrongLucasRejectsOtherCompositesBelow30000) {
  const auto prime = sieve(30000);
  const std::vector<u64> pseudoprimes = {5459, 5777, 10877, 16109, 18971, 22499, 24569, 25199};
  for (u64 n = 5; n < 30000; n += 2) {
    u64 factor = 0;
    const std::int64_t d = selfridge_d_u64(n, factor);
    if (d == 0 || factor) {
      EXPECT_FALSE(prime[n]) << n;
      continue;
    }
    const bool lucas = strong_lucas_probable_prime_u64(n, d);
    const bool listed = std::find(pseudoprimes.begin(), pseudoprimes.end(), n) != pseudoprimes.end();
    EXPECT_EQ(lucas, prime[n] || listed) << n;
  }
}

TEST(Prime64, JacobiMatchesEulerCriterionForPrimes) {
  for (u64 p : {3ULL, 5ULL, 7ULL, 101ULL, 1000003ULL, 4294967291ULL}) {
    for (u64 a = 0; a < 50; ++a) {
      const u64 e = naive_powmod(a, (p - 1) / 2, p);
      const int expected = e == 0 ? 0 : (e == 1 ? 1 : -1);
      EXPECT_EQ(jacobi_u64(a, p), expected) << a << "/" << p;
    }
  }
}

TEST(Prime64, SmallFactorFindsSmallestPrimeFactor) {
  EXPECT_EQ(small_factor_u64(91, 100), 7u);
  EXPECT_EQ(small_factor_u64(97, 100), 0u);
  EXPECT_EQ(small_factor_u64(1000003ULL * 999983ULL, 1000), 0u);
  EXPECT_EQ(small_factor_u64(1000003ULL * 999983ULL, 1000000), 999983u);
  EXPECT_EQ(small_factor_u64(3ULL * 1000003ULL, 2), 0u);
}

// Near 2^64 the Selfridge search reaches its perfect-square check; roots near
// 2^32 must not overflow (this band once hung).
TEST(Prime64, TopOfTheRangeAgreesWithGmp) {
  for (u64 n = ~u64{0} - 200001; n != 0 && n <= ~u64{0} - 1; n += 2) {
    mpz_class z(static_cast<unsigned long>(n));
    ASSERT_EQ(is_prime_u64(n), mpz_probab_prime_p(z.get_mpz_t(), 40) != 0) << n;
  }
  EXPECT_FALSE(is_prime_u64(4294967295ULL * 4294967295ULL));
  EXPECT_TRUE(is_prime_u64(18446744073709549621ULL));
}
