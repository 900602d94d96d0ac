/// @file bench_generic.cpp
/// @brief BPSW on a generic 3,000-digit prime (no special form): our
/// test_number against GMP's mpz_probab_prime_p(n, 0), which is BPSW in
/// GMP >= 6.2. Goal: ratio (GMP time / our time) >= 1.
#include <gmpxx.h>

#include "bench_common.hpp"
#include "primes/primality.hpp"

namespace {

constexpr unsigned long kDigits = 3000;

/// The next prime after a seeded random kDigits-digit number; deterministic.
mpz_class generic_prime() {
  gmp_randclass random(gmp_randinit_mt);
  random.seed(3000);
  mpz_class low, prime;
  mpz_ui_pow_ui(low.get_mpz_t(), 10, kDigits - 1);
  const mpz_class start = low + random.get_z_range(9 * low);
  mpz_nextprime(prime.get_mpz_t(), start.get_mpz_t());
  return prime;
}

bool ours_says_prime(const tk::primes::Number& number) {
  const auto outcome = tk::primes::test_number(number, tk::primes::TestPlan{});
  return outcome.verdict >= tk::primes::Verdict::probable_prime;
}

bool gmp_says_prime(const mpz_class& n) { return mpz_probab_prime_p(n.get_mpz_t(), 0) != 0; }

}  // namespace

int main() {
  const int repeats = bench::repeats({"BENCH_GENERIC_REPEATS", "BENCH_REPEATS"}, 5);
  const double setup = bench::cpu_seconds();
  const tk::primes::Number number{generic_prime(), std::nullopt};
  std::printf("bench_generic: %zu-digit prime (%zu bits, found in %.1f s), test_number vs mpz_probab_prime_p(n, 0), "
              "%d repeats\n", mpz_sizeinbase(number.value.get_mpz_t(), 10),
              mpz_sizeinbase(number.value.get_mpz_t(), 2), bench::cpu_seconds() - setup, repeats);

  bench::Results results("bench_generic");
  for (int r = 0; r < repeats; ++r) {
    bool mine = false, theirs = false;
    double t_ours = 0, t_peer = 0;
    if (r % 2 == 0) {
      t_ours = bench::time_cpu([&] { mine = ours_says_prime(number); });
      t_peer = bench::time_cpu([&] { theirs = gmp_says_prime(number.value); });
    } else {
      t_peer = bench::time_cpu([&] { theirs = gmp_says_prime(number.value); });
      t_ours = bench::time_cpu([&] { mine = ours_says_prime(number); });
    }
    if (!mine || !theirs)
      bench::fail(std::string("verdicts on the 3000-digit prime: ours ") + (mine ? "prime" : "composite") +
                  ", GMP " + (theirs ? "prime" : "composite"));
    results.add(t_ours, t_peer);
  }
  results.report(1.0);
}
