/// @file gerbicz_check.hpp
/// @brief Gerbicz's check of a long run of squarings x -> x^2 mod N (the
/// Proth test's a^(k*2^(n-1))), with a restart from the last verified
/// state when it fails: a hardware error or an arithmetic slip that the
/// squarer's own checks missed cannot change a verdict.
///
/// With u_0 the verified start and u_j = u_(j-1)^(2^B) the value every B
/// squarings, d_j = u_0*u_1*...*u_j (one multiplication per block) obeys
/// d_j = u_0 * d_(j-1)^(2^B). After `blocks` blocks that identity is
/// checked with B more squarings of d_(j-1); when it holds, u_j becomes the
/// verified start. The squarings past the last full block are run twice
/// from the verified state and compared.
#pragma once

#include <gmpxx.h>

#include <cstdint>
#include <functional>

#include "io/error.hpp"
#include "primes/modulus.hpp"

namespace tk::primes {

struct GerbiczPlan {
  std::uint64_t block = 1000;   ///< B: squarings between multiplications
  std::uint64_t blocks = 1000;  ///< blocks between checks
};

/// B = sqrt(squarings) within [32, 1000], checked every B blocks.
inline GerbiczPlan gerbicz_plan(std::uint64_t squarings) {
  std::uint64_t block = 32;
  while (block < 1000 && (block + 1) * (block + 1) <= squarings) ++block;
  return {block, block};
}

/// What the check loop needs around a squarer: square until `iteration`
/// reaches `last` (with `report`, reporting progress on the way; false
/// when a report or a cancel stopped it), load, store.
struct CheckedSquarer {
  std::function<bool(std::uint64_t& iteration, std::uint64_t last, bool report)> square_to;
  std::function<void(const mpz_class&)> load;
  std::function<void(mpz_class&)> store;
};

struct GerbiczOutcome {
  bool finished = false;
  std::uint64_t restarts = 0;
};

/// Squares `value` from `iteration` up to `last`, checked; `corrupt` (tests
/// only) may alter the value at a block's end and says whether it did.
inline GerbiczOutcome gerbicz_squarings(const CheckedSquarer& squarer, const Modulus& N, mpz_class& value,
                                        std::uint64_t& iteration, std::uint64_t last, const GerbiczPlan& plan,
                                        const std::function<bool(std::uint64_t, mpz_class&)>& corrupt) {
  constexpr std::uint64_t kMaxRestartsInARow = 3;
  GerbiczOutcome outcome;
  std::uint64_t verified_iteration = iteration, failures_in_a_row = 0;
  mpz_class verified = value, product = value, previous, check;
  auto multiply = [&](mpz_class& into, const mpz_class& by) {
    into *= by;
    N.reduce(into.get_mpz_t());
  };
  auto restart = [&] {
    if (++failures_in_a_row > kMaxRestartsInARow)
      throw Error("Gerbicz check failed " + std::to_string(failures_in_a_row) + " times in a row at iteration " +
                  std::to_string(verified_iteration));
    ++outcome.restarts;
    iteration = verified_iteration;
    value = verified;
    product = verified;
  };
  std::uint64_t blocks_done = 0;
  squarer.load(value);
  while (last - iteration >= plan.block) {
    const std::uint64_t block_end = iteration + plan.block;
    if (!squarer.square_to(iteration, block_end, true)) {
      squarer.store(value);
      return outcome;
    }
    squarer.store(value);
    if (corrupt && corrupt(iteration, value)) squarer.load(value);
    previous = product;
    multiply(product, value);
    if (++blocks_done < plan.blocks && last - iteration >= plan.block) continue;
    // d_j = u_0 * d_(j-1)^(2^B)?
    blocks_done = 0;
    squarer.load(previous);
    std::uint64_t scratch = 0;
    squarer.square_to(scratch, plan.block, false);
    squarer.store(check);
    multiply(check, verified);
    if (check == product) {
      verified_iteration = iteration;
      verified = value;
      product = value;
      failures_in_a_row = 0;
    } else {
      restart();
    }
    squarer.load(value);
  }
  // The tail, shorter than a block: twice from the verified state.
  while (iteration < last) {
    const std::uint64_t start = iteration;
    if (!squarer.square_to(iteration, last, true)) {
      squarer.store(value);
      return outcome;
    }
    mpz_class first;
    squarer.store(first);
    if (corrupt && corrupt(iteration, first)) squarer.load(first);
    squarer.load(value);
    std::uint64_t again = start;
    squarer.square_to(again, last, false);
    squarer.store(check);
    if (first == check) {
      value = first;
    } else {
      restart();
      iteration = start;
      squarer.load(value);
    }
  }
  outcome.finished = true;
  return outcome;
}

}  // namespace tk::primes
