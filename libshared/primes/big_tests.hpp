/// @file big_tests.hpp
/// @brief Probable-prime tests for integers of any size with GMP, using the
/// Modulus' reduction (special form k*2^n+c when it has one).
#pragma once

#include <gmpxx.h>

#include <atomic>
#include <cstdint>

#include "primes/modulus.hpp"

namespace tk::primes {

/// a^(N-1) == 1 (mod N). N odd, N > 3.
bool fermat_probable_prime(const Modulus& N, const mpz_class& base);

/// Miller-Rabin strong probable prime to `base`. N odd, N > 3. With a
/// special-form N, the test stops early when `cancel` becomes true (its
/// result is then meaningless); GMP's mpz_powm, used otherwise, cannot stop.
bool strong_probable_prime(const Modulus& N, const mpz_class& base, const std::atomic<bool>* cancel = nullptr);

/// Result of choosing Selfridge's D for N.
struct SelfridgeChoice {
  std::int64_t d = 0;    ///< 0 when N is a perfect square
  mpz_class factor = 0;  ///< a nontrivial factor found on the way, else 0
};
SelfridgeChoice selfridge_d(const mpz_class& N);

/// Strong Lucas probable prime with P = 1, Q = (1 - D)/4 (D from
/// selfridge_d). Sets `factor` if the test stumbles on one.
/// `zero_at_last` (when given) tells whether V_{(N+1)/2} = 0, the condition
/// that proves N = k*2^n - 1 prime under Rodseth's criterion.
bool strong_lucas_probable_prime(const Modulus& N, std::int64_t d, mpz_class& factor,
                                 const std::atomic<bool>* cancel = nullptr, bool* zero_at_last = nullptr);

/// One doubling step of the Lucas U chain (P = 1, Q = q) with GMP:
/// (U_j, U_(j+1)) to (U_2j, U_2j+1), or to (U_2j+1, U_2j+2) when `odd`,
/// by three squarings and two remainders (Hackman's formulas, see
/// strong_lucas_probable_prime); the results lie in (-N, N).
class LucasDoubler {
 public:
  LucasDoubler(const Modulus& N, long q);
  void operator()(mpz_class& u, mpz_class& u_next, bool odd);

 private:
  const Modulus& n_;
  long q_;
  mpz_class high_, low_, square_, diff_;
};

}  // namespace tk::primes
