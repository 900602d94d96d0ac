/// @file test_right_angle_transform.cpp
/// @brief RightAngleSquarer's acyclic squares against the exact integer
/// squares (schoolbook, in 64-bit integers) of random digits, at every
/// kind of length it plans (radix-3, radix-2 and radix-4 passes, blocks
/// run whole and one at a time), for each SIMD width this CPU has.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "primes/right_angle_transform.hpp"
#include "simd_widths.hpp"

namespace {

using tk::primes::RightAngleSquarer;

std::vector<std::int64_t> exact_square(const std::vector<std::int64_t>& x) {
  std::vector<std::int64_t> z(2 * x.size(), 0);
  for (std::size_t i = 0; i < x.size(); ++i) {
    z[2 * i] += x[i] * x[i];
    for (std::size_t l = i + 1; l < x.size(); ++l) z[i + l] += 2 * x[i] * x[l];
  }
  return z;
}

// The worst distance of L * the transform's square from the exact square,
// for random digits of `bits` bits (balanced) filling the first L/2 places.
double worst_error(RightAngleSquarer& squarer, int bits, std::uint32_t seed) {
  const std::size_t length = squarer.length();
  std::mt19937_64 random(seed);
  std::uniform_int_distribution<std::int64_t> digit(-(std::int64_t{1} << (bits - 1)),
                                                    (std::int64_t{1} << (bits - 1)) - 1);
  std::vector<std::int64_t> x(length / 2);
  std::vector<double> input(length, 0.0), output(length, -1.0);
  for (std::size_t j = 0; j < x.size(); ++j) input[j] = static_cast<double>(x[j] = digit(random));
  squarer.square(input.data(), output.data());
  const auto z = exact_square(x);
  double worst = 0;
  for (std::size_t j = 0; j < length; ++j)
    worst = std::max(worst, std::fabs(output[j] / static_cast<double>(length) - static_cast<double>(z[j])));
  return worst;
}

using simd_test::widths_here;

TEST(RightAngleSquarer, ExactSquaresAtEveryKindOfLength) {
  const auto widths = widths_here();
  if (widths.empty()) GTEST_SKIP() << "no AVX2 with FMA on this CPU";
  // 2^a, 3 * 2^a, 9 * 2^a, 27 * 2^a; odd and even powers of 4 over the
  // lanes; lengths whose blocks all fit one inner block and lengths with
  // passes over the whole array (L/2 > 1024).
  const std::size_t lengths[] = {64,   96,   128,  192,  256,  288,  384,  512,  576,   864,  1024,
                                 1536, 2048, 2304, 3072, 3456, 4096, 6144, 9216, 13824, 18432};
  int tried = 0;
  for (auto simd : widths)
    for (std::size_t length : lengths) {
      auto squarer = RightAngleSquarer::create(length, simd);
      if (!squarer) continue;  // below 4 vectors of points
      ++tried;
      EXPECT_LT(worst_error(*squarer, 16, static_cast<std::uint32_t>(length)), 0.01)
          << "length " << length << ", " << squarer->lanes() << " lanes";
    }
  EXPECT_GE(tried, 20);
}

TEST(RightAngleSquarer, RefusesLengthsItCannotPlan) {
  for (std::size_t length : {0, 2, 10, 80, 100, 112, 4095, 3584, 17280})
    EXPECT_EQ(RightAngleSquarer::create(length), nullptr) << length;
}

}  // namespace
