/// @file quality_policies_test.cpp
/// @brief The charts against sequences worked by hand and against the exact
/// Shewhart ARL (published: 370.4 in control, 43.9 at a 1σ shift); the
/// simulated lathe against closed forms (a noise-free batch, the stable
/// process's σ against the sample spread of its measurements).
#include <gtest/gtest.h>

#include <boost/math/distributions/normal.hpp>
#include <cmath>
#include <vector>

#include "io/error.hpp"
#include "quality/adjustment_policy.hpp"
#include "quality/lathe_sim.hpp"

namespace {

using namespace tk::quality;

/// The exact ARL of a Shewhart chart with limits ± L σ under a shift of `shift` σ:
/// 1/p, p = Φ(−L − shift) + 1 − Φ(L − shift), the oracle of the simulated ARLs.
double shewhart_arl(double l, double shift) {
  const boost::math::normal_distribution<double> unit;
  return 1 / (boost::math::cdf(unit, -l - shift) + boost::math::cdf(boost::math::complement(unit, l - shift)));
}

std::unique_ptr<AdjustmentPolicy> chart(PolicyKind kind, const ChartSettings& c = {}) {
  return make_policy(kind, {}, c);
}

TEST(Charts, ShewhartAlarmsBeyondLSigmaAndCorrectsByThePoint) {
  const auto p = chart(PolicyKind::shewhart, {.target = 10, .sigma = 0.01});
  EXPECT_FALSE(p->observe(10.0299).alarm);
  EXPECT_FALSE(p->observe(9.9701).alarm);
  const PolicyStep step = p->observe(10.031);
  EXPECT_TRUE(step.alarm);
  EXPECT_NEAR(step.correction, -0.031, 1e-12);
}

TEST(Charts, EwmaByHand) {
  // λ = 0.5, L = 3, σ = 1: limit 3 √(0.5/1.5) = 1.7320508. Deviations 1, 2, 2:
  // z = 0.5, 1.25, 1.625 (no alarm), then 3: z = 2.3125 → alarm, correction −2.3125, z back to 0.
  const auto p = chart(PolicyKind::ewma, {.ewma_lambda = 0.5});
  for (const double x : {1.0, 2.0, 2.0}) EXPECT_FALSE(p->observe(x).alarm);
  const PolicyStep step = p->observe(3);
  EXPECT_TRUE(step.alarm);
  EXPECT_NEAR(step.correction, -2.3125, 1e-12);
  EXPECT_FALSE(p->observe(1.7).alarm);  // z = 0.85 from zero state
}

TEST(Charts, CusumByHandWithMontgomerysShiftEstimate) {
  // k = 0.5, h = 5, σ = 1. Deviations 2, 2, 2, 1: C+ = 1.5, 3, 4.5, 5 (not > 5), then 2: C+ = 6.5 → alarm
  // after N+ = 5 positive periods: μ̂ − μ0 = K + C+/N+ = 0.5 + 1.3 = 1.8, correction −1.8.
  const auto p = chart(PolicyKind::cusum);
  for (const double x : {2.0, 2.0, 2.0, 1.0}) EXPECT_FALSE(p->observe(x).alarm);
  const PolicyStep step = p->observe(2);
  EXPECT_TRUE(step.alarm);
  EXPECT_NEAR(step.correction, -1.8, 1e-12);
  // A downward run: C− = 2.5, 5 (not > 5), 7.5 → alarm, N− = 3: μ̂ − μ0 = −(0.5 + 2.5), correction +3.
  for (const double x : {-3.0, -3.0}) EXPECT_FALSE(p->observe(x).alarm);
  const PolicyStep down = p->observe(-3);
  EXPECT_TRUE(down.alarm);
  EXPECT_NEAR(down.correction, 3.0, 1e-12);
}

TEST(Charts, ShewhartArlMatchesPublishedValues) {
  EXPECT_NEAR(shewhart_arl(3, 0), 370.4, 0.05);
  EXPECT_NEAR(shewhart_arl(3, 1), 43.9, 0.05);
}

TEST(Charts, SimulatedShewhartArlWithinItsStandardError) {
  const RunLengthEstimate in_control = average_run_length(PolicyKind::shewhart, {}, {}, 0, 0, 20000, 11);
  EXPECT_NEAR(in_control.mean, shewhart_arl(3, 0), 4 * in_control.standard_error);
  // Run lengths are geometric: sd = √(1 − p)/p, so the standard error is √(ARL(ARL − 1)/runs).
  const double arl = shewhart_arl(3, 0);
  EXPECT_NEAR(in_control.standard_error, std::sqrt(arl * (arl - 1) / 20000), 0.05 * in_control.standard_error);
  const RunLengthEstimate shifted = average_run_length(PolicyKind::shewhart, {}, {}, 1, 0, 20000, 12);
  EXPECT_NEAR(shifted.mean, shewhart_arl(3, 1), 4 * shifted.standard_error);
  EXPECT_EQ(shifted.censored, 0u);
}

TEST(Charts, RefuseBadSettings) {
  EXPECT_THROW(chart(PolicyKind::ewma, {.ewma_lambda = 0}), tk::Error);
  EXPECT_THROW(chart(PolicyKind::cusum, {.cusum_h = 0}), tk::Error);
  EXPECT_THROW(chart(PolicyKind::shewhart, {.sigma = 0}), tk::Error);
  EXPECT_THROW(parse_policy("xbar"), tk::Error);
  EXPECT_EQ(parse_policy("cusum"), PolicyKind::cusum);
}

TEST(LatheSim, NoiseFreeWearByHand) {
  // 0.004 mm per part, no thermal drift, no noise, band ±0.02: parts 1..5 are
  // inside (0.004 i ≤ 0.02), parts 6..10 outside; mean |deviation| = 0.004·5.5 = 0.022.
  LatheSettings s;
  s.parts = 10, s.wear_mm_per_part = 0.004, s.thermal_mm = 0;
  s.allowance_sd_mm = s.process_sd_mm = s.gauge_sd_mm = 0;
  const auto none = make_policy(PolicyKind::none, {}, {});
  std::vector<double> sizes;
  const LatheOutcome out = simulate_lathe(s, *none, [&](const PartRecord& p) { sizes.push_back(p.size_mm); });
  EXPECT_EQ(out.in_tolerance, 5u);
  EXPECT_NEAR(out.mean_abs_deviation_mm, 0.022, 1e-12);
  EXPECT_NEAR(out.max_abs_deviation_mm, 0.04, 1e-12);
  for (std::size_t i = 0; i < sizes.size(); ++i) EXPECT_NEAR(sizes[i], 40 + 0.004 * static_cast<double>(i + 1), 1e-12);
}

TEST(LatheSim, CorrectionsMoveTheFollowingParts) {
  // Shewhart with σ = 0.001: the first part beyond 40.003 (part 1 at 40.004) is
  // corrected by −0.004, so part 2 comes out at 40.004 again: every part alarms.
  LatheSettings s;
  s.parts = 6, s.wear_mm_per_part = 0.004, s.thermal_mm = 0;
  s.allowance_sd_mm = s.process_sd_mm = s.gauge_sd_mm = 0;
  const auto shewhart = make_policy(PolicyKind::shewhart, {}, {.target = 40, .sigma = 0.001});
  const LatheOutcome out =
      simulate_lathe(s, *shewhart, [](const PartRecord& p) { EXPECT_NEAR(p.size_mm, 40.004, 1e-9); });
  EXPECT_EQ(out.corrections, 6u);
}

TEST(LatheSim, InControlSigmaMatchesTheSampleSpread) {
  // The stable process with a strongly quadratic force model: σ² = σp² + σg² +
  // g² s² + 2 b11² s⁴, where the last term is 3.6 % of σ² (1.8 % of σ), and the
  // set-up absorbs E[y] = y(ā) + b11 s², so the measured mean is the nominal.
  LatheSettings s = stable_process({});
  s.parts = 200000;
  s.force_model = {.b1 = 0.004, .b12 = 0.01, .b11 = 0.03};
  s.allowance_sd_mm = 0.3;
  double sum = 0, square_sum = 0;
  const auto none = make_policy(PolicyKind::none, {}, {});
  simulate_lathe(s, *none, [&](const PartRecord& p) {
    sum += p.measured_mm - 40, square_sum += (p.measured_mm - 40) * (p.measured_mm - 40);
  });
  const double n = static_cast<double>(s.parts), sd = std::sqrt((square_sum - sum * sum / n) / (n - 1));
  // The sample sd's own relative error is about 0.16 % here (0.2 % with the quadratic term's tails).
  EXPECT_NEAR(sd, in_control_sigma(s), 0.008 * in_control_sigma(s));
  EXPECT_NEAR(sum / n, 0, 4 * sd / std::sqrt(n));
}

TEST(LatheSim, EveryPolicyMeetsTheSameDraws) {
  LatheSettings s;
  s.parts = 50;
  std::vector<double> allowances;
  const auto none = make_policy(PolicyKind::none, {}, {});
  simulate_lathe(s, *none, [&](const PartRecord& p) { allowances.push_back(p.allowance_mm); });
  const auto cusum = make_policy(PolicyKind::cusum, {}, {.target = 40, .sigma = 0.003});
  std::size_t i = 0;
  simulate_lathe(s, *cusum, [&](const PartRecord& p) { EXPECT_EQ(p.allowance_mm, allowances[i++]); });
}

TEST(LatheSim, RefusesImpossibleSettings) {
  const auto none = make_policy(PolicyKind::none, {}, {});
  LatheSettings band;
  band.lower_mm = 40.01;
  EXPECT_THROW(simulate_lathe(band, *none), tk::Error);
  LatheSettings noise;
  noise.gauge_sd_mm = -1;
  EXPECT_THROW(simulate_lathe(noise, *none), tk::Error);
}

}  // namespace
