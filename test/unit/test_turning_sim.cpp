/// @file test_turning_sim.cpp
/// @brief The turning model against closed forms: Kienzle's force at
/// hand-computed points, the load it puts on the drive, the first-order
/// lag's step response 1 - e^(-t/τ), the baseline time L / (f n); and the
/// seed's observations as inequalities on the default simulation: the
/// original law oscillates and shortens the cut, the modified law does not
/// oscillate.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "io/error.hpp"
#include "machining/turning_sim.hpp"

namespace {

using namespace tk::machining;

TEST(TurningModel, KienzleForceByHand) {
  CuttingModel m;
  m.kappa_deg = 90;  // h = f, b = a_p
  m.kc11_n_mm2 = 2000, m.mc = 0;  // m_c = 0: F_c = k_c A = 2000 * 2 * 0.5
  EXPECT_NEAR(kienzle_force_n(m, 2, 0.5), 2000, 1e-9);
  m.kc11_n_mm2 = 1990, m.mc = 0.5;  // h^0.5 = 0.25^0.5 = 0.5: 1990 * 3 * 0.5
  EXPECT_NEAR(kienzle_force_n(m, 3, 0.25), 2985, 1e-9);
  m.kappa_deg = 30;  // sin 30° = 1/2: h = 0.5 * 0.5 = 0.25, b = 1 / 0.5 = 2: 1990 * 2 * 0.5
  EXPECT_NEAR(kienzle_force_n(m, 1, 0.5), 1990, 1e-9);
  // The defaults (E295, κ 95°) at the seed's 0.4 mm/rev and 3 mm:
  // h = 0.4 sin 95° = 0.398478, b = 3 / sin 95° = 3.011460,
  // h^0.74 = exp(0.74 ln 0.398478) = 0.506137: F_c = 1990 * 3.011460 * 0.506137 = 3033.4 N.
  EXPECT_NEAR(kienzle_force_n(CuttingModel{}, 3, 0.4), 3033.4, 0.1);
}

TEST(TurningModel, SpindleLoadIsCuttingPowerOverUsableDrivePower) {
  CuttingModel m;
  m.kappa_deg = 90, m.kc11_n_mm2 = 1990, m.mc = 0.5;
  // F_c 2985 N at 120 m/min = 2 m/s: 5970 W; 0.8 * 9000 W usable: 82.9166... %.
  EXPECT_NEAR(spindle_load_pct(m, 3, 0.25, 120), 100 * 5970.0 / 7200, 1e-9);
}

TEST(TurningModel, LagStepResponseIsOneMinusExp) {
  const double tau = 0.1, step = 0.008;
  FirstOrderLag lag(tau, step);
  lag.reset(0);
  for (int n = 1; n <= 200; ++n) ASSERT_NEAR(lag.update(1), 1 - std::exp(-n * step / tau), 1e-12) << n;
  FirstOrderLag none(0, step);
  none.reset(5);
  EXPECT_DOUBLE_EQ(none.update(7), 7);
}

/// 100 mm at a_p 1 on a diameter of 100/π mm at 60 m/min: n = 10 rev/s; at
/// 0.5 mm/rev the feed rate is 5 mm/s: 20 s.
TurningParams round_numbers() {
  TurningParams p;
  p.profile = {{0, 100, 1}};
  p.diameter_mm = 100 / std::numbers::pi;
  p.cutting_speed_m_min = 60;
  p.feed_mm_rev = 0.5;
  return p;
}

TEST(TurningSim, BaselineTimeIsLengthOverFeedRate) {
  const TurningParams p = round_numbers();
  EXPECT_NEAR(spindle_speed_rev_s(p), 10, 1e-12);
  EXPECT_NEAR(baseline_time_s(p), 20, 1e-12);
  const RunStats run = simulate_turning(p, std::nullopt, 60);
  EXPECT_NEAR(run.time_s, 20, 1e-9);
  EXPECT_EQ(run.cycles, 2500u);  // 20 s / 8 ms
  // The default part: 204 mm at 0.4 mm/rev and n = 170000 / (80 π) / min.
  const TurningParams d;
  const double n = 170000 / (std::numbers::pi * 80) / 60;
  EXPECT_NEAR(baseline_time_s(d), 204 / (0.4 * n), 1e-9);
  EXPECT_NEAR(simulate_turning(d, std::nullopt, 60).time_s, 204 / (0.4 * n), 1e-9);
}

TEST(TurningSim, BaselineOverloadIsTheTimeInTheCollars) {
  // At 100 % the 3 mm collars load the drive above 66 % (1.1 M_z) and the
  // 1 mm stretches do not: the time above is the collars' 24 mm at the
  // baseline feed rate, within a cycle at each of the six steps.
  const TurningParams d;
  const double n = 170000 / (std::numbers::pi * 80) / 60;
  EXPECT_GT(spindle_load_pct(d.cutting, 3, 0.4, 170), 66);
  EXPECT_LT(spindle_load_pct(d.cutting, 1, 0.4, 170), 66);
  const RunStats run = simulate_turning(d, std::nullopt, 60);
  EXPECT_NEAR(run.time_above_mz_s, 24 / (0.4 * n), 6 * d.ipo_s);
}

TEST(TurningSim, SignalFollowsTheLagAcrossAStepInTheAllowance) {
  TurningParams p = round_numbers();
  p.profile = {{0, 10, 1}, {10, 20, 3}};
  p.noise_pct = 0;
  const double low = spindle_load_pct(p.cutting, 1, 0.5, 60), high = spindle_load_pct(p.cutting, 3, 0.5, 60);
  std::vector<TraceSample> samples;
  simulate_turning(p, std::nullopt, 60, [&](const TraceSample& s) { samples.push_back(s); });
  std::size_t first_deep = 0;
  while (samples[first_deep].depth_mm < 2) ++first_deep;
  EXPECT_NEAR(samples[first_deep].z_mm, 10, 5 * 0.008 + 1e-9);  // 5 mm/s x 8 ms a cycle
  for (std::size_t i = first_deep; i < samples.size(); ++i) {
    const double t = static_cast<double>(i - first_deep + 1) * p.ipo_s;
    ASSERT_NEAR(samples[i].load_pct, low + (high - low) * (1 - std::exp(-t / p.lag_s)), 1e-9) << i;
    ASSERT_DOUBLE_EQ(samples[i].load_true_pct, high);
  }
}

TEST(TurningSim, NoiseIsDeterministicPerSeed) {
  TurningParams p;
  FeedOverrideParams law;
  const RunStats a = simulate_turning(p, law, 60), b = simulate_turning(p, law, 60);
  EXPECT_EQ(a.time_s, b.time_s);
  EXPECT_EQ(a.oscillation_pct, b.oscillation_pct);
  p.seed = 2;
  EXPECT_NE(simulate_turning(p, law, 60).time_s, a.time_s);
}

// The seed's observations, from the default model (nothing here is fitted
// to them): the original law oscillates in the 1 mm stretches and cuts
// about 20 % faster than 100 %; k 0.1, p 0.1, d 25 remove the oscillation.
TEST(TurningSim, SeedObservationsComeOutOfTheDefaults) {
  const TurningParams p;
  FeedOverrideParams original, modified;
  modified.variant = OverrideVariant::modified;
  const double baseline = baseline_time_s(p);
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    TurningParams q = p;
    q.seed = seed;
    const RunStats o = simulate_turning(q, original, 60), m = simulate_turning(q, modified, 60);
    EXPECT_GT(o.oscillation_pct, 5) << seed;
    EXPECT_EQ(q.profile[o.oscillation_segment].depth_mm, 1) << seed;  // the seed saw it at 1 mm
    EXPECT_LT(o.time_s / baseline, 0.9) << seed;
    EXPECT_GT(o.time_s / baseline, 0.7) << seed;
    EXPECT_LT(m.oscillation_pct, 1) << seed;
    EXPECT_LT(m.time_s / baseline, 0.9) << seed;
    // Both keep the true load near M_z on average and far from the baseline's overload.
    EXPECT_NEAR(o.mean_load_pct, 60, 3) << seed;
    EXPECT_LT(o.time_above_mz_s, simulate_turning(q, std::nullopt, 60).time_above_mz_s) << seed;
  }
  // Without noise the original law settles: its oscillation is the noise
  // amplified by a lightly damped loop, not a limit cycle.
  TurningParams quiet = p;
  quiet.noise_pct = 0;
  EXPECT_LT(simulate_turning(quiet, original, 60).oscillation_pct, 1);
}

TEST(TurningSim, RejectsBadProfilesAndParameters) {
  EXPECT_THROW(check_profile({}), tk::Error);
  EXPECT_THROW(check_profile({{0, 10, 1}, {11, 20, 1}}), tk::Error);  // a gap
  EXPECT_THROW(check_profile({{0, 10, 1}, {10, 10, 1}}), tk::Error);  // empty
  EXPECT_THROW(check_profile({{0, 10, -1}}), tk::Error);
  EXPECT_NO_THROW(check_profile(default_profile()));
  TurningParams p;
  p.ipo_s = 0;
  EXPECT_THROW(validate(p), tk::UsageError);
  p = {};
  p.cutting.efficiency = 1.5;
  EXPECT_THROW(validate(p), tk::UsageError);
  p = {};
  p.max_cycles = 100;  // the default cut needs about 4,500
  FeedOverrideParams law;
  EXPECT_THROW(simulate_turning(p, law, 60), tk::Error);
}

}  // namespace
