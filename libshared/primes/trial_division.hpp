/// @file trial_division.hpp
/// @brief Trial division of big numbers by the primes up to a bound.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "primes/number.hpp"

namespace tk::primes {

/// The primes up to 2^20, sieved once and shared by all threads.
const std::vector<std::uint32_t>& small_primes();

/// Calls f(p) for every prime 3 <= p <= bound, in order, until f returns true.
template <class F>
void for_each_odd_prime(std::uint64_t bound, F&& f);

/// Smallest odd prime p <= bound dividing the number (p != N), or 0. With a
/// k*b^n+c form each prime costs O(log n) word operations instead of a pass
/// over N.
std::uint64_t trial_factor(const Number& number, std::uint64_t bound);

/// Segmented sieve over [low, high] calling f(p) for each prime; stops early
/// when f returns true. Used beyond the cached table.
void sieve_segment_primes(std::uint64_t low, std::uint64_t high, const std::function<bool(std::uint64_t)>& f);

template <class F>
void for_each_odd_prime(std::uint64_t bound, F&& f) {
  for (std::uint32_t p : small_primes()) {
    if (p > bound) return;
    if (p != 2 && f(static_cast<std::uint64_t>(p))) return;
  }
  const std::uint64_t cached = small_primes().back();
  if (bound > cached) sieve_segment_primes(cached + 1, bound, f);
}

}  // namespace tk::primes
