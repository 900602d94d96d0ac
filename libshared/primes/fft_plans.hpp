/// @file fft_plans.hpp
/// @brief FFTW's real transforms for the squarers: one pair of plans per
/// length, made once per process and shared, and the lengths FFTW does fast.
#pragma once

#include <fftw3.h>

#include <cstddef>
#include <vector>

namespace tk::primes {

/// A square whose worst rounding error passes this is redone by GMP: the
/// error of a correct rounding is far below it at the digit sizes chosen.
inline constexpr double kMaxRoundoff = 0.4;

/// Out-of-place real -> half spectrum and back (unnormalised); executed
/// on any arrays allocated by fftw_alloc_*, as the squarers' are.
struct RealFftPlans {
  fftw_plan forward = nullptr;
  fftw_plan inverse = nullptr;
};

/// The plans for `length` (even), planned on first use and kept until exit.
const RealFftPlans* real_fft_plans(std::size_t length);

/// The square of a real sequence of `length` values, from `input` into
/// `output` (unnormalised: each value `length` times too large), through
/// the half spectrum `spectrum`.
void square_by_real_fft(const RealFftPlans& plans, double* input, fftw_complex* spectrum, double* output,
                        std::size_t length);

/// Lengths FFTW transforms fast, ascending: 2^a times 1, 3, 5, 7 or 9
/// (measured here; factors like 11 cost half as much again).
const std::vector<std::size_t>& fast_fft_lengths();

}  // namespace tk::primes
