/// @file weighted_squaring.cpp
/// @brief WeightedSquaring's squaring: transform, one pass that rounds,
/// checks and carries, the division by k, one pass that folds and
/// balances the digits into the next transform's input.
#include "primes/weighted_squaring.hpp"

#include <fftw3.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "primes/fft_plans.hpp"
#include "primes/weighted_rounding.hpp"
#include "primes/weighted_squaring_detail.hpp"

namespace tk::primes {

namespace {

using namespace weighted_detail;

// A square whose worst rounding error passes this is redone by GMP.
constexpr double kMaxRoundoff = 0.4;

// Rounds to the nearest integer for |v| < 2^51 without a library call.
inline double round_to_integer(double v) {
  constexpr double shifter = 6755399441055744.0;  // 1.5 * 2^52
  return (v + shifter) - shifter;
}

class StepClock {
 public:
  explicit StepClock(bool on) : on_(on) {
    if (on_) last_ = std::chrono::steady_clock::now();
  }
  void lap(double& into) {
    if (!on_) return;
    const auto now = std::chrono::steady_clock::now();
    into += std::chrono::duration<double>(now - last_).count();
    last_ = now;
  }

 private:
  bool on_;
  std::chrono::steady_clock::time_point last_;
};

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
  StepClock clock(timing_);
  auto* spectrum = static_cast<fftw_complex*>(spectrum_);
  fftw_execute_dft_r2c(plans_->forward, input_, spectrum);
  clock.lap(times_.forward);
  for (std::size_t j = 0; j <= length_ / 2; ++j) {
    const double re = spectrum[j][0], im = spectrum[j][1];
    spectrum[j][0] = re * re - im * im;
    spectrum[j][1] = 2.0 * re * im;
  }
  clock.lap(times_.pointwise);
  fftw_execute_dft_c2r(plans_->inverse, spectrum, output_);
  clock.lap(times_.inverse);

  const RoundedCoefficients rounded =
      round_coefficients(output_, output_weight_.data(), rotation_.data(), coefficient_.data(), coefficients_);
  // Carry. Below 2^n the digits need not be normal: the fold's balanced
  // carrying takes the coefficients as they are. Only their carry into
  // 2^n (c_m = floor(L / 2^n)) is needed, for H + c_m: a two-instruction
  // chain, run alongside the carries from 2^n up, which turn those
  // coefficients into normal digits and pack them into limbs for the
  // division (`pending` holds the `filled` < 64 bits not yet in a limb).
  // A coefficient is below 2^51 and the carry below 2^(52-s), so their
  // sum fits 64 bits. Everything in locals: stores through high_ could
  // otherwise alias the members, and the compiler would reload them.
  const std::int64_t* __restrict z = coefficient_.data();
  const std::uint8_t* __restrict bits = bits_.data();
  std::uint64_t* __restrict high = high_.data();
  const std::size_t low_digits = low_digits_, coefficients = coefficients_;
  std::int64_t low_carry = 0, carry = 0;
  std::uint64_t pending = 0;
  unsigned filled = 0;
  std::size_t limb = 0;
  auto high_digit = [&](std::size_t j) {
    const unsigned s = bits[j];
    const std::int64_t total = z[j] + carry;
    carry = total >> s;  // arithmetic shift: floor division by 2^s
    const std::uint64_t digit = static_cast<std::uint64_t>(total) & ((std::uint64_t{1} << s) - 1);
    const std::uint64_t joined = pending | (digit << filled);
    high[limb] = joined;
    const bool full = filled + s >= 64;  // no branch: a limb fills at an irregular digit
    pending = full ? (digit >> 1) >> (63 - filled) : joined;
    limb += full;
    filled = filled + s - (full ? 64 : 0);
  };
  for (std::size_t j = 0; j < low_digits; ++j) {  // the high part has more coefficients than the low
    low_carry = (z[j] + low_carry) >> bits[j];
    high_digit(low_digits + j);
  }
  for (std::size_t j = 2 * low_digits; j < coefficients; ++j) high_digit(j);
  high[limb] = pending;
  std::fill(high_.begin() + static_cast<std::ptrdiff_t>(limb) + 1, high_.end(), 0);
  // H = packed + c_m. Only a tiny square (x below 2^(n/2)) can have
  // packed < -c_m, leaving a carry of -1 at the top: GMP squares those.
  low_carry_ = low_carry;
  const auto limbs = static_cast<mp_size_t>(high_limbs_);
  const mp_limb_t overflow = low_carry >= 0 ? mpn_add_1(high, high, limbs, static_cast<mp_limb_t>(low_carry))
                                            : mpn_sub_1(high, high, limbs, static_cast<mp_limb_t>(-low_carry));
  const double worst = rounded.worst;
  const bool out_of_range = rounded.out_of_range;
  square_mod_p_ = rounded.sum;
  clock.lap(times_.carry);
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
  StepClock clock(timing_);
  const std::uint64_t k = form_.k, n = form_.n;
  const std::uint64_t r = mpn_divrem_1(quotient_.data(), 0, high_.data(), static_cast<mp_size_t>(high_limbs_), k);
  clock.lap(times_.divide);
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
  const std::int64_t top = form_.c < 0 ? static_cast<std::int64_t>(r + b) : static_cast<std::int64_t>(r) - static_cast<std::int64_t>(b);
  fold_into_input(top - low_carry_, static_cast<std::int64_t>(a) - static_cast<std::int64_t>(minus));
  // The folded value is P - (q - c*a)*N - minus: its residue mod p, for the
  // next square's check, follows from the square's (checked) and q's. A
  // fold that went wrong then fails that check and is redone by GMP.
  const std::uint64_t q_mod_p = mpn_mod_1(quotient_.data(), static_cast<mp_size_t>(high_limbs_), kP61);
  const std::uint64_t multiple = form_.c < 0 ? reduce61(q_mod_p + a) : reduce61(q_mod_p + kP61 - a % kP61);
  value_mod_p_ = reduce61(square_mod_p_ + 2 * kP61 - multiply61(multiple, modulus_mod_p_) - minus);
  clock.lap(times_.fold);
}

void WeightedSquaring::fold_into_input(std::int64_t top, std::int64_t bottom) {
  // c = -1 adds the quotient, c = +1 subtracts it. Locals, as above.
  const std::int64_t sign = -form_.c;
  const std::uint8_t* __restrict bits = bits_.data();
  const double* __restrict weight = input_weight_.data();
  const std::int64_t* __restrict low = coefficient_.data();
  const mp_limb_t* __restrict q = quotient_.data();
  double* __restrict input = input_;
  const std::size_t low_digits = low_digits_, digits = digits_;
  std::int64_t carry = bottom;
  auto put = [&](std::size_t j, std::int64_t total) {
    const unsigned s = bits[j];
    const std::int64_t up = (total + (std::int64_t{1} << (s - 1))) >> s;  // balanced: digit in [-2^(s-1), 2^(s-1))
    const std::int64_t digit = total - (up << s);
    carry = up;
    input[j] = static_cast<double>(digit) * weight[j];
  };
  std::uint64_t position = 0;  // e_j, kept by adding (one memory stream fewer than reading exponent_)
  for (std::size_t j = 0; j < low_digits; ++j) {
    put(j, low[j] + sign * static_cast<std::int64_t>(bits_at(q, position, bits[j])) + carry);
    position += bits[j];
  }
  carry += top;
  for (std::size_t j = low_digits; j + 1 < digits; ++j) put(j, carry);
  const std::size_t last = digits - 1;  // takes what is left, unbalanced
  input[last] = static_cast<double>(carry) * weight[last];
}

}  // namespace tk::primes
