/// @file simd_widths.hpp
/// @brief The SIMD widths of RightAngleSquarer this CPU runs (AVX2 forced
/// on an AVX-512 machine too), for tests that cover each.
#pragma once

#include <vector>

#include "primes/right_angle_transform.hpp"

namespace simd_test {

inline std::vector<tk::primes::RightAngleSquarer::Simd> widths_here() {
  using Simd = tk::primes::RightAngleSquarer::Simd;
  std::vector<Simd> widths;
  for (auto simd : {Simd::avx2, Simd::avx512})
    if (tk::primes::RightAngleSquarer::create(64, simd)) widths.push_back(simd);
  return widths;
}

}  // namespace simd_test
