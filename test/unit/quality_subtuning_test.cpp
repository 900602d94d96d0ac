/// @file quality_subtuning_test.cpp
/// @brief Student t critical values against published tables and against
/// Boost beyond the table; the sub-tuning test against a case worked by hand
/// (4 parts), against long-double two-pass sums on long runs, and its edge
/// cases (identical sizes, exact lines, the gauge's resolution, one-sided
/// alternatives, correction to the nominal).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "io/error.hpp"
#include "quality/student_t.hpp"
#include "quality/subtuning.hpp"

namespace {

using namespace tk::quality;

/// The least-squares line over i = 1..n in long double, two passes, the
/// residuals summed directly: an independent path with no cancellation to suffer.
struct LongFit {
  long double a = 0, b = 0, sse = 0, sxx = 0;
};
LongFit two_pass_fit(const std::vector<double>& sizes) {
  const long double n = sizes.size(), mean_i = (n + 1) / 2;
  long double mean = 0;
  for (const double v : sizes) mean += v;
  mean /= n;
  LongFit fit;
  long double sxy = 0;
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    const long double di = static_cast<long double>(i + 1) - mean_i;
    sxy += di * (sizes[i] - mean), fit.sxx += di * di;
  }
  fit.b = sxy / fit.sxx, fit.a = mean - fit.b * mean_i;
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    const long double r = sizes[i] - (fit.a + fit.b * static_cast<long double>(i + 1));
    fit.sse += r * r;
  }
  return fit;
}

TEST(StudentCritical, TwoSidedPublishedValues) {
  // t_{0.975, k}: the two-sided 5 % points of any statistics table.
  const StudentCriticalValues t(0.05, Sidedness::two);
  EXPECT_NEAR(t.at(6), 2.446912, 1e-6);
  EXPECT_NEAR(t.at(8), 2.306004, 1e-6);
  EXPECT_NEAR(t.at(10), 2.228139, 1e-6);
  EXPECT_NEAR(t.at(14), 2.144787, 1e-6);
  EXPECT_NEAR(t.at(18), 2.100922, 1e-6);
  EXPECT_NEAR(t.at(1), 12.706205, 1e-6);
  EXPECT_NEAR(t.at(6), 2.446912, 1e-6);  // from the table this time
}

TEST(StudentCritical, OneSidedPublishedValues) {
  const StudentCriticalValues t(0.05, Sidedness::one);
  EXPECT_NEAR(t.at(10), 1.812461, 1e-6);
  EXPECT_NEAR(t.at(6), 1.943180, 1e-6);
  const StudentCriticalValues t01(0.01, Sidedness::two);
  EXPECT_NEAR(t01.at(10), 3.169273, 1e-6);
}

TEST(StudentCritical, SeriesBeyondTheTableAgreesWithBoost) {
  for (const double alpha : {0.2, 0.05, 0.001, 1e-8}) {
    const StudentCriticalValues t(alpha, Sidedness::two);
    for (const std::size_t df : {StudentCriticalValues::kTableLimit, StudentCriticalValues::kTableLimit + 1,
                                 std::size_t{100000}, std::size_t{10000000}}) {
      const double exact = student_t_upper_quantile(alpha / 2, static_cast<double>(df));
      EXPECT_NEAR(t.at(df), exact, 2e-14 * exact) << "alpha " << alpha << " df " << df;
    }
  }
}

TEST(StudentCritical, RefusesBadAlpha) {
  EXPECT_THROW(StudentCriticalValues(0, Sidedness::two), tk::Error);
  EXPECT_THROW(StudentCriticalValues(1, Sidedness::two), tk::Error);
  EXPECT_THROW(StudentCriticalValues(0.5, Sidedness::one), tk::Error);
  EXPECT_THROW(StudentCriticalValues(std::nan(""), Sidedness::two), tk::Error);
}

TEST(SubTuner, FourPartsByHandWithThePapersStatistic) {
  // Eq. (3)-(6) as printed. Sizes 10.000 10.002 10.001 10.003 at i = 1..4: ī = 2.5, mean 10.0015,
  // Σ(i−ī)² = 5, Σ(i−ī)(A−Ā) = 0.004, so b = 0.0008, a = 10.0015 − 2.5 b = 9.9995;
  // residuals −0.0003 0.0009 −0.0009 0.0003, SSE = 1.8e-6, S² = SSE/3 = 6e-7;
  // t = |ã − A_T4| / S · √(4/2) = 4 b / S · √2 = 5.8423739..., t_crit(6) = 2.446912:
  // sub-tune by ΔA = ã − A_T4 = −4 b.
  SubTuner tuner({.statistic = TrendStatistic::paper});
  const double sizes[] = {10.000, 10.002, 10.001, 10.003};
  SubTuneStep step;
  for (int i = 0; i < 3; ++i) {
    step = tuner.observe(sizes[i]);
    EXPECT_EQ(step.decision, Decision::insufficient);
    EXPECT_EQ(step.n, static_cast<std::uint64_t>(i + 1));
    EXPECT_TRUE(std::isnan(step.t));
  }
  EXPECT_NEAR(step.b, 0.0005, 1e-12);  // three parts: b = (10.001 − 10.000)/2
  step = tuner.observe(sizes[3]);
  EXPECT_NEAR(step.b, 0.0008, 1e-12);
  EXPECT_NEAR(step.a, 9.9995, 1e-12);
  EXPECT_NEAR(step.s, std::sqrt(6e-7), 1e-12);
  EXPECT_NEAR(step.t, 0.0032 / std::sqrt(6e-7) * std::sqrt(2.0), 1e-9);
  EXPECT_EQ(step.df, 6u);
  EXPECT_NEAR(step.t_crit, 2.446912, 1e-6);
  EXPECT_EQ(step.decision, Decision::subtune);
  EXPECT_NEAR(step.correction, -0.0032, 1e-12);
  EXPECT_NEAR(step.offset, -0.0032, 1e-12);
  const SubTuneStep next = tuner.observe(10.0);
  EXPECT_EQ(next.run, 2u);
  EXPECT_EQ(next.n, 1u);
  EXPECT_EQ(next.decision, Decision::insufficient);
  EXPECT_NEAR(next.offset, -0.0032, 1e-12);
}

TEST(SubTuner, SlopeStatisticByHandIsTheDefault) {
  // The same four parts: s² = SSE/2 = 9e-7, t = b √5 / s = 1.8856..., t_crit(2) = 4.302653: no sub-tune.
  SubTuner tuner({});
  SubTuneStep step;
  for (const double size : {10.000, 10.002, 10.001, 10.003}) step = tuner.observe(size);
  EXPECT_NEAR(step.s, std::sqrt(9e-7), 1e-12);
  EXPECT_NEAR(step.t, 0.0008 * std::sqrt(5.0) / std::sqrt(9e-7), 1e-9);
  EXPECT_EQ(step.df, 2u);
  EXPECT_NEAR(step.t_crit, 4.302653, 1e-6);
  EXPECT_EQ(step.decision, Decision::none);
}

TEST(SubTuner, IdenticalSizesNeverSubTune) {
  SubTuner tuner({});
  for (int i = 0; i < 1000; ++i) {
    const SubTuneStep step = tuner.observe(25.004);
    if (step.n >= 4) {
      EXPECT_EQ(step.s, 0);
      EXPECT_EQ(step.t, 0);
      EXPECT_EQ(step.decision, Decision::none);
    }
  }
}

TEST(SubTuner, AnExactLineIsSignificantAndTheResolutionTamesIt) {
  // 0.5 µm per part with no noise: S_N is 0 up to rounding, so t is infinite or huge.
  SubTuner exact({.statistic = TrendStatistic::paper});
  SubTuneStep step;
  for (int i = 0; i < 4; ++i) step = exact.observe(40 + 0.0005 * i);
  EXPECT_EQ(step.decision, Decision::subtune);
  EXPECT_GT(step.t, 1e6);
  // With a 1 µm gauge, S_N ≥ 1e-3/√12: t = 4·0.0005/2.887e-4·√2 = 9.8 — still significant;
  // with a 10 µm gauge t = 0.98 and the drift is not yet significant.
  SubTuner coarse({.statistic = TrendStatistic::paper, .resolution = 0.01});
  for (int i = 0; i < 4; ++i) step = coarse.observe(40 + 0.0005 * i);
  EXPECT_NEAR(step.s, 0.01 / std::sqrt(12.0), 1e-15);
  EXPECT_NEAR(step.t, 4 * 0.0005 / (0.01 / std::sqrt(12.0)) * std::sqrt(2.0), 1e-9);
  EXPECT_EQ(step.decision, Decision::none);
}

TEST(SubTuner, OneSidedAlternativesWatchOneDirection) {
  SubTuner greater({.alternative = Alternative::greater, .statistic = TrendStatistic::paper}),
      less({.alternative = Alternative::less, .statistic = TrendStatistic::paper});
  SubTuneStep up, down;
  for (const double size : {10.003, 10.001, 10.002, 10.000}) {  // shrinking, t = 5.84 as by hand
    up = greater.observe(size);
    down = less.observe(size);
  }
  EXPECT_EQ(up.decision, Decision::none);
  EXPECT_EQ(down.decision, Decision::subtune);
  EXPECT_NEAR(down.t_crit, 1.943180, 1e-6);  // one-sided 5 % at 6 df
  EXPECT_NEAR(down.correction, 0.0032, 1e-12);
}

TEST(SubTuner, CorrectionToTheNominal) {
  // The by-hand run: A_T(4) = 9.9995 + 4·0.0008 = 10.0027; to a nominal of 10.000: −0.0027.
  SubTuner tuner({.statistic = TrendStatistic::paper, .target = 10.0});
  SubTuneStep step;
  for (const double size : {10.000, 10.002, 10.001, 10.003}) step = tuner.observe(size);
  EXPECT_EQ(step.decision, Decision::subtune);
  EXPECT_NEAR(step.correction, -0.0027, 1e-12);
}

TEST(SubTuner, LongRunMatchesTwoPassLongDouble) {
  // 10^6 parts at 12 345.678 mm with noise of 1 µm, a flat process, and the
  // slope test at α = 1e-12 so the run never ends (the paper's t grows as
  // N^1.5 |b| and ends it): the co-moments must agree with a two-pass
  // computation in long double, which has no cancellation to suffer.
  SubTuner tuner({.alpha = 1e-12, .statistic = TrendStatistic::slope});
  std::mt19937_64 random(7);
  std::normal_distribution<double> noise(0, 0.001);
  std::vector<double> sizes(1000000);
  SubTuneStep step;
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    sizes[i] = 12345.678 + noise(random);
    step = tuner.observe(sizes[i]);
  }
  ASSERT_EQ(step.run, 1u);
  const auto [a, b, sse, sxx] = two_pass_fit(sizes);
  const long double s = std::sqrt(sse / (sizes.size() - 2.0L));
  const double t = static_cast<double>(std::abs(b) * std::sqrt(sxx) / s);
  EXPECT_NEAR(step.b, static_cast<double>(b), 1e-6 * std::abs(static_cast<double>(b)));
  EXPECT_NEAR(step.a, static_cast<double>(a), 1e-9);
  EXPECT_NEAR(step.s, static_cast<double>(s), 1e-9 * static_cast<double>(s));
  EXPECT_NEAR(step.t, t, 1e-6 * t);
  EXPECT_EQ(step.df, sizes.size() - 2);
}

TEST(SubTuner, LongRunWithAStrongTrendKeepsItsSpread) {
  // Sizes growing by 1 µm per part for 10^6 parts with 1 µm noise, watched
  // for shrinking only (--alternative less), so the run never ends: the
  // spread is a 1e-11 sliver of the sizes' moment, so SSE = Myy − b·Mxy
  // would cancel (it lost 1e-3 of s here); the recursive SSE must match the
  // two-pass long-double fit.
  SubTuner tuner({.alternative = Alternative::less, .statistic = TrendStatistic::paper});
  std::mt19937_64 random(3);
  std::normal_distribution<double> noise(0, 0.001);
  std::vector<double> sizes(1000000);
  SubTuneStep step;
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    sizes[i] = 40 + 0.001 * static_cast<double>(i + 1) + noise(random);
    step = tuner.observe(sizes[i]);
  }
  ASSERT_EQ(step.run, 1u);
  const auto [a, b, sse, sxx] = two_pass_fit(sizes);
  const double s = static_cast<double>(std::sqrt(sse / (sizes.size() - 1.0L)));
  EXPECT_NEAR(step.b, static_cast<double>(b), 1e-9 * static_cast<double>(b));
  EXPECT_NEAR(step.a, static_cast<double>(a), 1e-9);
  EXPECT_NEAR(step.s, s, 1e-7 * s);
  EXPECT_EQ(step.decision, Decision::none);
}

TEST(SubTuner, ResetKeepsNothingButTheTable) {
  SubTuner tuner({});
  for (const double size : {10.000, 10.002, 10.001, 10.003, 10.0}) tuner.observe(size);
  tuner.reset();
  const SubTuneStep first = tuner.observe(5.0);
  EXPECT_EQ(first.run, 1u);
  EXPECT_EQ(first.n, 1u);
  EXPECT_EQ(first.offset, 0);
}

TEST(SubTuner, RefusesBadSettings) {
  EXPECT_THROW(SubTuner({.min_parts = 1}), tk::Error);
  EXPECT_THROW(SubTuner({.statistic = TrendStatistic::slope, .min_parts = 2}), tk::Error);
  EXPECT_THROW(SubTuner({.resolution = -1}), tk::Error);
  EXPECT_THROW(SubTuner({.alpha = 0}), tk::Error);
}

}  // namespace
