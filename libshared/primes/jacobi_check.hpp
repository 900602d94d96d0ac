/// @file jacobi_check.hpp
/// @brief The periodic check of LLR's Lucas sequence u -> u^2 - 2 mod N
/// (the Jacobi check of Prime95 and LLR 4), with a restart from the last
/// verified state when it fails.
///
/// u_i = alpha^m + alpha^-m with m = k*2^i and alpha*alpha' = 1, so for
/// i >= 1, u_i - 2 = (alpha^(m/2) - alpha^(-m/2))^2 = (P^2 - 4)*U_(m/2)^2,
/// whose Jacobi symbol modulo N is (P^2 - 4 / N) = (P-2 / N)(P+2 / N) = -1
/// by the choice of P (for D = 13, (117 / N) = (13 / N) = -1), prime or
/// not; 0 means a common factor and is no error. A wrong value has -1 or
/// +1 about equally often, so each check catches an error with odds 1/2
/// (Gerbicz's check, for Proth, catches every one).
#pragma once

#include <gmpxx.h>

#include <cstdint>
#include <functional>
#include <string>

#include "io/error.hpp"
#include "primes/gerbicz_check.hpp"

namespace tk::primes {

/// Squarings between checks: one check (mpz_jacobi, 6 ms at 172,000
/// bits) costs about 1% of them at any size measured here.
constexpr std::uint64_t kJacobiCheckEvery = 5000;

/// Squares `value` (minus 2 each time) from `iteration` up to `last`,
/// checked every `every` squarings and at the end; `corrupt` as for
/// gerbicz_squarings. Returns the outcome (restarts counted).
inline GerbiczOutcome jacobi_checked_squarings(const CheckedSquarer& squarer, const mpz_class& N, mpz_class& value,
                                               std::uint64_t& iteration, std::uint64_t last, std::uint64_t every,
                                               const std::function<bool(std::uint64_t, mpz_class&)>& corrupt) {
  constexpr std::uint64_t kMaxRestartsInARow = 3;
  GerbiczOutcome outcome;
  std::uint64_t verified_iteration = iteration, failures_in_a_row = 0;
  mpz_class verified = value, shifted;
  squarer.load(value);
  while (iteration < last) {
    const std::uint64_t next = std::min(last, iteration + every);
    if (!squarer.square_to(iteration, next, true)) {
      squarer.store(value);
      return outcome;
    }
    squarer.store(value);
    if (corrupt && corrupt(iteration, value)) squarer.load(value);
    shifted = value - 2;
    if (mpz_jacobi(shifted.get_mpz_t(), N.get_mpz_t()) != 1) {  // -1 or 0: as it must be
      verified = value;
      verified_iteration = iteration;
      failures_in_a_row = 0;
      continue;
    }
    if (++failures_in_a_row > kMaxRestartsInARow)
      throw Error("the Jacobi check of the Lucas sequence failed " + std::to_string(failures_in_a_row) +
                  " times in a row at iteration " + std::to_string(verified_iteration));
    ++outcome.restarts;
    iteration = verified_iteration;
    value = verified;
    squarer.load(value);
  }
  outcome.finished = true;
  return outcome;
}

}  // namespace tk::primes
