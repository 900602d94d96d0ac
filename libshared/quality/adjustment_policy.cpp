/// @file adjustment_policy.cpp
#include "quality/adjustment_policy.hpp"

#include <fmt/format.h>

#include <cmath>

#include "io/error.hpp"

namespace tk::quality {

namespace {

class NoPolicy final : public AdjustmentPolicy {
 public:
  PolicyKind kind() const override { return PolicyKind::none; }
  PolicyStep observe(double) override { return {}; }
  void reset() override {}
};

class SubTunePolicy final : public AdjustmentPolicy {
 public:
  explicit SubTunePolicy(const SubTuneSettings& s) : tuner_(s) {}
  PolicyKind kind() const override { return PolicyKind::subtune; }
  PolicyStep observe(double size) override {
    const SubTuneStep step = tuner_.observe(size);
    return {step.decision == Decision::subtune, step.correction, step.a + step.b * static_cast<double>(step.n), step.t,
            step.t_crit};
  }
  void reset() override { tuner_.reset(); }  // the t table survives the ARL's many runs

 private:
  SubTuner tuner_;
};

class ShewhartPolicy final : public AdjustmentPolicy {
 public:
  explicit ShewhartPolicy(const ChartSettings& c) : c_(c), limit_(c.shewhart_l * c.sigma) {}
  PolicyKind kind() const override { return PolicyKind::shewhart; }
  PolicyStep observe(double size) override {
    const double deviation = size - c_.target;
    const bool alarm = std::abs(deviation) > limit_;
    return {alarm, alarm ? -deviation : 0.0, size, deviation, limit_};
  }
  void reset() override {}

 private:
  ChartSettings c_;
  double limit_;
};

class EwmaPolicy final : public AdjustmentPolicy {
 public:
  explicit EwmaPolicy(const ChartSettings& c)
      : c_(c), limit_(c.ewma_l * c.sigma * std::sqrt(c.ewma_lambda / (2 - c.ewma_lambda))) {}
  PolicyKind kind() const override { return PolicyKind::ewma; }
  PolicyStep observe(double size) override {
    z_ += c_.ewma_lambda * (size - c_.target - z_);  // z as a deviation from the target
    const bool alarm = std::abs(z_) > limit_;
    const PolicyStep step{alarm, alarm ? -z_ : 0.0, c_.target + z_, z_, limit_};
    if (alarm) z_ = 0;
    return step;
  }
  void reset() override { z_ = 0; }

 private:
  ChartSettings c_;
  double limit_;
  double z_ = 0;
};

class CusumPolicy final : public AdjustmentPolicy {
 public:
  explicit CusumPolicy(const ChartSettings& c) : k_(c.cusum_k * c.sigma), h_(c.cusum_h * c.sigma), target_(c.target) {}
  PolicyKind kind() const override { return PolicyKind::cusum; }
  PolicyStep observe(double size) override {
    const double x = size - target_;
    upper_ = std::max(0.0, upper_ + x - k_);
    lower_ = std::max(0.0, lower_ - x - k_);
    upper_run_ = upper_ > 0 ? upper_run_ + 1 : 0;
    lower_run_ = lower_ > 0 ? lower_run_ + 1 : 0;
    // Montgomery's estimate of the mean while a sum is above 0: target ± (K + C/N).
    const bool up = upper_ >= lower_;
    const double shift = up ? (upper_ > 0 ? k_ + upper_ / static_cast<double>(upper_run_) : 0.0)
                            : -(k_ + lower_ / static_cast<double>(lower_run_));
    PolicyStep step{std::max(upper_, lower_) > h_, 0, target_ + shift, up ? upper_ : -lower_, h_};
    if (step.alarm) step.correction = -shift, reset();
    return step;
  }
  void reset() override { upper_ = lower_ = 0, upper_run_ = lower_run_ = 0; }

 private:
  double k_, h_, target_;
  double upper_ = 0, lower_ = 0;
  std::uint64_t upper_run_ = 0, lower_run_ = 0;
};

void check(bool ok, const char* what, double value) { require(ok, fmt::format("{}, not {}", what, value)); }

}  // namespace

std::string_view policy_name(PolicyKind kind) {
  switch (kind) {
    case PolicyKind::none: return "none";
    case PolicyKind::subtune: return "subtune";
    case PolicyKind::shewhart: return "shewhart";
    case PolicyKind::ewma: return "ewma";
    case PolicyKind::cusum: return "cusum";
  }
  return "?";
}

PolicyKind parse_policy(std::string_view name) {
  for (const PolicyKind k :
       {PolicyKind::none, PolicyKind::subtune, PolicyKind::shewhart, PolicyKind::ewma, PolicyKind::cusum})
    if (policy_name(k) == name) return k;
  throw Error(fmt::format("unknown policy '{}' (none, subtune, shewhart, ewma or cusum)", name));
}

std::unique_ptr<AdjustmentPolicy> make_policy(PolicyKind kind, const SubTuneSettings& subtune,
                                              const ChartSettings& charts) {
  check(std::isfinite(charts.target), "the target must be finite", charts.target);
  check(charts.sigma > 0 && std::isfinite(charts.sigma), "sigma must be positive", charts.sigma);
  check(charts.shewhart_l > 0, "the Shewhart L must be positive", charts.shewhart_l);
  check(charts.ewma_lambda > 0 && charts.ewma_lambda <= 1, "the EWMA λ must lie in (0, 1]", charts.ewma_lambda);
  check(charts.ewma_l > 0, "the EWMA L must be positive", charts.ewma_l);
  check(charts.cusum_k >= 0, "the CUSUM k must be 0 or positive", charts.cusum_k);
  check(charts.cusum_h > 0, "the CUSUM h must be positive", charts.cusum_h);
  switch (kind) {
    case PolicyKind::none: return std::make_unique<NoPolicy>();
    case PolicyKind::subtune: return std::make_unique<SubTunePolicy>(subtune);
    case PolicyKind::shewhart: return std::make_unique<ShewhartPolicy>(charts);
    case PolicyKind::ewma: return std::make_unique<EwmaPolicy>(charts);
    case PolicyKind::cusum: return std::make_unique<CusumPolicy>(charts);
  }
  throw Error("unknown policy");
}

}  // namespace tk::quality
