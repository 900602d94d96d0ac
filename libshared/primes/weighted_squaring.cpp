/// @file weighted_squaring.cpp
/// @brief WeightedSquaring's squaring of t = x/k: transform, one pass that
/// rounds and checks, the carries, the multiplication by k that reduces
/// the square, and the pass that weighs the digits into the next input.
#include "primes/weighted_squaring.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "primes/fft_plans.hpp"
#include "primes/right_angle_transform.hpp"
#include "primes/weighted_passes.hpp"
#include "primes/weighted_rounding.hpp"
#include "primes/weighted_squaring_detail.hpp"

namespace tk::primes {

using namespace weighted_detail;

void WeightedSquaring::square_minus(unsigned long minus) {
  if (square_and_reduce(minus)) return;
  ++fallbacks_;
  square_by_gmp(minus);
}

// N = k*2^n + c. With P = t^2 = L + H*2^n (L = sum of the carried
// coefficients below digit m, H those from m up, shifted down by n bits),
// k*P = k*L - c*H + H*N, and since e_(j+m) = e_j + n, k*L - c*H is the
// digits k*d_j - c*d_(j+m) below 2^n plus a few from there up: Y*2^n with
// Y small. Y = a*k + b then folds as -c*a + b*2^n: the value held next is
// k*P - (H + a)*N + c*minus*2^n, which is below about (k + 1)*2^n in size.
bool WeightedSquaring::square_and_reduce(unsigned long minus) {
  if (threads_) {
    pace();
    if (split_active_) return square_and_reduce_split(minus);
  }
  if (weigh_in_transform_) return square_and_reduce_fused(minus);
  RoundedCoefficients rounded;
  std::int64_t* z = coefficient_.data();
  const std::size_t m = low_digits_;
  if (right_angle_) {
    weigh_pending();  // a split square left the digits unweighted
    right_angle_->square_in_place();
    const RightAngleWeights weights{round_a_.data(), round_b_.data(), round_c_.data(), round_d_.data()};
    rounded = round_right_angle(right_angle_->real(), right_angle_->imaginary(), weights, rotation_.data(), z,
                                length_ / 2, m, coefficients_, wide_);
  } else {
    square_by_real_fft(*plans_, input_, static_cast<fftw_complex*>(spectrum_), output_, length_);
    rounded = round_coefficients(output_, output_weight_.data(), rotation_.data(), z, coefficients_, m);
  }
  if (!rounding_checks_out(rounded)) return false;
  // Carried in two halves, each until its digits are small enough to
  // multiply by k's halves: the low half's carry into 2^n moves to H (it
  // comes back as -c times it at digit 0), nothing carries out of the top.
  const std::uint8_t* bits = bits_.data();
  const std::int64_t low_carry = balance_digits(z, bits, m, carry_enough(), wide_);
  if (balance_digits(z + m, bits + m, coefficients_ - m, carry_enough(), wide_) != 0) return false;
  const std::int64_t c = form_.c;
  const Upper upper = upper_part(z);  // before the low digits are overwritten
  const SplitK split{k_low_, k_high_, static_cast<unsigned>(max_digit_bits_)};
  multiply_low_by_k(z, bits, m, split, c < 0, wide_);
  z[0] -= c * low_carry;
  const std::int64_t carry = balance_digits(z, bits, m, kProductCarryEnough, wide_);
  const i128 y = static_cast<i128>(upper) + carry + c * static_cast<i128>(minus);
  std::int64_t a = 0, b = 0;
  if (!divide_by_k(y, form_.k, a, b)) return false;  // cannot happen for t held here; never fold a wrong value
  const std::int64_t left = absorb_at_bottom(z, bits, m, -c * a);
  write_input(b + left);
  update_residue(rounded, low_carry, a, minus);
  return true;
}

// The same steps where AVX-512 squares, fewer passes over memory: the
// transform's first pass weighs the digits, the rounding pass carries
// each range once, the multiplication by k carries its product once and
// writes it into product_, which becomes the digits.
bool WeightedSquaring::square_and_reduce_fused(unsigned long minus) {
  right_angle_->square_in_place_from(digit_.data(), re_weight_.data(), im_weight_.data());
  weights_pending_ = false;
  std::int64_t* z = coefficient_.data();
  const std::size_t m = low_digits_;
  const std::uint8_t* bits = bits_.data();
  const RightAngleWeights weights{round_a_.data(), round_b_.data(), round_c_.data(), round_d_.data()};
  const CarriedCoefficients carried =
      round_right_angle_carried(right_angle_->real(), right_angle_->imaginary(), weights, rotation_.data(), bits, z,
                                length_ / 2, m, coefficients_);
  if (!rounding_checks_out(carried.rounded)) return false;
  // balance_digits' passes from its second on, where the first left more
  std::int64_t low_carry = carried.low_carry, top_carry = carried.top_carry;
  if (carried.low_largest > carry_enough()) low_carry += balance_digits(z, bits, m, carry_enough(), wide_);
  if (carried.high_largest > carry_enough())
    top_carry += balance_digits(z + m, bits + m, coefficients_ - m, carry_enough(), wide_);
  if (top_carry != 0) return false;
  const SplitK split{k_low_, k_high_, static_cast<unsigned>(max_digit_bits_)};
  std::int64_t* next = product_.data();
  std::int64_t carry = 0;
  if (multiply_and_carry(z, next, bits, m, split, form_.c < 0, -form_.c * low_carry, carry) > kProductCarryEnough)
    carry += balance_digits(next, bits, m, kProductCarryEnough, wide_);
  return fold_product(carry, carried.rounded, low_carry, minus);
}

// The fused and the split squarings' end: product_ holds the carried low
// digits of k*L - c*H (coefficient_, unchanged, the square's), `carry`
// the carry out of them. Y folds; the top digits are written; product_
// becomes the digits held, to be weighted by the next square.
bool WeightedSquaring::fold_product(std::int64_t carry, const RoundedCoefficients& rounded, std::int64_t low_carry,
                                    unsigned long minus) {
  const std::int64_t c = form_.c;
  const std::size_t m = low_digits_;
  const i128 y = static_cast<i128>(upper_part(coefficient_.data())) + carry + c * static_cast<i128>(minus);
  std::int64_t a = 0, b = 0;
  if (!divide_by_k(y, form_.k, a, b)) return false;  // cannot happen for t held here; never fold a wrong value
  const std::int64_t left = absorb_at_bottom(product_.data(), bits_.data(), m, -c * a);
  write_top_digits(product_.data(), bits_.data(), m, digits_, b + left);
  digit_.swap(product_);
  weights_pending_ = true;
  update_residue(rounded, low_carry, a, minus);
  return true;
}

bool WeightedSquaring::rounding_checks_out(const RoundedCoefficients& rounded) {
  worst_roundoff_ = std::max(worst_roundoff_, rounded.worst);
  square_mod_p_ = reduce61(rounded.sum + rounded.sum_high);
  // Every coefficient rounded safely and they give t^2 mod p.
  return !rounded.out_of_range && rounded.worst <= kMaxRoundoff &&
         square_mod_p_ == multiply61(value_mod_p_, value_mod_p_) && multiplies_in_64_bits_;
}

// Y's digits from m up: -c*d_(j+m) and, at m, the high half of k times
// d_(m-1); Horner's rule in 128 bits (Y < 2^118 for k < 2^56), wrapping
// rather than overflowing on a freak.
WeightedSquaring::Upper WeightedSquaring::upper_part(const std::int64_t* z) const {
  const std::size_t m = low_digits_;
  const std::int64_t c = form_.c;
  u128 upper = 0;
  for (std::size_t j = coefficients_ - m; j-- > m;) {
    i128 digit = -c * static_cast<i128>(z[j + m]);
    if (j == m) digit += static_cast<i128>(k_high_ * z[m - 1]) * (i128{1} << (max_digit_bits_ - bits_[m - 1]));
    upper = upper * (u128{1} << bits_[j]) + static_cast<u128>(digit);
  }
  return upper;
}

// t' mod p, from the checked square's two sums: Y's low digits are
// k*(L - low_carry*2^n) - c*(H + low_carry) = k*L - c*H - low_carry*N.
void WeightedSquaring::update_residue(const RoundedCoefficients& rounded, std::int64_t low_carry, std::int64_t a,
                                      unsigned long minus) {
  const std::int64_t c = form_.c;
  auto signed61 = [](std::int64_t v) {
    const std::uint64_t r = reduce61(v < 0 ? 0 - static_cast<std::uint64_t>(v) : static_cast<std::uint64_t>(v));
    return v < 0 && r != 0 ? kP61 - r : r;
  };
  const std::uint64_t high = multiply61(rounded.sum_high, inverse_two_n_mod_p_);
  const std::uint64_t kp = multiply61(k_mod_p_, rounded.sum);
  const std::uint64_t ch = c < 0 ? high : kP61 - high;  // -c*H
  const std::uint64_t multiple = reduce61(signed61(low_carry) + signed61(a));
  const std::uint64_t plus = multiply61(signed61(c * static_cast<std::int64_t>(minus)), two_n_mod_p_);
  value_mod_p_ = reduce61(kp + ch + plus + kP61 - multiply61(multiple, modulus_mod_p_));
}

void WeightedSquaring::write_input(std::int64_t top) {
  if (weigh_in_transform_) {  // the digits alone: the next square's first pass weighs them
    std::copy(coefficient_.begin(), coefficient_.begin() + static_cast<std::ptrdiff_t>(low_digits_), digit_.begin());
    write_top_digits(digit_.data(), bits_.data(), low_digits_, digits_, top);
    weights_pending_ = true;
    return;
  }
  weights_pending_ = false;  // every digit weighted here
  FoldTarget target{digit_.data(), input_, input_weight_.data(), nullptr, nullptr, wide_};
  if (right_angle_) {
    target = {digit_.data(), right_angle_->real(), re_weight_.data(), right_angle_->imaginary(), im_weight_.data(),
              wide_};
    // The transform works in place: the square's values past the digits go.
    std::fill(target.re + digits_, target.re + length_ / 2, 0.0);
    std::fill(target.im + digits_, target.im + length_ / 2, 0.0);
  }
  tk::primes::write_input(coefficient_.data(), target, bits_.data(), low_digits_, digits_, top);
}

// k*2^n = -c (mod N), so 1/k = -c*2^n.
mpz_class WeightedSquaring::held_form(const mpz_class& x) const {
  const mpz_class N = modulus_of(form_);
  mpz_class inverse_k = 1;
  inverse_k <<= static_cast<mp_bitcnt_t>(form_.n);
  if (form_.c > 0) inverse_k = N - inverse_k;
  mpz_class t = x * inverse_k;
  mpz_mod(t.get_mpz_t(), t.get_mpz_t(), N.get_mpz_t());
  return t;
}

void WeightedSquaring::load(const mpz_class& x) {
  const mpz_class t = held_form(x);
  std::vector<mp_limb_t> limbs(form_.n / 64 + 4, 0);
  mpz_export(limbs.data(), nullptr, -1, sizeof(mp_limb_t), 0, 0, t.get_mpz_t());
  for (std::size_t j = 0; j < low_digits_; ++j)
    coefficient_[j] = static_cast<std::int64_t>(bits_at(limbs.data(), exponent_[j], bits_[j]));
  const std::int64_t carry = balance_digits(coefficient_.data(), bits_.data(), low_digits_, 1, wide_);
  const mpz_class top = t >> static_cast<mp_bitcnt_t>(form_.n);  // below k
  write_input(static_cast<std::int64_t>(top.get_ui()) + carry);
  value_mod_p_ = mpz_fdiv_ui(t.get_mpz_t(), kP61);
}

// The digits are balanced (some negative): carried into non-negative
// digits first, so the value packs into limbs; the last carry (negative
// for a negative value) is added at the top. x = k*t.
void WeightedSquaring::store(mpz_class& x) const {
  std::vector<mp_limb_t> limbs(exponent_[digits_] / 64 + 3, 0);
  std::int64_t carry = 0;
  for (std::size_t j = 0; j < digits_; ++j) {
    const std::int64_t digit = digit_[j] + carry;
    const std::int64_t low = digit & ((std::int64_t{1} << bits_[j]) - 1);
    carry = digit >> bits_[j];
    const std::size_t at = exponent_[j] / 64;
    const unsigned shift = exponent_[j] % 64;
    limbs[at] |= static_cast<mp_limb_t>(low) << shift;
    if (shift != 0) limbs[at + 1] |= static_cast<mp_limb_t>(low) >> (64 - shift);
  }
  mpz_import(x.get_mpz_t(), limbs.size(), -1, sizeof(mp_limb_t), 0, 0, limbs.data());
  if (carry != 0) {
    mpz_class top = carry;
    top <<= static_cast<mp_bitcnt_t>(exponent_[digits_]);
    x += top;
  }
  x *= form_.k;
  const mpz_class N = modulus_of(form_);
  mpz_mod(x.get_mpz_t(), x.get_mpz_t(), N.get_mpz_t());
}

bool WeightedSquaring::holds_carried_residue() const {
  std::uint64_t sum = 0;
  for (std::size_t j = 0; j < digits_; ++j)
    sum = fold61(sum + times_power61(residue61(digit_[j]), static_cast<unsigned>(rotation_[j])));
  return reduce61(sum) == value_mod_p_;
}

void WeightedSquaring::square_by_gmp(unsigned long minus) {
  mpz_class x;
  store(x);
  x = x * x - minus;
  load(x);
}

}  // namespace tk::primes
