/// @file weighted_passes.hpp
/// @brief WeightedSquaring's two carry passes, as free functions compiled
/// twice (BMI2/AVX2 where the CPU has them, chosen at run time: variable
/// shifts without the CL register take a third of the instructions).
#pragma once

#include <gmp.h>

#include <cstddef>
#include <cstdint>

namespace tk::primes {

struct HighCarry {
  std::int64_t low_carry = 0;  ///< floor(L / 2^n): the coefficients below 2^n carried into 2^n
  std::int64_t top_carry = 0;  ///< what carried out of the last coefficient (0 for a square that fits)
  std::size_t last_limb = 0;   ///< the last limb written
};

/// Carries z[low_digits..coefficients) into normal digits packed into
/// `high` from bit 0, and the low coefficients' carry alongside.
HighCarry carry_into_limbs(const std::int64_t* z, const std::uint8_t* bits, std::size_t low_digits,
                           std::size_t coefficients, std::uint64_t* high);

/// Where the fold puts the next transform's input: the integer digits,
/// and each digit times re_weight[j] into re[j] and, for the right-angle
/// transform (im not null), times im_weight[j] into im[j].
struct FoldTarget {
  std::int64_t* digits;
  double* re;
  const double* re_weight;
  double* im = nullptr;
  const double* im_weight = nullptr;
  bool wide = true;  ///< AVX-512 where the CPU has it
};

/// Digit j = the balanced digits of low[j] + sign * (bits e_j.. of q) for
/// j < low_digits, plus `bottom` at digit 0 and `top` at digit low_digits;
/// the last of the `digits` takes what is left.
/// exponent[j] = e_j, the bit where digit j starts.
void fold_digits(const std::int64_t* low, const mp_limb_t* q, const std::uint8_t* bits, const std::uint64_t* exponent,
                 const FoldTarget& target, std::size_t low_digits, std::size_t digits, std::int64_t bottom,
                 std::int64_t top, bool add_quotient);

}  // namespace tk::primes
