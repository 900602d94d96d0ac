/// @file student_t.cpp
#include "quality/student_t.hpp"

#include <fmt/format.h>

#include <boost/math/distributions/normal.hpp>
#include <boost/math/distributions/students_t.hpp>
#include <cmath>

#include "io/error.hpp"

namespace tk::quality {

double student_t_upper_quantile(double tail, double df) {
  if (!(tail > 0 && tail < 0.5))
    throw Error(fmt::format("a t quantile's tail probability must lie in (0, 0.5), not {}", tail));
  if (!(df > 0) || !std::isfinite(df))
    throw Error(fmt::format("a t distribution needs positive degrees of freedom, not {}", df));
  return boost::math::quantile(boost::math::complement(boost::math::students_t_distribution<double>(df), tail));
}

StudentCriticalValues::StudentCriticalValues(double alpha, Sidedness sidedness)
    : tail_(sidedness == Sidedness::two ? alpha / 2 : alpha) {
  if (!(alpha > 0 && alpha < (sidedness == Sidedness::two ? 1.0 : 0.5)))
    throw Error(fmt::format("alpha must lie in (0, {}) for a {}-sided test, not {}",
                            sidedness == Sidedness::two ? 1 : 0.5, sidedness == Sidedness::two ? "two" : "one", alpha));
  normal_quantile_ = boost::math::quantile(boost::math::complement(boost::math::normal_distribution<double>(), tail_));
  // The Cornish-Fisher series (Abramowitz & Stegun 26.7.5) in powers of 1/ν.
  const double z = normal_quantile_, z2 = z * z;
  series_[0] = (z2 + 1) * z / 4;
  series_[1] = ((5 * z2 + 16) * z2 + 3) * z / 96;
  series_[2] = (((3 * z2 + 19) * z2 + 17) * z2 - 15) * z / 384;
  series_[3] = ((((79 * z2 + 776) * z2 + 1482) * z2 - 1920) * z2 - 945) * z / 92160;
}

double StudentCriticalValues::compute(std::size_t df) const {
  if (df == 0) throw Error("a t test needs at least one degree of freedom");
  if (df < kTableLimit) {
    if (table_.size() <= df) table_.resize(std::max(df + 1, 2 * table_.size()), 0.0);
    return table_[df] = student_t_upper_quantile(tail_, static_cast<double>(df));
  }
  const double v = 1.0 / static_cast<double>(df);
  return normal_quantile_ + v * (series_[0] + v * (series_[1] + v * (series_[2] + v * series_[3])));
}

}  // namespace tk::quality
