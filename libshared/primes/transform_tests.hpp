/// @file transform_tests.hpp
/// @brief The long loops of the base-2 strong test and of the strong Lucas
/// test for a generic N, on TransformModulus (squares in the spectrum,
/// Barrett's reduction by transforms). A step whose checks fail is done
/// again by the caller's GMP step, so the results are GMP's.
#pragma once

#include <gmpxx.h>

#include <atomic>
#include <functional>
#include <optional>

namespace tk::primes {

/// From these sizes on (bits of N) the transform loops beat GMP's
/// (bench_transform_reduction, 2026-11-27, runs on a loaded 2-core host,
/// ratios GMP time / ours: base 2 against mpz_powm 0.63-0.67 at 2,000
/// bits, 0.64-1.09 at 3,000, 0.78-0.94 at 3,500, 1.27-1.75 at 4,000; the
/// Lucas chain against GMP's squarings and divisions 0.98-1.05 at 2,000,
/// 0.94-0.95 at 2,500, 0.98-1.31 at 3,000, 1.29-1.60 at 4,000).
constexpr std::size_t kTransformPowerFromBits = 4000;
constexpr std::size_t kTransformLucasFromBits = 3000;

/// Whether the transform loops are worth taking for N, by its size.
inline bool transform_power_pays(const mpz_class& N) {
  return mpz_sizeinbase(N.get_mpz_t(), 2) >= kTransformPowerFromBits;
}
inline bool transform_lucas_pays(const mpz_class& N) {
  return mpz_sizeinbase(N.get_mpz_t(), 2) >= kTransformLucasFromBits;
}

/// 2^exponent mod N (exponent >= 1), or nothing where N has no transform
/// (too small or large, or no AVX2 with FMA) or `cancel` was set.
std::optional<mpz_class> transform_power_of_two(const mpz_class& N, const mpz_class& exponent,
                                                const std::atomic<bool>* cancel = nullptr);

/// U_k and U_(k+1) mod N for P = 1 and Q = q, k >= 1, by the doubling
/// steps below from U_1 = U_2 = 1, or nothing where N has no transform for
/// this q or `cancel` was set. `gmp_step(u, u_next, odd)` takes (U_j,
/// U_(j+1)) to (U_2j, U_(2j+1)), or to (U_(2j+1), U_(2j+2)) when odd, with
/// GMP: it redoes a step whose checks failed.
using LucasStep = std::function<void(mpz_class& u, mpz_class& u_next, bool odd)>;
std::optional<std::pair<mpz_class, mpz_class>> transform_lucas_u(const mpz_class& N, long q, const mpz_class& k,
                                                                 const LucasStep& gmp_step,
                                                                 const std::atomic<bool>* cancel = nullptr);

}  // namespace tk::primes
