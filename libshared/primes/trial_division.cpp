/// @file trial_division.cpp
#include "primes/trial_division.hpp"

#include <algorithm>
#include <cmath>

#include "primes/montgomery64.hpp"
#include "primes/prime_range.hpp"

namespace tk::primes {

namespace {

constexpr std::uint32_t kCachedLimit = 1u << 20;

std::uint64_t mulmod(std::uint64_t a, std::uint64_t b, std::uint64_t m) {
  return static_cast<std::uint64_t>(static_cast<u128>(a) * b % m);
}

std::uint64_t powmod(std::uint64_t base, std::uint64_t exponent, std::uint64_t m) {
  std::uint64_t result = 1 % m;
  base %= m;
  while (exponent) {
    if (exponent & 1) result = mulmod(result, base, m);
    base = mulmod(base, base, m);
    exponent >>= 1;
  }
  return result;
}

}  // namespace

const std::vector<std::uint32_t>& small_primes() {
  // libprimesieve: a hand-written sieve here took 50 ms of every sanitized
  // process that reads a number (a third of its start), ~2 ms in release.
  static const std::vector<std::uint32_t> primes = primes_between_32(2, kCachedLimit);
  return primes;
}

void sieve_segment_primes(std::uint64_t low, std::uint64_t high, const std::function<bool(std::uint64_t)>& f) {
  constexpr std::uint64_t kSegment = 1u << 18;
  const auto& base = small_primes();
  for (std::uint64_t start = low; start <= high; start += kSegment) {
    const std::uint64_t stop = std::min(high, start + kSegment - 1);
    std::vector<bool> composite(stop - start + 1);
    for (std::uint32_t p : base) {
      const std::uint64_t square = std::uint64_t{p} * p;
      if (square > stop) break;
      std::uint64_t first = std::max(square, (start + p - 1) / p * p);
      for (std::uint64_t j = first; j <= stop; j += p) composite[j - start] = true;
    }
    for (std::uint64_t i = start; i <= stop; ++i)
      if (!composite[i - start] && i > 1 && f(i)) return;
    if (stop == high) return;
  }
}

std::uint64_t trial_factor(const Number& number, std::uint64_t bound) {
  const mpz_class& n = number.value;
  std::uint64_t found = 0;
  if (number.form && number.form->c != 0) {
    const KbncForm& form = *number.form;
    for_each_odd_prime(bound, [&](std::uint64_t p) {
      std::uint64_t r = mulmod(mpz_fdiv_ui(form.k.get_mpz_t(), p), powmod(form.b, form.n, p), p);
      const std::uint64_t c_mod = form.c >= 0 ? static_cast<std::uint64_t>(form.c) % p
                                              : (p - static_cast<std::uint64_t>(-(form.c + 1)) % p - 1) % p;
      r = (r + c_mod) % p;
      if (r == 0 && n != p) found = p;
      return found != 0;
    });
    return found;
  }
  // Generic: one pass over N per group of primes whose product fits a word.
  std::vector<std::uint64_t> group;
  std::uint64_t product = 1;
  auto flush = [&]() {
    if (group.empty()) return false;
    const std::uint64_t r = mpz_fdiv_ui(n.get_mpz_t(), product);
    for (std::uint64_t p : group)
      if (r % p == 0 && n != p) {
        found = p;
        return true;
      }
    group.clear();
    product = 1;
    return false;
  };
  for_each_odd_prime(bound, [&](std::uint64_t p) {
    if (product > ~std::uint64_t{0} / p && flush()) return true;
    group.push_back(p);
    product *= p;
    return false;
  });
  if (!found) flush();
  return found;
}

}  // namespace tk::primes
