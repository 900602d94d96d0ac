/// @file transform_digits.cpp
/// @brief Conversions and carries of 18-bit digits in doubles. The carries
/// run in two passes without a serial chain, so they vectorise: the first
/// splits each coefficient in three balanced pieces of 18 bits and adds
/// each piece to its place (a sum below 2^18.4), the second splits once
/// more (a carry of -1, 0 or 1).
#include "primes/transform_digits.hpp"

#include <cmath>
#include <vector>

namespace tk::primes::digits18 {

namespace {

constexpr double kInverseRadix = 1.0 / kRadix;
constexpr std::int64_t kRadixInt = std::int64_t{1} << kBits;
constexpr std::int64_t kDigitMask = kRadixInt - 1;

struct Pieces {
  double low, middle, high;
};

// y = low + 2^18 middle + 2^36 high, each balanced (|high| <= 2^15 for |y| < 2^51).
inline Pieces pieces_of(double y) {
  const double above = nearest(y * kInverseRadix);
  const double high = nearest(above * kInverseRadix);
  return {y - above * kRadix, above - high * kRadix, high};
}

}  // namespace

bool from_mpz(const mpz_class& x, double* digits, std::size_t count) {
  const mpz_srcptr z = x.get_mpz_t();
  const std::size_t limbs = mpz_size(z);
  const double sign = mpz_sgn(z) < 0 ? -1.0 : 1.0;
  std::int64_t carry = 0;
  for (std::size_t j = 0; j < count; ++j) {
    // bits [18 j, 18 j + 18) of |x|
    const std::size_t bit = j * kBits, limb = bit / 64, shift = bit % 64;
    std::uint64_t chunk = limb < limbs ? mpz_getlimbn(z, static_cast<mp_size_t>(limb)) >> shift : 0;
    if (shift > 64 - kBits && limb + 1 < limbs)
      chunk |= mpz_getlimbn(z, static_cast<mp_size_t>(limb + 1)) << (64 - shift);
    std::int64_t digit = static_cast<std::int64_t>(chunk & static_cast<std::uint64_t>(kDigitMask)) + carry;
    carry = digit >= (std::int64_t{1} << (kBits - 1)) ? 1 : 0;
    digit -= carry << kBits;
    digits[j] = sign * static_cast<double>(digit);
  }
  return carry == 0 && mpz_sizeinbase(z, 2) <= count * kBits;
}

mpz_class to_mpz(const double* digits, std::size_t count) {
  // Serial carry to digits in [0, 2^18) and a signed carry out.
  std::vector<std::uint64_t> bits((count * kBits + 63) / 64 + 1, 0);
  std::int64_t carry = 0;
  for (std::size_t j = 0; j < count; ++j) {
    const std::int64_t v = static_cast<std::int64_t>(digits[j]) + carry;
    const std::int64_t digit = v & kDigitMask;
    carry = (v - digit) / (std::int64_t{1} << kBits);
    const std::size_t bit = j * kBits, limb = bit / 64, shift = bit % 64;
    bits[limb] |= static_cast<std::uint64_t>(digit) << shift;
    if (shift > 64 - kBits) bits[limb + 1] |= static_cast<std::uint64_t>(digit) >> (64 - shift);
  }
  mpz_class value, top = static_cast<long>(carry);
  mpz_import(value.get_mpz_t(), bits.size(), -1, sizeof(std::uint64_t), 0, 0, bits.data());
  mpz_mul_2exp(top.get_mpz_t(), top.get_mpz_t(), count * kBits);
  return value + top;
}

TK_DIGIT_CLONES std::int64_t residue(const double* digits, std::size_t count) {
  // Exact in any order (integers, fewer than 2^30 / 2^18 digits in any
  // use): eight sums the compiler may keep in one vector; the even ones
  // gather the even places.
  double sums[8] = {};
  std::size_t j = 0;
  for (; j + 8 <= count; j += 8)
    for (std::size_t l = 0; l < 8; ++l) sums[l] += digits[j + l];
  for (; j < count; ++j) sums[j % 2] += digits[j];
  const double even = sums[0] + sums[2] + sums[4] + sums[6], odd = sums[1] + sums[3] + sums[5] + sums[7];
  if (!(std::fabs(even) < 1e15 && std::fabs(odd) < 1e15)) return -1;  // NaN or infinite digits: no residue matches
  const std::int64_t r =
      (static_cast<std::int64_t>(even) % kCheckModulus + (static_cast<std::int64_t>(odd) % kCheckModulus) * kRadixInt) %
      kCheckModulus;
  return r < 0 ? r + kCheckModulus : r;
}

std::int64_t residue_product(std::int64_t a, std::int64_t b) {
  auto normal = [](std::int64_t x) {
    return static_cast<std::uint64_t>((x % kCheckModulus + kCheckModulus) % kCheckModulus);
  };
  const std::uint64_t m = static_cast<std::uint64_t>(kCheckModulus), x = normal(a), y = normal(b);
  // x * y below 2^72: by the halves of y, each product below 2^54
  const std::uint64_t high = (x * (y >> kBits)) % m, low = (x * (y & static_cast<std::uint64_t>(kDigitMask))) % m;
  return static_cast<std::int64_t>(((high << kBits) % m + low) % m);
}

TK_DIGIT_CLONES void carry_acyclic(const double* y, std::size_t count, double* out, double* scratch) {
  // scratch_j = low_j + middle_(j-1) + high_(j-2), the ends apart so the
  // middle loop vectorises.
  auto at = [&](std::size_t j) { return j < count ? pieces_of(y[j]) : Pieces{0, 0, 0}; };
  for (std::size_t j = 0; j < 2 && j < count + 2; ++j) scratch[j] = at(j).low + (j == 1 ? at(0).middle : 0.0);
  for (std::size_t j = 2; j < count; ++j)
    scratch[j] = pieces_of(y[j]).low + pieces_of(y[j - 1]).middle + pieces_of(y[j - 2]).high;
  for (std::size_t j = count < 2 ? 2 : count; j < count + 2; ++j)
    scratch[j] = at(j).low + at(j - 1).middle + at(j - 2).high;
  scratch[count + 2] = 0;
  out[0] = scratch[0] - nearest(scratch[0] * kInverseRadix) * kRadix;
  for (std::size_t j = 1; j < count + 3; ++j)
    out[j] = scratch[j] - nearest(scratch[j] * kInverseRadix) * kRadix + nearest(scratch[j - 1] * kInverseRadix);
}

TK_DIGIT_CLONES void carry_negacyclic(const double* y, std::size_t count, double* out, double* scratch) {
  // Places past the top wrap to the bottom with their sign changed.
  scratch[0] = pieces_of(y[0]).low - pieces_of(y[count - 1]).middle - pieces_of(y[count - 2]).high;
  scratch[1] = pieces_of(y[1]).low + pieces_of(y[0]).middle - pieces_of(y[count - 1]).high;
  for (std::size_t j = 2; j < count; ++j)
    scratch[j] = pieces_of(y[j]).low + pieces_of(y[j - 1]).middle + pieces_of(y[j - 2]).high;
  out[0] = scratch[0] - nearest(scratch[0] * kInverseRadix) * kRadix - nearest(scratch[count - 1] * kInverseRadix);
  for (std::size_t j = 1; j < count; ++j)
    out[j] = scratch[j] - nearest(scratch[j] * kInverseRadix) * kRadix + nearest(scratch[j - 1] * kInverseRadix);
}

}  // namespace tk::primes::digits18
