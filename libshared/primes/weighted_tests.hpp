/// @file weighted_tests.hpp
/// @brief Miller-Rabin and Fermat tests of N = k*2^n +- 1 on the weighted
/// squaring (weighted_squaring.hpp) that riesel's proofs use: base^k by
/// GMP, then n or n - 1 squarings on the transform, the exponent's
/// remaining factor handled by the comparison at the end.
#pragma once

#include <gmpxx.h>

#include <atomic>
#include <optional>

#include "primes/modulus.hpp"
#include "primes/riesel_proof.hpp"

namespace tk::primes {

/// The strong probable-prime test to `base` (base mod N nonzero) on the
/// transform: for a Proth number every square of the chain is watched for
/// -1 (Watch in the .cpp). Nothing where it does not apply (no k*2^n +- 1
/// form of at least `from_bits` bits, where riesel's proofs take it, with
/// k < 2^56) or where a square's check failed (the GMP test decides).
/// Stops early, with a meaningless answer, when `cancel` becomes true.
/// `from_bits` lowers the size from which it applies (for tests).
std::optional<bool> weighted_strong_probable_prime(const Modulus& N, const mpz_class& base,
                                                   const std::atomic<bool>* cancel = nullptr,
                                                   std::size_t from_bits = kFftMinBits);

/// base^(N-1) == 1 (mod N) on the transform; nothing where it does not apply.
std::optional<bool> weighted_fermat_probable_prime(const Modulus& N, const mpz_class& base,
                                                   std::size_t from_bits = kFftMinBits);

/// Where the strong Lucas test's tail first reaches 0: W_1 = w, W_(r+1)
/// = W_r^2 - 2 for N = k*2^n - 1 (N + 1 = k*2^n, as in LLR).
struct LucasTail {
  std::uint64_t zero_at = 0;  ///< the first r <= last with W_r = 0, or 0 for none
};
/// W_1 .. W_last on the transform, each watched for 0 (its residue mod
/// 2^61 - 1, then exactly). Nothing where the transform does not apply or
/// a check failed; a meaningless answer when `cancel` becomes true.
std::optional<LucasTail> weighted_lucas_tail(const Modulus& N, const mpz_class& w, std::uint64_t last,
                                             const std::atomic<bool>* cancel = nullptr,
                                             std::size_t from_bits = kFftMinBits);

}  // namespace tk::primes
