/// @file weighted_squaring_detail.hpp
/// @brief Bit and modular helpers WeightedSquaring's two files share.
#pragma once

#include <gmpxx.h>

#include <cstdint>

#include "primes/modulus.hpp"

namespace tk::primes::weighted_detail {

__extension__ typedef unsigned __int128 u128;
__extension__ typedef __int128 i128;

/// `count` (< 64) bits of the limbs from bit `position` on; reads the limb
/// after, so the array must have one past the last bit asked for.
inline std::uint64_t bits_at(const mp_limb_t* limbs, std::uint64_t position, unsigned count) {
  const std::uint64_t at = position / 64;
  const unsigned shift = position % 64;
  const std::uint64_t word = (limbs[at] >> shift) | ((limbs[at + 1] << 1) << (63 - shift));
  return word & ((std::uint64_t{1} << count) - 1);
}

/// Arithmetic modulo the prime p = 2^61 - 1, where 2^e is a rotation.
constexpr std::uint64_t kP61 = (std::uint64_t{1} << 61) - 1;

/// |v| < 2^61 as a residue in [0, p].
inline std::uint64_t residue61(std::int64_t v) {
  return static_cast<std::uint64_t>(v) + (kP61 & static_cast<std::uint64_t>(v >> 63));
}
/// r * 2^e mod p for r <= p, 0 <= e < 61 (the result may be p, meaning 0).
inline std::uint64_t times_power61(std::uint64_t r, unsigned e) { return ((r << e) & kP61) + (r >> (61 - e)); }
/// Partial reduction: below 2^61 + 8 for any input below 2^64.
inline std::uint64_t fold61(std::uint64_t v) { return (v & kP61) + (v >> 61); }
inline std::uint64_t reduce61(std::uint64_t v) {
  v = fold61(fold61(v));
  return v >= kP61 ? v - kP61 : v;
}
inline std::uint64_t multiply61(std::uint64_t a, std::uint64_t b) {
  const u128 product = static_cast<u128>(a) * b;
  return reduce61((static_cast<std::uint64_t>(product) & kP61) + static_cast<std::uint64_t>(product >> 61));
}

// Y = a*k + b with 0 <= b < k (floor division); false when a does not fit 63 bits.
inline bool divide_by_k(i128 y, std::uint64_t k, std::int64_t& a, std::int64_t& b) {
  i128 quotient = y / static_cast<i128>(k), remainder = y % static_cast<i128>(k);
  if (remainder < 0) {
    remainder += k;
    --quotient;
  }
  const i128 limit = i128{1} << 62;
  if (quotient >= limit || quotient <= -limit) return false;
  a = static_cast<std::int64_t>(quotient);
  b = static_cast<std::int64_t>(remainder);
  return true;
}

inline mpz_class modulus_of(const SpecialForm& form) {
  mpz_class N = form.k;
  N <<= static_cast<mp_bitcnt_t>(form.n);
  return N + form.c;
}

}  // namespace tk::primes::weighted_detail
