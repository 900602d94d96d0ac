/// @file control_sim_test.cpp
/// @brief The sampled feed-drive loop: high_frequency_share against the
/// analytic power share of tones on exact bins (and a brute-force DFT); the
/// plant substeps change nothing when the force is held and there is no cut,
/// and with the cut the run converges at order 2 in them; the length unit
/// changes nothing for PID; a coarse encoder hides a small offset completely;
/// the controller's estimates (quantised, differenced, low-passed)
/// recomputed from the x column; the force saturates at K_t K_a V; the
/// summary figures against the time series recomputed here.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "control/feed_drive_sim.hpp"
#include "feed_drive_run.hpp"
#include "io/error.hpp"

using tk::test::run_feed_drive;

namespace {

using namespace tk::control;

constexpr double kTwoPi = 2 * std::numbers::pi;

/// n samples at period T of c + a1 sin(2π f1 t) + a2 cos(2π f2 t + 0.3), f on exact bins.
std::vector<double> tones(std::size_t n, double period, double c, double a1, double f1, double a2, double f2) {
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) * period;
    x[i] = c + a1 * std::sin(kTwoPi * f1 * t) + a2 * std::cos(kTwoPi * f2 * t + 0.3);
  }
  return x;
}

TEST(HighFrequencyShare, TwoTonesGiveTheAnalyticShare) {
  // 1000 samples at 10 kHz: bins every 10 Hz. A tone of amplitude A has mean
  // power A²/2, a constant c has c²; the share above 1 kHz of
  // 3 sin(2π 100 t) + 1 cos(2π 2500 t + 0.3) is (1/2) / (9/2 + 1/2) = 0.1.
  const double T = 1e-4;
  EXPECT_NEAR(high_frequency_share(tones(1000, T, 0, 3, 100, 1, 2500), T, 1000), 0.1, 1e-12);
  // With a constant 2 (power 4): 0.5 / (4 + 4.5 + 0.5).
  EXPECT_NEAR(high_frequency_share(tones(1000, T, 2, 3, 100, 1, 2500), T, 1000), 0.5 / 9, 1e-12);
  // An odd length (no Nyquist bin), both tones above: 1; both below: 0.
  const double bin999 = 1 / (999 * T);  // bins 121 and 400: 1211.2 and 4004.0 Hz
  EXPECT_NEAR(high_frequency_share(tones(999, T, 0, 1, 121 * bin999, 2, 400 * bin999), T, 1000), 1, 1e-12);
  EXPECT_NEAR(high_frequency_share(tones(1000, T, 0, 1, 200, 2, 900), T, 1000), 0, 1e-12);
  // The Nyquist tone (−1)^i counts once and lies above any cut-off below 5 kHz.
  std::vector<double> nyquist(64);
  for (std::size_t i = 0; i < nyquist.size(); ++i) nyquist[i] = i % 2 ? -1 : 1;
  EXPECT_NEAR(high_frequency_share(nyquist, T, 4999), 1, 1e-12);
  nyquist[0] += 8;  // an impulse spreads power over every bin
  {
    // By brute force: the power at each frequency min(k, n − k)/(nT) from an O(n²) DFT.
    const std::size_t n = nyquist.size();
    double total = 0, above = 0;
    for (std::size_t k = 0; k < n; ++k) {
      double re = 0, im = 0;
      for (std::size_t i = 0; i < n; ++i)
        re += nyquist[i] * std::cos(kTwoPi * k * i / n), im -= nyquist[i] * std::sin(kTwoPi * k * i / n);
      const double p = re * re + im * im, f = static_cast<double>(std::min(k, n - k)) / (n * T);
      total += p;
      if (f > 1000) above += p;
    }
    EXPECT_NEAR(high_frequency_share(nyquist, T, 1000), above / total, 1e-12);
  }
  // "Above" the cut-off is strict: a tone exactly on it (bin 100) counts as below.
  EXPECT_NEAR(high_frequency_share(tones(1000, T, 0, 1, 1000, 1, 3000), T, 1000), 0.5, 1e-12);
  EXPECT_NEAR(high_frequency_share(tones(1000, T, 0, 1, 1000, 1, 3000), T, 990), 1, 1e-12);
  EXPECT_EQ(high_frequency_share(std::vector<double>(100, 0.0), T, 1000), 0);
  EXPECT_EQ(high_frequency_share({5.0}, T, 1000), 0);
}

FeedDriveConfig smooth_pid() {
  FeedDriveConfig c;
  c.gains.kind = ControllerKind::pid;
  c.encoder_mm = 0, c.position_filter_hz = 0, c.velocity_filter_hz = 0;
  c.hf_cutoff_hz = 0;
  c.duration_s = 0.2;
  c.initial_position_mm = 0.05;
  return c;
}

/// The plant step is exact for a held force, so without the cutting force
/// splitting the period into 1, 3 or 10 substeps gives the same run.
TEST(FeedDriveSim, SubstepsChangeNothingWithoutTheCut) {
  FeedDriveConfig c = smooth_pid();
  c.cut.enabled = false;
  c.substeps = 1;
  const std::vector<FeedDriveSample> one = run_feed_drive(c);
  for (const int substeps : {3, 10}) {
    c.substeps = substeps;
    const std::vector<FeedDriveSample> many = run_feed_drive(c);
    ASSERT_EQ(many.size(), one.size());
    double worst = 0;
    for (std::size_t i = 0; i < one.size(); ++i) worst = std::max(worst, std::abs(many[i].x_mm - one[i].x_mm));
    EXPECT_LT(worst, 1e-12) << substeps;
  }
  // With the cut on they differ (the disturbance is resolved finer).
  c.cut.enabled = true, c.cut.kte_n_mm = 27.7, c.cut.kre_n_mm = 26.6;
  c.substeps = 1;
  const std::vector<FeedDriveSample> coarse = run_feed_drive(c);
  c.substeps = 10;
  const std::vector<FeedDriveSample> fine = run_feed_drive(c);
  double worst = 0;
  for (std::size_t i = 0; i < fine.size(); ++i) worst = std::max(worst, std::abs(fine[i].x_mm - coarse[i].x_mm));
  EXPECT_GT(worst, 1e-9);
}

/// PID gains (kg/s², kg/s, kg/s³) mean the same in any length unit, so the
/// run in metres and newtons is the run in millimetres and millinewtons.
TEST(FeedDriveSim, LengthUnitDoesNotChangeAPidRun) {
  FeedDriveConfig c = smooth_pid();
  c.cut.kte_n_mm = 27.7, c.cut.kre_n_mm = 26.6;  // a cutting force worth seeing
  const std::vector<FeedDriveSample> mm = run_feed_drive(c);
  c.length_unit_m = 1;
  const std::vector<FeedDriveSample> m = run_feed_drive(c);
  ASSERT_EQ(mm.size(), m.size());
  double worst_x = 0, worst_f = 0, max_f = 0;
  for (std::size_t i = 0; i < m.size(); ++i) {
    worst_x = std::max(worst_x, std::abs(m[i].x_mm - mm[i].x_mm));
    worst_f = std::max(worst_f, std::abs(m[i].force_n - mm[i].force_n));
    max_f = std::max(max_f, std::abs(mm[i].force_n));
  }
  EXPECT_LT(worst_x, 1e-12);
  EXPECT_LT(worst_f, 1e-10 * max_f);
}

/// An encoder of 0.5 mm reads an axis at 0.2 mm as 0: with the reference at
/// 0, no feed-forward and no velocity seen, the PID puts out nothing and the
/// axis (at rest) stays where it is. Without the encoder it is pulled back.
TEST(FeedDriveSim, CoarseEncoderHidesASmallOffset) {
  FeedDriveConfig c = smooth_pid();
  c.cut.enabled = false;
  c.reference = Reference::step(0, 0);
  c.initial_position_mm = 0.2, c.initial_velocity_mm_s = 0;
  c.encoder_mm = 0.5;
  for (const FeedDriveSample& s : run_feed_drive(c)) {
    ASSERT_EQ(s.x_mm, 0.2) << s.t_s;
    ASSERT_EQ(s.force_n, 0) << s.t_s;
  }
  c.encoder_mm = 0;
  EXPECT_LT(std::abs(run_feed_drive(c).back().x_mm), 1e-3);
}

/// The amplifier input saturates at V: |F| ≤ K_t K_a V = 2 · 50 · 10 N.
TEST(FeedDriveSim, ForceSaturatesAtTheAmplifierLimit) {
  FeedDriveConfig c = smooth_pid();
  c.cut.enabled = false;
  c.initial_position_mm = 100;  // the PID asks for kN
  c.duration_s = 0.05;
  const std::vector<FeedDriveSample> samples = run_feed_drive(c);
  EXPECT_DOUBLE_EQ(samples.front().force_n, -1000);
  for (const FeedDriveSample& s : samples) ASSERT_LE(std::abs(s.force_n), 1000 * (1 + 1e-15));
  const FeedDriveSummary sum = simulate_feed_drive(c);
  EXPECT_GT(sum.saturated_share, 0.05);
  EXPECT_DOUBLE_EQ(sum.max_force_n, 1000);
  // A share of the measured samples: the saturated ones among those after --settle.
  std::size_t saturated_after = 0, after = 0;
  c.settle_s = 0.02;
  for (const FeedDriveSample& s : samples)
    if (s.t_s >= c.settle_s) ++after, saturated_after += std::abs(s.force_n) >= 1000 * (1 - 1e-15);
  EXPECT_DOUBLE_EQ(simulate_feed_drive(c).saturated_share, static_cast<double>(saturated_after) / after);
}

/// The summary figures recomputed from the time series (every sample).
TEST(FeedDriveSim, SummaryAgreesWithTheTimeSeries) {
  FeedDriveConfig c;  // the defaults: smc, encoder, velocity filter, cut
  c.duration_s = 0.3, c.settle_s = 0.1, c.hf_cutoff_hz = 1000;
  std::vector<FeedDriveSample> samples;
  const FeedDriveSummary sum = simulate_feed_drive(c, [&](const FeedDriveSample& s) { samples.push_back(s); });
  ASSERT_EQ(samples.size(), 3000u);
  double e2 = 0, ev2 = 0, s2 = 0, f2 = 0, max_e = 0, max_f = 0, variation = 0;
  std::vector<double> forces;
  for (const FeedDriveSample& s : samples) {
    ASSERT_NEAR(s.t_s, (&s - samples.data()) * c.period_s, 1e-15);
    ASSERT_NEAR(s.error_mm, s.x_ref_mm - s.x_mm, 1e-15);
    ASSERT_NEAR(s.x_ref_mm, std::sin(3 * s.t_s), 1e-15);
    if (s.t_s < c.settle_s) continue;
    e2 += s.error_mm * s.error_mm, ev2 += s.error_rate_mm_s * s.error_rate_mm_s;
    s2 += s.surface_mm_s * s.surface_mm_s, f2 += s.force_n * s.force_n;
    max_e = std::max(max_e, std::abs(s.error_mm)), max_f = std::max(max_f, std::abs(s.force_n));
    if (!forces.empty()) variation += std::abs(s.force_n - forces.back());
    forces.push_back(s.force_n);
  }
  const double n = static_cast<double>(forces.size());
  EXPECT_NEAR(sum.measured_s, n * c.period_s, 1e-15);
  EXPECT_NEAR(sum.rms_error_mm, std::sqrt(e2 / n), 1e-12 * std::sqrt(e2 / n));
  EXPECT_NEAR(sum.rms_velocity_error_mm_s, std::sqrt(ev2 / n), 1e-12 * std::sqrt(ev2 / n));
  EXPECT_NEAR(sum.rms_s, std::sqrt(s2 / n), 1e-12 * std::sqrt(s2 / n));
  EXPECT_NEAR(sum.effort_rms_n, std::sqrt(f2 / n), 1e-12 * std::sqrt(f2 / n));
  EXPECT_EQ(sum.max_error_mm, max_e);
  EXPECT_EQ(sum.max_force_n, max_f);
  EXPECT_NEAR(sum.chattering_n_s, variation / (n * c.period_s), 1e-9 * sum.chattering_n_s);
  EXPECT_NEAR(sum.hf_share, high_frequency_share(forces, c.period_s, 1000), 1e-12);
  EXPECT_EQ(sum.plant_steps, 3000u * 10);
  EXPECT_FALSE(sum.diverged);
  // The sine starts on the reference: x(0) = 0, and the reference's slope.
  EXPECT_EQ(samples.front().x_mm, 0);
  EXPECT_EQ(samples.front().error_rate_mm_s, 0);
}

/// What the controller sees, recovered from the time series: with a PID of
/// k_d = 1 alone against a reference at 0, F = −v̂ (kg·mm/s² = mN), and with
/// k_p = 1 alone F = −x̂. Recomputed here from the x column: the encoder
/// reading round(x/q)·q, the backward difference (r_k − r_{k−1})/T (v̂_0 the
/// true initial velocity) and first-order low-passes y += (1 − e^{−2π f T})(u − y).
TEST(FeedDriveSim, EstimatesAreQuantisedDifferencedAndFiltered) {
  for (const bool filtered : {false, true}) {
    for (const bool velocity : {true, false}) {
      FeedDriveConfig c = smooth_pid();
      c.reference = Reference::step(0, 0);
      c.gains.pid_feedforward = 0;
      c.gains.kp = velocity ? 0 : 1, c.gains.ki = 0, c.gains.kd = velocity ? 1 : 0;
      c.initial_position_mm = 0.0123, c.initial_velocity_mm_s = 0.7;
      c.cut.kte_n_mm = 27.7, c.cut.kre_n_mm = 26.6;  // the cut moves the axis about
      c.encoder_mm = 1e-5;
      if (filtered) c.velocity_filter_hz = 300, c.position_filter_hz = 150;
      c.duration_s = 0.05;
      const std::vector<FeedDriveSample> s = run_feed_drive(c);
      const double T = c.period_s, q = c.encoder_mm;
      const double av = filtered ? 1 - std::exp(-kTwoPi * 300 * T) : 1,
                   ax = filtered ? 1 - std::exp(-kTwoPi * 150 * T) : 1;
      double previous = std::round(s[0].x_mm / q) * q, v_hat = 0.7, x_hat = previous, worst = 0, moved = 0;
      for (std::size_t k = 0; k < s.size(); ++k) {
        if (k > 0) {
          const double reading = std::round(s[k].x_mm / q) * q;
          v_hat += av * ((reading - previous) / T - v_hat);
          x_hat += ax * (reading - x_hat);
          previous = reading;
        }
        const double want_n = -(velocity ? v_hat : x_hat) * 1e-3;
        worst = std::max(worst, std::abs(s[k].force_n - want_n) / (std::abs(want_n) + 1e-9));
        moved = std::max(moved, std::abs(s[k].x_mm - s[0].x_mm));
      }
      EXPECT_LT(worst, 1e-9) << (filtered ? "filtered " : "") << (velocity ? "velocity" : "position");
      EXPECT_GT(moved, 100 * q) << "the axis moves across many encoder counts";
    }
  }
}

/// With the cut, the disturbance is a first-order hold across each substep,
/// so the run converges at order 2 in the substeps: the distance to a run of
/// 64 substeps falls about fourfold per doubling (T = 1 ms, where the
/// difference is well above rounding).
TEST(FeedDriveSim, CutConvergesAtOrderTwoInTheSubsteps) {
  FeedDriveConfig c = smooth_pid();
  c.period_s = 1e-3, c.cut.feed_mm_min = 108;
  c.substeps = 64;
  const std::vector<FeedDriveSample> fine = run_feed_drive(c);
  std::vector<double> errors;
  for (const int n : {2, 4, 8}) {
    c.substeps = n;
    const std::vector<FeedDriveSample> s = run_feed_drive(c);
    double worst = 0;
    for (std::size_t k = 0; k < s.size(); ++k) worst = std::max(worst, std::abs(s[k].x_mm - fine[k].x_mm));
    errors.push_back(worst);
  }
  for (std::size_t i = 1; i < errors.size(); ++i) {
    // Against 64 substeps rather than the exact answer: err(n) − err(64) ≈ C (1/n² − 1/64²).
    const double n = 2.0 * (1 << i), want = (1 / (n * n / 4) - 1 / 4096.0) / (1 / (n * n) - 1 / 4096.0);
    EXPECT_NEAR(errors[i - 1] / errors[i], want, 0.1 * want) << "from " << n / 2 << " to " << n << " substeps";
  }
}

/// The disturbance column is the cutting force at the sample instants.
TEST(FeedDriveSim, DisturbanceColumnIsTheCuttingForce) {
  FeedDriveConfig c = smooth_pid();
  c.cut.kte_n_mm = 27.7, c.cut.kre_n_mm = 26.6;
  c.duration_s = 0.01;
  const MillingForce force(c.cut);
  for (const FeedDriveSample& s : run_feed_drive(c)) ASSERT_NEAR(s.disturbance_n, force.at(s.t_s), 1e-12 * 60) << s.t_s;
}

}  // namespace
