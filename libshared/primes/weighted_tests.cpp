/// @file weighted_tests.cpp
#include "primes/weighted_tests.hpp"

#include "primes/weighted_squaring.hpp"

namespace tk::primes {

namespace {

// N - 1 = k*2^n for N = k*2^n + 1; for N = k*2^n - 1, N - 1 = 2*d with
// d = k*2^(n-1) - 1 odd, so base^d = base^(k*2^(n-1)) / base. Both need
// only y = (base^k)^(2^m) for some m: that is all the transform computes.
std::unique_ptr<WeightedSquaring> squarer_for(const Modulus& N, std::size_t from_bits) {
  if (!N.form() || N.bits() < from_bits || (N.form()->c != 1 && N.form()->c != -1)) return nullptr;
  return WeightedSquaring::create(*N.form());
}

// (base^k)^(2^squarings) mod N, or nothing when cancelled.
std::optional<mpz_class> power_then_square(WeightedSquaring& squarer, const Modulus& N, const mpz_class& base,
                                           std::uint64_t squarings, const std::atomic<bool>* cancel) {
  mpz_class y;
  mpz_powm_ui(y.get_mpz_t(), base.get_mpz_t(), static_cast<unsigned long>(N.form()->k), N.value().get_mpz_t());
  squarer.load(y);
  for (std::uint64_t i = 0; i < squarings; ++i) {
    if (cancel && i % 1024 == 0 && cancel->load(std::memory_order_relaxed)) return std::nullopt;
    squarer.square_minus(0);
  }
  squarer.store(y);
  return y;
}

mpz_class reduced(const mpz_class& value, const Modulus& N) {
  mpz_class r;
  mpz_mod(r.get_mpz_t(), value.get_mpz_t(), N.value().get_mpz_t());
  return r;
}

}  // namespace

std::optional<bool> weighted_strong_probable_prime(const Modulus& N, const mpz_class& base,
                                                   const std::atomic<bool>* cancel, std::size_t from_bits) {
  auto squarer = squarer_for(N, from_bits);
  if (!squarer) return std::nullopt;
  const mpz_class b = reduced(base, N), minus_one = N.value() - 1;
  const std::uint64_t n = N.form()->n;
  if (N.form()->c == 1) {
    // x_i = b^(k*2^i). A prime has x_0 = 1 or some x_i = -1 (i < n), and
    // then x_(n-1) is -1 or 1; x_(n-1) = 1 leaves open where the chain
    // turned, which the GMP test finds. Anything else: composite.
    const auto last = power_then_square(*squarer, N, b, n - 1, cancel);
    if (!last) return false;
    if (*last == minus_one) return true;
    if (*last == 1) return std::nullopt;
    return false;
  }
  // s = 1: passes when b^d = +-1, that is y = b^(k*2^(n-1)) = +-b.
  const auto y = power_then_square(*squarer, N, b, n - 1, cancel);
  if (!y) return false;
  return *y == b || *y == N.value() - b;
}

std::optional<bool> weighted_fermat_probable_prime(const Modulus& N, const mpz_class& base, std::size_t from_bits) {
  auto squarer = squarer_for(N, from_bits);
  if (!squarer) return std::nullopt;
  const mpz_class b = reduced(base, N);
  const auto y = power_then_square(*squarer, N, b, N.form()->n, nullptr);  // b^(k*2^n)
  // N - 1 = k*2^n, or k*2^n - 2: then b^(N-1) = 1 when b^(k*2^n) = b^2.
  return *y == (N.form()->c == 1 ? mpz_class(1) : reduced(b * b, N));
}

std::optional<mpz_class> weighted_minus_two_chain(const Modulus& N, const mpz_class& w, std::uint64_t steps,
                                                  const std::atomic<bool>* cancel, std::size_t from_bits) {
  auto squarer = squarer_for(N, from_bits);
  if (!squarer) return std::nullopt;
  squarer->load(reduced(w, N));
  for (std::uint64_t i = 0; i < steps; ++i) {
    if (cancel && i % 1024 == 0 && cancel->load(std::memory_order_relaxed)) return mpz_class(1);
    squarer->square_minus(2);
  }
  mpz_class last;
  squarer->store(last);
  return last;
}

}  // namespace tk::primes
