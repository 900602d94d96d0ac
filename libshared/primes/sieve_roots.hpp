/// @file sieve_roots.hpp
/// @brief For each sieving prime p and each member k*2^e+c of a form, the
/// one x (mod p) whose candidate p divides: k = -c*2^-e (mod p), then
/// x = (k - k_first)/c_step (mod p), as an offset from the first x.
///
/// 2^-n is the same fixed-exponent power for every prime, so primes below
/// 2^32 go through it sixteen at a time in 32-bit Montgomery arithmetic
/// (independent chains keep the multiplier busy); a multiplication by 1/2 is
/// a shift. Larger primes use 64-bit Montgomery arithmetic one at a time.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "primes/sieve_spec.hpp"

namespace tk::primes {

class SieveRootFinder {
 public:
  /// Marks a prime that divides c: its members are then the same for every x.
  static constexpr std::uint64_t kNoRoot = std::numeric_limits<std::uint64_t>::max();

  explicit SieveRootFinder(const SieveSpec& spec);

  std::size_t member_count() const { return members_.size(); }
  const std::vector<SieveMember>& members() const { return members_; }

  /// roots[i * member_count() + m] for primes[i] (odd primes). Throws Error
  /// when a prime divides c and every candidate.
  void find(const std::uint64_t* primes, std::size_t count, std::uint64_t* roots) const;

 private:
  void find_small(const std::uint64_t* primes, std::size_t count, std::uint64_t* roots) const;
  void find_large(std::uint64_t p, std::uint64_t* roots) const;
  /// Offsets from 2^-n mod p (t) for one prime, given c_step^-1 (or 0 when p | c).
  void store(std::uint64_t p, std::uint64_t t, std::uint64_t inverse_step, std::uint64_t* roots) const;
  void handle_prime_dividing_step(std::uint64_t p, std::uint64_t* roots) const;

  std::uint64_t n_;
  std::vector<SieveMember> members_;
  unsigned max_offset_ = 0;
  std::uint64_t k_first_;  ///< k at the first x
  std::uint64_t step_;     ///< k grows by this per x (c, or 1 for a plain k range)
};

}  // namespace tk::primes
