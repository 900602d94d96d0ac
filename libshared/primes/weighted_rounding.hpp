/// @file weighted_rounding.hpp
/// @brief The first half of WeightedSquaring's carry pass, the part with
/// no carry: unweight and round the inverse transform's output, track the
/// worst rounding error, and sum the coefficients times 2^(e_j) modulo
/// 2^61 - 1. Vectorised (AVX-512 or AVX2 where the CPU has it, chosen at
/// run time).
#pragma once

#include <cstddef>
#include <cstdint>

namespace tk::primes {

struct RoundedCoefficients {
  double worst = 0;            ///< largest |value - rounded|
  std::uint64_t sum = 0;       ///< sum of z_j * 2^(e_j) mod 2^61 - 1 over j < low, reduced
  std::uint64_t sum_high = 0;  ///< the same over j >= low
  bool out_of_range = false;   ///< some |value| >= 2^51 (or NaN): not rounded
};

/// z[j] = round(output[j] * weight[j]) for j < count; rotation[j] = e_j mod 61.
/// The sums are split at index `low` (the reduction needs both parts).
RoundedCoefficients round_coefficients(const double* output, const double* weight, const std::uint64_t* rotation,
                                       std::int64_t* z, std::size_t count, std::size_t low);

/// The right-angle transform's output (RightAngleSquarer::square_in_place),
/// unweighted and rounded: for j < half, z[j] = round(re*a + im*b) and
/// z[j + half] = round(im*c - re*d), the weights at j (theta^-j, the
/// digits' weights and the scale in one). half is a multiple of 8; z and
/// rotation have 2 * half places (weights zero and rotations zero past the
/// square's last coefficient). The sums are split at index `low` < half.
/// Only z[j] for j < count (the square's coefficients) is written.
struct RightAngleWeights {
  const double* a;
  const double* b;
  const double* c;
  const double* d;
};
/// `wide`: AVX-512 where the CPU has it, else AVX2.
RoundedCoefficients round_right_angle(const double* re, const double* im, const RightAngleWeights& weights,
                                      const std::uint64_t* rotation, std::int64_t* z, std::size_t half, std::size_t low,
                                      std::size_t count, bool wide);

/// round_right_angle (AVX-512 only) with balance_digits' first lane pass
/// done on the rounded integers before they are stored, on digits [0, low)
/// and [low, count) as two ranges (bits: the digits' sizes): what
/// round_right_angle, then balance_digits' first pass on each range,
/// leave. Further passes, where a range's largest carry calls for them,
/// are the caller's.
struct CarriedCoefficients {
  RoundedCoefficients rounded;    ///< of the integers as rounded, before any carry
  std::int64_t low_carry = 0;     ///< out of digit low - 1
  std::int64_t top_carry = 0;     ///< out of digit count - 1
  std::int64_t low_largest = 0;   ///< the largest carry moved in [0, low)
  std::int64_t high_largest = 0;  ///< the same in [low, count)
};
CarriedCoefficients round_right_angle_carried(const double* re, const double* im, const RightAngleWeights& weights,
                                              const std::uint64_t* rotation, const std::uint8_t* bits, std::int64_t* z,
                                              std::size_t half, std::size_t low, std::size_t count);

/// round_right_angle on the points j < half whose index modulo `period`
/// is in [from, to) (multiples of the lanes, 8), and their partners at
/// j + half: one thread's part of a split square. The sums are reduced;
/// combine() adds two parts' (the same as one pass over both).
RoundedCoefficients round_right_angle_columns(const double* re, const double* im, const RightAngleWeights& weights,
                                              const std::uint64_t* rotation, std::int64_t* z, std::size_t half,
                                              std::size_t low, std::size_t period, std::size_t from, std::size_t to,
                                              bool wide);
RoundedCoefficients combine(const RoundedCoefficients& a, const RoundedCoefficients& b);

}  // namespace tk::primes
