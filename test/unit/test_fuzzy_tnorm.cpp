/// @file test_fuzzy_tnorm.cpp
/// @brief The six t-norms at hand-computed points, their n-ary forms
/// against folding the binary ones (and the paper's three-input Hamacher
/// formula), the t-norm axioms on a grid, and the membership functions.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "fuzzy/engine.hpp"
#include "fuzzy/membership.hpp"
#include "fuzzy/tnorm.hpp"

namespace {

using tk::fuzzy::TNorm;

constexpr std::array<TNorm, 6> kAll{TNorm::minimum,     TNorm::product,       TNorm::drastic,
                                    TNorm::lukasiewicz, TNorm::trigonometric, TNorm::hamacher};

TEST(TNorm, HandComputedAtPoint7Point4) {
  // sin(0.35 pi) sin(0.2 pi) = 0.8910065 x 0.5877853 = 0.5237205; 2/pi asin of it = 0.3509127.
  EXPECT_DOUBLE_EQ(tk::fuzzy::tnorm(TNorm::minimum, 0.7, 0.4), 0.4);
  EXPECT_NEAR(tk::fuzzy::tnorm(TNorm::product, 0.7, 0.4), 0.28, 1e-15);
  EXPECT_NEAR(tk::fuzzy::tnorm(TNorm::lukasiewicz, 0.7, 0.4), 0.1, 1e-15);
  EXPECT_EQ(tk::fuzzy::tnorm(TNorm::drastic, 0.7, 0.4), 0);
  EXPECT_NEAR(tk::fuzzy::tnorm(TNorm::hamacher, 0.7, 0.4), 0.28 / 0.82, 1e-15);  // 0.341463
  EXPECT_NEAR(tk::fuzzy::tnorm(TNorm::trigonometric, 0.7, 0.4), 0.3509127, 1e-7);
}

TEST(TNorm, NamesRoundTrip) {
  for (TNorm t : kAll) EXPECT_EQ(tk::fuzzy::tnorm_from_name(tk::fuzzy::tnorm_name(t)), t);
  EXPECT_FALSE(tk::fuzzy::tnorm_from_name("maximum"));
}

TEST(TNorm, NaryEqualsFoldedBinary) {
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> unit(0, 1);
  for (int trial = 0; trial < 2000; ++trial) {
    std::vector<double> mu(1 + trial % 5);
    for (double& m : mu) {
      const double r = unit(random);
      m = r < 0.1 ? 0 : r < 0.25 ? 1 : unit(random);  // the ends, where the forms have their cases
    }
    for (TNorm t : kAll) {
      double folded = mu[0];
      for (std::size_t i = 1; i < mu.size(); ++i) folded = tk::fuzzy::tnorm(t, folded, mu[i]);
      EXPECT_NEAR(tk::fuzzy::tnorm(t, mu), folded, 1e-12) << tk::fuzzy::tnorm_name(t) << " trial " << trial;
    }
  }
}

TEST(TNorm, HamacherMatchesThePapersThreeInputFormula) {
  std::mt19937_64 random(12);
  std::uniform_real_distribution<double> unit(0, 1);
  for (int trial = 0; trial < 1000; ++trial) {
    const double a = unit(random), b = unit(random), c = unit(random);
    const double paper = a * b * c / (a * b + a * c + b * c - 2 * a * b * c);
    const std::array<double, 3> mu{a, b, c};
    EXPECT_NEAR(tk::fuzzy::tnorm(TNorm::hamacher, mu), paper, 1e-12);
  }
  // The paper's denominator vanishes with two zeros: 0 there, as with one.
  const std::array<double, 3> zeros{0, 0, 0.5}, one_zero{0, 0.3, 0.5};
  EXPECT_EQ(tk::fuzzy::tnorm(TNorm::hamacher, zeros), 0);
  EXPECT_EQ(tk::fuzzy::tnorm(TNorm::hamacher, one_zero), 0);
}

TEST(TNorm, AxiomsOnAGrid) {
  // Boundary T(a, 1) = a, commutativity, monotonicity, and drastic <= T <= minimum.
  for (TNorm t : kAll) {
    for (int i = 0; i <= 20; ++i) {
      const double a = i / 20.0;
      EXPECT_NEAR(tk::fuzzy::tnorm(t, a, 1), a, 1e-12) << tk::fuzzy::tnorm_name(t);
      EXPECT_NEAR(tk::fuzzy::tnorm(t, 1, a), a, 1e-12) << tk::fuzzy::tnorm_name(t);
      EXPECT_NEAR(tk::fuzzy::tnorm(t, a, 0), 0, 1e-12) << tk::fuzzy::tnorm_name(t);
      for (int j = 0; j <= 20; ++j) {
        const double b = j / 20.0;
        const double v = tk::fuzzy::tnorm(t, a, b);
        EXPECT_NEAR(v, tk::fuzzy::tnorm(t, b, a), 1e-12);
        EXPECT_LE(v, std::min(a, b) + 1e-12);
        EXPECT_GE(v, tk::fuzzy::tnorm(TNorm::drastic, a, b) - 1e-12);
        if (j > 0) {
          EXPECT_GE(v + 1e-12, tk::fuzzy::tnorm(t, a, (j - 1) / 20.0)) << tk::fuzzy::tnorm_name(t);
        }
      }
    }
  }
}

TEST(Membership, TrapezoidAndTriangle) {
  // The paper's 10-bit LIGHT {-1, 0, 100, 700} and DARK {100, 700, 1024, 1025}.
  const tk::fuzzy::Trapezoid light{-1, 0, 100, 700}, dark{100, 700, 1024, 1025};
  EXPECT_EQ(light(0), 1);
  EXPECT_EQ(light(100), 1);
  EXPECT_DOUBLE_EQ(light(400), 0.5);
  EXPECT_EQ(light(700), 0);
  EXPECT_DOUBLE_EQ(dark(400), 0.5);
  EXPECT_EQ(dark(1024), 1);
  EXPECT_EQ(dark(1025), 0);
  EXPECT_EQ(dark(99), 0);
  // Vertical edges are steps.
  const tk::fuzzy::Trapezoid step{0, 0, 5, 5};
  EXPECT_EQ(step(0), 1);
  EXPECT_EQ(step(5), 1);
  EXPECT_EQ(step(5.0001), 0);
  EXPECT_EQ(step(-0.0001), 0);
  const tk::fuzzy::Term tri = tk::fuzzy::Term::triangle("T", 0, 2, 6);
  EXPECT_DOUBLE_EQ(tri.membership(1), 0.5);
  EXPECT_EQ(tri.membership(2), 1);
  EXPECT_DOUBLE_EQ(tri.membership(5), 0.25);
  EXPECT_EQ(tri.membership(6), 0);
  EXPECT_TRUE(std::isnan(tri.membership(NAN)));
}

}  // namespace
