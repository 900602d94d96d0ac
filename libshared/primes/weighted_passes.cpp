/// @file weighted_passes.cpp
#include "primes/weighted_passes.hpp"

#include "primes/weighted_squaring_detail.hpp"

namespace tk::primes {

namespace {

using namespace weighted_detail;

// A coefficient is below 2^51 and the carry below 2^(52-s), so their sum
// fits 64 bits. `pending` holds the `filled` (< 64) bits not yet in a
// full limb; no branch (a limb fills at an irregular digit).
__attribute__((always_inline)) inline HighCarry carry_body(const std::int64_t* __restrict z,
                                                          const std::uint8_t* __restrict bits, std::size_t low_digits,
                                                          std::size_t coefficients, std::uint64_t* __restrict high) {
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
    const bool full = filled + s >= 64;
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
  return {low_carry, carry, limb};
}

template <bool kAdd, bool kComplex>
__attribute__((always_inline)) inline void fold_body(const std::int64_t* __restrict low, const mp_limb_t* __restrict q,
                                                     const std::uint8_t* __restrict bits, const FoldTarget& target,
                                                     std::size_t low_digits, std::size_t digits, std::int64_t bottom,
                                                     std::int64_t top) {
  std::int64_t* __restrict digit_out = target.digits;
  double* __restrict re = target.re;
  double* __restrict im = target.im;
  const double* __restrict re_weight = target.re_weight;
  const double* __restrict im_weight = target.im_weight;
  auto write = [&](std::size_t j, std::int64_t digit) {
    digit_out[j] = digit;
    const double d = static_cast<double>(digit);
    re[j] = d * re_weight[j];
    if constexpr (kComplex) im[j] = d * im_weight[j];
  };
  std::int64_t carry = bottom;
  auto put = [&](std::size_t j, std::int64_t total) {
    const unsigned s = bits[j];
    const std::int64_t up = (total + (std::int64_t{1} << (s - 1))) >> s;  // balanced: digit in [-2^(s-1), 2^(s-1))
    carry = up;
    write(j, total - (up << s));
  };
  std::uint64_t position = 0;  // e_j, kept by adding
  for (std::size_t j = 0; j < low_digits; ++j) {
    const auto quotient = static_cast<std::int64_t>(bits_at(q, position, bits[j]));
    put(j, (kAdd ? low[j] + quotient : low[j] - quotient) + carry);
    position += bits[j];
  }
  carry += top;
  for (std::size_t j = low_digits; j + 1 < digits; ++j) put(j, carry);
  write(digits - 1, carry);  // the last takes what is left, unbalanced
}

#define TK_FOLD_ARGS                                                                                        \
  const std::int64_t *low, const mp_limb_t *q, const std::uint8_t *bits, const FoldTarget &target,          \
      std::size_t low_digits, std::size_t digits, std::int64_t bottom, std::int64_t top, bool add_quotient
#define TK_FOLD_ONE(add, complex) fold_body<add, complex>(low, q, bits, target, low_digits, digits, bottom, top)
#define TK_FOLD_CALL(body)                                                           \
  if (target.im)                                                                     \
    return add_quotient ? TK_FOLD_ONE(true, true) : TK_FOLD_ONE(false, true);        \
  return add_quotient ? TK_FOLD_ONE(true, false) : TK_FOLD_ONE(false, false)

__attribute__((target("avx2,bmi,bmi2"))) HighCarry carry_fast(const std::int64_t* z, const std::uint8_t* bits,
                                                              std::size_t low_digits, std::size_t coefficients,
                                                              std::uint64_t* high) {
  return carry_body(z, bits, low_digits, coefficients, high);
}
HighCarry carry_portable(const std::int64_t* z, const std::uint8_t* bits, std::size_t low_digits,
                         std::size_t coefficients, std::uint64_t* high) {
  return carry_body(z, bits, low_digits, coefficients, high);
}
__attribute__((target("avx2,bmi,bmi2"))) void fold_fast(TK_FOLD_ARGS) { TK_FOLD_CALL(fold_body); }
void fold_portable(TK_FOLD_ARGS) { TK_FOLD_CALL(fold_body); }

#undef TK_FOLD_ARGS
#undef TK_FOLD_ONE
#undef TK_FOLD_CALL

bool cpu_is_fast() {
  static const bool fast = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("bmi2");
  return fast;
}

}  // namespace

HighCarry carry_into_limbs(const std::int64_t* z, const std::uint8_t* bits, std::size_t low_digits,
                           std::size_t coefficients, std::uint64_t* high) {
  return cpu_is_fast() ? carry_fast(z, bits, low_digits, coefficients, high)
                       : carry_portable(z, bits, low_digits, coefficients, high);
}

void fold_digits(const std::int64_t* low, const mp_limb_t* q, const std::uint8_t* bits, const FoldTarget& target,
                 std::size_t low_digits, std::size_t digits, std::int64_t bottom, std::int64_t top, bool add_quotient) {
  if (cpu_is_fast())
    fold_fast(low, q, bits, target, low_digits, digits, bottom, top, add_quotient);
  else
    fold_portable(low, q, bits, target, low_digits, digits, bottom, top, add_quotient);
}

}  // namespace tk::primes
