/// @file subtuning.cpp
#include "quality/subtuning.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "io/error.hpp"

namespace tk::quality {

std::string_view decision_name(Decision d) {
  switch (d) {
    case Decision::insufficient: return "insufficient";
    case Decision::none: return "none";
    case Decision::subtune: return "subtune";
  }
  return "?";
}

SubTuner::SubTuner(const SubTuneSettings& settings)
    : settings_(settings),
      critical_(settings.alpha, settings.alternative == Alternative::two_sided ? Sidedness::two : Sidedness::one),
      spread_floor_sq_(settings.resolution * settings.resolution / 12) {
  // Two parts always lie on their line: a spread needs three.
  if (settings.min_parts < 3)
    throw Error(fmt::format("a trend test needs at least 3 parts in a run, not {}", settings.min_parts));
  if (std::isinf(settings.target)) throw Error("the sub-tuning target must be finite");
  if (!(settings.resolution >= 0) || !std::isfinite(settings.resolution))
    throw Error(fmt::format("the gauge resolution must be 0 or positive, not {}", settings.resolution));
}

void SubTuner::start_run() {
  ++run_;
  n_ = 0;
  mean_size_ = co_moment_ = sse_ = 0;
}

void SubTuner::reset() {
  start_run();
  run_ = 1;
  offset_ = 0;
}

SubTuneStep SubTuner::observe(double size) {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  ++n_;
  // The x's are 1..n, so their mean and moment are exact closed forms, and the
  // previous mean of x is n/2: only the sizes need Welford's update.
  const double n = static_cast<double>(n_);
  if (n_ == 1) origin_ = size;
  size -= origin_;  // sizes near the run's first keep their digits: 40.0012 − 40.0007, not 40.0012
  if (n_ >= 3) {
    // The residual sum of squares by recursive least squares: the new part's
    // error against the line so far, e, adds e²/(1 + h), h its leverage. Each
    // step adds noise-sized terms, where Σ(A − Ā)² − b·Σ(i − ī)(A − Ā) would
    // cancel a drift's huge moment down to the noise.
    const double m = n - 1, moment_i_before = m * (m * m - 1) / 12;
    const double b_before = co_moment_ / moment_i_before;
    const double e = size - (mean_size_ + b_before * (n / 2));  // the line so far at i = n, n/2 past its x̄ = n/2
    // 1 + h = 1 + 1/m + (n/2)²/Σ(i − ī)² = n(n + 1)/((n − 1)(n − 2)) for x = 1..m, new x = n.
    sse_ += e * e * (m * (n - 2)) / (n * (n + 1));
  }
  const double dsize = size - mean_size_;
  mean_size_ += dsize / n;
  co_moment_ += n / 2 * (size - mean_size_);
  const double mean_i = (n + 1) / 2, moment_i = n * (n * n - 1) / 12;

  SubTuneStep step;
  step.run = run_, step.n = n_, step.offset = offset_;
  step.a = step.b = step.s = step.t = step.t_crit = nan;
  if (n_ >= 2) {
    step.b = co_moment_ / moment_i;
    step.a = origin_ + (mean_size_ - step.b * mean_i);
  }
  if (n_ < settings_.min_parts) return step;

  const bool paper = settings_.statistic == TrendStatistic::paper;
  const double spread_sq = std::max(sse_ / (paper ? n - 1 : n - 2), spread_floor_sq_);
  step.s = std::sqrt(spread_sq);
  // |ã − A_TN| = n |b̃|; its standard error is s n/√Σ(i − ī)² (slope) or, as eq. (6) prints it, S_N √(2/n).
  const double rise = std::abs(step.b) * (paper ? n : std::sqrt(moment_i));
  const double scale = paper ? std::sqrt(n / 2) : 1.0;
  step.t = step.s > 0 ? rise / step.s * scale : (rise > 0 ? std::numeric_limits<double>::infinity() : 0.0);
  step.df = paper ? 2 * (n_ - 1) : n_ - 2;
  step.t_crit = critical_.at(step.df);
  const bool right_way = settings_.alternative == Alternative::two_sided ||
                         (settings_.alternative == Alternative::greater ? step.b > 0 : step.b < 0);
  const bool significant = right_way && step.t > step.t_crit;
  if (!significant) {
    step.decision = Decision::none;
    return step;
  }
  step.decision = Decision::subtune;
  step.correction = std::isnan(settings_.target) ? -step.b * n : settings_.target - (step.a + step.b * n);
  offset_ += step.correction;
  step.offset = offset_;
  start_run();
  return step;
}

}  // namespace tk::quality
