/// @file weighted_rounding.cpp
#include "primes/weighted_rounding.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "primes/weighted_squaring_detail.hpp"

namespace tk::primes {

namespace {

using namespace weighted_detail;

typedef double v4d __attribute__((vector_size(32)));
typedef std::int64_t v4i __attribute__((vector_size(32)));
typedef std::uint64_t v4u __attribute__((vector_size(32)));

// Adding 1.5*2^52 rounds |v| < 2^51 to an integer, which then sits in the
// low bits of the sum's representation: subtracting the shifter's bits
// gives it as an int64 with no conversion instruction.
constexpr double kShifter = 6755399441055744.0;

template <bool kAvx2>
__attribute__((always_inline)) inline RoundedCoefficients round_with(const double* __restrict output, const double* __restrict weight,
                                      const std::uint8_t* __restrict rotation, std::int64_t* __restrict z,
                                      std::size_t count) {
  const v4d shifter = {kShifter, kShifter, kShifter, kShifter};
  std::int64_t shifter_bits;
  std::memcpy(&shifter_bits, &kShifter, sizeof shifter_bits);
  const v4i shifter_int = {shifter_bits, shifter_bits, shifter_bits, shifter_bits};
  const v4d limit = {0x1p51, 0x1p51, 0x1p51, 0x1p51};
  const v4u p = {kP61, kP61, kP61, kP61};
  const v4u sixty_one = {61, 61, 61, 61};
  v4d worst = {0, 0, 0, 0};
  v4i bad = {0, 0, 0, 0};
  v4u sum = {0, 0, 0, 0};
  std::size_t j = 0;
  for (; j + 4 <= count; j += 4) {
    v4d value, w;
    std::memcpy(&value, output + j, sizeof value);
    std::memcpy(&w, weight + j, sizeof w);
    value *= w;
    const v4d moved = value + shifter;
    const v4d rounded = moved - shifter;
    const v4d error = value > rounded ? value - rounded : rounded - value;
    worst = error > worst ? error : worst;
    const v4d magnitude = value > -value ? value : -value;
    const v4i fits = magnitude < limit;  // all ones where |value| < 2^51 (false for NaN)
    bad |= ~fits;
    const v4i zi = (v4i)((v4u)moved - (v4u)shifter_int) & fits;  // unsigned: lanes out of range wrap harmlessly
    std::memcpy(z + j, &zi, sizeof zi);
    const v4u residue = (v4u)zi + (p & (v4u)(zi >> 63));
    const v4u e = {rotation[j], rotation[j + 1], rotation[j + 2], rotation[j + 3]};
    const v4u term = ((residue << e) & p) + (residue >> (sixty_one - e));
    sum += term;
    sum = (sum & p) + (sum >> 61);
  }
  RoundedCoefficients result;
  std::uint64_t total = 0;
  for (int lane = 0; lane < 4; ++lane) {
    result.worst = std::max(result.worst, worst[lane]);
    result.out_of_range |= bad[lane] != 0;
    total = fold61(total + sum[lane]);
  }
  for (; j < count; ++j) {  // the last few, one at a time
    const double value = output[j] * weight[j];
    const double rounded = (value + kShifter) - kShifter;
    result.worst = std::max(result.worst, std::fabs(value - rounded));
    const bool fits = std::fabs(value) < 0x1p51;
    result.out_of_range |= !fits;
    z[j] = fits ? static_cast<std::int64_t>(rounded) : 0;
    total = fold61(total + times_power61(residue61(z[j]), rotation[j]));
  }
  (void)kAvx2;
  result.sum = reduce61(total);
  return result;
}

__attribute__((target("avx2"))) RoundedCoefficients round_avx2(const double* output, const double* weight,
                                                               const std::uint8_t* rotation, std::int64_t* z,
                                                               std::size_t count) {
  return round_with<true>(output, weight, rotation, z, count);
}

RoundedCoefficients round_portable(const double* output, const double* weight, const std::uint8_t* rotation,
                                   std::int64_t* z, std::size_t count) {
  return round_with<false>(output, weight, rotation, z, count);
}

}  // namespace

RoundedCoefficients round_coefficients(const double* output, const double* weight, const std::uint8_t* rotation,
                                       std::int64_t* z, std::size_t count) {
  static const bool avx2 = __builtin_cpu_supports("avx2");
  return avx2 ? round_avx2(output, weight, rotation, z, count) : round_portable(output, weight, rotation, z, count);
}

}  // namespace tk::primes
