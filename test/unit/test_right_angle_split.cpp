/// @file test_right_angle_split.cpp
/// @brief RightAngleSquarer's split interface (forward_in_place,
/// inverse_in_place, multiply_pointwise, multiply_in_place) against exact
/// integer products (schoolbook in 64-bit integers) of random digits, the
/// negacyclic product modulo X^L + 1 and the acyclic one, on each SIMD
/// width this CPU has (AVX2 forced on an AVX-512 machine too); and the
/// split square against the fused square_in_place.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "primes/right_angle_transform.hpp"
#include "simd_widths.hpp"

namespace right_angle_split_test {

using tk::primes::RightAngleSquarer;
using Digits = std::vector<std::int64_t>;

// x * y modulo X^L + 1, L = x.size() = y.size().
Digits exact_negacyclic(const Digits& x, const Digits& y) {
  const std::size_t length = x.size();
  Digits z(length, 0);
  for (std::size_t i = 0; i < length; ++i)
    for (std::size_t j = 0; j < length; ++j) {
      const std::size_t k = i + j;
      if (k < length) z[k] += x[i] * y[j];
      else z[k - length] -= x[i] * y[j];
    }
  return z;
}

Digits random_digits(std::size_t length, std::size_t used, int bits, std::mt19937_64& random) {
  std::uniform_int_distribution<std::int64_t> digit(-(std::int64_t{1} << (bits - 1)),
                                                    (std::int64_t{1} << (bits - 1)) - 1);
  Digits x(length, 0);
  for (std::size_t j = 0; j < used; ++j) x[j] = digit(random);
  return x;
}

// c_j = (x_j + i x_(j+N)) theta^j into the transform's arrays.
void weight(RightAngleSquarer& t, const Digits& x) {
  const std::size_t n = t.points();
  for (std::size_t j = 0; j < n; ++j) {
    const double a = static_cast<double>(x[j]), b = static_cast<double>(x[j + n]);
    t.real()[j] = a * t.theta_cos()[j] - b * t.theta_sin()[j];
    t.imaginary()[j] = a * t.theta_sin()[j] + b * t.theta_cos()[j];
  }
}

// The worst distance of (arrays times theta^-j / N) from z.
double distance(RightAngleSquarer& t, const Digits& z) {
  const std::size_t n = t.points();
  double worst = 0;
  for (std::size_t j = 0; j < n; ++j) {
    const double r = t.real()[j], m = t.imaginary()[j], c = t.theta_cos()[j], s = t.theta_sin()[j];
    const double low = (r * c + m * s) / static_cast<double>(n), high = (m * c - r * s) / static_cast<double>(n);
    worst =
        std::max({worst, std::fabs(low - static_cast<double>(z[j])), std::fabs(high - static_cast<double>(z[j + n]))});
  }
  return worst;
}

using simd_test::widths_here;

// Lengths with radix-3, -2 and -4 passes, and ones (L/2 > 1024) whose
// outer passes run over the whole array.
const std::size_t kLengths[] = {64, 96, 192, 288, 576, 1152, 2304, 3072, 4608};

struct Product {
  std::unique_ptr<RightAngleSquarer> t;
  std::vector<double> spectrum_re, spectrum_im;
};

// y's spectrum kept, then x weighted into the arrays.
Product prepare(std::size_t length, RightAngleSquarer::Simd simd, const Digits& x, const Digits& y) {
  Product p{RightAngleSquarer::create(length, simd), {}, {}};
  if (!p.t) return p;
  weight(*p.t, y);
  p.t->forward_in_place();
  p.spectrum_re.assign(p.t->real(), p.t->real() + p.t->points());
  p.spectrum_im.assign(p.t->imaginary(), p.t->imaginary() + p.t->points());
  weight(*p.t, x);
  return p;
}

TEST(RightAngleSplit, NegacyclicProductsFusedAndSplitOnEveryWidth) {
  const auto widths = widths_here();
  if (widths.empty()) GTEST_SKIP() << "no AVX2 with FMA on this CPU";
  std::mt19937_64 random(23);
  int tried = 0;
  for (auto simd : widths)
    for (std::size_t length : kLengths) {
      const Digits x = random_digits(length, length, 12, random), y = random_digits(length, length, 12, random);
      const Digits z = exact_negacyclic(x, y);
      for (bool fused : {true, false}) {
        Product p = prepare(length, simd, x, y);
        if (!p.t) continue;
        ++tried;
        if (fused) {
          p.t->multiply_in_place(p.spectrum_re.data(), p.spectrum_im.data());
        } else {
          p.t->forward_in_place();
          p.t->multiply_pointwise(p.spectrum_re.data(), p.spectrum_im.data());
          p.t->inverse_in_place();
        }
        EXPECT_LT(distance(*p.t, z), 0.01)
            << "length " << length << ", " << p.t->lanes() << " lanes, " << (fused ? "fused" : "split");
      }
    }
  EXPECT_GE(tried, 2 * 16);
}

// Inputs in the lower half: the negacyclic product is the acyclic one.
TEST(RightAngleSplit, AcyclicProductOfLowerHalves) {
  const auto widths = widths_here();
  if (widths.empty()) GTEST_SKIP() << "no AVX2 with FMA on this CPU";
  std::mt19937_64 random(24);
  for (auto simd : widths) {
    const std::size_t length = 1152;
    const Digits x = random_digits(length, length / 2, 18, random), y = random_digits(length, length / 2, 18, random);
    Product p = prepare(length, simd, x, y);
    ASSERT_TRUE(p.t);
    p.t->multiply_in_place(p.spectrum_re.data(), p.spectrum_im.data());
    Digits z(length, 0);
    for (std::size_t i = 0; i < length / 2; ++i)
      for (std::size_t j = 0; j < length / 2; ++j) z[i + j] += x[i] * y[j];
    EXPECT_LT(distance(*p.t, z), 0.05) << p.t->lanes() << " lanes";
  }
}

TEST(RightAngleSplit, ForwardSquareInverseIsTheFusedSquare) {
  const auto widths = widths_here();
  if (widths.empty()) GTEST_SKIP() << "no AVX2 with FMA on this CPU";
  std::mt19937_64 random(25);
  for (auto simd : widths)
    for (std::size_t length : kLengths) {
      const Digits x = random_digits(length, length, 12, random);
      auto split = RightAngleSquarer::create(length, simd), fused = RightAngleSquarer::create(length, simd);
      if (!split) continue;
      weight(*split, x);
      weight(*fused, x);
      fused->square_in_place();
      split->forward_in_place();
      for (std::size_t j = 0; j < split->points(); ++j) {
        const double r = split->real()[j], m = split->imaginary()[j];
        split->real()[j] = r * r - m * m;
        split->imaginary()[j] = 2 * r * m;
      }
      split->inverse_in_place();
      const Digits z = exact_negacyclic(x, x);
      EXPECT_LT(distance(*split, z), 0.01) << length;
      EXPECT_LT(distance(*fused, z), 0.01) << length;
    }
}

}  // namespace right_angle_split_test
