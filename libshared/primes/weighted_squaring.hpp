/// @file weighted_squaring.hpp
/// @brief Repeated squaring modulo N = k*2^n +- 1 by a weighted transform
/// (Crandall-Fagin's variable digits), the reduction and the carries done
/// on the digits: the state between squarings is the transform's input.
///
/// x is held as m + t balanced digits: digit j has s_j = e_(j+1) - e_j bits,
/// e_j = ceil(n*j/m), so 2^n falls exactly on digit m and digits m.. hold
/// the part above 2^n (k's bits). The transform's input is digit j times
/// the weight 2^(e_j - n*j/m), in [1, 2); the acyclic square (a real FFT
/// of length L >= 2(m+t) - 1, zero-padded: k of up to 56 bits leaves no
/// room for the cyclic form's precision) then gives, after dividing by the
/// same weights, the integers z_j = sum of x_i*x_l*2^(e_i+e_l-e_j), the
/// square's coefficients at 2^(e_j). One pass rounds, checks and carries
/// them; the part above 2^n goes to limbs for one division by k (GMP's
/// mpn_mod_1 for the remainder, then mpn_divexact_1); one pass folds
/// the quotient back (k*2^n = -c mod N) while carrying
/// into balanced digits and weighting them for the next transform.
///
/// Every square is checked, as FftSquaring's: worst rounding error below
/// 0.4, nothing carried out of the top, and the coefficients must give the
/// square modulo the prime 2^61 - 1 (a coefficient rounded the wrong way
/// changes that sum by a power of two). A square failing a check is
/// redone with GMP (fallbacks()).
#pragma once

#include <gmpxx.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "primes/modulus.hpp"

namespace tk::primes {

struct RealFftPlans;
class RightAngleSquarer;

class WeightedSquaring {
 public:
  /// Nothing when the form is not k*2^n +- 1 with k odd, k < 2^56, n >= 64,
  /// or N is too large for double precision at every length.
  static std::unique_ptr<WeightedSquaring> create(const SpecialForm& form);
  /// Which transform squares: our right-angle transform
  /// (right_angle_transform.hpp) at the widest SIMD the CPU has, or at AVX2
  /// width, where it plans the length, else FFTW's real transforms; or
  /// FFTW's always. TOOLKIT_RIESEL_TRANSFORM=avx2 or fftw sets create()'s.
  enum class Transform { widest, avx2, fftw };

  /// A given transform length and largest digit size, unchecked for
  /// rounding safety (for tests of the checks); nothing when the square
  /// would not fit the length.
  static std::unique_ptr<WeightedSquaring> create_with(const SpecialForm& form, std::size_t length, int digit_bits,
                                                       Transform transform = Transform::widest);

  WeightedSquaring(const WeightedSquaring&) = delete;
  WeightedSquaring& operator=(const WeightedSquaring&) = delete;
  ~WeightedSquaring();

  void load(const mpz_class& x);   ///< any x >= 0; held modulo N
  void store(mpz_class& x) const;  ///< 0 <= x < N
  /// x := x^2 - minus (mod N).
  void square_minus(unsigned long minus);

  /// The held value's residue modulo 2^61 - 1, carried from square to
  /// square (the held value is x plus a small multiple of N, |j| <= 4).
  std::uint64_t held_mod_p61() const { return value_mod_p_; }
  /// Whether the digits held give that residue: the last fold, which no
  /// square has checked yet, went right.
  bool holds_carried_residue() const;

  std::size_t transform_length() const { return length_; }
  /// "right-angle, 8 lanes" or "FFTW": which transform squares.
  std::string transform_name() const;
  int digit_bits() const { return max_digit_bits_; }  ///< the largest s_j
  double worst_roundoff() const { return worst_roundoff_; }
  std::uint64_t fallbacks() const { return fallbacks_; }

 private:
  WeightedSquaring(const SpecialForm& form, std::size_t length, std::size_t low_digits, Transform transform);

  bool square_and_carry();  ///< transforms; the square's digits into low_/high_; false when a check fails
  void divide_and_fold(unsigned long minus);
  /// Balanced, weighted digits of the low coefficients -/+ the quotient's low n bits, with
  /// `top` times 2^n and `bottom` added, into the transform's input (and x mod 2^61-1).
  void fold_into_input(std::int64_t top, std::int64_t bottom);
  void square_by_gmp(unsigned long minus);
  void right_angle_weights();

  SpecialForm form_;
  std::size_t length_;
  std::size_t low_digits_;    ///< m: digits below 2^n
  std::size_t digits_;        ///< m + t: digits of the input
  std::size_t coefficients_;  ///< 2*digits_ - 1: coefficients of the square
  int max_digit_bits_ = 0;
  std::vector<std::uint64_t> exponent_;  ///< e_j, j <= coefficients_
  std::vector<std::uint8_t> bits_;       ///< s_j
  std::vector<std::uint8_t> rotation_;   ///< e_j mod 61: 2^(e_j) mod 2^61-1 is a rotation
  std::vector<double> input_weight_;     ///< 2^(e_j - nj/m)
  std::vector<double> output_weight_;    ///< its inverse over L
  // The right-angle transform's: input_weight_ times cos and sin(pi*j/L),
  // and the rounding's weights (weighted_rounding.hpp).
  std::vector<double> re_weight_, im_weight_, round_a_, round_b_, round_c_, round_d_;
  std::vector<std::int64_t> digit_;  ///< the input's digits, for store()
  std::vector<mp_limb_t> high_;      ///< the square's bits from 2^n up
  std::vector<mp_limb_t> quotient_;  ///< high_ / k, zero-padded
  std::size_t high_limbs_ = 0;
  // FFTW's arrays, null where our transform squares in its own.
  double* input_ = nullptr;              ///< FFTW-aligned, length_, zero past digits_
  double* output_ = nullptr;             ///< FFTW-aligned, length_
  void* spectrum_ = nullptr;             ///< FFTW-aligned, length_/2 + 1 complex
  const RealFftPlans* plans_ = nullptr;  ///< FFTW's, where right_angle_ is not used
  std::unique_ptr<RightAngleSquarer> right_angle_;
  bool wide_ = true;  ///< the passes may use AVX-512 (where the CPU has it)
  std::vector<std::int64_t>
      coefficient_;                  ///< the square's coefficients, rounded (below 2^n: the fold's input); L places
  std::int64_t low_carry_ = 0;       ///< floor(L / 2^n) of those below 2^n, moved into H
  std::uint64_t value_mod_p_ = 0;    ///< the input's value mod 2^61-1
  std::uint64_t square_mod_p_ = 0;   ///< its square's, from the coefficients
  std::uint64_t modulus_mod_p_ = 0;  ///< N's
  double worst_roundoff_ = 0;
  std::uint64_t fallbacks_ = 0;
};

}  // namespace tk::primes
