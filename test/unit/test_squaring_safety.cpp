/// @file test_squaring_safety.cpp
/// @brief The safety net both FFT squarers share (FftSquaring, the padded
/// FFT, and WeightedSquaring): digits too wide to round correctly must be
/// caught and redone by GMP, never give a wrong square.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include "primes/fft_squaring.hpp"
#include "primes/weighted_squaring.hpp"
#include "squaring_chain.hpp"

namespace {

using namespace tk::primes;
using squaring_test::expect_chain_matches;
using squaring_test::value_of;

template <class Squarer>
class SquaringSafety : public ::testing::Test {};
using Squarers = ::testing::Types<FftSquaring, WeightedSquaring>;
TYPED_TEST_SUITE(SquaringSafety, Squarers);

TYPED_TEST(SquaringSafety, DigitsTooWideAreCaughtAndRedoneByGmp) {
  // 30-bit digits at length 4096: coefficients near 2^67, far past a
  // double's 53 bits, so nearly every square rounds wrongly. Every one must
  // be caught and redone, and the chain must still equal GMP's.
  const SpecialForm form{778965587811ull, 40000, -1};
  auto squarer = TypeParam::create_with(form, 4096, 30);
  ASSERT_NE(squarer, nullptr);
  gmp_randclass random(gmp_randinit_default);
  random.seed(11);
  expect_chain_matches(*squarer, form, random.get_z_range(value_of(form)), 2, 10);
  EXPECT_EQ(squarer->fallbacks(), 10u);
}

TYPED_TEST(SquaringSafety, BorderlineDigitsStillNeverGiveAWrongSquare) {
  // 23-bit digits at length 8192: errors near 0.5, some squares caught and
  // some (correctly) kept; whatever the split, the values must be GMP's.
  const SpecialForm form{3, 90000, 1};
  auto squarer = TypeParam::create_with(form, 8192, 23);
  ASSERT_NE(squarer, nullptr);
  gmp_randclass random(gmp_randinit_default);
  random.seed(12);
  expect_chain_matches(*squarer, form, random.get_z_range(value_of(form)), 0, 30);
}

TYPED_TEST(SquaringSafety, RefusesFormsItCannotReduce) {
  EXPECT_EQ(TypeParam::create(SpecialForm{3, 63, -1}), nullptr);                   // n < 64: GMP's job
  EXPECT_EQ(TypeParam::create(SpecialForm{4, 1000, -1}), nullptr);                 // even k
  EXPECT_EQ(TypeParam::create(SpecialForm{3, 1000, 5}), nullptr);                  // c other than +-1
  EXPECT_EQ(TypeParam::create_with(SpecialForm{3, 10000, -1}, 512, 16), nullptr);  // would not fit the length
}

}  // namespace
