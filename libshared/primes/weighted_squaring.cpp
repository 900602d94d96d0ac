/// @file weighted_squaring.cpp
/// @brief WeightedSquaring's squaring: transform, one pass that rounds,
/// checks and carries, the division by k, one pass that folds and
/// balances the digits into the next transform's input.
#include "primes/weighted_squaring.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>

#include "primes/fft_plans.hpp"
#include "primes/right_angle_transform.hpp"
#include "primes/weighted_passes.hpp"
#include "primes/weighted_rounding.hpp"
#include "primes/weighted_squaring_detail.hpp"

namespace tk::primes {

namespace {

using namespace weighted_detail;

}  // namespace

void WeightedSquaring::square_minus(unsigned long minus) {
  if (!square_and_carry()) {
    ++fallbacks_;
    square_by_gmp(minus);
    return;
  }
  divide_and_fold(minus);
}

bool WeightedSquaring::square_and_carry() {
  RoundedCoefficients rounded;
  if (right_angle_) {
    right_angle_->square_in_place();
    const RightAngleWeights weights{round_a_.data(), round_b_.data(), round_c_.data(), round_d_.data()};
    rounded = round_right_angle(right_angle_->real(), right_angle_->imaginary(), weights, rotation_.data(),
                                coefficient_.data(), length_ / 2, wide_);
  } else {
    square_by_real_fft(*plans_, input_, static_cast<fftw_complex*>(spectrum_), output_, length_);
    rounded = round_coefficients(output_, output_weight_.data(), rotation_.data(), coefficient_.data(), coefficients_);
  }
  // Carry. Below 2^n the digits need not be normal: the fold's balanced
  // carrying takes the coefficients as they are. Only their carry into
  // 2^n (c_m = floor(L / 2^n)) is needed, for H + c_m, and an estimate
  // from the top ones serves (weighted_passes.cpp); the carries from 2^n
  // up turn those coefficients into normal digits packed into limbs for
  // the division.
  const HighCarry carried =
      carry_into_limbs(coefficient_.data(), bits_.data(), low_digits_, coefficients_, high_.data());
  std::fill(high_.begin() + static_cast<std::ptrdiff_t>(carried.last_limb) + 1, high_.end(), 0);
  const std::int64_t low_carry = carried.low_carry, carry = carried.top_carry;
  std::uint64_t* high = high_.data();
  // H = packed + c_m. Only a tiny square (x below 2^(n/2)) can have
  // packed < -c_m, leaving a carry of -1 at the top: GMP squares those.
  low_carry_ = low_carry;
  const auto limbs = static_cast<mp_size_t>(high_limbs_);
  const mp_limb_t overflow = low_carry >= 0 ? mpn_add_1(high, high, limbs, static_cast<mp_limb_t>(low_carry))
                                            : mpn_sub_1(high, high, limbs, static_cast<mp_limb_t>(-low_carry));
  const double worst = rounded.worst;
  const bool out_of_range = rounded.out_of_range;
  square_mod_p_ = rounded.sum;
  worst_roundoff_ = std::max(worst_roundoff_, worst);
  // The square fits below the last coefficient, so nothing carries out of
  // the top; and the coefficients must give x^2 mod p.
  return !out_of_range && worst <= kMaxRoundoff && carry == 0 && overflow == 0 && high_[high_limbs_ - 1] == 0 &&
         square_mod_p_ == multiply61(value_mod_p_, value_mod_p_);
}

// N = k*2^n + c, so k*2^n = -c (mod N). The square P = H*2^n + L with
// H = q*k + r is -c*q + r*2^n + L; q itself reaches past 2^n by under
// 2^(kbits+5): q = q_lo + q_hi*2^n with q_hi = a*k + b folds once more to
// -c*q_lo + a + (r - c*b)*2^n, below about 2*N in size whatever x was.
void WeightedSquaring::divide_and_fold(unsigned long minus) {
  const std::uint64_t k = form_.k, n = form_.n;
  // r = H mod k first (GMP's mpn_mod_1, about 1.5 cycles a limb here),
  // then (H - r)/k by Hensel's exact division, a short multiply chain:
  // together well under half the time of mpn_divrem_1's dependent divisions.
  const auto limbs = static_cast<mp_size_t>(high_limbs_);
  const std::uint64_t r = mpn_mod_1(high_.data(), limbs, k);
  mpn_sub_1(high_.data(), high_.data(), limbs, r);
  mpn_divexact_1(quotient_.data(), high_.data(), limbs, k);
  const std::size_t at = n / 64;
  const unsigned shift = n % 64;
  const std::uint64_t q_high = (quotient_[at] >> shift) | ((quotient_[at + 1] << 1) << (63 - shift));
  bool beyond = (quotient_[at + 1] >> shift) != 0 && shift != 0;
  if (shift == 0) beyond = quotient_[at + 1] != 0;
  for (std::size_t i = at + 2; i < high_limbs_; ++i) beyond |= quotient_[i] != 0;
  if (beyond || q_high >= (std::uint64_t{1} << 62)) {  // cannot happen for x held here; never fold a wrong value
    ++fallbacks_;
    std::fill(quotient_.begin(), quotient_.end(), 0);
    square_by_gmp(minus);
    return;
  }
  const std::uint64_t a = q_high / k, b = q_high % k;
  const std::int64_t top =
      form_.c < 0 ? static_cast<std::int64_t>(r + b) : static_cast<std::int64_t>(r) - static_cast<std::int64_t>(b);
  fold_into_input(top - low_carry_, static_cast<std::int64_t>(a) - static_cast<std::int64_t>(minus));
  // The folded value is P - (q - c*a)*N - minus: its residue mod p, for the
  // next square's check, follows from the square's (checked) and q's. A
  // fold that went wrong then fails that check (a fallback is counted; the
  // wrong value is what GMP squares), and the proof's Gerbicz or Jacobi
  // check sends the proof back to its last verified value.
  const std::uint64_t q_mod_p = mpn_mod_1(quotient_.data(), static_cast<mp_size_t>(high_limbs_), kP61);
  const std::uint64_t multiple = form_.c < 0 ? reduce61(q_mod_p + a) : reduce61(q_mod_p + kP61 - a % kP61);
  value_mod_p_ = reduce61(square_mod_p_ + 2 * kP61 - multiply61(multiple, modulus_mod_p_) - minus);
}

void WeightedSquaring::fold_into_input(std::int64_t top, std::int64_t bottom) {
  FoldTarget target{digit_.data(), input_, input_weight_.data(), nullptr, nullptr, wide_};
  if (right_angle_) {
    target = {digit_.data(), right_angle_->real(), re_weight_.data(), right_angle_->imaginary(), im_weight_.data(),
              wide_};
    // The transform works in place: the square's values past the digits go.
    std::fill(target.re + digits_, target.re + length_ / 2, 0.0);
    std::fill(target.im + digits_, target.im + length_ / 2, 0.0);
  }
  // c = -1 adds the quotient, c = +1 subtracts it.
  fold_digits(coefficient_.data(), quotient_.data(), bits_.data(), exponent_.data(), target, low_digits_, digits_,
              bottom, top, form_.c < 0);
}

}  // namespace tk::primes
