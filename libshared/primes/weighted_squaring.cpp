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

  // Unweight and round each coefficient, sum it times 2^(e_j) mod p, and
  // carry: a coefficient is below 2^51 and the carry below 2^(52-s), so
  // their sum fits 64 bits and its low s_j bits are the digit (>= 0).
  double worst = 0;
  std::uint64_t sum = 0;
  std::int64_t carry = 0;
  bool out_of_range = false;  // only with digits too wide (create_with): never convert those
  auto coefficient = [&](std::size_t j) {
    const double value = output_[j] * output_weight_[j];
    const double rounded = round_to_integer(value);
    worst = std::max(worst, std::fabs(value - rounded));
    const bool representable = std::fabs(value) < 0x1p51;  // false for NaN too
    out_of_range |= !representable;
    const std::int64_t z = representable ? static_cast<std::int64_t>(rounded) : 0;
    sum = fold61(sum + times_power61(residue61(z), rotation_[j]));
    const std::int64_t total = z + carry;
    carry = total >> bits_[j];  // arithmetic shift: floor division by 2^s
    return static_cast<std::uint64_t>(total) & ((std::uint64_t{1} << bits_[j]) - 1);
  };
  for (std::size_t j = 0; j < low_digits_; ++j) low_[j] = static_cast<std::int64_t>(coefficient(j));
  // From 2^n up, the digits go straight into limbs for the division.
  u128 pending = 0;
  unsigned filled = 0;
  std::size_t limb = 0;
  for (std::size_t j = low_digits_; j < coefficients_; ++j) {
    pending |= static_cast<u128>(coefficient(j)) << filled;
    filled += bits_[j];
    high_[limb] = static_cast<std::uint64_t>(pending);
    const bool full = filled >= 64;
    limb += full;
    pending = full ? pending >> 64 : pending;
    filled -= full ? 64 : 0;
  }
  high_[limb] = static_cast<std::uint64_t>(pending);
  std::fill(high_.begin() + static_cast<std::ptrdiff_t>(limb) + 1, high_.end(), 0);
  clock.lap(times_.carry);
  worst_roundoff_ = std::max(worst_roundoff_, worst);
  // The square fits below the last coefficient, so nothing carries out of
  // the top; and the coefficients must give x^2 mod p.
  return !out_of_range && worst <= kMaxRoundoff && carry == 0 &&
         reduce61(sum) == multiply61(value_mod_p_, value_mod_p_);
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
  fold_into_input(top, static_cast<std::int64_t>(a) - static_cast<std::int64_t>(minus));
  clock.lap(times_.fold);
}

void WeightedSquaring::fold_into_input(std::int64_t top, std::int64_t bottom) {
  // c = -1 adds the quotient, c = +1 subtracts it.
  const std::int64_t sign = -form_.c;
  std::int64_t carry = bottom;
  std::uint64_t sum = 0;
  auto put = [&](std::size_t j, std::int64_t total) {
    const unsigned s = bits_[j];
    const std::int64_t up = (total + (std::int64_t{1} << (s - 1))) >> s;  // balanced: digit in [-2^(s-1), 2^(s-1))
    const std::int64_t digit = total - (up << s);
    carry = up;
    input_[j] = static_cast<double>(digit) * input_weight_[j];
    sum = fold61(sum + times_power61(residue61(digit), rotation_[j]));
  };
  const mp_limb_t* q = quotient_.data();
  for (std::size_t j = 0; j < low_digits_; ++j)
    put(j, low_[j] + sign * static_cast<std::int64_t>(bits_at(q, exponent_[j], bits_[j])) + carry);
  carry += top;
  for (std::size_t j = low_digits_; j + 1 < digits_; ++j) put(j, carry);
  const std::size_t last = digits_ - 1;  // takes what is left, unbalanced
  input_[last] = static_cast<double>(carry) * input_weight_[last];
  sum = fold61(sum + times_power61(residue61(carry), rotation_[last]));
  value_mod_p_ = reduce61(sum);
}

}  // namespace tk::primes
