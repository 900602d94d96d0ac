/// @file weighted_tests.cpp
#include "primes/weighted_tests.hpp"

#include <vector>

#include "primes/weighted_squaring.hpp"
#include "primes/weighted_squaring_detail.hpp"

namespace tk::primes {

namespace {

// N - 1 = k*2^n for N = k*2^n + 1; for N = k*2^n - 1, N - 1 = 2*d with
// d = k*2^(n-1) - 1 odd, so base^d = base^(k*2^(n-1)) / base. Both need
// only (base^k)^(2^m) for some m: that is all the transform computes.
std::unique_ptr<WeightedSquaring> squarer_for(const Modulus& N, std::size_t from_bits) {
  if (!N.form() || N.bits() < from_bits || (N.form()->c != 1 && N.form()->c != -1)) return nullptr;
  return WeightedSquaring::create(*N.form());
}

mpz_class reduced(mpz_class value, const Modulus& N) {
  N.reduce(value.get_mpz_t());
  return value;
}

// Watches a chain of squares for one residue v mod N without leaving the
// transform: the value held is t + j*N with t = held_form(v), |j| <= 2,
// when it is v, so its residue mod 2^61 - 1 (carried along) is one of
// those of t + j*N (|j| <= 4 here, to spare); only then is it taken out
// and compared exactly.
class Watch {
 public:
  Watch(const Modulus& N, const WeightedSquaring& squarer, const mpz_class& target) : target_(target) {
    const mpz_class held = squarer.held_form(target);
    for (long j = -4; j <= 4; ++j) {
      const mpz_class shifted = held + j * N.value();
      residues_.push_back(mpz_fdiv_ui(shifted.get_mpz_t(), weighted_detail::kP61));
    }
  }
  bool seen(const WeightedSquaring& squarer) const {
    bool maybe = false;
    for (std::uint64_t r : residues_) maybe |= r == squarer.held_mod_p61();
    if (!maybe) return false;
    mpz_class x;
    squarer.store(x);
    return x == target_;
  }

 private:
  mpz_class target_;
  std::vector<std::uint64_t> residues_;
};

// A verdict only from a chain whose every square and last fold checked
// out: a square redone by GMP after a failed check may have squared a
// wrong value (riesel's proofs have their own checks; here GMP decides).
std::optional<bool> if_checked(const WeightedSquaring& squarer, bool verdict) {
  if (squarer.fallbacks() != 0 || !squarer.holds_carried_residue()) return std::nullopt;
  return verdict;
}

bool cancelled(const std::atomic<bool>* cancel, std::uint64_t step) {
  return cancel && step % 1024 == 0 && cancel->load(std::memory_order_relaxed);
}

// (b^k)^(2^squarings) mod N on the transform; nothing when cancelled.
std::optional<mpz_class> power_then_square(WeightedSquaring& squarer, const Modulus& N, const mpz_class& b,
                                           std::uint64_t squarings, const std::atomic<bool>* cancel) {
  mpz_class y;
  mpz_powm_ui(y.get_mpz_t(), b.get_mpz_t(), static_cast<unsigned long>(N.form()->k), N.value().get_mpz_t());
  squarer.load(y);
  for (std::uint64_t i = 0; i < squarings; ++i) {
    if (cancelled(cancel, i)) return std::nullopt;
    squarer.square_minus(0);
  }
  squarer.store(y);
  return y;
}

bool coprime(const mpz_class& b, const Modulus& N) {
  mpz_class g;
  mpz_gcd(g.get_mpz_t(), b.get_mpz_t(), N.value().get_mpz_t());
  return g == 1;
}

}  // namespace

std::optional<bool> weighted_strong_probable_prime(const Modulus& N, const mpz_class& base,
                                                   const std::atomic<bool>* cancel, std::size_t from_bits) {
  auto squarer = squarer_for(N, from_bits);
  if (!squarer) return std::nullopt;
  const mpz_class b = reduced(base, N), minus_one = N.value() - 1;
  const std::uint64_t n = N.form()->n;
  if (N.form()->c == 1) {
    // x_i = b^(k*2^i): passes when x_0 = 1 or some x_i = -1, i < n.
    mpz_class x;
    mpz_powm_ui(x.get_mpz_t(), b.get_mpz_t(), static_cast<unsigned long>(N.form()->k), N.value().get_mpz_t());
    if (x == 1 || x == minus_one) return true;
    squarer->load(x);
    const Watch watch(N, *squarer, minus_one);
    for (std::uint64_t i = 1; i < n; ++i) {
      if (cancelled(cancel, i)) return false;
      squarer->square_minus(0);
      if (watch.seen(*squarer)) return if_checked(*squarer, true);
    }
    return if_checked(*squarer, false);
  }
  // s = 1: passes when b^d = +-1, that is y = b^(k*2^(n-1)) = +-b, as long
  // as b is prime to N (else b^d is not +-1 whatever y is).
  if (!coprime(b, N)) return false;
  const auto y = power_then_square(*squarer, N, b, n - 1, cancel);
  if (!y) return false;
  return if_checked(*squarer, *y == b || *y == N.value() - b);
}

std::optional<bool> weighted_fermat_probable_prime(const Modulus& N, const mpz_class& base, std::size_t from_bits) {
  auto squarer = squarer_for(N, from_bits);
  if (!squarer) return std::nullopt;
  const mpz_class b = reduced(base, N);
  // N - 1 = k*2^n, or k*2^n - 2: then b^(N-1) = 1 when b^(k*2^n) = b^2
  // and b is prime to N.
  if (N.form()->c == -1 && !coprime(b, N)) return false;
  const auto y = power_then_square(*squarer, N, b, N.form()->n, nullptr);  // b^(k*2^n)
  return if_checked(*squarer, *y == (N.form()->c == 1 ? mpz_class(1) : reduced(b * b, N)));
}

std::optional<LucasTail> weighted_lucas_tail(const Modulus& N, const mpz_class& w, std::uint64_t last,
                                             const std::atomic<bool>* cancel, std::size_t from_bits) {
  auto squarer = squarer_for(N, from_bits);
  if (!squarer) return std::nullopt;
  const mpz_class first = reduced(w, N);
  if (first == 0) return LucasTail{1};
  squarer->load(first);
  const Watch watch(N, *squarer, 0);
  for (std::uint64_t r = 2; r <= last; ++r) {
    if (cancelled(cancel, r)) return LucasTail{0};
    squarer->square_minus(2);
    if (watch.seen(*squarer)) {
      if (!if_checked(*squarer, true)) return std::nullopt;
      return LucasTail{r};
    }
  }
  if (!if_checked(*squarer, true)) return std::nullopt;
  return LucasTail{0};
}

}  // namespace tk::primes
