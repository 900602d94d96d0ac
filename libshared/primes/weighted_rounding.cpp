/// @file weighted_rounding.cpp
#include "primes/weighted_rounding.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "primes/cpu_features.hpp"
#include "primes/weighted_carry_lanes.hpp"
#include "primes/weighted_squaring_detail.hpp"

// The vector helpers are always inlined into functions compiled for
// AVX2 or AVX-512, so no vector crosses a call.
#pragma GCC diagnostic ignored "-Wpsabi"

namespace tk::primes {

namespace {

using namespace weighted_detail;

typedef double v4d __attribute__((vector_size(32)));
typedef std::int64_t v4i __attribute__((vector_size(32)));
typedef std::uint64_t v4u __attribute__((vector_size(32)));
typedef double v8d __attribute__((vector_size(64)));
typedef std::int64_t v8i __attribute__((vector_size(64)));
typedef std::uint64_t v8u __attribute__((vector_size(64)));

#define TK_INLINE __attribute__((always_inline)) inline

// Adding 1.5*2^52 rounds |v| < 2^51 to an integer, which then sits in the
// low bits of the sum's representation: subtracting the shifter's bits
// gives it as an int64 with no conversion instruction.
constexpr double kShifter = 6755399441055744.0;
// 2^51's bits: a double's magnitude is at least 2^51 (or NaN) when its
// bits without the sign are at least these.
constexpr std::int64_t kRangeBits = std::int64_t{(1023 + 51)} << 52;

template <class V>
TK_INLINE V load(const double* p) {
  V v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

// Worst error, out-of-range lanes and the sum mod p, over vectors of
// values: V doubles, I and U the same lanes as signed and unsigned.
template <class V, class I, class U>
struct Rounder {
  static constexpr std::size_t kLanes = sizeof(V) / sizeof(double);
  V worst{}, shifter{};
  I shifter_int{}, biggest_bits{}, magnitude_mask{};
  U sum{}, sum_high{}, p{}, sixty_one{};

  TK_INLINE Rounder() {
    std::int64_t shifter_bits;
    std::memcpy(&shifter_bits, &kShifter, sizeof shifter_bits);
    for (std::size_t l = 0; l < kLanes; ++l) {
      shifter[l] = kShifter;
      shifter_int[l] = shifter_bits;
      magnitude_mask[l] = std::numeric_limits<std::int64_t>::max();
      p[l] = kP61;
      sixty_one[l] = 61;
    }
  }

  // `value` rounded to integers, the worst error and the range noted.
  TK_INLINE I round(const V& value) {
    // The range check is an integer max on the magnitude's bits: a NaN or
    // an infinity has more than any finite value, so it fails too. Out of
    // range, z and the error are nonsense (finish() caps the error at 1/2),
    // but the square is then refused whole.
    const I magnitude_bits = (I)value & magnitude_mask;
    biggest_bits = magnitude_bits > biggest_bits ? magnitude_bits : biggest_bits;
    const V moved = value + shifter;
    const V rounded = moved - shifter;
    const V error = (V)((I)(value - rounded) & magnitude_mask);
    worst = error > worst ? error : worst;
    return (I)((U)moved - (U)shifter_int);
  }
  // The lanes' z_j * 2^(e_j) mod p.
  TK_INLINE U rotated(const I& zi, const std::uint64_t* __restrict rotation) const {
    const U residue = (U)zi + (p & (U)(zi >> 63));
    U e;  // 64-bit entries: a plain load, no widening shuffle
    std::memcpy(&e, rotation, sizeof e);
    return ((residue << e) & p) + (residue >> (sixty_one - e));
  }
  // Rounds `value` into z and returns the lanes' z_j * 2^(e_j) mod p.
  TK_INLINE U term(const V& value, const std::uint64_t* __restrict rotation, std::int64_t* __restrict z) {
    const I zi = round(value);
    std::memcpy(z, &zi, sizeof zi);
    return rotated(zi, rotation);
  }
  TK_INLINE void accumulate(U& into, const U& t) const {
    into += t;
    into = (into & p) + (into >> 61);
  }
  TK_INLINE void add_low(const V& value, const std::uint64_t* __restrict rotation, std::int64_t* __restrict z) {
    accumulate(sum, term(value, rotation, z));
  }
  TK_INLINE void add_high(const V& value, const std::uint64_t* __restrict rotation, std::int64_t* __restrict z) {
    accumulate(sum_high, term(value, rotation, z));
  }
  // The vector where the low coefficients end: its first `low_lanes` to sum.
  TK_INLINE void add_split(const V& value, const std::uint64_t* __restrict rotation, std::int64_t* __restrict z,
                           std::size_t low_lanes) {
    const U t = term(value, rotation, z);
    U low{}, high{};
    for (std::size_t l = 0; l < kLanes; ++l) (l < low_lanes ? low : high)[l] = t[l];
    accumulate(sum, low);
    accumulate(sum_high, high);
  }

  TK_INLINE RoundedCoefficients finish() const {
    RoundedCoefficients result;
    std::uint64_t total = 0, total_high = 0;
    for (std::size_t lane = 0; lane < kLanes; ++lane) {
      result.worst = std::max(result.worst, worst[lane]);
      result.out_of_range |= biggest_bits[lane] >= kRangeBits;
      total = fold61(total + sum[lane]);
      total_high = fold61(total_high + sum_high[lane]);
    }
    if (result.out_of_range) result.worst = std::min(result.worst, 0.5);
    result.sum = total;
    result.sum_high = total_high;
    return result;
  }
};

template <class V, class I, class U>
TK_INLINE RoundedCoefficients round_with(const double* __restrict output, const double* __restrict weight,
                                         const std::uint64_t* __restrict rotation, std::int64_t* __restrict z,
                                         std::size_t count, std::size_t low) {
  Rounder<V, I, U> rounder;
  constexpr std::size_t lanes = Rounder<V, I, U>::kLanes;
  std::size_t j = 0;
  // Whole vectors below `low`, the one across it, the rest: no select in the loops.
  for (; j + lanes <= count && j + lanes <= low; j += lanes)
    rounder.add_low(load<V>(output + j) * load<V>(weight + j), rotation + j, z + j);
  if (j + lanes <= count && j < low) {
    rounder.add_split(load<V>(output + j) * load<V>(weight + j), rotation + j, z + j, low - j);
    j += lanes;
  }
  for (; j + lanes <= count; j += lanes)
    rounder.add_high(load<V>(output + j) * load<V>(weight + j), rotation + j, z + j);
  RoundedCoefficients result = rounder.finish();
  std::uint64_t total = result.sum, total_high = result.sum_high;
  for (; j < count; ++j) {  // the last few, one at a time
    const double value = output[j] * weight[j];
    const double rounded = (value + kShifter) - kShifter;
    result.worst = std::max(result.worst, std::fabs(value - rounded));
    const bool fits = std::fabs(value) < 0x1p51;
    result.out_of_range |= !fits;
    z[j] = fits ? static_cast<std::int64_t>(rounded) : 0;
    std::uint64_t& into = j < low ? total : total_high;
    into = fold61(into + times_power61(residue61(z[j]), rotation[j]));
  }
  result.sum = reduce61(total);
  result.sum_high = reduce61(total_high);
  return result;
}

template <class V, class I, class U>
TK_INLINE RoundedCoefficients round_right_angle_with(const double* __restrict re, const double* __restrict im,
                                                     const RightAngleWeights& w,
                                                     const std::uint64_t* __restrict rotation,
                                                     std::int64_t* __restrict z, std::size_t half, std::size_t low,
                                                     std::size_t count) {
  Rounder<V, I, U> rounder;
  constexpr std::size_t lanes = Rounder<V, I, U>::kLanes;
  // Below `low`, across it (one vector), past it: no select in the loops.
  // The partners at j + half are rounded only below `count` (past it the
  // square is zero: its weights are).
  const std::size_t low_end = low / lanes * lanes;
  const std::size_t partner_end = count > half ? std::min(half, (count - half + lanes - 1) / lanes * lanes) : 0;
  // The weights' pointers as locals: z's stores cannot then make the loop reload them.
  const double* __restrict a = w.a;
  const double* __restrict b = w.b;
  const double* __restrict c = w.c;
  const double* __restrict d = w.d;
  auto both = [&](std::size_t j, auto&& first) __attribute__((always_inline)) {
    const V r = load<V>(re + j), m = load<V>(im + j);
    first(r * load<V>(a + j) + m * load<V>(b + j), j);
    if (j < partner_end) rounder.add_high(m * load<V>(c + j) - r * load<V>(d + j), rotation + half + j, z + half + j);
  };
  std::size_t j = 0;
  for (; j < low_end; j += lanes)
    both(j, [&](const V& v, std::size_t at) { rounder.add_low(v, rotation + at, z + at); });
  if (j < half && j < low) {
    both(j, [&](const V& v, std::size_t at) { rounder.add_split(v, rotation + at, z + at, low - at); });
    j += lanes;
  }
  for (; j < half; j += lanes) both(j, [&](const V& v, std::size_t at) { rounder.add_high(v, rotation + at, z + at); });
  RoundedCoefficients result = rounder.finish();
  result.sum = reduce61(result.sum);
  result.sum_high = reduce61(result.sum_high);
  return result;
}

__attribute__((target("avx512f,avx512dq"))) RoundedCoefficients round_avx512(const double* output, const double* weight,
                                                                             const std::uint64_t* rotation,
                                                                             std::int64_t* z, std::size_t count,
                                                                             std::size_t low) {
  return round_with<v8d, v8i, v8u>(output, weight, rotation, z, count, low);
}

__attribute__((target("avx2"))) RoundedCoefficients round_avx2(const double* output, const double* weight,
                                                               const std::uint64_t* rotation, std::int64_t* z,
                                                               std::size_t count, std::size_t low) {
  return round_with<v4d, v4i, v4u>(output, weight, rotation, z, count, low);
}

RoundedCoefficients round_portable(const double* output, const double* weight, const std::uint64_t* rotation,
                                   std::int64_t* z, std::size_t count, std::size_t low) {
  return round_with<v4d, v4i, v4u>(output, weight, rotation, z, count, low);
}

__attribute__((target("avx512f,avx512dq"))) RoundedCoefficients right_angle_avx512(const double* re, const double* im,
                                                                                   const RightAngleWeights& weights,
                                                                                   const std::uint64_t* rotation,
                                                                                   std::int64_t* z, std::size_t half,
                                                                                   std::size_t low, std::size_t count) {
  return round_right_angle_with<v8d, v8i, v8u>(re, im, weights, rotation, z, half, low, count);
}

__attribute__((target("avx2"))) RoundedCoefficients right_angle_avx2(const double* re, const double* im,
                                                                     const RightAngleWeights& weights,
                                                                     const std::uint64_t* rotation, std::int64_t* z,
                                                                     std::size_t half, std::size_t low,
                                                                     std::size_t count) {
  return round_right_angle_with<v4d, v4i, v4u>(re, im, weights, rotation, z, half, low, count);
}

// round_right_angle with the first lane pass of balance_digits done on
// the rounded integers before they are stored, on each range: [0, low)
// and [low, count). The low stream (j < half) and the partner stream
// (half + j) carry at once; the carry out of digit half - 1 into digit
// half is added when the low stream ends, the one out of digit count - 1
// taken off as the top carry. The sums are of the integers as rounded.
TK_INLINE CarriedCoefficients right_angle_carried_with(const double* __restrict re, const double* __restrict im,
                                                       const RightAngleWeights& w,
                                                       const std::uint64_t* __restrict rotation,
                                                       const std::uint8_t* __restrict bits, std::int64_t* __restrict z,
                                                       std::size_t half, std::size_t low, std::size_t count) {
  using carry_lanes::Lanes;
  Rounder<v8d, v8i, v8u> rounder;
  carry_lanes::CarryLanes lows, partners;
  const std::size_t partner_end = count > half ? std::min(half, (count - half + 7) / 8 * 8) : 0;
  const std::size_t split_at = low / 8 * 8;  // the vector holding digit `low` (low < half)
  const double* __restrict a = w.a;
  const double* __restrict b = w.b;
  const double* __restrict c = w.c;
  const double* __restrict d = w.d;
  // A whole vector of each stream at j, the low stream's sum into `sum`.
  auto whole = [&](std::size_t j, v8u & sum) __attribute__((always_inline)) {
    const v8d r = load<v8d>(re + j), m = load<v8d>(im + j);
    const v8i zi = rounder.round(r * load<v8d>(a + j) + m * load<v8d>(b + j));
    rounder.accumulate(sum, rounder.rotated(zi, rotation + j));
    carry_lanes::store(z + j, lows.carried(zi, bits + j));
    if (j >= partner_end) return;
    const v8i partner = rounder.round(m * load<v8d>(c + j) - r * load<v8d>(d + j));
    rounder.accumulate(rounder.sum_high, rounder.rotated(partner, rotation + half + j));
    carry_lanes::store(z + half + j, partners.carried(partner, bits + half + j));
  };
  std::size_t j = 0;
  for (; j < split_at; j += 8) whole(j, rounder.sum);
  // The split vector: lanes below `low` end the low range, whose carry out
  // of its last digit goes to low_carry, not into digit `low`; the lanes
  // from there on start the high range (their sums too).
  CarriedCoefficients result;
  const auto low_lanes = static_cast<std::int64_t>(low - j);
  const Lanes lane = {0, 1, 2, 3, 4, 5, 6, 7};
  const Lanes in_low = lane < low_lanes;  // all ones or zero per lane
  const Lanes largest_before = lows.largest, before = lows.before;
  lows.largest = Lanes{};
  v8u split_sum{};
  whole(j, split_sum);
  result.low_carry = carry_lanes::shifted_in(before, lows.before)[low_lanes];
  z[low] -= result.low_carry;                 // the carry into digit `low` was added: taken back out
  const Lanes moved = lows.largest & in_low;  // this vector's carries of the low range
  result.low_largest = carry_lanes::CarryLanes::largest_of(largest_before > moved ? largest_before : moved);
  lows.largest &= ~in_low;  // the high range's from here
  rounder.accumulate(rounder.sum, split_sum & (v8u)in_low);
  rounder.accumulate(rounder.sum_high, split_sum & ~(v8u)in_low);
  j += 8;
  for (; j < half; j += 8) whole(j, rounder.sum_high);
  const std::int64_t into_half = lows.last_up();
  const std::size_t end = partner_end > 0 ? half + partner_end : half;
  if (partner_end > 0) z[half] += into_half;
  if (count < end) {
    result.top_carry = z[count];
    z[count] = 0;
  } else {
    result.top_carry = partner_end > 0 ? partners.last_up() : into_half;
  }
  result.high_largest = std::max(lows.most(), partner_end > 0 ? partners.most() : std::int64_t{0});
  result.rounded = rounder.finish();
  result.rounded.sum = reduce61(result.rounded.sum);
  result.rounded.sum_high = reduce61(result.rounded.sum_high);
  return result;
}

__attribute__((target("avx512f,avx512dq"))) CarriedCoefficients right_angle_carried_avx512(
    const double* re, const double* im, const RightAngleWeights& w, const std::uint64_t* rotation,
    const std::uint8_t* bits, std::int64_t* z, std::size_t half, std::size_t low, std::size_t count) {
  return right_angle_carried_with(re, im, w, rotation, bits, z, half, low, count);
}

}  // namespace

CarriedCoefficients round_right_angle_carried(const double* re, const double* im, const RightAngleWeights& weights,
                                              const std::uint64_t* rotation, const std::uint8_t* bits, std::int64_t* z,
                                              std::size_t half, std::size_t low, std::size_t count) {
  return right_angle_carried_avx512(re, im, weights, rotation, bits, z, half, low, count);
}

RoundedCoefficients round_coefficients(const double* output, const double* weight, const std::uint64_t* rotation,
                                       std::int64_t* z, std::size_t count, std::size_t low) {
  if (cpu::has_avx512()) return round_avx512(output, weight, rotation, z, count, low);
  return cpu::has_avx2() ? round_avx2(output, weight, rotation, z, count, low)
                         : round_portable(output, weight, rotation, z, count, low);
}

// Only the right-angle transform's callers come here, and it needs AVX2.
RoundedCoefficients round_right_angle(const double* re, const double* im, const RightAngleWeights& weights,
                                      const std::uint64_t* rotation, std::int64_t* z, std::size_t half, std::size_t low,
                                      std::size_t count, bool wide) {
  return wide && cpu::has_avx512() ? right_angle_avx512(re, im, weights, rotation, z, half, low, count)
                                   : right_angle_avx2(re, im, weights, rotation, z, half, low, count);
}

// ---- One square split over threads ----

namespace {

template <class V, class I, class U>
TK_INLINE RoundedCoefficients round_columns_with(const double* __restrict re, const double* __restrict im,
                                                 const RightAngleWeights& w, const std::uint64_t* __restrict rotation,
                                                 std::int64_t* __restrict z, std::size_t half, std::size_t low,
                                                 std::size_t period, std::size_t from, std::size_t to) {
  Rounder<V, I, U> rounder;
  constexpr std::size_t lanes = Rounder<V, I, U>::kLanes;
  for (std::size_t base = 0; base < half; base += period)
    for (std::size_t j = base + from; j < base + to; j += lanes) {
      const V r = load<V>(re + j), m = load<V>(im + j);
      const V value = r * load<V>(w.a + j) + m * load<V>(w.b + j);
      if (j + lanes <= low) rounder.add_low(value, rotation + j, z + j);
      else if (j < low) rounder.add_split(value, rotation + j, z + j, low - j);
      else rounder.add_high(value, rotation + j, z + j);
      rounder.add_high(m * load<V>(w.c + j) - r * load<V>(w.d + j), rotation + half + j, z + half + j);
    }
  RoundedCoefficients result = rounder.finish();
  result.sum = reduce61(result.sum);
  result.sum_high = reduce61(result.sum_high);
  return result;
}

#define TK_COLUMNS_ARGS                                                                                \
  const double *re, const double *im, const RightAngleWeights &weights, const std::uint64_t *rotation, \
      std::int64_t *z, std::size_t half, std::size_t low, std::size_t period, std::size_t from, std::size_t to
__attribute__((target("avx512f,avx512dq"))) RoundedCoefficients columns_avx512(TK_COLUMNS_ARGS) {
  return round_columns_with<v8d, v8i, v8u>(re, im, weights, rotation, z, half, low, period, from, to);
}
__attribute__((target("avx2"))) RoundedCoefficients columns_avx2(TK_COLUMNS_ARGS) {
  return round_columns_with<v4d, v4i, v4u>(re, im, weights, rotation, z, half, low, period, from, to);
}
#undef TK_COLUMNS_ARGS

}  // namespace

RoundedCoefficients round_right_angle_columns(const double* re, const double* im, const RightAngleWeights& weights,
                                              const std::uint64_t* rotation, std::int64_t* z, std::size_t half,
                                              std::size_t low, std::size_t period, std::size_t from, std::size_t to,
                                              bool wide) {
  return wide && cpu::has_avx512() ? columns_avx512(re, im, weights, rotation, z, half, low, period, from, to)
                                   : columns_avx2(re, im, weights, rotation, z, half, low, period, from, to);
}

RoundedCoefficients combine(const RoundedCoefficients& a, const RoundedCoefficients& b) {
  RoundedCoefficients sum;
  sum.worst = std::max(a.worst, b.worst);
  sum.sum = reduce61(a.sum + b.sum);
  sum.sum_high = reduce61(a.sum_high + b.sum_high);
  sum.out_of_range = a.out_of_range || b.out_of_range;
  return sum;
}

}  // namespace tk::primes
