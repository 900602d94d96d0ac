/// @file control_plant_test.cpp
/// @brief The exact feed-drive step against closed forms: the hold weights
/// φ1..φ3 against 90-digit values (Python's decimal, summing the series
/// Σ (−z)^j/(j+k)! to convergence) and against long-double closed forms on
/// both sides of the series/closed-form switch; one step of m v̇ = −b v + w(t)
/// against the analytic solution for constant and linear w (and b = 0);
/// ten thousand steps under a constant force against the closed-form
/// trajectory.
#include <gtest/gtest.h>

#include <cmath>

#include "control/drive_plant.hpp"

namespace {

using namespace tk::control;

/// φ_k(z) computed outside this project (Python decimal, 90 digits, the
/// series summed to 1e-80), rounded to 17 significant digits.
struct PhiByHand {
  double z, phi1, phi2, phi3;
};
constexpr PhiByHand kPhi[] = {
    {1e-8, 9.99999995000000030e-01, 4.99999998333333362e-01, 1.66666666250000012e-01},
    {0.001, 9.99500166625008291e-01, 4.99833374991668078e-01, 1.66625008331944630e-01},
    {0.1, 9.51625819640404269e-01, 4.83741803595957309e-01, 1.62581964040426824e-01},
    {0.49, 7.90558379215477447e-01, 4.27431879152086913e-01, 1.48098205812067507e-01},
    {0.5, 7.86938680574733151e-01, 4.26122638850533697e-01, 1.47754722298932606e-01},
    {0.51, 7.83342002328890286e-01, 4.24819603276685664e-01, 1.47412542594733992e-01},
    {1, 6.32120558828557666e-01, 3.67879441171442334e-01, 1.32120558828557666e-01},
    {3, 3.16737643877378683e-01, 2.27754118707540448e-01, 9.07486270974865172e-02},
    {10, 9.99954600070237509e-02, 9.00004539992976249e-02, 4.09999546000702347e-02},
    {40, 2.50000000000000014e-02, 2.43750000000000008e-02, 1.18906250000000002e-02},
};

TEST(HoldWeights, MatchHighPrecisionValues) {
  for (const PhiByHand& p : kPhi) {
    const HoldWeights w = HoldWeights::at(p.z);
    // A few ulps: the series and the closed forms (above 0.5, where they
    // cancel at most one digit) are both good to ~1e-15 relative.
    EXPECT_NEAR(w.phi1, p.phi1, 4e-16 * p.phi1) << "z = " << p.z;
    EXPECT_NEAR(w.phi2, p.phi2, 4e-15 * p.phi2) << "z = " << p.z;
    EXPECT_NEAR(w.phi3, p.phi3, 4e-15 * p.phi3) << "z = " << p.z;
    EXPECT_NEAR(w.decay, std::exp(-p.z), 1e-16) << "z = " << p.z;
  }
  const HoldWeights zero = HoldWeights::at(0);
  EXPECT_EQ(zero.decay, 1);
  EXPECT_DOUBLE_EQ(zero.phi1, 1);
  EXPECT_DOUBLE_EQ(zero.phi2, 0.5);
  EXPECT_DOUBLE_EQ(zero.phi3, 1.0 / 6);
}

/// Closed forms in long double (64-bit mantissa), where the cancellation of
/// 1 − φ1 etc. costs digits only below z ~ 1e-2; checked from 0.02 up, and
/// the recurrences φ_{k+1} = (1/k! − φ_k)/z that define them.
TEST(HoldWeights, MatchLongDoubleClosedFormsAcrossTheSwitch) {
  for (double z = 0.02; z < 60; z *= 1.0137) {
    const long double zl = z;
    const long double p1 = -std::expm1(-zl) / zl, p2 = (1 - p1) / zl, p3 = (0.5L - p2) / zl;
    const HoldWeights w = HoldWeights::at(z);
    ASSERT_NEAR(w.phi1, static_cast<double>(p1), 1e-15 * static_cast<double>(p1)) << "z = " << z;
    ASSERT_NEAR(w.phi2, static_cast<double>(p2), 1e-14 * static_cast<double>(p2)) << "z = " << z;
    ASSERT_NEAR(w.phi3, static_cast<double>(p3), 1e-13 * static_cast<double>(p3)) << "z = " << z;
  }
  // The two branches meet at 0.5 without a jump: the derivative of φ_k is
  // bounded by 1/k!, so φ_k(0.5 ± 1e-12) differ from φ_k(0.5) by < 1e-12.
  const HoldWeights below = HoldWeights::at(std::nextafter(0.5, 0.0)), at = HoldWeights::at(0.5);
  EXPECT_NEAR(below.phi1, at.phi1, 1e-15);
  EXPECT_NEAR(below.phi2, at.phi2, 1e-15);
  EXPECT_NEAR(below.phi3, at.phi3, 1e-15);
}

/// The exact solution of m v̇ = −b v + w0 + s τ over [0, h] from (x0, v0), in
/// long double. With a = b/m, E = e^{−ah}:
///   v = v0 E + (w0/m)(1 − E)/a + (s/m)(h/a − (1 − E)/a²)
///   x = x0 + v0 (1 − E)/a + (w0/(m a))(h − (1 − E)/a) + (s/m)(h²/(2a) − h/a² + (1 − E)/a³)
/// and for b = 0: v = v0 + (w0 h + s h²/2)/m, x = x0 + v0 h + (w0 h²/2 + s h³/6)/m.
AxisState analytic_step(double m, double b, double h, AxisState s0, double w0, double slope) {
  const long double M = m, H = h, W = w0, S = slope, X = s0.x, V = s0.v;
  if (b == 0)
    return {static_cast<double>(X + V * H + (W * H * H / 2 + S * H * H * H / 6) / M),
            static_cast<double>(V + (W * H + S * H * H / 2) / M)};
  const long double a = static_cast<long double>(b) / M, one_minus = -std::expm1(-a * H), E = std::exp(-a * H);
  const long double v = V * E + W / M * one_minus / a + S / M * (H / a - one_minus / (a * a));
  const long double x = X + V * one_minus / a + W / (M * a) * (H - one_minus / a) +
                        S / M * (H * H / (2 * a) - H / (a * a) + one_minus / (a * a * a));
  return {static_cast<double>(x), static_cast<double>(v)};
}

TEST(DrivePlant, OneStepMatchesTheAnalyticSolution) {
  struct Case {
    double m, b, h;
  };
  // a·h = 0.25 (series branch), 2.5 (closed forms), 1e-6, and no damping.
  const Case cases[] = {{10, 250, 1e-3}, {10, 250, 1e-1}, {10, 250, 4e-8}, {7, 0, 0.01}, {0.5, 3, 0.2}};
  for (const Case& c : cases) {
    DrivePlant plant;
    plant.configure(c.m, c.b, c.h);
    const AxisState start{0.3, -2.5};
    // Constant w: force 40, disturbance 15 throughout (w = 25).
    AxisState s = start;
    plant.step(s, 40, 15, 15);
    AxisState want = analytic_step(c.m, c.b, c.h, start, 25, 0);
    const double x_scale = std::abs(want.x - start.x) + 1e-300, v_scale = std::abs(want.v) + std::abs(start.v);
    EXPECT_NEAR(s.x, want.x, 1e-13 * (std::abs(start.x) + x_scale)) << c.m << " " << c.b << " " << c.h;
    EXPECT_NEAR(s.v, want.v, 1e-13 * v_scale) << c.m << " " << c.b << " " << c.h;
    // Linear w: the disturbance goes from −20 to 60 across the step, so
    // w = F − F_d goes from 60 to −20: w0 = 60, slope −80/h.
    s = start;
    plant.step(s, 40, -20, 60);
    want = analytic_step(c.m, c.b, c.h, start, 60, -80 / c.h);
    EXPECT_NEAR(s.x, want.x, 1e-13 * (std::abs(start.x) + std::abs(want.x - start.x)))
        << c.m << " " << c.b << " " << c.h;
    EXPECT_NEAR(s.v, want.v, 1e-13 * (std::abs(want.v) + std::abs(start.v) + 60 * c.h / c.m))
        << c.m << " " << c.b << " " << c.h;
  }
}

/// The linear part of the disturbance on its own, from rest at x = 0: the
/// answer is the ramp response alone, so the x_from_dw and v_from_dw weights
/// (φ3, φ2) are checked without the larger terms masking them.
TEST(DrivePlant, RampDisturbanceAloneFromRest) {
  for (const double h : {0.002, 0.02, 0.3}) {  // a·h = 0.05, 0.5, 7.5
    DrivePlant plant;
    plant.configure(10, 250, h);
    AxisState s{};
    plant.step(s, 0, 0, 1);  // w = −τ/h
    const AxisState want = analytic_step(10, 250, h, {}, 0, -1 / h);
    EXPECT_NEAR(s.x, want.x, 1e-14 * std::abs(want.x)) << h;
    EXPECT_NEAR(s.v, want.v, 1e-14 * std::abs(want.v)) << h;
  }
}

/// Constant force F from (x0, v0): v(t) = v∞ + (v0 − v∞) e^{−at}, v∞ = F/b,
/// x(t) = x0 + v∞ t + (v0 − v∞)(1 − e^{−at})/a; b = 0: x0 + v0 t + F t²/(2m).
TEST(DrivePlant, ManyStepsFollowTheClosedFormTrajectory) {
  const double h = 1e-4, force = 300, x0 = -1.5, v0 = 4;
  for (const double b : {250.0, 0.0}) {
    const double m = 10, a = b / m;
    DrivePlant plant;
    plant.configure(m, b, h);
    AxisState s{x0, v0};
    double max_dev_x = 0, max_dev_v = 0, max_x = 0, max_v = 0;
    for (int n = 1; n <= 10000; ++n) {
      plant.step(s, force, 0, 0);
      const long double t = n * static_cast<long double>(h);
      long double x, v;
      if (b > 0) {
        const long double v_inf = force / static_cast<long double>(b);
        v = v_inf + (v0 - v_inf) * std::exp(-a * t);
        x = x0 + v_inf * t + (v0 - v_inf) * -std::expm1(-a * t) / a;
      } else {
        v = v0 + force * t / m;
        x = x0 + v0 * t + force * t * t / (2 * m);
      }
      max_dev_x = std::max(max_dev_x, static_cast<double>(std::abs(s.x - x)));
      max_dev_v = std::max(max_dev_v, static_cast<double>(std::abs(s.v - v)));
      max_x = std::max(max_x, static_cast<double>(std::abs(x)));
      max_v = std::max(max_v, static_cast<double>(std::abs(v)));
    }
    // 10^4 steps of rounding at ~1e-16 each: well under 1e-11 relative.
    EXPECT_LT(max_dev_x, 1e-11 * max_x) << "b = " << b;
    EXPECT_LT(max_dev_v, 1e-11 * max_v) << "b = " << b;
  }
}

/// Splitting a step must not change the answer: two steps of h/2 with the
/// disturbance's midpoint between them equal one step of h (the model is
/// exact for a linear disturbance).
TEST(DrivePlant, HalvingTheStepIsExactForLinearDisturbance) {
  DrivePlant whole, half;
  whole.configure(10, 250, 0.04);
  half.configure(10, 250, 0.02);
  AxisState a{0.1, 2}, b{0.1, 2};
  whole.step(a, 500, 100, 300);
  half.step(b, 500, 100, 200);
  half.step(b, 500, 200, 300);
  EXPECT_NEAR(a.x, b.x, 1e-15 * std::abs(a.x) + 1e-16);
  EXPECT_NEAR(a.v, b.v, 1e-14 * std::abs(a.v));
}

}  // namespace
