/// @file transform_reduction.hpp
/// @brief Arithmetic modulo a generic N (no special form) on our own
/// transform: residues are 18-bit digits in doubles (transform_digits.hpp),
/// squares and products are taken in the spectrum, and the reduction is
/// Barrett's (Handbook of Applied Cryptography, Algorithm 14.42) with the
/// spectra of mu = floor(2^(s1+s2) / N) and of N stored:
///   q = floor(floor(a / 2^s1) * mu / 2^s2), r = a - q*N,
/// the quotient from an acyclic product, the remainder from a product
/// modulo 2^K + 1 (K a little above the bits of N), where it is exact.
/// The quotient is only approximate (the digits' carries are not complete
/// below it), so r = a - q*N lies within a few N of 0 instead of in
/// [0, N): residues are kept so, and reduced exactly at the end.
///
/// Every step is checked: each rounded coefficient lies within 0.25 of an
/// integer, the values modulo 2^36 - 1 agree with the factors' (which
/// catches any wrong coefficient, carry or quotient product), and a
/// remainder fits the digits a residue has. A step that fails reports it,
/// and the caller does it again with GMP: a failed check never gives a
/// wrong result.
#pragma once

#include <gmpxx.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "primes/right_angle_transform.hpp"

namespace tk::primes {

class TransformModulus {
 public:
  /// A residue: value() = sum of digits[j] * 2^(18 j), |value| < 2.2 N,
  /// congruent to what it stands for modulo N; `check` is its value mod
  /// 2^36 - 1 (transform_digits.hpp).
  struct Residue {
    std::vector<double> digits;
    std::int64_t check = 0;
  };

  /// Nothing when N (odd, > 2^64) is past the transforms' lengths or the
  /// CPU has no AVX2 with FMA. `spread` bounds the size of what reduce()
  /// is given: |a| <= spread * (the largest |x * y| of two residues).
  static std::unique_ptr<TransformModulus> create(const mpz_class& N, std::uint64_t spread,
                                                  RightAngleSquarer::Simd simd = RightAngleSquarer::Simd::best);

  TransformModulus(const TransformModulus&) = delete;
  TransformModulus& operator=(const TransformModulus&) = delete;
  ~TransformModulus();

  const mpz_class& modulus() const { return n_; }
  /// Digits a residue holds (M), and points of its spectrum.
  std::size_t digits() const { return digits_; }
  std::size_t points() const { return square_->points(); }

  /// x (any integer below about 2^(18 M - 2) in size, usually in [0, N)).
  Residue load(const mpz_class& x) const;
  /// The residue's value reduced modulo N, in [0, N).
  mpz_class value(const Residue& x) const;

  /// The spectrum of x at the squaring length: real and imaginary parts,
  /// points() each, in re and im.
  void spectrum(const Residue& x, double* re, double* im);

  /// The spectrum the squaring transform holds, as a sum of products of
  /// residues' spectra, to be reduced: write it here, then reduce().
  double* product_real() { return square_->real(); }
  double* product_imaginary() { return square_->imaginary(); }
  /// out := (factor times the product held, reduced), given its value
  /// modulo 2^36 - 1 (`check`) from its factors'. False when a check failed
  /// (out is then undefined): the caller redoes the step otherwise.
  bool reduce(std::int64_t check, double factor, Residue& out);

  /// Steps where a check failed, since creation (for tests and reports).
  std::uint64_t failures() const { return failures_; }

 private:
  TransformModulus() = default;
  bool reduce_digits(const double* a, std::size_t count, Residue& out);

  mpz_class n_;
  std::size_t bits_ = 0;
  std::size_t digits_ = 0;                        ///< M: digits of a residue
  std::size_t low_shift_ = 0;                     ///< s1 / 18
  std::size_t high_shift_ = 0;                    ///< s2 / 18
  std::unique_ptr<RightAngleSquarer> square_;     ///< products of two residues
  std::unique_ptr<RightAngleSquarer> quotient_;   ///< floor(a / 2^s1) times mu, acyclic
  std::unique_ptr<RightAngleSquarer> remainder_;  ///< q times N modulo 2^K + 1
  std::vector<double> mu_re_, mu_im_, n_re_, n_im_;
  std::vector<double> n_digits_;
  std::int64_t n_check_ = 0;
  std::size_t quotient_digits_count_ = 0;  ///< digits of floor(a / 2^s1) taken
  std::vector<double> coefficients_, product_, scratch_, quotient_digits_, folded_, remainder_digits_;  ///< work
  std::uint64_t failures_ = 0;
};

}  // namespace tk::primes
