/// @file montgomery64.hpp
/// @brief Arithmetic modulo an odd 64-bit n in Montgomery form (R = 2^64):
/// one multiplication and no division per modular product.
#pragma once

#include <cstdint>

namespace tk::primes {

using u64 = std::uint64_t;
__extension__ typedef unsigned __int128 u128;

class Montgomery64 {
 public:
  /// n must be odd and greater than 1.
  explicit Montgomery64(u64 n) : n_(n) {
    // Newton iteration for n^-1 mod 2^64: each step doubles the correct bits.
    u64 inverse = n;  // correct to 3 bits for odd n
    for (int i = 0; i < 5; ++i) inverse *= 2 - n * inverse;
    inverse_ = inverse;
    r2_ = static_cast<u64>((static_cast<u128>(0) - n) % n);  // 2^128 mod n
    one_ = static_cast<u64>((static_cast<u128>(1) << 64) % n);
  }

  u64 modulus() const { return n_; }
  u64 one() const { return one_; }

  /// REDC: t / 2^64 mod n for t < n * 2^64. With m = t * n^-1 mod 2^64,
  /// t - m*n is divisible by 2^64 and lies in (-n*2^64, n*2^64): subtract the
  /// high halves and add n back on a borrow. No 129-bit carry, so no
  /// hard-to-predict branch when n > 2^63.
  u64 reduce(u128 t) const {
    const u64 m = static_cast<u64>(t) * inverse_;
    const u64 mn_high = static_cast<u64>((static_cast<u128>(m) * n_) >> 64);
    const u64 t_high = static_cast<u64>(t >> 64);
    const u64 r = t_high - mn_high;
    return t_high < mn_high ? r + n_ : r;
  }

  u64 mul(u64 a, u64 b) const { return reduce(static_cast<u128>(a) * b); }
  u64 to_form(u64 a) const { return mul(a % n_, r2_); }
  u64 from_form(u64 a) const { return reduce(a); }
  u64 add(u64 a, u64 b) const {
    const u64 s = a + b;
    return (s < a || s >= n_) ? s - n_ : s;
  }
  u64 sub(u64 a, u64 b) const { return a >= b ? a - b : a - b + n_; }
  /// a / 2 mod n (works in or out of Montgomery form).
  u64 half(u64 a) const { return (a & 1) ? static_cast<u64>((static_cast<u128>(a) + n_) >> 1) : a >> 1; }
  u64 pow(u64 base_form, u64 exponent) const {
    u64 result = one_;
    while (exponent) {
      if (exponent & 1) result = mul(result, base_form);
      base_form = mul(base_form, base_form);
      exponent >>= 1;
    }
    return result;
  }

 private:
  u64 n_, inverse_, r2_, one_;
};

}  // namespace tk::primes
