/// @file prime64.hpp
/// @brief Primality tests for 64-bit integers in native Montgomery
/// arithmetic. BPSW is a proof below 2^64: no BPSW pseudoprime exists there.
#pragma once

#include <cstdint>

namespace tk::primes {

/// Smallest prime factor of n that is at most `bound` (n itself excluded),
/// or 0 when there is none. n > 1.
std::uint64_t small_factor_u64(std::uint64_t n, std::uint64_t bound);

/// a^(n-1) == 1 (mod n); odd n > 2. Bases that are 0 mod n pass.
bool fermat_probable_prime_u64(std::uint64_t n, std::uint64_t base);

/// Miller-Rabin strong probable prime to `base`; odd n > 2. Bases that are
/// 0 mod n pass.
bool strong_probable_prime_u64(std::uint64_t n, std::uint64_t base);

/// Selfridge's parameter for the strong Lucas test: the first D in
/// 5, -7, 9, -11, ... with Jacobi(D, n) = -1. Returns 0 when n is a perfect
/// square (no such D exists) and sets `factor` when some D shares a factor
/// with n. Odd n > 2.
std::int64_t selfridge_d_u64(std::uint64_t n, std::uint64_t& factor);

/// Strong Lucas probable prime with Selfridge's parameters P = 1,
/// Q = (1 - D) / 4, for a D from selfridge_d_u64 (not 0). Odd n > 2.
bool strong_lucas_probable_prime_u64(std::uint64_t n, std::int64_t d);

/// Deterministic primality for every 64-bit n (BPSW after trial division).
bool is_prime_u64(std::uint64_t n);

/// Jacobi symbol (a/n) for odd n > 0.
int jacobi_u64(std::uint64_t a, std::uint64_t n);

}  // namespace tk::primes
