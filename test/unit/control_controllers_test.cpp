/// @file control_controllers_test.cpp
/// @brief The four controllers: the sliding-mode switching sign (with the
/// + sign the sliding variable reaches zero at the rate Λ/m and stays in a
/// band of width ~Λ T/m; with the seed's − sign it runs away at Λ/m); the
/// PID default gains put the nominal closed loop's poles at a triple pole
/// (the characteristic polynomial and its first two derivatives vanish
/// there, and the sampled loop follows the closed-form triple-pole
/// response); the laws by hand; validation of gains and configurations.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "control/feed_controllers.hpp"
#include "control/feed_drive_sim.hpp"
#include "feed_drive_run.hpp"
#include "io/error.hpp"

using tk::test::run_feed_drive;

namespace {

using namespace tk::control;

/// The smooth loop: exact model (m̂ = m, b̂ = b), no encoder, no filters, no
/// cut, no spectrum; the axis starts `offset_mm` off the reference.
FeedDriveConfig smooth_config(ControllerKind kind, double offset_mm) {
  FeedDriveConfig c;
  c.gains.kind = kind;
  c.mass_estimate_kg = c.plant.mass_kg, c.damping_estimate_kg_s = c.plant.damping_kg_s;
  c.encoder_mm = 0, c.position_filter_hz = 0, c.velocity_filter_hz = 0;
  c.cut.enabled = false;
  c.hf_cutoff_hz = 0;
  c.initial_position_mm = offset_mm;  // the sine starts at 0
  return c;
}

/// m Ṡ = (model error) + F_d − sw Λ sign(S); with the exact model and no cut
/// the surface moves at exactly ∓Λ/m. S0 = μ e0 = 2 · (−0.1) = −0.2 mm/s.
TEST(FeedController, SwitchingSignPlusConvergesMinusDiverges) {
  FeedDriveConfig c = smooth_config(ControllerKind::smc, 0.1);
  c.gains.switching = 400;  // kg·mm/s²: Λ/m = 40 mm/s², reaching time 0.2/40 = 5 ms
  c.duration_s = 0.3;
  const double rate = c.gains.switching / c.plant.mass_kg, band = c.gains.switching * c.period_s / c.plant.mass_kg;

  const std::vector<FeedDriveSample> good = run_feed_drive(c);
  EXPECT_NEAR(good.front().surface_mm_s, -0.2, 1e-12);
  double worst_after_reaching = 0;
  for (const FeedDriveSample& s : good)
    if (s.t_s > 0.006) worst_after_reaching = std::max(worst_after_reaching, std::abs(s.surface_mm_s));
  EXPECT_LT(worst_after_reaching, 2 * band) << "with +Λ sign(S) the surface stays in the chattering band";
  // Halfway to the reaching time, S has covered about half the way.
  const FeedDriveSample& halfway = good.at(25);  // t = 25 T = 2.5 ms
  EXPECT_NEAR(halfway.surface_mm_s, -0.2 + rate * halfway.t_s, 0.01);

  c.gains.switching_sign = -1;
  const std::vector<FeedDriveSample> bad = run_feed_drive(c);
  // |S| grows like |S0| + (Λ/m) t: at 0.29 s about 11.8 mm/s.
  const FeedDriveSample& last = bad.back();
  EXPECT_NEAR(last.surface_mm_s, -0.2 - rate * last.t_s, 0.05 * rate * last.t_s);
  EXPECT_GT(std::abs(last.error_mm), 1) << "and the error with it";
  // The summary says so too.
  c.duration_s = 3, c.divergence_mm = 10;
  const FeedDriveSummary diverged = simulate_feed_drive(c);
  EXPECT_TRUE(diverged.diverged);
  EXPECT_GT(diverged.diverged_at_s, 0.3);
  c.gains.switching_sign = +1;
  EXPECT_FALSE(simulate_feed_drive(c).diverged);
}

/// The super-twisting law shares the surface and the sign convention.
TEST(FeedController, SuperTwistingConvergesWithPlusSign) {
  FeedDriveConfig c = smooth_config(ControllerKind::sta, 0.1);
  c.duration_s = 0.3;
  const std::vector<FeedDriveSample> good = run_feed_drive(c);
  double worst = 0;
  for (const FeedDriveSample& s : good)
    if (s.t_s > 0.1) worst = std::max(worst, std::abs(s.surface_mm_s));
  EXPECT_LT(worst, 0.01);
  c.gains.switching_sign = -1;
  const std::vector<FeedDriveSample> bad = run_feed_drive(c);
  EXPECT_GT(std::abs(bad.back().surface_mm_s), 1);
}

/// p(s) = m̂ s³ + (b̂ + k_d) s² + k_p s + k_i, from m̂ ẍ + b̂ ẋ = k_p e + k_i ∫e + k_d ė
/// with e = −x, differentiated once. A triple root at −ω: p, p', p'' vanish.
TEST(FeedController, PidDefaultGainsGiveATriplePole) {
  for (const double bandwidth : {5.0, 20.0, 80.0}) {
    ControllerGains g;
    g.kind = ControllerKind::pid, g.pid_bandwidth_hz = bandwidth;
    const double m = 7, b = 200;
    const FeedController pid(g, m, b, 1e-4);
    const double w = 2 * std::numbers::pi * bandwidth, s = -w;
    const double c3 = m, c2 = b + pid.kd(), c1 = pid.kp(), c0 = pid.ki();
    const double p = ((c3 * s + c2) * s + c1) * s + c0, dp = (3 * c3 * s + 2 * c2) * s + c1, ddp = 6 * c3 * s + 2 * c2;
    // Scale: the size of the terms, m ω³ (p), m ω² (p'), m ω (p'').
    EXPECT_NEAR(p / (m * w * w * w), 0, 1e-12) << bandwidth;
    EXPECT_NEAR(dp / (m * w * w), 0, 1e-12) << bandwidth;
    EXPECT_NEAR(ddp / (m * w), 0, 1e-12) << bandwidth;
    EXPECT_GE(pid.kd(), 0);
    // Explicit gains are taken as given.
    g.kp = 1, g.ki = 2, g.kd = 3;
    const FeedController fixed(g, m, b, 1e-4);
    EXPECT_EQ(fixed.kp(), 1);
    EXPECT_EQ(fixed.ki(), 2);
    EXPECT_EQ(fixed.kd(), 3);
  }
}

/// With x_ref ≡ 0, x(0) = x0, ẋ(0) = 0 and the triple pole at −ω, the loop's
/// integral q = ∫x solves (D + ω)³ q = 0 with q(0) = 0, q'(0) = x0, q''(0) = 0:
/// q = (x0 t + ω x0 t²) e^{−ωt}, so x = q' = x0 (1 + ωt − ω² t²) e^{−ωt}.
/// The sampled loop (T = 2 µs, ωT = 2.5e-4) follows it to O(ωT).
TEST(FeedController, PidSampledLoopFollowsTheTriplePoleResponse) {
  FeedDriveConfig c = smooth_config(ControllerKind::pid, 1);
  c.plant.mass_kg = c.mass_estimate_kg = 7, c.plant.damping_kg_s = c.damping_estimate_kg_s = 200;
  c.reference = Reference::step(0, 0);
  c.initial_velocity_mm_s = 0;
  c.period_s = 2e-6, c.substeps = 1, c.duration_s = 0.06;
  const double w = 2 * std::numbers::pi * c.gains.pid_bandwidth_hz;
  double worst = 0;
  for (const FeedDriveSample& s : run_feed_drive(c)) {
    const double want = (1 + w * s.t_s - w * w * s.t_s * s.t_s) * std::exp(-w * s.t_s);
    worst = std::max(worst, std::abs(s.x_mm - want));
  }
  EXPECT_LT(worst, 4 * w * c.period_s);
  EXPECT_GT(worst, 1e-9) << "a sampled loop cannot be exact";
}

/// Without switching (Λ = 0) and with x_ref ≡ 0, x(0) = x0, ẋ(0) = 0, the two
/// equivalent controls give linear loops (smcsim(1), CONTROLLERS):
///   F_eq    = m̂ (μ ė + λ e) + b̂ ẋ:   m ẍ + (b − b̂ + m̂ μ) ẋ + m̂ λ x = 0,
///   printed = m̂ λ e:                  m ẍ + b ẋ + m̂ λ x = 0,
/// so x = x0 (r2 e^{r1 t} − r1 e^{r2 t}) / (r2 − r1) with the roots r1, r2.
/// With the exact model F_eq's loop is the surface's s² + μ s + λ (eq. 5's
/// Ṡ = 0), the printed one's s² + (b/m) s + λ: they agree only at μ = b/m.
TEST(FeedController, EquivalentControlsGiveTheirCharacteristicPolynomials) {
  struct Case {
    double m_hat, b_hat;
    bool printed;
  };
  for (const Case k : {Case{10, 250, false}, Case{10, 250, true}, Case{7, 200, false}, Case{7, 200, true}}) {
    FeedDriveConfig c = smooth_config(ControllerKind::smc, 1);
    c.mass_estimate_kg = k.m_hat, c.damping_estimate_kg_s = k.b_hat;
    c.gains.switching = 0, c.gains.printed_bracket = k.printed;
    c.reference = Reference::step(0, 0);
    c.initial_velocity_mm_s = 0;
    c.period_s = 1e-5, c.substeps = 1, c.duration_s = 2;
    const double m = c.plant.mass_kg, b = c.plant.damping_kg_s, mu = c.gains.mu, lambda = c.gains.lambda;
    const double damping = k.printed ? b : b - k.b_hat + k.m_hat * mu;
    const double disc = std::sqrt(damping * damping - 4 * m * k.m_hat * lambda);
    const double r1 = (-damping + disc) / (2 * m), r2 = (-damping - disc) / (2 * m);
    double worst = 0;
    const std::vector<FeedDriveSample> samples = run_feed_drive(c);
    for (const FeedDriveSample& s : samples) {
      const double want = disc > 0 ? (r2 * std::exp(r1 * s.t_s) - r1 * std::exp(r2 * s.t_s)) / (r2 - r1)
                                   : (1 - r1 * s.t_s) * std::exp(r1 * s.t_s);  // the double root
      worst = std::max(worst, std::abs(s.x_mm - want));
    }
    EXPECT_LT(worst, 1e-4) << k.m_hat << " " << k.printed;  // O(T) of the fast root: 25/s · 1e-5 s
    if (k.m_hat == 10 && !k.printed) {
      EXPECT_EQ(r1, -1);  // s² + 2s + 1
    }
    // The printed law's slow root, about −m̂λ/b, keeps over 90 % of the offset at 2 s.
    if (k.printed) {
      EXPECT_GT(samples.back().x_mm, 0.9);
    } else {
      EXPECT_LT(samples.back().x_mm, 0.85);
    }
  }
}

TEST(FeedController, LawsByHand) {
  ControlInput in{};
  in.x_ref = 1, in.v_ref = 2, in.a_ref = 3, in.x = 0.5, in.v = 1.5;
  in.error = 0.5, in.error_rate = 0.5, in.error_integral = 0.25, in.surface = -0.7;
  ControllerGains g;  // smc: μ 2, λ 1, Λ 40
  FeedController smc(g, 7, 200, 1e-4);
  // 7 (3 + 2·0.5 + 1·0.5) + 200·1.5 + 40·sign(−0.7) = 31.5 + 300 − 40
  EXPECT_DOUBLE_EQ(smc.force(in), 291.5);
  g.boundary_layer = 1.4;  // sat(−0.7/1.4) = −0.5
  EXPECT_DOUBLE_EQ(FeedController(g, 7, 200, 1e-4).force(in), 331.5 - 20);
  g.printed_bracket = true;  // 7 (3 + (200/7)·2 + 1·0.5) − 20: 24.5 + 400 − 20
  EXPECT_NEAR(FeedController(g, 7, 200, 1e-4).force(in), 404.5, 1e-12);
  g.boundary_layer = 0, g.switching_sign = -1;  // and the seed's sign: + 40
  EXPECT_NEAR(FeedController(g, 7, 200, 1e-4).force(in), 464.5, 1e-12);
  g = ControllerGains{};
  g.kind = ControllerKind::sta;  // α 200, β 200: 331.5 + 200·√0.7·(−1) + w, then w −= 1e-4·200
  FeedController sta(g, 7, 200, 1e-4);
  EXPECT_NEAR(sta.force(in), 331.5 - 200 * std::sqrt(0.7), 1e-12);
  EXPECT_NEAR(sta.force(in), 331.5 - 200 * std::sqrt(0.7) - 0.02, 1e-12);
  g.printed_bracket = true;  // the same switching on 424.5
  FeedController sta_printed(g, 7, 200, 1e-4);
  EXPECT_NEAR(sta_printed.force(in), 424.5 - 200 * std::sqrt(0.7), 1e-12);
  g = ControllerGains{};
  g.kind = ControllerKind::pid, g.kp = 10, g.ki = 100, g.kd = 4, g.pid_feedforward = 0.5;
  // 0.5 (7·3 + 200·2) + 10·0.5 + 100·0.25 + 4·0.5
  EXPECT_DOUBLE_EQ(FeedController(g, 7, 200, 1e-4).force(in), 210.5 + 5 + 25 + 2);
  g = ControllerGains{};
  g.kind = ControllerKind::ppd, g.position_gain = 30, g.velocity_p = 50, g.velocity_d = 0.1, g.velocity_feedforward = 1;
  FeedController ppd(g, 7, 200, 1e-4);
  // velocity command 2 + 30·0.5 = 17, error 15.5: 50·15.5 (no derivative the first time)
  EXPECT_DOUBLE_EQ(ppd.force(in), 775);
  in.v = 1.4;  // error 15.6: + 0.1 · 0.1/1e-4
  EXPECT_NEAR(ppd.force(in), 780 + 100, 1e-9);
}

TEST(FeedController, RejectsBadGains) {
  const auto throws = [](auto change) {
    ControllerGains g;
    change(g);
    EXPECT_THROW(g.validate(), tk::Error);
    EXPECT_THROW(FeedController(g, 7, 200, 1e-4), tk::Error);
  };
  throws([](ControllerGains& g) { g.mu = NAN; });
  throws([](ControllerGains& g) { g.lambda = -1; });
  throws([](ControllerGains& g) { g.switching = INFINITY; });
  throws([](ControllerGains& g) { g.boundary_layer = -0.1; });
  throws([](ControllerGains& g) { g.alpha = NAN; });
  throws([](ControllerGains& g) { g.beta = -2; });
  throws([](ControllerGains& g) { g.kp = NAN; });
  throws([](ControllerGains& g) { g.ki = INFINITY; });
  throws([](ControllerGains& g) { g.kd = NAN; });
  throws([](ControllerGains& g) { g.pid_bandwidth_hz = 0; });
  throws([](ControllerGains& g) { g.pid_bandwidth_hz = NAN; });
  throws([](ControllerGains& g) { g.velocity_bandwidth_hz = -1; });
  throws([](ControllerGains& g) { g.velocity_feedforward = 1.5; });
  throws([](ControllerGains& g) { g.pid_feedforward = NAN; });
  throws([](ControllerGains& g) { g.velocity_d = -1; });
  EXPECT_THROW(parse_controller_kind("lqr"), tk::Error);
  for (const char* name : {"smc", "sta", "pid", "ppd"})
    EXPECT_STREQ(controller_name(parse_controller_kind(name)), name);
}

TEST(FeedDriveConfig, RejectsImpossibleRuns) {
  const auto throws = [](auto change) {
    FeedDriveConfig c;
    change(c);
    EXPECT_THROW(c.validate(), tk::Error);
    EXPECT_THROW(simulate_feed_drive(c), tk::Error);
  };
  throws([](FeedDriveConfig& c) { c.plant.mass_kg = -10; });
  throws([](FeedDriveConfig& c) { c.plant.mass_kg = 0; });
  throws([](FeedDriveConfig& c) { c.plant.damping_kg_s = NAN; });
  throws([](FeedDriveConfig& c) { c.plant.mass_end_kg = NAN; });
  throws([](FeedDriveConfig& c) { c.plant.mass_end_kg = 0; });
  throws([](FeedDriveConfig& c) { c.mass_estimate_kg = 0; });
  throws([](FeedDriveConfig& c) { c.period_s = 0; });
  throws([](FeedDriveConfig& c) { c.period_s = NAN; });
  throws([](FeedDriveConfig& c) { c.duration_s = -1; });
  throws([](FeedDriveConfig& c) { c.substeps = 0; });
  throws([](FeedDriveConfig& c) { c.encoder_mm = -1e-5; });
  throws([](FeedDriveConfig& c) { c.velocity_filter_hz = INFINITY; });
  throws([](FeedDriveConfig& c) { c.voltage_limit_v = 0; });
  throws([](FeedDriveConfig& c) { c.settle_s = c.duration_s; });
  throws([](FeedDriveConfig& c) { c.initial_position_mm = INFINITY; });
  throws([](FeedDriveConfig& c) { c.duration_s = 1e7, c.period_s = 1e-4; });
  throws([](FeedDriveConfig& c) { c.gains.kp = NAN; });
  throws([](FeedDriveConfig& c) { c.cut.teeth = 0; });
  EXPECT_NO_THROW(FeedDriveConfig{}.validate());
}

}  // namespace
