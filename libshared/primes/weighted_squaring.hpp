/// @file weighted_squaring.hpp
/// @brief Repeated squaring modulo N = k*2^n +- 1 by a weighted transform
/// (Crandall-Fagin's variable digits), the reduction and the carries done
/// on the digits: the state between squarings is the transform's input.
///
/// What is held is not x but t = x/k (mod N): since k*2^n = -c (mod N),
/// k's inverse is -c*2^n and the next value, t' = x'/k = k*t^2 - minus/k,
/// needs no division. t is held as m + t balanced digits: digit j has
/// s_j = e_(j+1) - e_j bits, e_j = ceil(n*j/m), so 2^n falls exactly on
/// digit m and digits m.. hold the part above 2^n (k's bits). The
/// transform's input is digit j times the weight 2^(e_j - n*j/m), in
/// [1, 2); the acyclic square (a real FFT of length L >= 2(m+t) - 1,
/// zero-padded: k of up to 56 bits leaves no room for the cyclic form's
/// precision) then gives, after dividing by the same weights, the integers
/// z_j, the square's coefficients at 2^(e_j). Since e_(j+m) = e_j + n,
/// k*t^2 = sum over j < m of (k*z_j - c*z_(j+m))*2^(e_j) plus the few
/// coefficients' part above 2^n, mod N: one pass rounds and checks, one
/// carries the coefficients into digits small enough to multiply by k (in
/// two halves of k), one multiplies, one carries the product, and the small
/// part above 2^n (Y, below about 2^(2*kbits + 6)) folds by one word
/// division, Y = a*k + b giving -c*a + b*2^n; the last pass weighs the
/// digits into the next transform's input. Where AVX-512 squares, the
/// passes fuse: the transform's first pass weighs, the rounding carries
/// once, the multiplication carries its product once (the same digits,
/// fewer sweeps over memory). load() and store() convert.
///
#pragma once

#include <gmpxx.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "primes/modulus.hpp"
#include "primes/skewed_allocator.hpp"
#include "primes/weighted_passes.hpp"
#include "primes/weighted_rounding.hpp"

namespace tk::primes {

struct RealFftPlans;
class RightAngleSquarer;
class ProofThreads;

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

  /// A given transform length and average digit size (the low digits are
  /// ceil(n / average_bits)), unchecked for rounding safety (for tests of
  /// the checks); nothing when the square would not fit the length.
  static std::unique_ptr<WeightedSquaring> create_with(const SpecialForm& form, std::size_t length, double average_bits,
                                                       Transform transform = Transform::widest);

  WeightedSquaring(const WeightedSquaring&) = delete;
  WeightedSquaring& operator=(const WeightedSquaring&) = delete;
  ~WeightedSquaring();

  void load(const mpz_class& x);   ///< any x >= 0; held modulo N (as x/k)
  void store(mpz_class& x) const;  ///< 0 <= x < N
  /// x := x^2 - minus (mod N).
  void square_minus(unsigned long minus);

  /// x/k mod N: what is held for x (plus a small multiple of N, |j| <= 2).
  mpz_class held_form(const mpz_class& x) const;
  /// The held value's residue modulo 2^61 - 1, carried from square to
  /// square: that of held_form(x) + j*N.
  std::uint64_t held_mod_p61() const { return value_mod_p_; }
  /// Whether the digits held give that residue: the last fold, which no
  /// square has checked yet, went right.
  bool holds_carried_residue() const;

  /// The digits held (balanced, digit j at 2^(e_j)): a split squaring
  /// (use_threads) must leave exactly the one-thread squaring's.
  const SkewedVector<std::int64_t>& held_digits() const { return digit_; }

  std::size_t transform_length() const { return length_; }
  /// "right-angle, 8 lanes" or "FFTW": which transform squares.
  std::string transform_name() const;
  int digit_bits() const { return max_digit_bits_; }      ///< the largest s_j
  std::size_t low_digits() const { return low_digits_; }  ///< m: the digits below 2^n
  double worst_roundoff() const { return worst_roundoff_; }
  std::uint64_t fallbacks() const { return fallbacks_; }

  /// Splits each squaring over `count` threads (created here, kept until
  /// this object goes or the count changes; 1 ends the split). The digits
  /// after every squaring are the same as on one thread. False (one
  /// thread) where FFTW squares: only our transform splits. `paced`:
  /// every few thousand squarings, 32 split and 32 on one thread are timed
  /// (wall clock) and the faster way squares until the next trial, so a
  /// split that other work on the cores makes slower stops costing.
  bool use_threads(unsigned count, bool paced = false);
  unsigned threads() const;
  /// Whether the next squaring is split (false between paced trials that
  /// found one thread faster).
  bool splitting() const { return threads_ && split_active_; }
  /// The shortest transform length split: measured (bench_riesel's
  /// split table, riesel(1)), or TOOLKIT_PROOF_THREADS_FROM's.
  static std::size_t split_from_length();

 private:
  WeightedSquaring(const SpecialForm& form, std::size_t length, std::size_t low_digits, Transform transform);

  /// t := k*t^2 + c*minus*2^n on the transform; false (nothing held
  /// changed) when a check fails.
  bool square_and_reduce(unsigned long minus);
  /// The same where the transform weighs the digits (AVX-512): the carries fused into the passes before them.
  bool square_and_reduce_fused(unsigned long minus);
  /// The same, split over threads_ (weighted_squaring_split.cpp).
  bool square_and_reduce_split(unsigned long minus);
  /// Those two's end, from the carried product in product_ (weighted_squaring.cpp).
  bool fold_product(std::int64_t carry, const RoundedCoefficients& rounded, std::int64_t low_carry,
                    unsigned long minus);
  /// The carries before the multiplication by k stop at this (the digits then multiply in 64 bits).
  std::int64_t carry_enough() const {
    return (std::int64_t{1} << digit_bound_bits_) - (std::int64_t{1} << (max_digit_bits_ - 1)) - 1;
  }
  /// The product's carries stop at this: the next square's digits may
  /// exceed [-2^(s-1), 2^(s-1)) by up to 2^10 (under 0.1 % of a 20-bit
  /// digit, no change in rounding), a lane pass fewer than carrying to 1.
  static constexpr std::int64_t kProductCarryEnough = 1024;
  /// Notes the rounding; whether the square is safe to reduce.
  bool rounding_checks_out(const RoundedCoefficients& rounded);
  /// Y's digits from m up (weighted_squaring.cpp), from the carried coefficients.
  __extension__ typedef unsigned __int128 Upper;
  Upper upper_part(const std::int64_t* z) const;
  /// t' mod 2^61-1 from the checked square, after the fold by a.
  void update_residue(const RoundedCoefficients& rounded, std::int64_t low_carry, std::int64_t a, unsigned long minus);
  /// The digits weighted into the transform's input (after a split square).
  void weigh_pending();
  /// The digits from coefficient_[0..m) and `top` at 2^n, weighted into the transform's input.
  void write_input(std::int64_t top);
  void square_by_gmp(unsigned long minus);
  void right_angle_weights();
  void split_k();

  SpecialForm form_;
  std::size_t length_;
  std::size_t low_digits_;    ///< m: digits below 2^n
  std::size_t digits_;        ///< m + t: digits of the input
  std::size_t coefficients_;  ///< 2*digits_ - 1: coefficients of the square
  int max_digit_bits_ = 0;
  std::vector<std::uint64_t> exponent_;   ///< e_j, j <= coefficients_
  SkewedVector<std::uint8_t> bits_;       ///< s_j for j < coefficients_, then zeros
  SkewedVector<std::uint64_t> rotation_;  ///< e_j mod 61: 2^(e_j) mod 2^61-1 is a rotation
  std::vector<double> input_weight_;      ///< 2^(e_j - nj/m)
  std::vector<double> output_weight_;     ///< its inverse over L
  // The right-angle transform's: input_weight_ times cos and sin(pi*j/L),
  // and the rounding's weights (weighted_rounding.hpp).
  SkewedVector<double> re_weight_, im_weight_, round_a_, round_b_, round_c_, round_d_;
  SkewedVector<std::int64_t> digit_;     ///< the input's digits, for store()
  std::int64_t k_low_ = 0, k_high_ = 0;  ///< k = k_high_*2^max_digit_bits_ + k_low_
  /// The coefficients are carried until every digit is below 2^digit_bound_bits_ (so
  /// k_low_ and k_high_ times a digit fit 64 bits); false where no bound fits.
  int digit_bound_bits_ = 0;
  bool multiplies_in_64_bits_ = false;
  // FFTW's arrays, null where our transform squares in its own.
  double* input_ = nullptr;              ///< FFTW-aligned, length_, zero past digits_
  double* output_ = nullptr;             ///< FFTW-aligned, length_
  void* spectrum_ = nullptr;             ///< FFTW-aligned, length_/2 + 1 complex
  const RealFftPlans* plans_ = nullptr;  ///< FFTW's, where right_angle_ is not used
  std::unique_ptr<RightAngleSquarer> right_angle_;
  bool wide_ = true;  ///< the passes may use AVX-512 (where the CPU has it)
  /// The digits are weighted by the transform's first pass (AVX-512), not
  /// by a pass of their own: write_input() leaves them pending.
  bool weigh_in_transform_ = false;
  SkewedVector<std::int64_t> coefficient_;  ///< the square's coefficients, rounded, then carried; L places
  std::uint64_t value_mod_p_ = 0;           ///< the input's value (t) mod 2^61-1
  std::uint64_t square_mod_p_ = 0;          ///< its square's, from the coefficients
  std::uint64_t modulus_mod_p_ = 0;         ///< N's
  std::uint64_t k_mod_p_ = 0, two_n_mod_p_ = 0, inverse_two_n_mod_p_ = 0;  ///< k's, 2^n's, 2^-n's
  double worst_roundoff_ = 0;
  std::uint64_t fallbacks_ = 0;
  // The threads of a split squaring; the product's digits (the split and
  // the fused squarings write them here, then swap them with digit_); each
  // thread's rounding; and whether digit_ is yet to be weighted.
  std::unique_ptr<ProofThreads> threads_;
  SkewedVector<std::int64_t> product_;
  std::vector<RoundedCoefficients> rounded_parts_;
  CarryExchange carry_exchange_;
  bool weights_pending_ = false;
  // Pacing (use_threads): where in the cycle of trials and stretches, and the split trial's time.
  bool split_active_ = true;
  bool paced_ = false;
  std::int64_t pace_left_ = 0;  ///< squarings left in this trial or stretch
  int pace_phase_ = 2;          ///< 0 split trial, 1 one-thread trial, 2 stretch
  std::int64_t stretch_ = 0;
  double pace_mark_ = 0, split_seconds_ = 0;
  void pace();
};

}  // namespace tk::primes
