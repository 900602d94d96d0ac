/// @file weighted_passes.cpp
#include "primes/weighted_passes.hpp"

// GCC 12 warns inside its own AVX-512 intrinsics (their _mm512_undefined).
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#pragma GCC diagnostic ignored "-Wuninitialized"
#include <immintrin.h>

#include <cmath>

#include "primes/cpu_features.hpp"
#include "primes/weighted_squaring_detail.hpp"

namespace tk::primes {

namespace {

using namespace weighted_detail;

// The low coefficients' carry into 2^n, floor(L / 2^n), from the top
// ones alone, in doubles: each term is below 2^51 times 2^-(n - e_j), the
// sum about 2^31 with 2^-21 to spare, and what lies more than 2^110 below
// 2^n is ignored, so this is the exact floor or one off it. The value is
// exact whatever this is (H*2^n + L with this moved from L to H is still
// the square): it only keeps the top digit small, and one off leaves it
// one larger or smaller. No serial pass over the low coefficients here.
inline std::int64_t low_carry_estimate(const std::int64_t* z, const std::uint8_t* bits, std::size_t low_digits) {
  double sum = 0, scale = 1;
  for (std::size_t j = low_digits; j-- > 0 && scale > 0x1p-110;) {
    scale *= std::ldexp(1.0, -bits[j]);  // 2^-(n - e_j)
    sum += static_cast<double>(z[j]) * scale;
  }
  return static_cast<std::int64_t>(std::floor(sum));
}

// A coefficient is below 2^51 and the carry below 2^(52-s), so their sum
// fits 64 bits. `pending` holds the `filled` (< 64) bits not yet in a
// full limb; no branch (a limb fills at an irregular digit).
__attribute__((always_inline)) inline HighCarry carry_body(const std::int64_t* __restrict z,
                                                           const std::uint8_t* __restrict bits, std::size_t low_digits,
                                                           std::size_t coefficients, std::uint64_t* __restrict high) {
  std::int64_t carry = 0;
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
  for (std::size_t j = low_digits; j < coefficients; ++j) high_digit(j);
  high[limb] = pending;
  return {low_carry_estimate(z, bits, low_digits), carry, limb};
}

// Three passes, so the serial one is short: the quotient's bits joined
// to the low coefficients (independent digits), the balanced carry (the
// only chain: an add, a shift, a subtract), then the digits weighted into
// the transform's input (vectorised where the CPU converts int64 lanes).
template <bool kAdd>
__attribute__((always_inline)) inline void join_quotient(const std::int64_t* __restrict low,
                                                         const mp_limb_t* __restrict q,
                                                         const std::uint8_t* __restrict bits,
                                                         const std::uint64_t* __restrict exponent,
                                                         std::int64_t* __restrict joined, std::size_t low_digits) {
  for (std::size_t j = 0; j < low_digits; ++j) {
    const auto quotient = static_cast<std::int64_t>(bits_at(q, exponent[j], bits[j]));
    joined[j] = kAdd ? low[j] + quotient : low[j] - quotient;
  }
}

// Balanced digits: digit in [-2^(s-1), 2^(s-1)), the rest carried up.
// Half of 2^s is added before the carry, so the chain is an add and a shift.
struct Balancer {
  std::int64_t* __restrict digit;
  const std::uint8_t* __restrict bits;

  __attribute__((always_inline)) std::int64_t step(std::size_t j, std::int64_t carry) const {
    const unsigned s = bits[j];
    const std::int64_t total = digit[j] + (std::int64_t{1} << (s - 1));
    const std::int64_t up = (total + carry) >> s;
    digit[j] = total + carry - (up << s) - (std::int64_t{1} << (s - 1));
    return up;
  }
  // Adds `carry` at digit `from` and carries it on until it is absorbed or
  // reaches `end` (then returned): two or three digits for a carry that
  // came from another chain.
  __attribute__((always_inline)) std::int64_t absorb(std::size_t from, std::size_t end, std::int64_t carry) const {
    for (std::size_t j = from; carry != 0 && j < end; ++j) carry = step(j, carry);
    return carry;
  }
};

// The top digits hold only what carries in (`up`); the last takes what is
// left, unbalanced.
__attribute__((always_inline)) inline void balance_top(std::int64_t* __restrict digit,
                                                       const std::uint8_t* __restrict bits, std::size_t low_digits,
                                                       std::size_t digits, std::int64_t up) {
  const Balancer balancer{digit, bits};
  for (std::size_t j = low_digits; j + 1 < digits; ++j) {
    digit[j] = 0;
    up = balancer.step(j, up);
  }
  digit[digits - 1] = up;
}

// The low digits carry in kChains independent chains over as many
// stretches, interleaved (one chain is bound by its add-and-shift
// latency); each chain's last carry is then absorbed at the start of the
// next stretch. The value is the serial pass's; the digits are as balanced.
constexpr std::size_t kChains = 4;

__attribute__((always_inline)) inline void balance(std::int64_t* __restrict digit, const std::uint8_t* __restrict bits,
                                                   std::size_t low_digits, std::size_t digits, std::int64_t bottom,
                                                   std::int64_t top) {
  const Balancer balancer{digit, bits};
  const std::size_t stretch = low_digits / kChains;
  std::int64_t carry[kChains] = {bottom};
  for (std::size_t i = 0; i < stretch; ++i)
    for (std::size_t c = 0; c < kChains; ++c) carry[c] = balancer.step(c * stretch + i, carry[c]);
  for (std::size_t j = kChains * stretch; j < low_digits; ++j)
    carry[kChains - 1] = balancer.step(j, carry[kChains - 1]);
  for (std::size_t c = 1; c < kChains; ++c) {
    const std::size_t end = c + 1 < kChains ? (c + 1) * stretch : low_digits;
    carry[c] += balancer.absorb(c * stretch, end, carry[c - 1]);
  }
  balance_top(digit, bits, low_digits, digits, carry[kChains - 1] + top);
}

__attribute__((always_inline)) inline void weigh(const FoldTarget& target, std::size_t digits) {
  const std::int64_t* __restrict digit = target.digits;
  double* __restrict re = target.re;
  const double* __restrict re_weight = target.re_weight;
  for (std::size_t j = 0; j < digits; ++j) re[j] = static_cast<double>(digit[j]) * re_weight[j];
  if (!target.im) return;
  double* __restrict im = target.im;
  const double* __restrict im_weight = target.im_weight;
  for (std::size_t j = 0; j < digits; ++j) im[j] = static_cast<double>(digit[j]) * im_weight[j];
}

// join_quotient eight digits at a time: each digit's bits (s <= 56) lie
// in the eight bytes from byte e_j / 8 on, one gather (scale 1) then a
// shift by e_j mod 8 and a mask (the scalar loop spends about fifteen
// instructions a digit on it; two gathers of whole limbs took twice as long).
template <bool kAdd>
__attribute__((target("avx512f,avx512dq,avx512vl,avx2,bmi,bmi2"))) void join_quotient_avx512(
    const std::int64_t* __restrict low, const mp_limb_t* __restrict q, const std::uint8_t* __restrict bits,
    const std::uint64_t* __restrict exponent, std::int64_t* __restrict joined, std::size_t low_digits) {
  const __m512i one = _mm512_set1_epi64(1), seven = _mm512_set1_epi64(7);
  const auto* bytes = reinterpret_cast<const char*>(q);
  std::size_t j = 0;
  for (; j + 8 <= low_digits; j += 8) {
    const __m512i e = _mm512_loadu_si512(exponent + j);
    const __m512i word = _mm512_i64gather_epi64(_mm512_srli_epi64(e, 3), bytes, 1);
    const __m512i size = _mm512_cvtepu8_epi64(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(bits + j)));
    const __m512i mask = _mm512_sub_epi64(_mm512_sllv_epi64(one, size), one);
    const __m512i quotient = _mm512_and_si512(_mm512_srlv_epi64(word, _mm512_and_si512(e, seven)), mask);
    const __m512i coefficient = _mm512_loadu_si512(low + j);
    _mm512_storeu_si512(joined + j,
                        kAdd ? _mm512_add_epi64(coefficient, quotient) : _mm512_sub_epi64(coefficient, quotient));
  }
  for (; j < low_digits; ++j) {
    const auto quotient = static_cast<std::int64_t>(bits_at(q, exponent[j], bits[j]));
    joined[j] = kAdd ? low[j] + quotient : low[j] - quotient;
  }
}

// The low digits balanced in lanes, eight at a time, by passes that each
// move every digit's excess over [-2^(s-1), 2^(s-1)) one digit up at once
// (the carry a digit takes in is what its neighbour gave off before this
// pass). Each pass divides the excess by about 2^s; passes run until no
// carry exceeds 1, so a digit ends within one of balanced (2^51 to 1 in
// three passes at s = 17), which costs the transform nothing, while the
// scalar chain is bound by its add-and-shift latency. The value is the
// same; returns the carry out of the last low digit.
__attribute__((target("avx512f,avx512dq,avx512vl,avx2,bmi,bmi2"))) std::int64_t balance_lanes(
    std::int64_t* __restrict digit, const std::uint8_t* __restrict bits, std::size_t low_digits) {
  const __m512i one = _mm512_set1_epi64(1);
  const std::size_t whole = low_digits / 8 * 8;
  std::int64_t carried_out = 0;
  for (int pass = 0; pass < 64; ++pass) {
    __m512i before = _mm512_setzero_si512(), largest = _mm512_setzero_si512();
    for (std::size_t j = 0; j < whole; j += 8) {
      const __m512i size = _mm512_cvtepu8_epi64(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(bits + j)));
      const __m512i half = _mm512_sllv_epi64(one, _mm512_sub_epi64(size, one));
      const __m512i total = _mm512_add_epi64(_mm512_loadu_si512(digit + j), half);
      const __m512i up = _mm512_srav_epi64(total, size);
      const __m512i kept = _mm512_sub_epi64(_mm512_sub_epi64(total, _mm512_sllv_epi64(up, size)), half);
      // lane i takes lane i-1's carry; lane 0 the previous vector's last
      _mm512_storeu_si512(digit + j, _mm512_add_epi64(kept, _mm512_alignr_epi64(up, before, 7)));
      largest = _mm512_max_epi64(largest, _mm512_abs_epi64(up));
      before = up;
    }
    std::int64_t carry = whole > 0 ? static_cast<std::int64_t>(_mm512_mask_reduce_max_epi64(0x80, before)) : 0;
    std::int64_t tail_largest = 0;
    for (std::size_t j = whole; j < low_digits; ++j) {
      const unsigned s = bits[j];
      const std::int64_t total = digit[j] + (std::int64_t{1} << (s - 1));
      const std::int64_t up = total >> s;
      digit[j] = total - (up << s) - (std::int64_t{1} << (s - 1)) + carry;
      tail_largest = std::max(tail_largest, up < 0 ? -up : up);
      carry = up;
    }
    carried_out += carry;
    if (std::max(static_cast<std::int64_t>(_mm512_reduce_max_epi64(largest)), tail_largest) <= 1) break;
  }
  return carried_out;
}

template <bool kAdd, bool kGather>
__attribute__((always_inline)) inline void fold_body(const std::int64_t* low, const mp_limb_t* q,
                                                     const std::uint8_t* bits, const std::uint64_t* exponent,
                                                     const FoldTarget& target, std::size_t low_digits,
                                                     std::size_t digits, std::int64_t bottom, std::int64_t top) {
  if constexpr (kGather) {
    join_quotient_avx512<kAdd>(low, q, bits, exponent, target.digits, low_digits);
    target.digits[0] += bottom;
    balance_top(target.digits, bits, low_digits, digits, balance_lanes(target.digits, bits, low_digits) + top);
  } else {
    join_quotient<kAdd>(low, q, bits, exponent, target.digits, low_digits);
    balance(target.digits, bits, low_digits, digits, bottom, top);
  }
  weigh(target, digits);
}

#define TK_FOLD_ARGS                                                                                               \
  const std::int64_t *low, const mp_limb_t *q, const std::uint8_t *bits, const std::uint64_t *exponent,            \
      const FoldTarget &target, std::size_t low_digits, std::size_t digits, std::int64_t bottom, std::int64_t top, \
      bool add_quotient
#define TK_FOLD_CALL(gather)                                                                                     \
  return add_quotient ? fold_body<true, gather>(low, q, bits, exponent, target, low_digits, digits, bottom, top) \
                      : fold_body<false, gather>(low, q, bits, exponent, target, low_digits, digits, bottom, top)

__attribute__((target("avx2,bmi,bmi2"))) HighCarry carry_fast(const std::int64_t* z, const std::uint8_t* bits,
                                                              std::size_t low_digits, std::size_t coefficients,
                                                              std::uint64_t* high) {
  return carry_body(z, bits, low_digits, coefficients, high);
}
HighCarry carry_portable(const std::int64_t* z, const std::uint8_t* bits, std::size_t low_digits,
                         std::size_t coefficients, std::uint64_t* high) {
  return carry_body(z, bits, low_digits, coefficients, high);
}
__attribute__((target("avx512f,avx512dq,avx512vl,avx2,bmi,bmi2"))) void fold_avx512(TK_FOLD_ARGS) {
  TK_FOLD_CALL(true);
}
__attribute__((target("avx2,bmi,bmi2"))) void fold_fast(TK_FOLD_ARGS) { TK_FOLD_CALL(false); }
void fold_portable(TK_FOLD_ARGS) { TK_FOLD_CALL(false); }

#undef TK_FOLD_ARGS
#undef TK_FOLD_CALL

}  // namespace

HighCarry carry_into_limbs(const std::int64_t* z, const std::uint8_t* bits, std::size_t low_digits,
                           std::size_t coefficients, std::uint64_t* high) {
  return cpu::has_avx2() ? carry_fast(z, bits, low_digits, coefficients, high)
                         : carry_portable(z, bits, low_digits, coefficients, high);
}

void fold_digits(const std::int64_t* low, const mp_limb_t* q, const std::uint8_t* bits, const std::uint64_t* exponent,
                 const FoldTarget& target, std::size_t low_digits, std::size_t digits, std::int64_t bottom,
                 std::int64_t top, bool add_quotient) {
  if (cpu::has_avx512() && target.wide)
    fold_avx512(low, q, bits, exponent, target, low_digits, digits, bottom, top, add_quotient);
  else if (cpu::has_avx2()) fold_fast(low, q, bits, exponent, target, low_digits, digits, bottom, top, add_quotient);
  else fold_portable(low, q, bits, exponent, target, low_digits, digits, bottom, top, add_quotient);
}

}  // namespace tk::primes
