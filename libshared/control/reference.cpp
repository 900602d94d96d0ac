/// @file reference.cpp
#include "control/reference.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "io/error.hpp"
#include "io/record_fields.hpp"
#include "io/record_reader.hpp"

namespace tk::control {

namespace {
void require_finite(double v, const char* what) {
  if (!std::isfinite(v)) throw Error(fmt::format("the reference {} must be a finite number, not {}", what, v));
}
}  // namespace

Reference Reference::analytic(Kind kind, std::pair<double, const char*> p1, std::pair<double, const char*> p2,
                              const char* description) {
  require_finite(p1.first, p1.second);
  require_finite(p2.first, p2.second);
  Reference r;
  r.kind_ = kind, r.p1_ = p1.first, r.p2_ = p2.first;
  r.description_ = fmt::format(fmt::runtime(description), p1.first, p2.first);
  return r;
}

Reference Reference::sine(double amplitude_mm, double omega_rad_s) {
  return analytic(Kind::sine, {amplitude_mm, "amplitude"}, {omega_rad_s, "frequency"}, "{:g} mm sin({:g} rad/s t)");
}

Reference Reference::step(double height_mm, double at_s) {
  return analytic(Kind::step, {height_mm, "step height"}, {at_s, "step time"}, "{:g} mm step at {:g} s");
}

Reference Reference::ramp(double slope_mm_s, double at_s) {
  return analytic(Kind::ramp, {slope_mm_s, "ramp slope"}, {at_s, "ramp start"}, "{:g} mm/s ramp from {:g} s");
}

Reference Reference::from_records(const std::string& path) {
  Reference r;
  r.kind_ = Kind::samples;
  io::RecordReader reader({path});
  reader.expect_columns({{"t", "x"}});
  Record record;
  bool have_v = true, have_a = true;
  while (reader.next(record)) {
    const Location where = reader.where();
    const double t = io::number_field(record, "t", where), x = io::number_field(record, "x", where);
    if (!std::isfinite(t) || !std::isfinite(x)) throw Error("t and x must be finite numbers", where);
    if (!r.t_.empty() && !(t > r.t_.back()))
      throw Error(fmt::format("t must increase strictly: {} after {}", t, r.t_.back()), where);
    const std::optional<double> v = io::optional_number_field(record, "v", where),
                                a = io::optional_number_field(record, "a", where);
    if ((v && !std::isfinite(*v)) || (a && !std::isfinite(*a))) throw Error("v and a must be finite numbers", where);
    r.t_.push_back(t), r.x_.push_back(x), r.v_.push_back(v.value_or(0)), r.a_.push_back(a.value_or(0));
    have_v = have_v && v.has_value(), have_a = have_a && a.has_value();
  }
  const std::size_t n = r.t_.size();
  if (n < 2)
    throw Error(fmt::format("a reference needs at least two samples, found {}", n),
                Location{path == "-" ? "<stdin>" : path});
  // Finite differences (one-sided at the ends) where a column is missing.
  const auto derivative = [&](const std::vector<double>& f, std::vector<double>& out) {
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t lo = i == 0 ? 0 : i - 1, hi = i + 1 == n ? n - 1 : i + 1;
      out[i] = (f[hi] - f[lo]) / (r.t_[hi] - r.t_[lo]);
    }
  };
  if (!have_v) derivative(r.x_, r.v_);
  if (!have_a) derivative(r.v_, r.a_);
  for (std::size_t i = 0; i < n; ++i)  // samples so close in time that a difference overflows
    if (!std::isfinite(r.v_[i]) || !std::isfinite(r.a_[i]))
      throw Error(fmt::format("the derivatives of the reference are not finite near t = {} s", r.t_[i]),
                  Location{path});
  r.description_ = fmt::format("{} samples from {}", n, path);
  return r;
}

ReferenceSample Reference::at(double t) const {
  switch (kind_) {
    case Kind::sine: {
      const double s = std::sin(p2_ * t), c = std::cos(p2_ * t);
      return {p1_ * s, p1_ * p2_ * c, -p1_ * p2_ * p2_ * s};
    }
    case Kind::step: return {t >= p2_ ? p1_ : 0, 0, 0};
    case Kind::ramp: return {t > p2_ ? p1_ * (t - p2_) : 0, t > p2_ ? p1_ : 0, 0};
    case Kind::samples: break;
  }
  if (t < t_.front()) return {x_.front(), 0, 0};
  if (t == t_.front()) return {x_.front(), v_.front(), a_.front()};
  if (t >= t_.back()) return {x_.back(), 0, 0};
  const std::size_t i = static_cast<std::size_t>(std::upper_bound(t_.begin(), t_.end(), t) - t_.begin()) - 1;
  const double h = t_[i + 1] - t_[i], u = (t - t_[i]) / h;
  // Cubic Hermite between (x_i, v_i) and (x_{i+1}, v_{i+1}); a interpolated linearly.
  const double h00 = (1 + 2 * u) * (1 - u) * (1 - u), h10 = u * (1 - u) * (1 - u), h01 = u * u * (3 - 2 * u),
               h11 = u * u * (u - 1);
  const double d00 = 6 * u * u - 6 * u, d10 = 3 * u * u - 4 * u + 1, d01 = -d00, d11 = 3 * u * u - 2 * u;
  return {h00 * x_[i] + h10 * h * v_[i] + h01 * x_[i + 1] + h11 * h * v_[i + 1],
          (d00 * x_[i] + d01 * x_[i + 1]) / h + d10 * v_[i] + d11 * v_[i + 1], a_[i] + u * (a_[i + 1] - a_[i])};
}

}  // namespace tk::control
