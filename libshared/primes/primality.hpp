/// @file primality.hpp
/// @brief Chooses and runs a primality test on a Number: the 64-bit fast
/// path below 2^64, GMP with the special-form reduction above.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "primes/number.hpp"

namespace tk::primes {

/// Ordered from weakest to strongest, so a form's verdict is its members'
/// minimum. prime_if_grh is a proof that holds if the Generalised Riemann
/// Hypothesis does (TestKind::mr_grh).
enum class Verdict { composite, unknown, probable_prime, prime_if_grh, prime };
std::string_view verdict_name(Verdict verdict);

enum class TestKind { trial, fermat, miller_rabin, mr_grh, lucas, bpsw };
std::string_view test_name(TestKind kind);
/// Parses "trial", "fermat", "mr" (or "miller-rabin"), "mr-grh", "lucas", "bpsw".
std::optional<TestKind> parse_test_kind(std::string_view text);

/// The largest base TestKind::mr_grh tries on n: every a < 2 (ln n)^2 (Theorem
/// 2.3 of "Prime Hunting"), that is floor(2 (ln n)^2), and no more than
/// n - 2. 2 (ln n)^2 is irrational, so no base sits on the bound; computed
/// in long double, it is rounded up past a value just below an integer
/// (one base more), never down. n > 2.
std::uint64_t grh_last_base(const mpz_class& n);

struct TestPlan {
  TestKind kind = TestKind::bpsw;
  std::vector<std::uint64_t> bases;          ///< Fermat / Miller-Rabin bases (default {2})
  unsigned random_bases = 0;                 ///< extra bases drawn at random
  std::uint64_t seed = 0;                    ///< with the number, fixes the random bases
  std::optional<std::uint64_t> trial_bound;  ///< none: automatic by size; 0: none
  /// BPSW on numbers of at least this many bits runs its Miller-Rabin and
  /// Lucas halves on two threads; 0: never.
  std::size_t split_bits = 0;
};

/// Where splitting BPSW over two threads pays for the thread start.
inline constexpr std::size_t kDefaultSplitBits = 20000;

struct TestOutcome {
  Verdict verdict = Verdict::unknown;
  std::string witness;  ///< for composites: "factor 3", "base 2", "lucas D=-7", ...
};

/// The automatic trial-division bound for a number of `bits` bits.
std::uint64_t default_trial_bound(std::size_t bits);

TestOutcome test_number(const Number& number, const TestPlan& plan);

}  // namespace tk::primes
