/// @file cpu_features.hpp
/// @brief The two SIMD levels the weighted squaring's kernels are compiled
/// for (right_angle_kernels, weighted_rounding, weighted_passes), each
/// asked of the CPU once.
#pragma once

namespace tk::primes::cpu {

/// AVX2 with FMA, BMI and BMI2 (every AVX2 CPU since Haswell has all four).
inline bool has_avx2() {
  static const bool has = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") &&
                          __builtin_cpu_supports("bmi") && __builtin_cpu_supports("bmi2");
  return has;
}

/// AVX-512 F, DQ and VL, on top of has_avx2().
inline bool has_avx512() {
  static const bool has = has_avx2() && __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") &&
                          __builtin_cpu_supports("avx512vl");
  return has;
}

}  // namespace tk::primes::cpu
