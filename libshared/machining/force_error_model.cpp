/// @file force_error_model.cpp
/// @brief Least-squares calibration of the quadratic force-error model and
/// its inversions: the set-up correction and the feed for a target error.
#include "machining/force_error_model.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <set>

#include "io/error.hpp"

namespace tk::machining {

namespace {

constexpr int kTerms = 6;  // 1, a, f, a f, a², f²
constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// Above this the scaled design is singular to working precision (σ_min is
/// rounding noise, ~1/ε = 4.5e15 times below σ_max; exact conics give 1e16 and
/// more), so the points lie on a conic rather than near one.
constexpr double kSingularCondition = 1e15;

void check_finite(std::span<const CalibrationPoint> points) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    const CalibrationPoint& p = points[i];
    for (const auto& [name, value] : {std::pair{"a", p.a}, std::pair{"f", p.f}, std::pair{"y", p.y}})
      if (!std::isfinite(value))
        throw Error(fmt::format("calibration point {}: {} is not finite ({})", i + 1, name, value));
  }
}

template <class Field>
std::size_t distinct_count(std::span<const CalibrationPoint> points, Field field) {
  std::set<double> values;
  for (const CalibrationPoint& p : points) values.insert(field(p));
  return values.size();
}

/// (a, f) on one straight line: the correlation of a and f is ±1 to rounding.
/// Then f is a linear function of a and the columns 1, a, f are dependent.
bool collinear(std::span<const CalibrationPoint> points) {
  long double mean_a = 0, mean_f = 0;
  for (const CalibrationPoint& p : points) {
    mean_a += p.a;
    mean_f += p.f;
  }
  mean_a /= points.size();
  mean_f /= points.size();
  long double saa = 0, sff = 0, saf = 0;
  for (const CalibrationPoint& p : points) {
    const long double da = p.a - mean_a, df = p.f - mean_f;
    saa += da * da;
    sff += df * df;
    saf += da * df;
  }
  return saf * saf >= (1 - 1e-12L) * saa * sff;
}

void check_design_shape(std::span<const CalibrationPoint> points) {
  if (points.size() < kTerms)
    throw Error(fmt::format("the calibration needs at least 6 points (a, f, y) for the six coefficients; it has {}",
                            points.size()));
  check_finite(points);
  // A quadratic in f needs three levels of f to pin its curvature b22; the same for a.
  if (const std::size_t feeds = distinct_count(points, [](const CalibrationPoint& p) { return p.f; }); feeds < 3)
    throw Error(fmt::format("the calibration needs at least 3 distinct feeds f; it has {}", feeds));
  if (const std::size_t depths = distinct_count(points, [](const CalibrationPoint& p) { return p.a; }); depths < 3)
    throw Error(fmt::format("the calibration needs at least 3 distinct depths a; it has {}", depths));
  if (collinear(points))
    throw Error(
        "the calibration's (a, f) lie on one line (a and f collinear), so the six coefficients are not "
        "determined; vary a and f independently");
}

}  // namespace

double ForceErrorModel::error_at(double a, double f) const {
  return b0 + a * (b1 + b11 * a + b12 * f) + f * (b2 + b22 * f);
}

ForceErrorFit fit_force_error_model(std::span<const CalibrationPoint> points) {
  check_design_shape(points);
  const auto n = static_cast<Eigen::Index>(points.size());
  Eigen::MatrixXd design(n, kTerms);
  Eigen::VectorXd y(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const CalibrationPoint& p = points[static_cast<std::size_t>(i)];
    design.row(i) << 1, p.a, p.f, p.a * p.f, p.a * p.a, p.f * p.f;
    y(i) = p.y;
  }
  // a ~ 1 mm and f² ~ 0.01 mm²: without scaling the condition number would
  // measure the units, not how well the points determine the coefficients.
  Eigen::Matrix<double, kTerms, 1> scale = design.cwiseAbs().colwise().maxCoeff().transpose();
  for (double& s : scale) s = s > 0 ? s : 1;  // an all-zero column (a f on the axes) stays singular
  design *= scale.cwiseInverse().asDiagonal();

  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(design);
  // Q is orthogonal, so the singular values of the design are those of R (6×6).
  const Eigen::Matrix<double, kTerms, kTerms> r = qr.matrixQR().topRows(kTerms).triangularView<Eigen::Upper>();
  const auto sigma = Eigen::JacobiSVD<Eigen::Matrix<double, kTerms, kTerms>>(r).singularValues();
  const double condition =
      sigma(kTerms - 1) > 0 ? sigma(0) / sigma(kTerms - 1) : std::numeric_limits<double>::infinity();
  if (condition > kSingularCondition)
    throw Error(
        fmt::format("the calibration's (a, f) lie on one conic, so the six coefficients are not determined "
                    "(condition number {:.1e} of the scaled design); spread the calibration's a and f",
                    condition));
  if (condition > kMaxDesignCondition)
    throw Error(fmt::format(
        "ill-conditioned: condition number {:.1e} of the scaled design; spread the calibration's a and f", condition));

  const Eigen::Matrix<double, kTerms, 1> beta = qr.solve(y).cwiseQuotient(scale);
  ForceErrorFit fit;
  fit.model = {beta(0), beta(1), beta(2), beta(3), beta(4), beta(5)};
  fit.points = points.size();
  fit.condition = condition;
  double mean_y = 0;
  for (const CalibrationPoint& p : points) mean_y += p.y;
  mean_y /= static_cast<double>(points.size());
  double sse = 0, sst = 0;
  for (const CalibrationPoint& p : points) {
    const double fitted = fit.model.error_at(p.a, p.f);
    fit.fitted.push_back(fitted);
    fit.residuals.push_back(p.y - fitted);
    sse += (p.y - fitted) * (p.y - fitted);
    sst += (p.y - mean_y) * (p.y - mean_y);
  }
  const double dof = static_cast<double>(points.size()) - kTerms;
  fit.r2 = sst > 0 ? 1 - sse / sst : 1;
  fit.adjusted_r2 = dof > 0 ? 1 - (1 - fit.r2) * (static_cast<double>(points.size()) - 1) / dof : kNaN;
  fit.residual_sd = dof > 0 ? std::sqrt(sse / dof) : kNaN;
  return fit;
}

double setup_correction(const ForceErrorModel& m, double a, double f) { return -m.error_at(a, f); }

namespace {

/// B² - 4AC with each product's rounding error recovered by fma, so a near
/// double root keeps the digits that B² and 4AC have in common.
double discriminant(double a, double b, double c) {
  const double bb = b * b, four_ac = 4 * a * c;
  const double bb_err = std::fma(b, b, -bb), four_ac_err = std::fma(4 * a, c, -four_ac);
  return (bb - four_ac) + (bb_err - four_ac_err);
}

/// The real roots of a x² + b x + c (a != 0), distinct, without cancellation.
std::vector<double> quadratic_roots(double a, double b, double c) {
  double disc = discriminant(a, b, c);
  // Negative by rounding only: the parabola touches zero, a double root.
  if (disc < 0 && -disc <= 8 * kEps * (b * b + 4 * std::abs(a * c))) disc = 0;
  if (disc < 0) return {};
  if (disc == 0) return {-b / (2 * a)};
  const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
  const double r1 = q / a, r2 = c / q;  // q != 0: disc > 0 makes |q| > 0
  return r1 == r2 ? std::vector<double>{r1} : std::vector<double>{r1, r2};
}

}  // namespace

FeedChoice feed_for_error(const ForceErrorModel& m, double a, double target, double f_min, double f_max) {
  for (const double v : {m.b0, m.b1, m.b2, m.b12, m.b11, m.b22, a, target, f_min, f_max})
    if (!std::isfinite(v)) throw Error(fmt::format("feed for error: non-finite input ({})", v));
  if (!(f_min > 0)) throw Error(fmt::format("feed for error: f_min must be positive, not {}", f_min));
  if (f_min > f_max) throw Error(fmt::format("feed for error: f_min {} exceeds f_max {}", f_min, f_max));

  FeedChoice choice;
  const double qa = m.b22, qb = m.b2 + m.b12 * a, qc = m.b0 + m.b1 * a + m.b11 * a * a - target;
  const double y_lo = m.error_at(a, f_min), y_hi = m.error_at(a, f_max);
  choice.error_min = std::min(y_lo, y_hi);
  choice.error_max = std::max(y_lo, y_hi);
  if (qa != 0) {
    const double vertex = -qb / (2 * qa);
    if (vertex > f_min && vertex < f_max) {
      const double y_vertex = m.error_at(a, vertex);
      choice.error_min = std::min(choice.error_min, y_vertex);
      choice.error_max = std::max(choice.error_max, y_vertex);
    }
  }

  std::vector<double> roots;
  if (qa != 0) {
    // Scaling by a power of two leaves the roots (and every bit of the
    // coefficients) alone and keeps b² and 4ac inside double range.
    const double scale = std::ldexp(1.0, -std::ilogb(std::max({std::abs(qa), std::abs(qb), std::abs(qc)})));
    roots = quadratic_roots(qa * scale, qb * scale, qc * scale);
  } else if (qb != 0) {
    roots = {-qc / qb};
  } else {
    // y does not depend on f: every feed or none. Equal within the rounding of the sum that formed qc.
    const double terms = std::abs(m.b0) + std::abs(m.b1 * a) + std::abs(m.b11 * a * a) + std::abs(target);
    if (std::abs(qc) <= 8 * kEps * terms) {
      choice.status = FeedStatus::solved;
      choice.every_feed = true;
      choice.roots_in_range = 1;
      choice.feed = f_max;
      choice.error = y_hi;
    }
    return choice;
  }

  const double tol = 1e-12 * std::max(f_max - f_min, f_max);
  for (const double root : roots) {
    if (!std::isfinite(root) || root < f_min - tol || root > f_max + tol) continue;
    const double feed = std::clamp(root, f_min, f_max);
    ++choice.roots_in_range;
    if (choice.status == FeedStatus::none || feed > choice.feed) choice.feed = feed;
    choice.status = FeedStatus::solved;
  }
  if (choice.status == FeedStatus::solved) choice.error = m.error_at(a, choice.feed);
  return choice;
}

std::string_view feed_status_name(FeedStatus status) { return status == FeedStatus::solved ? "solved" : "none"; }

}  // namespace tk::machining
