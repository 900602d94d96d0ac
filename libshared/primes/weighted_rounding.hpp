/// @file weighted_rounding.hpp
/// @brief The first half of WeightedSquaring's carry pass, the part with
/// no carry: unweight and round the inverse transform's output, track the
/// worst rounding error, and sum the coefficients times 2^(e_j) modulo
/// 2^61 - 1. Vectorised (AVX2 where the CPU has it, chosen at run time).
#pragma once

#include <cstddef>
#include <cstdint>

namespace tk::primes {

struct RoundedCoefficients {
  double worst = 0;          ///< largest |value - rounded|
  std::uint64_t sum = 0;     ///< sum of z_j * 2^(e_j) mod 2^61 - 1, reduced
  bool out_of_range = false;  ///< some |value| >= 2^51 (or NaN): not rounded
};

/// z[j] = round(output[j] * weight[j]) for j < count; rotation[j] = e_j mod 61.
RoundedCoefficients round_coefficients(const double* output, const double* weight, const std::uint8_t* rotation,
                                       std::int64_t* z, std::size_t count);

}  // namespace tk::primes
