/// @file control_milling_force_test.cpp
/// @brief The feed-direction milling force against the linear edge-force
/// model written out here on its own (long double, tooth by tooth, angles
/// from fmod): slot and up-milling, 1 to 4 teeth, with and without the edge
/// terms; the rotation Stepper against at() over 10^5 steps; the mean over a
/// revolution against Altintas's closed-form average; the tooth-passing
/// period; validation.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "control/milling_force.hpp"
#include "io/error.hpp"

namespace {

using namespace tk::control;

constexpr long double kPi = std::numbers::pi_v<long double>;

/// F_d = −Σ_j F_x,j, F_x = −F_t cos φ − F_r sin φ, F_t = a (K_tc f_z sin φ + K_te),
/// F_r = a (K_rc f_z sin φ + K_re), for each tooth j whose angle
/// φ_j = Ω t + 2π j / N (mod 2π) lies in [0, φ_exit], φ_exit = acos(1 − 2 a_e / D).
double brute_force(const MillingCut& c, double t) {
  if (!c.enabled) return 0;
  const long double omega = c.spindle_rpm / 60.0L * 2 * kPi;
  const long double fz = c.feed_mm_min / (static_cast<long double>(c.spindle_rpm) * c.teeth);
  const long double ae = c.radial_depth_mm < 0 ? c.diameter_mm : c.radial_depth_mm;
  const long double exit = std::acos(1 - 2 * ae / c.diameter_mm);
  long double fd = 0;
  for (int j = 0; j < c.teeth; ++j) {
    const long double phi = std::fmod(omega * t + 2 * kPi * j / c.teeth, 2 * kPi);
    if (phi < 0 || phi > exit) continue;
    const long double h = fz * std::sin(phi);
    const long double ft = c.axial_depth_mm * (c.ktc_n_mm2 * h + c.kte_n_mm);
    const long double fr = c.axial_depth_mm * (c.krc_n_mm2 * h + c.kre_n_mm);
    fd -= -ft * std::cos(phi) - fr * std::sin(phi);
  }
  return static_cast<double>(fd);
}

/// The size of one tooth's force, for relative tolerances.
double scale(const MillingCut& c) {
  return c.axial_depth_mm *
         (std::max(c.ktc_n_mm2, c.krc_n_mm2) * c.feed_per_tooth_mm() + std::max(c.kte_n_mm, c.kre_n_mm));
}

std::vector<MillingCut> cuts() {
  std::vector<MillingCut> out;
  for (int teeth = 1; teeth <= 4; ++teeth)
    for (const double radial : {-1.0, 0.3, 0.45})  // slot, up-milling below and at half the diameter
      for (const bool edge : {false, true}) {
        MillingCut c;
        c.teeth = teeth, c.radial_depth_mm = radial;
        c.feed_mm_min = 50 + 30 * teeth;  // a chip big enough that shear and edge terms compare
        if (edge) c.kte_n_mm = 27.7, c.kre_n_mm = 26.6;
        out.push_back(c);
      }
  return out;
}

TEST(MillingForce, AtMatchesTheFormulaToothByTooth) {
  std::mt19937_64 rng(20240611);
  std::uniform_real_distribution<double> when(0, 0.5);
  for (const MillingCut& c : cuts()) {
    const MillingForce force(c);
    const double tol = 1e-11 * scale(c) * c.teeth;
    int nonzero = 0;
    for (int i = 0; i < 2000; ++i) {
      const double t = when(rng);
      const double want = brute_force(c, t);
      ASSERT_NEAR(force.at(t), want, tol) << "teeth " << c.teeth << " a_e " << c.radial_depth_mm << " t " << t;
      nonzero += want != 0;
    }
    EXPECT_GT(nonzero, 100) << "the cut is engaged some of the time";
  }
  MillingCut off;
  off.enabled = false;
  EXPECT_EQ(MillingForce(off).at(0.0123), 0);
}

TEST(MillingForce, SlotWithTheDefaultCutByHand) {
  // Defaults: 2 teeth, a = 0.9 mm, f_z = 1.08 / (11520 · 2) = 4.6875e-5 mm,
  // shear only. At φ = π/2 for tooth 0 (t = T_rev / 4) tooth 1 is at 3π/2,
  // out of the cut: F_d = F_t cos(π/2) + F_r sin(π/2) = a K_rc f_z.
  const MillingCut c;
  const double t_rev = 60 / c.spindle_rpm;
  EXPECT_NEAR(MillingForce(c).at(t_rev / 4), 0.9 * 168.8 * 4.6875e-5, 1e-15);
  // At φ = π/4: F_d = a f_z sin φ (K_tc cos φ + K_rc sin φ) = a f_z (K_tc + K_rc)/2.
  EXPECT_NEAR(MillingForce(c).at(t_rev / 8), 0.9 * 4.6875e-5 * (767.01 + 168.8) / 2, 1e-15);
}

TEST(MillingForce, StepperFollowsAtOver1e5Steps) {
  for (const MillingCut& c : cuts()) {
    if ((c.teeth != 3 && c.teeth != 2) || c.kte_n_mm == 0) continue;  // with the edge terms (jumps at entry and exit)
    const MillingForce force(c);
    const double h = 1.0137e-6, t0 = 0.0123;  // 10^5 steps: about 23 revolutions
    MillingForce::Stepper stepper(force, h);
    stepper.start(t0);
    double worst = 0;
    for (int i = 0; i <= 100000; ++i) {
      worst = std::max(worst, std::abs(stepper.value() - force.at(t0 + i * h)));
      stepper.advance();
    }
    // The rotation's rounding grows at most like n·ε: 1e5 · 2.2e-16 per unit.
    EXPECT_LT(worst, 1e-10 * scale(c) * c.teeth) << "teeth " << c.teeth << " a_e " << c.radial_depth_mm;
  }
}

/// A step longer than a revolution (Ω h > 2π: a slow control period with
/// one substep) must still land on the right angle.
TEST(MillingForce, StepperHandlesStepsLongerThanARevolution) {
  MillingCut c;
  c.feed_mm_min = 100, c.kte_n_mm = 27.7, c.kre_n_mm = 26.6;
  const MillingForce force(c);
  // Times chosen at least 0.004 π away from a tooth entry or exit, where the
  // edge terms jump (t0 + i h, i < 50; Ω = 384π rad/s).
  const double t0 = 0.00117;
  for (const double h : {0.012345678, 0.0311111, 0.30007}) {  // Ω h = 14.9, 37.5, 362 rad
    MillingForce::Stepper stepper(force, h);
    stepper.start(t0);
    for (int i = 0; i < 50; ++i) {
      ASSERT_NEAR(stepper.value(), force.at(t0 + i * h), 1e-9 * scale(c)) << "h " << h << " step " << i;
      stepper.advance();
    }
  }
}

/// Mean over a revolution (Altintas, Manufacturing Automation, eq. 2.15):
///   F̄_x = (N a f_z / 8π)[K_tc cos 2φ − K_rc (2φ − sin 2φ)]_0^φex + (N a / 2π)[−K_te sin φ + K_re cos φ]_0^φex,
/// F̄_d = −F̄_x. For a slot (φex = π): F̄_d = N a K_rc f_z / 4 + N a K_re / π.
double closed_form_mean(const MillingCut& c) {
  const double n = c.teeth, a = c.axial_depth_mm, fz = c.feed_per_tooth_mm();
  const double ae = c.radial_depth_mm < 0 ? c.diameter_mm : c.radial_depth_mm;
  const double ex = std::acos(1 - 2 * ae / c.diameter_mm), pi = std::numbers::pi;
  const auto shear = [&](double p) { return c.ktc_n_mm2 * std::cos(2 * p) - c.krc_n_mm2 * (2 * p - std::sin(2 * p)); };
  const auto edge = [&](double p) { return -c.kte_n_mm * std::sin(p) + c.kre_n_mm * std::cos(p); };
  return -(n * a * fz / (8 * pi) * (shear(ex) - shear(0)) + n * a / (2 * pi) * (edge(ex) - edge(0)));
}

TEST(MillingForce, MeanOverARevolutionIsTheClosedForm) {
  for (const MillingCut& c : cuts()) {
    const MillingForce force(c);
    const double t_rev = 60 / c.spindle_rpm;
    const int m = 50000;
    double sum = 0;
    for (int i = 0; i < m; ++i) sum += force.at((i + 0.5) * t_rev / m);  // midpoint rule
    // The integrand jumps at entry/exit when the edge terms are on (or at an
    // up-milling exit): the midpoint rule's error is then O(jump / m).
    const double tol = 4 * scale(c) * c.teeth / m;
    EXPECT_NEAR(sum / m, closed_form_mean(c), tol) << "teeth " << c.teeth << " a_e " << c.radial_depth_mm;
  }
  // The slot, shear only: N a K_rc f_z / 4 (the tangential part averages to zero).
  MillingCut slot;
  slot.teeth = 3, slot.feed_mm_min = 100;
  EXPECT_NEAR(closed_form_mean(slot), 3 * 0.9 * 168.8 * slot.feed_per_tooth_mm() / 4, 1e-15);
  const MillingForce force(slot);
  double sum = 0;
  const int m = 100000;
  for (int i = 0; i < m; ++i) sum += force.at((i + 0.5) * 60 / slot.spindle_rpm / m);
  EXPECT_NEAR(sum / m, 3 * 0.9 * 168.8 * slot.feed_per_tooth_mm() / 4, 1e-8 * scale(slot));
}

TEST(MillingForce, RepeatsAtTheToothPassingPeriod) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> when(0, 0.05);
  for (const MillingCut& c : cuts()) {
    const MillingForce force(c);
    EXPECT_DOUBLE_EQ(c.tooth_frequency_hz(), c.spindle_rpm / 60 * c.teeth);
    const double period = 1 / c.tooth_frequency_hz();  // 60 / (rpm · N)
    double biggest_difference_at_half = 0;
    for (int i = 0; i < 500; ++i) {
      const double t = when(rng);
      ASSERT_NEAR(force.at(t + period), force.at(t), 1e-11 * scale(c) * c.teeth) << "teeth " << c.teeth << " t " << t;
      biggest_difference_at_half =
          std::max(biggest_difference_at_half, std::abs(force.at(t + period / 2) - force.at(t)));
    }
    // ... and not at half of it: the tooth period is the smallest period
    // (but for the constant force of a four-tooth slot, below).
    if (c.teeth == 4 && c.radial_depth_mm < 0 && c.kte_n_mm == 0) continue;
    EXPECT_GT(biggest_difference_at_half, 0.02 * scale(c)) << "teeth " << c.teeth << " a_e " << c.radial_depth_mm;
  }
}

/// Four teeth in a slot, shear only: two teeth are always in the cut at φ and
/// φ + π/2, and a f_z [K_tc sin φ cos φ + K_rc sin² φ] summed over the pair is
/// a f_z K_rc whatever φ (sin φ cos φ − cos φ sin φ = 0, sin² + cos² = 1).
TEST(MillingForce, FourToothSlotGivesAConstantForce) {
  MillingCut c;
  c.teeth = 4, c.feed_mm_min = 120;
  const MillingForce force(c);
  const double want = c.axial_depth_mm * c.krc_n_mm2 * c.feed_per_tooth_mm();
  for (int i = 0; i < 1000; ++i) ASSERT_NEAR(force.at(i * 1.37e-5), want, 1e-12 * scale(c)) << i;
}

TEST(MillingForce, RejectsImpossibleCuts) {
  const auto throws = [](auto change) {
    MillingCut c;
    change(c);
    EXPECT_THROW(c.validate(), tk::Error);
    EXPECT_THROW(MillingForce{c}, tk::Error);
  };
  throws([](MillingCut& c) { c.teeth = 0; });
  throws([](MillingCut& c) { c.teeth = 65; });
  throws([](MillingCut& c) { c.diameter_mm = 0; });
  throws([](MillingCut& c) { c.diameter_mm = NAN; });
  throws([](MillingCut& c) { c.spindle_rpm = -1; });
  throws([](MillingCut& c) { c.axial_depth_mm = INFINITY; });
  throws([](MillingCut& c) { c.feed_mm_min = -0.1; });
  throws([](MillingCut& c) { c.radial_depth_mm = 0; });
  throws([](MillingCut& c) { c.radial_depth_mm = 0.91; });
  throws([](MillingCut& c) { c.ktc_n_mm2 = NAN; });
  throws([](MillingCut& c) { c.kre_n_mm = -INFINITY; });
  MillingCut fine;
  fine.radial_depth_mm = 0.9, fine.feed_mm_min = 0;
  EXPECT_NO_THROW(fine.validate());
}

}  // namespace
