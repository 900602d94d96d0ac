/// @file test_turning_sim.cpp
/// @brief The turning model against closed forms and published figures:
/// Kienzle's force by hand and against Röhm's table of specific cutting
/// forces for St 50-2 (E295); the load on the drive; the first-order lags'
/// step responses (the load signal's 1 - e^(-t/τ), the feed axis's
/// following error v/K_v as Siemens defines K_v); the chip as the travel
/// over one revolution; the baseline time L / (f n).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "io/error.hpp"
#include "machining/turning_sim.hpp"

namespace {

using namespace tk::machining;

TEST(TurningModel, KienzleForceByHand) {
  CuttingModel m;
  m.kappa_deg = 90;               // h = f, b = a_p
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

TEST(TurningModel, E295ConstantsReproduceRoehmsTableForSt50) {
  // Röhm, "RN 1391" clamping-force guide, table 2: specific cutting force
  // k_c of St 50-2 (1.0050) at a setting angle of 45° for feeds s = 0.16,
  // 0.25, 0.4, 0.63, 1.0 and 1.6 mm: 3.50, 3.10, 2.75, 2.45, 2.15, 1.95 kN/mm².
  CuttingModel m;
  m.kappa_deg = 45;
  const double feeds[] = {0.16, 0.25, 0.4, 0.63, 1.0, 1.6};
  const double table[] = {3500, 3100, 2750, 2450, 2150, 1950};
  for (int i = 0; i < 6; ++i) {
    const double kc = kienzle_force_n(m, 1, feeds[i]) / (1 * feeds[i]);  // F_c / (a_p s)
    EXPECT_NEAR(kc / table[i], 1, 0.015) << feeds[i];
  }
}

TEST(TurningModel, SpindleLoadIsCuttingPowerOverUsableDrivePower) {
  CuttingModel m;
  m.kappa_deg = 90, m.kc11_n_mm2 = 1990, m.mc = 0.5;
  // F_c 2985 N at 120 m/min = 2 m/s: 5970 W; 0.8 * 9000 W usable: 82.9166... %.
  EXPECT_NEAR(spindle_load_pct(m, 3, 0.25, 120), 100 * 5970.0 / 7200, 1e-9);
}

TEST(TurningModel, LoadSignalStepResponseIsOneMinusExp) {
  const double tau = 0.04, step = 0.008;
  FirstOrderLag lag(tau, step);
  lag.reset(0);
  for (int n = 1; n <= 100; ++n) ASSERT_NEAR(lag.update(1), 1 - std::exp(-n * step / tau), 1e-12) << n;
  FirstOrderLag none(0, step);
  none.reset(5);
  EXPECT_DOUBLE_EQ(none.update(7), 7);
}

TEST(TurningModel, FeedAxisFollowingErrorIsVelocityOverKv) {
  // Siemens: "with a Kv factor of 1 and a velocity of 1 m/min, the following
  // error will be 1 mm". A start from rest at 1 m/min (1000/60 mm/s):
  // after 50 lags the axis trails the command by v / K_v = 1 mm.
  TurningParams p;
  p.kv = 1;
  EXPECT_NEAR(axis_lag_s(p), 0.06, 1e-15);
  const double v = 1000.0 / 60, T = 0.002;
  FeedAxis axis(axis_lag_s(p), T, 0);
  double z = 0;
  const int steps = 1500;  // 3 s
  for (int i = 0; i < steps; ++i) z += axis.advance(v);
  EXPECT_NEAR(v * steps * T - z, 1.0, 1e-9);
  EXPECT_NEAR(axis.velocity(), v, 1e-9);
  // Position at time t from rest: v (t - τ (1 - e^(-t/τ))), exactly at the steps.
  FeedAxis again(0.06, T, 0);
  z = 0;
  for (int i = 1; i <= 30; ++i) {
    z += again.advance(v);
    const double t = i * T;
    ASSERT_NEAR(z, v * (t - 0.06 * (1 - std::exp(-t / 0.06))), 1e-12) << i;
  }
  // A lag of 10^20 steps (a tiny K_v): the axis keeps its speed, it does not
  // jump to the command.
  FeedAxis sluggish(T * 1e20, T, v);
  EXPECT_NEAR(sluggish.advance(2 * v), v * T, 1e-12 * v * T);
}

TEST(TurningModel, ChipIsTheTravelOverOneRevolution) {
  // 2.5 cycles a revolution, 0.1 mm a cycle before the start: 0.25 mm.
  RevolutionHistory h(2.5, 10, 0.1);
  EXPECT_NEAR(h.travel_over_revolution(), 0.25, 1e-12);
  // The tool stops: the chip thins over one revolution to nothing.
  h.push(10);                                                 // z: ..., 9.8, 9.9, 10, 10
  EXPECT_NEAR(h.travel_over_revolution(), 10 - 9.85, 1e-12);  // z(t - 2.5) halfway 9.8 .. 9.9
  h.push(10);
  EXPECT_NEAR(h.travel_over_revolution(), 10 - 9.95, 1e-12);
  h.push(10);
  EXPECT_NEAR(h.travel_over_revolution(), 0, 1e-12);
  // A whole number of cycles: the travel over exactly that many.
  RevolutionHistory whole(3, 0, 0.2);
  EXPECT_NEAR(whole.travel_over_revolution(), 0.6, 1e-12);
  whole.push(0.5);
  EXPECT_NEAR(whole.travel_over_revolution(), 0.5 - (-0.4), 1e-12);
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
  // The default part: 204 mm at 0.4 mm/rev and n = 140000 / (80 π) / min.
  const TurningParams d;
  const double n = 140000 / (std::numbers::pi * 80) / 60;
  EXPECT_NEAR(baseline_time_s(d), 204 / (0.4 * n), 1e-9);
  EXPECT_NEAR(simulate_turning(d, std::nullopt, 60).time_s, 204 / (0.4 * n), 1e-9);
}

TEST(TurningSim, TheDeepestCutFitsTheDriveAtTheProgrammedFeed) {
  // v_c is chosen so that 3 mm at 0.4 mm/rev and 100 % stays within the
  // 9 kW drive (the load at 1 mm is then a third of it).
  const TurningParams d;
  const double deep = spindle_load_pct(d.cutting, 3, 0.4, d.cutting_speed_m_min);
  EXPECT_LT(deep, 100);
  EXPECT_GT(deep, 95);
  EXPECT_NEAR(spindle_load_pct(d.cutting, 1, 0.4, d.cutting_speed_m_min), deep / 3, 1e-9);
}

TEST(TurningSim, TraceChipMatchesPositionsOneRevolutionApart) {
  // Under the law the feed changes; the chip each cycle is z(t) - z(t - T_rev)
  // from the trace's own positions (linear between cycle starts).
  TurningParams p;
  p.noise_pct = 0;
  std::vector<TraceSample> s;
  simulate_turning(p, FeedOverrideParams{}, 60, [&](const TraceSample& x) { s.push_back(x); });
  const double rev_cycles = 1 / (spindle_speed_rev_s(p) * p.ipo_s);
  const auto whole = static_cast<std::size_t>(rev_cycles);
  const double frac = rev_cycles - static_cast<double>(whole);
  std::size_t checked = 0;
  double lowest = 1, highest = 0;
  for (std::size_t k = whole + 1; k < s.size(); ++k) {
    const double back = s[k - whole].z_mm + frac * (s[k - whole - 1].z_mm - s[k - whole].z_mm);
    ASSERT_NEAR(s[k].chip_mm, s[k].z_mm - back, 1e-9) << k;
    lowest = std::min(lowest, s[k].chip_mm), highest = std::max(highest, s[k].chip_mm);
    ++checked;
  }
  EXPECT_GT(checked, 1000u);
  EXPECT_LT(lowest, 0.4);  // the law did change the feed
  EXPECT_GT(highest, 0.4);
  EXPECT_LE(highest, 0.8 + 1e-9);  // at most 200 %
}

TEST(TurningSim, SignalFollowsTheSmoothingAcrossAStepInTheAllowance) {
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
    ASSERT_NEAR(samples[i].load_pct, low + (high - low) * (1 - std::exp(-t / p.load_smoothing_s)), 1e-9) << i;
    ASSERT_NEAR(samples[i].load_true_pct, high, 1e-9);
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
  p.kv = 0;
  EXPECT_THROW(validate(p), tk::UsageError);
  p = {};
  p.max_cycles = 100;  // the default cut needs thousands at 100 %: refused before it runs
  FeedOverrideParams law;
  EXPECT_THROW(simulate_turning(p, law, 60), tk::UsageError);
  // A drive too small for any cut: the law holds the override near 0 and the
  // run stops at the limit, a runtime error.
  p = {};
  p.cutting.rated_power_w = 100;  // the smallest --power, 0.1 kW
  p.max_cycles = 20000;
  try {
    simulate_turning(p, law, 60);
    ADD_FAILURE() << "no error";
  } catch (const tk::UsageError&) {
    ADD_FAILURE() << "a usage error";
  } catch (const tk::Error&) {
  }
}

}  // namespace
