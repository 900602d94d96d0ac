/// @file fft_squaring.cpp
#include "primes/fft_squaring.hpp"

#include "primes/fft_plans.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace tk::primes {

namespace {

__extension__ typedef unsigned __int128 u128;

// Largest digit size whose squares round safely at this length. Digits
// are balanced (|d| <= 2^(b-1)), so a coefficient of the square sums about
// L/2 products of random sign. Measured here on random digits: the worst
// rounding error grows 4x per digit bit and 2x per 4x length, and is about
// 0.02 at L = 2^14, b = 20 (0.08 at b = 21). The limit keeps it near 0.03
// (checked at run time all the same) and every coefficient below 2^51, so
// the rounding trick and the 64-bit carries are exact.
int max_digit_bits(std::size_t length) {
  const double log_length = std::log2(static_cast<double>(length));
  const int exact = static_cast<int>((51.0 - (log_length - 1.0)) / 2.0) + 1;
  const int safe = static_cast<int>(std::floor(27.0 - 0.5 * log_length));
  return std::min(exact, safe);
}

std::size_t digits_for(std::size_t bits, int digit_bits) {
  return (bits + static_cast<std::size_t>(digit_bits) - 1) / static_cast<std::size_t>(digit_bits) + 1;
}

// Rounds to the nearest integer for |v| < 2^51 without a library call.
inline double round_to_integer(double v) {
  constexpr double shifter = 6755399441055744.0;  // 1.5 * 2^52
  return (v + shifter) - shifter;
}

std::size_t bits_of(const SpecialForm& form) {
  mpz_class N = form.k;
  N <<= static_cast<mp_bitcnt_t>(form.n);
  N += form.c;
  return mpz_sizeinbase(N.get_mpz_t(), 2);
}

bool fits_fft_squaring(const SpecialForm& form) {
  return form.n >= 64 && (form.c == 1 || form.c == -1) && form.k % 2 == 1;
}

}  // namespace

std::unique_ptr<FftSquaring> FftSquaring::create(const SpecialForm& form) {
  if (!fits_fft_squaring(form)) return nullptr;
  const std::size_t bits = bits_of(form);
  for (std::size_t length : fast_fft_lengths())
    for (int b = 8; b <= max_digit_bits(length); ++b)
      if (2 * digits_for(bits, b) - 1 <= length) return std::unique_ptr<FftSquaring>(new FftSquaring(form, length, b));
  return nullptr;
}

std::unique_ptr<FftSquaring> FftSquaring::create_with(const SpecialForm& form, std::size_t length, int digit_bits) {
  if (!fits_fft_squaring(form) || digit_bits < 8 || digit_bits > 30 || length % 2 != 0) return nullptr;
  if (2 * digits_for(bits_of(form), digit_bits) - 1 > length) return nullptr;
  return std::unique_ptr<FftSquaring>(new FftSquaring(form, length, digit_bits));
}

FftSquaring::FftSquaring(const SpecialForm& form, std::size_t length, int digit_bits)
    : form_(form), length_(length), digit_bits_(digit_bits) {
  mpz_class N = form.k;
  N <<= static_cast<mp_bitcnt_t>(form.n);
  N += form.c;
  digits_ = digits_for(bits_of(form), digit_bits);
  limbs_ = mpz_size(N.get_mpz_t());
  modulus_.assign(limbs_ + 1, 0);
  mpz_export(modulus_.data(), nullptr, -1, sizeof(mp_limb_t), 0, 0, N.get_mpz_t());
  x_.assign(limbs_ + 1, 0);
  // The carries run over every coefficient of the square, a little past
  // 2*limbs_ limbs; the value itself fits 2*limbs_.
  const std::size_t carried_bits = (2 * digits_ - 1) * static_cast<std::size_t>(digit_bits) + 128;
  product_.assign(std::max(2 * limbs_ + 1, carried_bits / 64 + 1), 0);
  high_.assign(product_.size(), 0);
  quotient_.assign(product_.size(), 0);
  digit_buffer_.assign(2 * digits_ + 64, 0);  // zeros past the top for the packing
  real_ = fftw_alloc_real(length_);
  spectrum_ = fftw_alloc_complex(length_ / 2 + 1);
  plans_ = real_fft_plans(length_);
}

FftSquaring::~FftSquaring() {
  fftw_free(real_);
  fftw_free(spectrum_);
}

void FftSquaring::load(const mpz_class& x) {
  std::fill(x_.begin(), x_.end(), 0);
  mpz_export(x_.data(), nullptr, -1, sizeof(mp_limb_t), 0, 0, x.get_mpz_t());
}

void FftSquaring::store(mpz_class& x) const {
  mpz_import(x.get_mpz_t(), limbs_, -1, sizeof(mp_limb_t), 0, 0, x_.data());
}

void FftSquaring::split_into_digits() {
  const unsigned b = static_cast<unsigned>(digit_bits_);
  const std::uint64_t mask = (std::uint64_t{1} << b) - 1, half = std::uint64_t{1} << (b - 1);
  const auto radix = static_cast<std::int64_t>(mask + 1);
  std::uint64_t carry = 0;
  std::int64_t even_sum = 0, odd_sum = 0;  // digits at even and odd positions
  std::size_t offset = 0;
  auto take = [&](std::size_t i, std::int64_t& sum) {
    const std::size_t limb = offset / 64;
    const unsigned shift = offset % 64;
    std::uint64_t bits = x_[limb] >> shift;
    if (shift + b > 64) bits |= x_[limb + 1] << (64 - shift);
    offset += b;
    // Balanced: a digit of 2^(b-1) or more becomes digit - 2^b, carrying 1.
    // Branch-free, as the comparison is a coin toss.
    const std::uint64_t digit = (bits & mask) + carry;
    carry = digit >= half;
    const std::int64_t value = static_cast<std::int64_t>(digit) - static_cast<std::int64_t>(carry) * radix;
    real_[i] = static_cast<double>(value);
    sum += value;
  };
  const std::size_t below_top = digits_ - 1;
  std::size_t i = 0;
  for (; i + 2 <= below_top; i += 2) {
    take(i, even_sum);
    take(i + 1, odd_sum);
  }
  if (i < below_top) take(i++, even_sum);
  const auto top = static_cast<std::int64_t>(carry);
  real_[i] = static_cast<double>(top);
  ((i & 1) ? odd_sum : even_sum) += top;
  const std::int64_t at_one = even_sum + odd_sum, at_minus_one = even_sum - odd_sum;
  std::fill(real_ + digits_, real_ + length_, 0.0);
  // X(1)^2 and X(-1)^2, modulo 2^64, are what the square's coefficients
  // must sum to (plainly and alternately).
  square_at_one_ = static_cast<std::uint64_t>(at_one) * static_cast<std::uint64_t>(at_one);
  square_at_minus_one_ = static_cast<std::uint64_t>(at_minus_one) * static_cast<std::uint64_t>(at_minus_one);
}

bool FftSquaring::square_by_fft() {
  square_by_real_fft(*plans_, real_, static_cast<fftw_complex*>(spectrum_), real_, length_);

  // Round each coefficient and carry: a coefficient is below 2^51 and the
  // running carry below 2^(52-b), so their sum fits 64 bits and its low b
  // bits are the digit. Two coefficients a round keep the rounding checks
  // off the carry's dependency chain.
  const double scale = 1.0 / static_cast<double>(length_);
  const std::size_t coefficients = 2 * digits_ - 1;
  const unsigned b = static_cast<unsigned>(digit_bits_);
  const std::int64_t mask = (std::int64_t{1} << b) - 1;
  std::uint64_t* digit = digit_buffer_.data();
  double worst_even = 0, worst_odd = 0;
  std::uint64_t even_sum = 0, odd_sum = 0;  // wrapping: only compared modulo 2^64
  std::int64_t carry = 0;
  bool out_of_range = false;  // only with digits too wide (create_with): never convert those
  auto take = [&](std::size_t i, double& worst, std::uint64_t& sum) {
    const double value = real_[i] * scale;
    const double rounded = round_to_integer(value);
    worst = std::max(worst, std::fabs(value - rounded));
    const bool representable = std::fabs(value) < 0x1p51;  // false for NaN too
    out_of_range |= !representable;
    const std::int64_t coefficient = representable ? static_cast<std::int64_t>(rounded) : 0;
    sum += static_cast<std::uint64_t>(coefficient);
    const std::int64_t total = coefficient + carry;
    digit[i] = static_cast<std::uint64_t>(total & mask);
    carry = total >> b;  // arithmetic shift: floor division by 2^b
  };
  std::size_t i = 0;
  for (; i + 2 <= coefficients; i += 2) {
    take(i, worst_even, even_sum);
    take(i + 1, worst_odd, odd_sum);
  }
  if (i < coefficients) take(i, worst_even, even_sum);
  const double worst = std::max(worst_even, worst_odd);
  worst_roundoff_ = std::max(worst_roundoff_, worst);
  // x^2 < 2^(2*bits) <= 2^(b*(coefficients-1)), so nothing carries out of
  // the top; and the coefficients must sum to X(1)^2 and X(-1)^2.
  if (out_of_range || worst > kMaxRoundoff || carry != 0 || even_sum + odd_sum != square_at_one_ ||
      even_sum - odd_sum != square_at_minus_one_)
    return false;

  // Pack the digits into limbs. Each limb gathers the same number of
  // digits without branches (zeros lie past the last one), so the loop
  // carries nothing from one limb to the next and mispredicts nothing.
  const std::size_t total_bits = coefficients * b;
  const std::size_t index_step = 64 / b;
  const unsigned skip_step = 64 % b, reach = 64 / b + 2;
  std::size_t out = 0, index = 0;
  unsigned skip = 0;  // low bits of digit[index] that went to the previous limb
  for (std::size_t bit = 0; bit < total_bits; bit += 64, ++out) {
    std::uint64_t limb = digit[index] >> skip;
    unsigned filled = b - skip;
    for (unsigned t = 1; t < reach; ++t, filled += b)
      limb |= (digit[index + t] << (filled & 63)) & (std::uint64_t{0} - std::uint64_t{filled < 64});
    product_[out] = limb;
    index += index_step;
    skip += skip_step;
    if (skip >= b) {
      skip -= b;
      ++index;
    }
  }
  std::fill(product_.begin() + static_cast<std::ptrdiff_t>(out), product_.end(), 0);
  return true;
}

void FftSquaring::square_minus(unsigned long minus) {
  split_into_digits();
  if (!square_by_fft()) {
    ++fallbacks_;
    std::fill(product_.begin(), product_.end(), 0);
    mpn_sqr(product_.data(), x_.data(), static_cast<mp_size_t>(limbs_));
  }
  reduce_product(minus);
}

// N = k*2^n + c with c = -1 or +1, so k*2^n = -c (mod N). Split the square
// P = H*2^n + L and H = q*k + r: P = -c*q + r*2^n + L (mod N), where
// r*2^n + L < k*2^n and q < N + 2, so a subtraction or two of N, or one
// addition, finish the reduction.
void FftSquaring::reduce_product(unsigned long minus) {
  const std::size_t width = limbs_ + 1;  // x_, modulus_ and the sums below
  const auto p_size = static_cast<mp_size_t>(2 * limbs_ + 1);
  if (minus != 0) {
    if (mpn_zero_p(product_.data() + 1, p_size - 1) && product_[0] < minus) {
      // x^2 - minus < 0 only when x^2 < minus: the result is N - (minus - x^2).
      const mp_limb_t deficit = minus - product_[0];
      mpn_sub_1(x_.data(), modulus_.data(), static_cast<mp_size_t>(width), deficit);
      return;
    }
    mpn_sub_1(product_.data(), product_.data(), p_size, minus);
  }
  const std::size_t n_limb = form_.n / 64;
  const unsigned n_bit = form_.n % 64;
  const auto high_size = static_cast<mp_size_t>(static_cast<std::size_t>(p_size) - n_limb);
  if (n_bit == 0) std::copy_n(product_.data() + n_limb, high_size, high_.data());
  else mpn_rshift(high_.data(), product_.data() + n_limb, high_size, n_bit);
  const mp_limb_t remainder = mpn_divrem_1(quotient_.data(), 0, high_.data(), high_size, form_.k);

  // x = L + r*2^n, below k*2^n.
  std::fill(x_.begin(), x_.end(), 0);
  std::copy_n(product_.data(), n_limb, x_.data());
  if (n_bit != 0) {
    x_[n_limb] = (product_[n_limb] & ((mp_limb_t{1} << n_bit) - 1)) | (remainder << n_bit);
    x_[n_limb + 1] = remainder >> (64 - n_bit);
  } else {
    x_[n_limb] = remainder;
  }
  // The quotient is below N + 2, so it fits `width` limbs.
  const mp_limb_t* q = quotient_.data();
  const auto w = static_cast<mp_size_t>(width);
  if (form_.c == -1) {
    mpn_add_n(x_.data(), x_.data(), q, w);
    while (mpn_cmp(x_.data(), modulus_.data(), w) >= 0) mpn_sub_n(x_.data(), x_.data(), modulus_.data(), w);
  } else if (mpn_cmp(x_.data(), q, w) >= 0) {
    mpn_sub_n(x_.data(), x_.data(), q, w);
  } else {
    // x - q < 0: add N until the difference is non-negative.
    std::vector<mp_limb_t>& deficit = high_;
    mpn_sub_n(deficit.data(), q, x_.data(), w);
    while (mpn_cmp(deficit.data(), modulus_.data(), w) >= 0)
      mpn_sub_n(deficit.data(), deficit.data(), modulus_.data(), w);
    if (mpn_zero_p(deficit.data(), w)) std::fill(x_.begin(), x_.end(), 0);
    else mpn_sub_n(x_.data(), modulus_.data(), deficit.data(), w);
  }
}

}  // namespace tk::primes
