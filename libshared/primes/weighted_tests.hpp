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
/// transform; nothing where it does not apply (no k*2^n +- 1 form of at
/// least `from_bits` bits, where riesel's proofs take it, with k < 2^56) or cannot decide alone: a Proth
/// number whose square chain reaches 1 before its last step (a base that
/// is a square, say) goes to the GMP test, which finds where it did.
/// Stops early, with a meaningless answer, when `cancel` becomes true.
/// `from_bits` lowers the size from which it applies (for tests).
std::optional<bool> weighted_strong_probable_prime(const Modulus& N, const mpz_class& base,
                                                   const std::atomic<bool>* cancel = nullptr,
                                                   std::size_t from_bits = kFftMinBits);

/// base^(N-1) == 1 (mod N) on the transform; nothing where it does not apply.
std::optional<bool> weighted_fermat_probable_prime(const Modulus& N, const mpz_class& base, std::size_t from_bits = kFftMinBits);

/// W := W^2 - 2 repeated `steps` times from `w`, on the transform: the
/// tail of the strong Lucas test for N = k*2^n - 1 (N + 1 = k*2^n, as in
/// LLR). Nothing where the transform does not apply; a meaningless value
/// when `cancel` becomes true.
std::optional<mpz_class> weighted_minus_two_chain(const Modulus& N, const mpz_class& w, std::uint64_t steps,
                                                  const std::atomic<bool>* cancel = nullptr,
                                                  std::size_t from_bits = kFftMinBits);

}  // namespace tk::primes
