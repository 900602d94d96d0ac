/// @file force_error_model_test.cpp
/// @brief The force-error model against independent oracles: data generated
/// in long double from known coefficients (recovered exactly), hand-worked
/// cases, the normal equations solved in long double by Gaussian elimination
/// (a different path from the library's scaled QR), the refused designs, and
/// the feed inversion against closed forms and a brute-force sign-change scan.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "io/error.hpp"
#include "machining/force_error_model.hpp"

namespace {

using namespace tk::machining;

/// The message contains part (like gmock's HasSubstr; the unit tests link gtest only).
testing::AssertionResult HasSubstr(const std::string& part, const std::string& message) {
  if (message.find(part) != std::string::npos) return testing::AssertionSuccess();
  return testing::AssertionFailure() << "'" << message << "' lacks '" << part << "'";
}

/// Plausible magnitudes: errors of tens of µm at a ~ 1-3 mm, f ~ 0.1-0.5 mm/rev.
constexpr ForceErrorModel kKnown{0.012, 0.018, 0.09, 0.04, -0.0035, 0.15};

/// y in long double, rounded once: the data carry only their own rounding.
double exact_y(const ForceErrorModel& m, double a, double f) {
  const long double A = a, F = f;
  return static_cast<double>(m.b0 + m.b1 * A + m.b2 * F + m.b12 * A * F + m.b11 * A * A + m.b22 * F * F);
}

std::vector<CalibrationPoint> grid(const ForceErrorModel& m, std::vector<double> depths, std::vector<double> feeds) {
  std::vector<CalibrationPoint> points;
  for (double a : depths)
    for (double f : feeds) points.push_back({a, f, exact_y(m, a, f)});
  return points;
}

std::array<double, 6> coefficients(const ForceErrorModel& m) { return {m.b0, m.b1, m.b2, m.b12, m.b11, m.b22}; }

std::string fit_error(const std::vector<CalibrationPoint>& points) {
  try {
    fit_force_error_model(points);
  } catch (const tk::Error& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(ForceErrorFit, RecoversExactCoefficientsOnAGrid) {
  const auto points = grid(kKnown, {0.5, 1.2, 2.1, 3.0}, {0.05, 0.15, 0.3, 0.5});
  const ForceErrorFit fit = fit_force_error_model(points);
  const auto got = coefficients(fit.model), want = coefficients(kKnown);
  for (std::size_t j = 0; j < 6; ++j) EXPECT_NEAR(got[j], want[j], 1e-10 * std::abs(want[j])) << "coefficient " << j;
  EXPECT_EQ(fit.points, 16u);
  EXPECT_NEAR(fit.r2, 1, 1e-12);
  EXPECT_NEAR(fit.adjusted_r2, 1, 1e-12);
  EXPECT_LT(fit.residual_sd, 1e-15);
  EXPECT_GT(fit.condition, 1);
  EXPECT_LT(fit.condition, 1e4);  // a well-spread grid, far from the limit
  ASSERT_EQ(fit.fitted.size(), 16u);
  ASSERT_EQ(fit.residuals.size(), 16u);
  for (std::size_t i = 0; i < points.size(); ++i) {
    EXPECT_NEAR(fit.fitted[i], points[i].y, 1e-16) << i;
    EXPECT_NEAR(fit.residuals[i], 0, 1e-16) << i;
  }
}

/// Six points on the principal lattice of a triangle determine a quadratic
/// exactly: nothing is left for the residual statistics.
TEST(ForceErrorFit, SixPointsLeaveNoResidualDegreesOfFreedom) {
  std::vector<CalibrationPoint> points;
  for (const auto& [a, f] : {std::pair{1.0, 0.1}, {2.0, 0.1}, {3.0, 0.1}, {1.0, 0.2}, {2.0, 0.2}, {1.0, 0.3}})
    points.push_back({a, f, exact_y(kKnown, a, f)});
  const ForceErrorFit fit = fit_force_error_model(points);
  const auto got = coefficients(fit.model), want = coefficients(kKnown);
  for (std::size_t j = 0; j < 6; ++j) EXPECT_NEAR(got[j], want[j], 1e-10 * std::abs(want[j])) << "coefficient " << j;
  EXPECT_NEAR(fit.r2, 1, 1e-12);
  EXPECT_TRUE(std::isnan(fit.adjusted_r2));
  EXPECT_TRUE(std::isnan(fit.residual_sd));
}

/// y = 0.004 a: every other coefficient is zero, by hand.
TEST(ForceErrorFit, DepthOnlyErrorByHand) {
  std::vector<CalibrationPoint> points;
  for (double a : {1.0, 2.0, 3.0})
    for (double f : {0.1, 0.2, 0.4}) points.push_back({a, f, 0.004 * a});
  const ForceErrorFit fit = fit_force_error_model(points);
  EXPECT_NEAR(fit.model.b1, 0.004, 1e-16);
  for (double other : {fit.model.b0, fit.model.b2, fit.model.b12, fit.model.b11, fit.model.b22})
    EXPECT_NEAR(other, 0, 1e-15);
  EXPECT_NEAR(fit.r2, 1, 1e-12);
  EXPECT_NEAR(fit.model.error_at(2.5, 0.3), 0.01, 1e-16);
}

/// All y equal: SST == 0, and the documented convention is r2 = 1.
TEST(ForceErrorFit, ConstantErrorHasR2One) {
  std::vector<CalibrationPoint> points;
  for (double a : {1.0, 2.0, 3.0})
    for (double f : {0.1, 0.2, 0.4}) points.push_back({a, f, 0.02});
  const ForceErrorFit fit = fit_force_error_model(points);
  EXPECT_NEAR(fit.model.b0, 0.02, 1e-16);
  EXPECT_EQ(fit.r2, 1);
  EXPECT_EQ(fit.adjusted_r2, 1);
  EXPECT_LT(fit.residual_sd, 1e-16);
}

/// Solves X'X b = X'y in long double by Gaussian elimination with partial
/// pivoting: squaring the unscaled design's condition (~1e4) costs ~1e-11 in
/// long double, far below the 1e-9 compared.
std::array<long double, 6> normal_equations(const std::vector<CalibrationPoint>& points) {
  std::array<std::array<long double, 7>, 6> m{};
  for (const CalibrationPoint& p : points) {
    const long double a = p.a, f = p.f;
    const std::array<long double, 6> x{1, a, f, a * f, a * a, f * f};
    for (int i = 0; i < 6; ++i) {
      for (int j = 0; j < 6; ++j) m[i][j] += x[i] * x[j];
      m[i][6] += x[i] * p.y;
    }
  }
  for (int k = 0; k < 6; ++k) {
    int pivot = k;
    for (int i = k + 1; i < 6; ++i)
      if (std::abs(m[i][k]) > std::abs(m[pivot][k])) pivot = i;
    std::swap(m[k], m[pivot]);
    for (int i = k + 1; i < 6; ++i) {
      const long double factor = m[i][k] / m[k][k];
      for (int j = k; j < 7; ++j) m[i][j] -= factor * m[k][j];
    }
  }
  std::array<long double, 6> b{};
  for (int i = 5; i >= 0; --i) {
    long double s = m[i][6];
    for (int j = i + 1; j < 6; ++j) s -= m[i][j] * b[j];
    b[i] = s / m[i][i];
  }
  return b;
}

TEST(ForceErrorFit, NoisyDataMatchLongDoubleNormalEquations) {
  auto points = grid(kKnown, {0.5, 1.0, 1.6, 2.3, 3.0}, {0.05, 0.12, 0.25, 0.4, 0.5});
  std::mt19937_64 rng(20240611);
  std::normal_distribution<double> noise(0, 0.003);  // a few µm of measurement scatter
  for (CalibrationPoint& p : points) p.y += noise(rng);
  const ForceErrorFit fit = fit_force_error_model(points);
  const auto ref = normal_equations(points);
  const auto got = coefficients(fit.model);
  for (std::size_t j = 0; j < 6; ++j)
    EXPECT_NEAR(got[j], static_cast<double>(ref[j]), 1e-9 * std::abs(static_cast<double>(ref[j])))
        << "coefficient " << j;

  long double mean = 0, sse = 0, sst = 0;
  for (const CalibrationPoint& p : points) mean += p.y;
  mean /= points.size();
  for (std::size_t i = 0; i < points.size(); ++i) {
    const long double a = points[i].a, f = points[i].f;
    const long double y = ref[0] + ref[1] * a + ref[2] * f + ref[3] * a * f + ref[4] * a * a + ref[5] * f * f;
    EXPECT_NEAR(fit.residuals[i], static_cast<double>(points[i].y - y), 1e-12) << i;
    sse += (points[i].y - y) * (points[i].y - y);
    sst += (points[i].y - mean) * (points[i].y - mean);
  }
  const long double r2 = 1 - sse / sst, n = points.size();
  EXPECT_NEAR(fit.r2, static_cast<double>(r2), 1e-12);
  EXPECT_NEAR(fit.adjusted_r2, static_cast<double>(1 - (1 - r2) * (n - 1) / (n - 6)), 1e-12);
  EXPECT_NEAR(fit.residual_sd, static_cast<double>(std::sqrt(sse / (n - 6))), 1e-12);
  EXPECT_LT(fit.r2, 1);
}

TEST(ForceErrorFit, RefusesTooFewPoints) {
  auto points = grid(kKnown, {1, 2, 3}, {0.1, 0.2, 0.3});
  points.resize(5);
  const std::string message = fit_error(points);
  EXPECT_TRUE(HasSubstr("at least 6 points", message));
  EXPECT_TRUE(HasSubstr("it has 5", message));
}

TEST(ForceErrorFit, RefusesNonFiniteValues) {
  auto points = grid(kKnown, {1, 2, 3}, {0.1, 0.2, 0.3});
  points[4].y = std::nan("");
  const std::string message = fit_error(points);
  EXPECT_TRUE(HasSubstr("point 5", message));
  EXPECT_TRUE(HasSubstr("y is not finite", message));
  points[4].y = 0.01;
  points[1].a = INFINITY;
  EXPECT_TRUE(HasSubstr("a is not finite", fit_error(points)));
}

TEST(ForceErrorFit, RefusesTwoDistinctFeedsOrDepths) {
  EXPECT_TRUE(HasSubstr("the calibration needs at least 3 distinct feeds f; it has 2",
                        fit_error(grid(kKnown, {1, 2, 3, 4}, {0.1, 0.2}))));
  EXPECT_TRUE(HasSubstr("the calibration needs at least 3 distinct depths a; it has 2",
                        fit_error(grid(kKnown, {1, 2}, {0.1, 0.2, 0.3, 0.4}))));
}

TEST(ForceErrorFit, RefusesCollinearDepthAndFeed) {
  std::vector<CalibrationPoint> same, on_a_line;
  for (double v : {0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7}) {
    same.push_back({v, v, exact_y(kKnown, v, v)});
    on_a_line.push_back({10 * v, 0.05 + 0.3 * v, exact_y(kKnown, 10 * v, 0.05 + 0.3 * v)});
  }
  EXPECT_TRUE(HasSubstr("collinear", fit_error(same)));
  EXPECT_TRUE(HasSubstr("collinear", fit_error(on_a_line)));
}

/// Eight points on the ellipse (a - 2)² + ((f - 0.3)/0.1)² = 1: three or more
/// levels of each and no line, yet 1, a, f, a², f² are dependent.
TEST(ForceErrorFit, RefusesPointsOnOneConic) {
  std::vector<CalibrationPoint> points;
  for (int k = 0; k < 8; ++k) {
    const double t = k * M_PI / 4, a = 2 + std::cos(t), f = 0.3 + 0.1 * std::sin(t);
    points.push_back({a, f, exact_y(kKnown, a, f)});
  }
  const std::string message = fit_error(points);
  EXPECT_TRUE(HasSubstr("conic", message));
  EXPECT_TRUE(HasSubstr("not determined", message));
}

TEST(ForceErrorFit, RefusesNearlyEqualFeeds) {
  const auto points = grid(kKnown, {1, 2, 3}, {0.1, 0.1 + 1e-7, 0.1 + 2e-7});
  const std::string message = fit_error(points);
  EXPECT_TRUE(HasSubstr("ill-conditioned: condition number", message));
  EXPECT_TRUE(HasSubstr("spread the calibration's a and f", message));
  // The same design with levels 1e-3 apart is accepted (condition ~1e5).
  EXPECT_NO_THROW(fit_force_error_model(grid(kKnown, {1, 2, 3}, {0.1, 0.101, 0.102})));
}

TEST(ForceErrorSetup, CorrectionOpposesThePredictedError) {
  // y(2, 0.2) = 0.012 + 0.036 + 0.018 + 0.016 - 0.014 + 0.006 = 0.074 mm.
  EXPECT_NEAR(kKnown.error_at(2, 0.2), 0.074, 1e-16);
  EXPECT_NEAR(setup_correction(kKnown, 2, 0.2), -0.074, 1e-16);
  const ForceErrorModel negative{-0.01, 0, 0, 0, 0, 0};
  EXPECT_EQ(setup_correction(negative, 1, 0.1), 0.01);
}

/// The textbook root (-B + sqrt(B² - 4AC)) / 2A in long double: no
/// cancellation when B < 0, the case used here.
TEST(ForceErrorFeed, IncreasingErrorMatchesTheClosedForm) {
  const ForceErrorModel m{0.01, 0.002, -0.02, 0.01, 0.001, 0.3};  // y' = -0.02 + 0.01 a + 0.6 f > 0 on the range
  const double a = 1.5, target = 0.02;
  const long double A = m.b22, B = m.b2 + m.b12 * 1.5L, C = m.b0 + m.b1 * 1.5L + m.b11 * 1.5L * 1.5L - target;
  const double want = static_cast<double>((-B + std::sqrt(B * B - 4 * A * C)) / (2 * A));
  const FeedChoice choice = feed_for_error(m, a, target, 0.05, 0.5);
  ASSERT_EQ(choice.status, FeedStatus::solved);
  EXPECT_NEAR(choice.feed, want, 1e-15);
  EXPECT_NEAR(choice.error, target, 1e-16);
  EXPECT_EQ(choice.roots_in_range, 1);
  EXPECT_EQ(choice.error_min, m.error_at(a, 0.05));
  EXPECT_EQ(choice.error_max, m.error_at(a, 0.5));
  EXPECT_FALSE(choice.every_feed);
}

/// y - target = 2 (f - 0.1)(f - 0.3): roots 0.1 and 0.3, vertex 0.2.
constexpr double kTarget = 0.03;
constexpr ForceErrorModel kTwoRoots{0.06 + kTarget, 0, -0.8, 0, 0, 2};

TEST(ForceErrorFeed, TwoRootsChooseTheLarger) {
  FeedChoice choice = feed_for_error(kTwoRoots, 1, kTarget, 0.05, 0.5);
  ASSERT_EQ(choice.status, FeedStatus::solved);
  EXPECT_NEAR(choice.feed, 0.3, 1e-16);
  EXPECT_EQ(choice.roots_in_range, 2);
  EXPECT_NEAR(choice.error_min, kTarget - 0.02, 1e-16);           // at the vertex f = 0.2
  EXPECT_NEAR(choice.error_max, kTarget + 2 * 0.4 * 0.2, 1e-16);  // at f = 0.5
  choice = feed_for_error(kTwoRoots, 1, kTarget, 0.05, 0.2);
  ASSERT_EQ(choice.status, FeedStatus::solved);
  EXPECT_NEAR(choice.feed, 0.1, 1e-16);
  EXPECT_EQ(choice.roots_in_range, 1);
}

TEST(ForceErrorFeed, NoRootReportsTheReachableRange) {
  FeedChoice choice = feed_for_error(kTwoRoots, 1, kTarget - 0.05, 0.05, 0.5);  // below the vertex
  EXPECT_EQ(choice.status, FeedStatus::none);
  EXPECT_TRUE(std::isnan(choice.feed));
  EXPECT_EQ(choice.roots_in_range, 0);
  EXPECT_NEAR(choice.error_min, kTarget - 0.02, 1e-16);
  EXPECT_NEAR(choice.error_max, kTarget + 2 * 0.4 * 0.2, 1e-16);  // at f = 0.5
  // Between the roots, where y < target throughout: the range is y at the ends.
  choice = feed_for_error(kTwoRoots, 1, kTarget, 0.15, 0.25);
  EXPECT_EQ(choice.status, FeedStatus::none);
  EXPECT_NEAR(choice.error_min, kTarget - 0.02, 1e-16);             // the vertex 0.2 is inside
  EXPECT_NEAR(choice.error_max, kTarget - 2 * 0.05 * 0.15, 1e-16);  // at either end
  choice = feed_for_error(kTwoRoots, 1, kTarget, 0.32, 0.4);
  EXPECT_EQ(choice.status, FeedStatus::none);
  EXPECT_EQ(choice.error_min, kTwoRoots.error_at(1, 0.32));
  EXPECT_EQ(choice.error_max, kTwoRoots.error_at(1, 0.4));
}

TEST(ForceErrorFeed, LinearAndNearlyLinearCases) {
  // y = 0.01 + 0.02 a + (0.1 + 0.05 a) f; at a = 2: 0.05 + 0.2 f = 0.09 at f = 0.2.
  const ForceErrorModel linear{0.01, 0.02, 0.1, 0.05, 0, 0};
  const FeedChoice exact = feed_for_error(linear, 2, 0.09, 0.05, 0.5);
  ASSERT_EQ(exact.status, FeedStatus::solved);
  EXPECT_NEAR(exact.feed, 0.2, 1e-15);
  EXPECT_EQ(exact.roots_in_range, 1);
  ForceErrorModel nearly = linear;
  nearly.b22 = 1e-18;
  const FeedChoice close = feed_for_error(nearly, 2, 0.09, 0.05, 0.5);
  ASSERT_EQ(close.status, FeedStatus::solved);
  EXPECT_NEAR(close.feed, exact.feed, 1e-12);
  EXPECT_EQ(close.roots_in_range, 1);  // the other root, ~ -2e17, is far out
  nearly.b22 = -1e-18;
  EXPECT_NEAR(feed_for_error(nearly, 2, 0.09, 0.05, 0.5).feed, exact.feed, 1e-12);
}

TEST(ForceErrorFeed, RootAtTheRangeEndCounts) {
  const ForceErrorModel y_is_f{0, 0, 1, 0, 0, 0};
  FeedChoice choice = feed_for_error(y_is_f, 1, 0.5, 0.05, 0.5);
  ASSERT_EQ(choice.status, FeedStatus::solved);
  EXPECT_EQ(choice.feed, 0.5);
  choice = feed_for_error(y_is_f, 1, 0.05, 0.05, 0.5);
  ASSERT_EQ(choice.status, FeedStatus::solved);
  EXPECT_EQ(choice.feed, 0.05);
  // 1e-13 of the range beyond the end rounds onto the end; 1e-9 does not.
  choice = feed_for_error(y_is_f, 1, 0.5 * (1 + 1e-13), 0.05, 0.5);
  ASSERT_EQ(choice.status, FeedStatus::solved);
  EXPECT_EQ(choice.feed, 0.5);
  EXPECT_EQ(feed_for_error(y_is_f, 1, 0.5 * (1 + 1e-9), 0.05, 0.5).status, FeedStatus::none);
  // A single feed is a range too.
  EXPECT_EQ(feed_for_error(y_is_f, 1, 0.2, 0.2, 0.2).status, FeedStatus::solved);
}

TEST(ForceErrorFeed, ConstantErrorSolvesOnlyAtItsValue) {
  const ForceErrorModel flat{0.01, 0.02, 0.1, -0.05, 0, 0};  // at a = 2 the f terms cancel: y = 0.05
  FeedChoice choice = feed_for_error(flat, 2, 0.05, 0.05, 0.5);
  ASSERT_EQ(choice.status, FeedStatus::solved);
  EXPECT_TRUE(choice.every_feed);
  EXPECT_EQ(choice.feed, 0.5);
  EXPECT_EQ(choice.roots_in_range, 1);
  EXPECT_NEAR(choice.error_min, 0.05, 1e-17);
  EXPECT_NEAR(choice.error_max, 0.05, 1e-17);
  choice = feed_for_error(flat, 2, 0.0501, 0.05, 0.5);
  EXPECT_EQ(choice.status, FeedStatus::none);
  EXPECT_FALSE(choice.every_feed);
}

TEST(ForceErrorFeed, RefusesBadRanges) {
  auto message = [](double a, double target, double f_min, double f_max) -> std::string {
    try {
      feed_for_error(kKnown, a, target, f_min, f_max);
    } catch (const tk::Error& e) {
      return e.what();
    }
    return "(no error)";
  };
  EXPECT_TRUE(HasSubstr("exceeds f_max", message(1, 0.01, 0.5, 0.1)));
  EXPECT_TRUE(HasSubstr("f_min must be positive", message(1, 0.01, 0, 0.1)));
  EXPECT_TRUE(HasSubstr("f_min must be positive", message(1, 0.01, -0.1, 0.1)));
  EXPECT_TRUE(HasSubstr("non-finite", message(NAN, 0.01, 0.05, 0.1)));
  EXPECT_TRUE(HasSubstr("non-finite", message(1, INFINITY, 0.05, 0.1)));
  EXPECT_TRUE(HasSubstr("non-finite", message(1, 0.01, 0.05, INFINITY)));
  ForceErrorModel bad = kKnown;
  bad.b22 = NAN;
  EXPECT_THROW(feed_for_error(bad, 1, 0.01, 0.05, 0.5), tk::Error);
}

/// 200 random models and targets against a scan of y - target on 2e5 cells:
/// solved exactly when the scan sees a sign change, and the chosen feed in
/// (or at) the cell of the largest one.
TEST(ForceErrorFeed, AgreesWithABruteForceScan) {
  std::mt19937_64 rng(7);
  auto uniform = [&rng](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
  constexpr int kCells = 200000;
  int solved = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const ForceErrorModel m{uniform(-0.05, 0.05), uniform(-0.05, 0.05), uniform(-0.5, 0.5),
                            uniform(-0.2, 0.2),   uniform(-0.01, 0.01), uniform(-2, 2)};
    const double a = uniform(0.5, 3), f_min = uniform(0.03, 0.2), f_max = f_min + uniform(0.05, 0.4);
    // Half the targets are reached somewhere in range; the others may or may not be.
    const double target =
        trial % 2 ? m.error_at(a, uniform(f_min, f_max)) : m.error_at(a, uniform(f_min, f_max)) + uniform(-0.05, 0.05);
    const FeedChoice choice = feed_for_error(m, a, target, f_min, f_max);

    const double h = (f_max - f_min) / kCells;
    auto g = [&](int i) { return m.error_at(a, i == kCells ? f_max : f_min + i * h) - target; };
    int largest = -1;  // the cell [f_i, f_i+1] of the largest sign change
    for (int i = kCells - 1; i >= 0 && largest < 0; --i)
      if ((g(i) <= 0 && g(i + 1) >= 0) || (g(i) >= 0 && g(i + 1) <= 0)) largest = i;
    ASSERT_EQ(choice.status == FeedStatus::solved, largest >= 0) << "trial " << trial;
    if (largest < 0) continue;
    ++solved;
    EXPECT_GE(choice.feed, f_min + largest * h - 1e-12) << "trial " << trial;
    EXPECT_LE(choice.feed, f_min + (largest + 1) * h + 1e-12) << "trial " << trial;
    EXPECT_NEAR(choice.error, target, 1e-12) << "trial " << trial;
  }
  EXPECT_GT(solved, 100);  // both outcomes were exercised
  EXPECT_LT(solved, 200);
}

TEST(ForceErrorFeed, StatusNames) {
  EXPECT_EQ(feed_status_name(FeedStatus::solved), "solved");
  EXPECT_EQ(feed_status_name(FeedStatus::none), "none");
}

}  // namespace
