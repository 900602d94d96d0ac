/// @file force_error_model.hpp
/// @brief The force-induced dimensional error model of adaptive lathe control
/// (Georgiev et al., "Intelligent lathe turning computer control system
/// model", eq. 2): before a cut, the measured allowance (depth of cut a, mm)
/// sets the feed f (mm/rev) for a constant error, or the set-up correction at
/// a constant feed, through the quadratic
///   y = b0 + b1 a + b2 f + b12 a f + b11 a² + b22 f²   (y in mm).
/// The coefficients come from a least-squares fit to calibration cuts (the
/// paper does not say how they are found).
#pragma once

#include <cstddef>
#include <limits>
#include <span>
#include <string_view>
#include <vector>

namespace tk::machining {

struct ForceErrorModel {
  double b0 = 0, b1 = 0, b2 = 0, b12 = 0, b11 = 0, b22 = 0;
  /// y(a, f), the predicted force-induced error (mm).
  double error_at(double a, double f) const;
};

/// One calibration cut: depth a (mm), feed f (mm/rev), measured error y (mm).
struct CalibrationPoint {
  double a = 0, f = 0, y = 0;
};

struct ForceErrorFit {
  ForceErrorModel model;
  std::size_t points = 0;
  /// 1 - SSE/SST, SST about the mean of y. When SST == 0 (every y equal) the
  /// constant model reproduces the data and there is nothing left to explain:
  /// r2 (and adjusted_r2) is 1 then, not 0/0.
  double r2 = 0;
  /// 1 - (1 - r2)(n - 1)/(n - 6); NaN when points == 6 (no residual degrees of freedom).
  double adjusted_r2 = 0;
  /// sqrt(SSE/(n - 6)), mm; NaN when points == 6.
  double residual_sd = 0;
  /// 2-norm condition number of the design with each column divided by its max |value|.
  double condition = 0;
  std::vector<double> fitted, residuals;  ///< per point, input order; residual = y - fitted
};

/// Largest condition number of the scaled design that the fit accepts.
/// Well-spread calibrations (3 or more levels of a and of f across their
/// working ranges) give 1e1..1e3. Rounding alone costs about condition * 1e-16
/// of the coefficients, so 1e8 still leaves 8 good digits; above it the points
/// nearly lie on one conic, and the measurement noise of y is amplified by the
/// same factor into coefficients that mean nothing.
inline constexpr double kMaxDesignCondition = 1e8;

/// Least squares on the column-scaled design (Householder QR with column
/// pivoting). Throws tk::Error with a one-line message when there are fewer
/// than 6 points, a value is not finite, fewer than 3 distinct feeds or
/// depths, all (a, f) on one line, all (a, f) on one conic, or the condition
/// number exceeds kMaxDesignCondition. Distinct means different doubles;
/// nearly equal levels are left to the condition check.
ForceErrorFit fit_force_error_model(std::span<const CalibrationPoint> points);

/// The set-up correction (mm) that compensates the predicted error at a fixed feed: -y(a, f).
double setup_correction(const ForceErrorModel& m, double a, double f);

enum class FeedStatus { solved, none };

struct FeedChoice {
  FeedStatus status = FeedStatus::none;
  double feed = std::numeric_limits<double>::quiet_NaN();   ///< the chosen feed when solved
  double error = std::numeric_limits<double>::quiet_NaN();  ///< y(a, feed) when solved
  double error_min = 0, error_max = 0;                      ///< range of y(a, f) over [f_min, f_max]
  int roots_in_range = 0;                                   ///< distinct roots of y(a, f) = target in range
  /// y(a, ·) is constant and equals target, so every feed does: feed is
  /// f_max then and roots_in_range is 1.
  bool every_feed = false;
};

/// The feed f in [f_min, f_max] with y(a, f) = target: the roots of
/// b22 f² + (b2 + b12 a) f + (b0 + b1 a + b11 a² - target) = 0 by the
/// cancellation-free formula (q = -(B + sign(B) sqrt(B² - 4AC))/2, roots q/A
/// and C/q; the discriminant with fused multiply-adds), so a tiny b22 gives the
/// linear root to full precision; b22 == 0 is solved as linear. The LARGEST
/// root in range is chosen (the most productive feed); none when no root is.
/// Roots within 1e-12 of max(f_max - f_min, f_max) outside the range count as
/// at its end. A discriminant negative only by rounding counts as a double root.
/// A constant y (b22 == 0 and b2 + b12 a == 0) is solved, with every_feed,
/// only when it equals target within 8 ulp of the terms summed
/// (|b0| + |b1 a| + |b11 a²| + |target|).
/// Throws tk::Error for f_min > f_max, f_min <= 0 or non-finite inputs.
FeedChoice feed_for_error(const ForceErrorModel& m, double a, double target, double f_min, double f_max);

std::string_view feed_status_name(FeedStatus status);  ///< "solved", "none"

}  // namespace tk::machining
