/// @file prime64.cpp
#include "primes/prime64.hpp"

#include <array>
#include <bit>
#include <cmath>
#include <numeric>

#include "primes/montgomery64.hpp"

namespace tk::primes {

namespace {

/// Odd primes below 64 with their inverses mod 2^64: p | n exactly when
/// n * inverse <= (2^64 - 1) / p, a multiplication instead of a division.
struct SmallPrime {
  u64 prime, inverse, limit;
};

constexpr u64 inverse_mod_2_64(u64 p) {
  u64 x = p;
  for (int i = 0; i < 5; ++i) x *= 2 - p * x;
  return x;
}

constexpr std::array<SmallPrime, 17> kSmallPrimes = [] {
  constexpr u64 primes[] = {3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41, 43, 47, 53, 59, 61};
  std::array<SmallPrime, 17> table{};
  for (std::size_t i = 0; i < table.size(); ++i)
    table[i] = {primes[i], inverse_mod_2_64(primes[i]), ~u64{0} / primes[i]};
  return table;
}();

bool is_perfect_square(u64 n) {
  // The double estimate is within one of the root; products in 128 bits so
  // that roots near 2^32 cannot wrap around.
  u64 root = static_cast<u64>(std::sqrt(static_cast<double>(n)));
  if (root > 0xFFFFFFFFu) root = 0xFFFFFFFFu;
  while (static_cast<u128>(root) * root > n) --root;
  while (static_cast<u128>(root + 1) * (root + 1) <= n) ++root;
  return static_cast<u128>(root) * root == n;
}

}  // namespace

std::uint64_t small_factor_u64(std::uint64_t n, std::uint64_t bound) {
  if (n % 2 == 0) return n > 2 && bound >= 2 ? 2 : 0;
  for (const auto& p : kSmallPrimes) {
    if (p.prime > bound || p.prime * p.prime > n) return 0;
    if (n * p.inverse <= p.limit) return p.prime;
  }
  // Beyond the table: wheel over 6k +- 1.
  for (u64 d = 67; d <= bound && d * d <= n; d += 6) {
    if (n % d == 0) return d;
    if (d + 4 <= bound && n % (d + 4) == 0) return d + 4;
    if (d > (u64{1} << 32)) break;
  }
  return 0;
}

int jacobi_u64(std::uint64_t a, std::uint64_t n) {
  a %= n;
  int result = 1;
  while (a != 0) {
    const int twos = std::countr_zero(a);
    a >>= twos;
    if ((twos & 1) && ((n & 7) == 3 || (n & 7) == 5)) result = -result;
    if ((a & 3) == 3 && (n & 3) == 3) result = -result;
    const u64 t = a;
    a = n % t;
    n = t;
  }
  return n == 1 ? result : 0;
}

bool fermat_probable_prime_u64(std::uint64_t n, std::uint64_t base) {
  const Montgomery64 m(n);
  if (base % n == 0) return true;
  return m.pow(m.to_form(base), n - 1) == m.one();
}

bool strong_probable_prime_u64(std::uint64_t n, std::uint64_t base) {
  const Montgomery64 m(n);
  if (base % n == 0) return true;
  const int s = std::countr_zero(n - 1);
  const u64 d = (n - 1) >> s;
  const u64 minus_one = m.sub(0, m.one());
  u64 x = m.pow(m.to_form(base), d);
  if (x == m.one() || x == minus_one) return true;
  for (int r = 1; r < s; ++r) {
    x = m.mul(x, x);
    if (x == minus_one) return true;
    if (x == m.one()) return false;
  }
  return false;
}

std::int64_t selfridge_d_u64(std::uint64_t n, std::uint64_t& factor) {
  factor = 0;
  for (std::int64_t d = 5;; d = d > 0 ? -(d + 2) : -d + 2) {
    const u64 magnitude = static_cast<u64>(d > 0 ? d : -d);
    int j = jacobi_u64(magnitude, n);
    if (d < 0 && (n & 3) == 3) j = -j;  // (-1/n) = -1 when n = 3 (mod 4)
    if (j == -1) return d;
    if (j == 0 && magnitude % n != 0) {
      factor = std::gcd(magnitude, n);
      return d;
    }
    // Squares have no D with (D/n) = -1; check once the search runs long.
    if (d == -15 && is_perfect_square(n)) return 0;
  }
}

bool strong_lucas_probable_prime_u64(std::uint64_t n, std::int64_t d) {
  const Montgomery64 m(n);
  const std::int64_t q = (1 - d) / 4;
  auto to_form_signed = [&](std::int64_t v) {
    const u64 magnitude = static_cast<u64>(v < 0 ? -v : v) % n;
    const u64 form = m.to_form(magnitude);
    return v < 0 ? m.sub(0, form) : form;
  };
  const u64 d_form = to_form_signed(d), q_form = to_form_signed(q);
  // n + 1 = k * 2^s with k odd (n + 1 may be 2^64: handle via n >> 1).
  const u64 n_plus_1_half = (n >> 1) + 1;
  const int s = std::countr_zero(n_plus_1_half) + 1;
  const u64 k = n_plus_1_half >> (s - 1);

  // Walk k's bits from the top: (U, V, Q^m) for m = 1, then doubling and
  // incrementing: U2m = Um Vm, V2m = Vm^2 - 2Q^m, Um+1 = (Um + Vm)/2,
  // Vm+1 = (D Um + Vm)/2 (P = 1).
  u64 u = m.one(), v = m.one(), qk = q_form;
  for (int bit = 62 - std::countl_zero(k); bit >= 0; --bit) {
    u = m.mul(u, v);
    v = m.sub(m.mul(v, v), m.add(qk, qk));
    qk = m.mul(qk, qk);
    if ((k >> bit) & 1) {
      const u64 next_u = m.half(m.add(u, v));
      v = m.half(m.add(m.mul(d_form, u), v));
      u = next_u;
      qk = m.mul(qk, q_form);
    }
  }
  if (u == 0 || v == 0) return true;
  for (int r = 1; r < s; ++r) {
    v = m.sub(m.mul(v, v), m.add(qk, qk));
    if (v == 0) return true;
    qk = m.mul(qk, qk);
  }
  return false;
}

bool is_prime_u64(std::uint64_t n) {
  if (n < 2) return false;
  if (n < 4) return true;
  if (small_factor_u64(n, 61) != 0) return false;
  if (n < 67 * 67) return true;
  if (!strong_probable_prime_u64(n, 2)) return false;
  u64 factor = 0;
  const std::int64_t d = selfridge_d_u64(n, factor);
  if (d == 0 || factor != 0) return false;
  return strong_lucas_probable_prime_u64(n, d);
}

}  // namespace tk::primes
