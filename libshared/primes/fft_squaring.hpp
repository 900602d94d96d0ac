/// @file fft_squaring.hpp
/// @brief Repeated squaring modulo N = k*2^n +- 1 by a floating-point FFT,
/// for the long proofs where GMP's Toom squaring is the bottleneck.
///
/// x (0 <= x < N) is split into balanced digits of b bits; its square is a
/// real cyclic convolution (FFTW) of length L >= twice the digit count, so
/// nothing wraps; the coefficients are rounded back to integers, carried
/// into limbs, and reduced with the special form's shifts and one division
/// by k. Every square is checked: the largest rounding error must stay
/// below 0.4, nothing may carry out of the top, and the coefficients must
/// sum to X(1)^2 and X(-1)^2 (X the digit polynomial; a single coefficient
/// rounded the wrong way breaks both); a square failing any check is
/// recomputed with GMP (counted in fallbacks()).
#pragma once

#include <gmpxx.h>

#include <cstdint>
#include <memory>
#include <vector>

#include "primes/modulus.hpp"

namespace tk::primes {

struct RealFftPlans;

class FftSquaring {
 public:
  /// Nothing when the form is not k*2^n +- 1 or N is too large for double
  /// precision at any transform length the table holds.
  static std::unique_ptr<FftSquaring> create(const SpecialForm& form);
  /// A given transform length and digit size, unchecked for rounding
  /// safety (for tests of the checks); nothing when the square would wrap.
  static std::unique_ptr<FftSquaring> create_with(const SpecialForm& form, std::size_t length, int digit_bits);

  FftSquaring(const FftSquaring&) = delete;
  FftSquaring& operator=(const FftSquaring&) = delete;
  ~FftSquaring();

  void load(const mpz_class& x);  ///< 0 <= x < N
  void store(mpz_class& x) const;
  /// x := x^2 - minus (mod N), 0 <= x < N.
  void square_minus(unsigned long minus);

  std::size_t transform_length() const { return length_; }
  int digit_bits() const { return digit_bits_; }
  double worst_roundoff() const { return worst_roundoff_; }
  std::uint64_t fallbacks() const { return fallbacks_; }

 private:
  FftSquaring(const SpecialForm& form, std::size_t length, int digit_bits);

  void split_into_digits();
  bool square_by_fft();  ///< x^2 into product_; false when a check fails
  void reduce_product(unsigned long minus);

  SpecialForm form_;
  std::size_t length_;
  int digit_bits_;
  std::size_t digits_;  ///< balanced digits of any x < N, top carry included
  std::size_t limbs_;   ///< limbs of N
  std::vector<mp_limb_t> modulus_, x_, product_, high_, quotient_;
  std::vector<std::uint64_t> digit_buffer_;  ///< the square's digits after carrying
  double* real_ = nullptr;                   ///< FFTW-aligned, length_
  void* spectrum_ = nullptr;                 ///< FFTW-aligned, length_/2 + 1 complex
  const RealFftPlans* plans_ = nullptr;
  std::uint64_t square_at_one_ = 0, square_at_minus_one_ = 0;
  double worst_roundoff_ = 0;
  std::uint64_t fallbacks_ = 0;
};

}  // namespace tk::primes
