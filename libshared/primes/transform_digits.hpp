/// @file transform_digits.hpp
/// @brief Big integers as digits of 18 bits held in doubles, the form
/// RightAngleSquarer multiplies: x = sum_j d_j * 2^(18 j) with every
/// |d_j| <= 2^17 + 1 ("nearly balanced": the carries below leave a digit
/// one past the balanced range at most). A value modulo 2^36 - 1 is the
/// sum of its even digits plus 2^18 times the sum of its odd ones (2^36 = 1
/// there), whatever the carries: products are checked cheaply by it, the
/// residue of a product being the product of its factors' residues. (An
/// error passes only if it is a multiple of 2^36 - 1 = (2^18 - 1)(2^18 + 1);
/// a coefficient off by one, 2^(18 j), never is.)
#pragma once

#include <gmpxx.h>

#include <cstddef>
#include <cstdint>

// The passes over digits are short loops the compiler vectorises: built
// for AVX-512, AVX2 and the baseline, the CPU's best chosen at load time.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define TK_DIGIT_CLONES __attribute__((target_clones("avx512f", "avx2", "default")))
#else
#define TK_DIGIT_CLONES
#endif

namespace tk::primes::digits18 {

constexpr int kBits = 18;
constexpr double kRadix = 262144.0;  // 2^18
constexpr std::int64_t kCheckModulus = (std::int64_t{1} << (2 * kBits)) - 1;

/// The nearest integer to x, |x| < 2^51, in a double (ties to even).
inline double nearest(double x) {
  constexpr double kShift = 6755399441055744.0;  // 1.5 * 2^52
  return (x + kShift) - kShift;                  // exact without -ffast-math, which the build never sets
}

/// x's digits into digits[0..count), balanced; false when x does not fit.
bool from_mpz(const mpz_class& x, double* digits, std::size_t count);
/// The value of digits[0..count) (any integers below 2^51 in size).
mpz_class to_mpz(const double* digits, std::size_t count);

/// The value of digits[0..count) modulo 2^36 - 1, in [0, 2^36 - 1); -1
/// when a digit is NaN or infinite (so it matches no product's residue).
std::int64_t residue(const double* digits, std::size_t count);
/// (a * b) mod 2^36 - 1 for any a, b, the result in [0, 2^36 - 1).
std::int64_t residue_product(std::int64_t a, std::int64_t b);

/// Integer-valued coefficients y[0..count), |y| < 2^51, to nearly balanced
/// digits of the same value: out[0..count + 3). `scratch` holds count + 3
/// doubles; none of the arrays overlap.
void carry_acyclic(const double* y, std::size_t count, double* out, double* scratch);
/// The same modulo 2^(18 count) + 1: the carry out of the top comes back
/// negated at the bottom; out[0..count), scratch[0..count).
void carry_negacyclic(const double* y, std::size_t count, double* out, double* scratch);

}  // namespace tk::primes::digits18
