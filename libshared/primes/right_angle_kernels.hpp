/// @file right_angle_kernels.hpp
/// @brief RightAngleSquarer's passes, compiled once per SIMD width.
#pragma once

#include <cstddef>
#include <cstdint>

#include "primes/right_angle_transform.hpp"

namespace tk::primes::right_angle {

/// Everything one square reads and writes.
struct Arrays {
  double* re;
  double* im;
  const double* twiddle_re;
  const double* twiddle_im;
  const double* theta_cos;
  const double* theta_sin;
  std::size_t half;
  const RightAngleSquarer::Stage* stages;
  std::size_t stage_count;
  std::size_t inner_from;
  std::size_t inner_block;
  /// Where set (AVX-512 only), the first forward pass reads its points as
  /// digits[j] * (weight_re[j] + i*weight_im[j]) instead of re/im: the
  /// weighting pass fused into it, rounded as that pass rounds.
  const std::int64_t* digits = nullptr;
  const double* weight_re = nullptr;
  const double* weight_im = nullptr;
};

void square_avx512(const Arrays& arrays, const double* input, double* output);
void square_avx2(const Arrays& arrays, const double* input, double* output);
/// The forward passes alone, the inverse passes alone, the fused
/// forward-product-inverse with a stored spectrum (re, im), and the
/// pointwise product with it (see RightAngleSquarer's split interface).
void forward_avx512(const Arrays& arrays);
void forward_avx2(const Arrays& arrays);
void inverse_avx512(const Arrays& arrays);
void inverse_avx2(const Arrays& arrays);
void multiply_avx512(const Arrays& arrays, const double* re, const double* im);
void multiply_avx2(const Arrays& arrays, const double* re, const double* im);
void pointwise_avx512(const Arrays& arrays, const double* re, const double* im);
void pointwise_avx2(const Arrays& arrays, const double* re, const double* im);

/// One square split over threads: the outer passes on the columns whose
/// index modulo arrays.inner_block is in [from, to), forward or inverse
/// (all of them, in order); the inner passes and pointwise square of inner
/// blocks [first, last).
void outer_columns_avx512(const Arrays& arrays, bool forward, std::size_t from, std::size_t to);
void outer_columns_avx2(const Arrays& arrays, bool forward, std::size_t from, std::size_t to);
void inner_blocks_avx512(const Arrays& arrays, std::size_t first, std::size_t last);
void inner_blocks_avx2(const Arrays& arrays, std::size_t first, std::size_t last);

}  // namespace tk::primes::right_angle
