/// @file lathe_sim.cpp
#include "quality/lathe_sim.hpp"

#include <fmt/format.h>

#include <cmath>

#include "io/error.hpp"
#include "sim/gaussian_noise.hpp"

namespace tk::quality {

namespace {

/// Independent streams per source, so switching one source off (a stable
/// process, no gauge noise) leaves the others' draws unchanged.
struct LatheNoise {
  explicit LatheNoise(const LatheSettings& s)
      : allowance(s.allowance_sd_mm, s.seed * 4 + 1),
        process(s.process_sd_mm, s.seed * 4 + 2),
        gauge(s.gauge_sd_mm, s.seed * 4 + 3) {}
  sim::GaussianNoise allowance, process, gauge;
};

}  // namespace

void validate(const LatheSettings& s) {
  require(std::isfinite(s.nominal_mm) && std::isfinite(s.lower_mm) && std::isfinite(s.upper_mm),
          "the nominal size and the tolerance limits must be finite");
  require(s.lower_mm < s.nominal_mm && s.nominal_mm < s.upper_mm,
          fmt::format("the tolerance band {} to {} mm must contain the nominal {} mm", s.lower_mm, s.upper_mm,
                      s.nominal_mm));
  require(s.parts >= 1, "the batch needs at least one part");
  require(std::isfinite(s.wear_mm_per_part) && std::isfinite(s.thermal_mm), "wear and thermal drift must be finite");
  require(s.thermal_parts > 0 && std::isfinite(s.thermal_parts),
          fmt::format("the thermal time constant must be positive, not {} parts", s.thermal_parts));
  require(s.allowance_mm > 0 && std::isfinite(s.allowance_mm),
          fmt::format("the mean allowance must be positive, not {} mm", s.allowance_mm));
  for (const double sd : {s.allowance_sd_mm, s.process_sd_mm, s.gauge_sd_mm})
    require(sd >= 0 && std::isfinite(sd), fmt::format("a standard deviation must be 0 or positive, not {}", sd));
  require(s.feed_mm_rev > 0 && std::isfinite(s.feed_mm_rev),
          fmt::format("the feed must be positive, not {} mm/rev", s.feed_mm_rev));
}

double in_control_sigma(const LatheSettings& s) {
  double force_var = 0;
  if (!s.compensate_force) {
    const machining::ForceErrorModel& m = s.force_model;
    const double slope = m.b1 + m.b12 * s.feed_mm_rev + 2 * m.b11 * s.allowance_mm;  // dy/da at the mean allowance
    const double var_a = s.allowance_sd_mm * s.allowance_sd_mm;
    force_var = slope * slope * var_a + 2 * m.b11 * m.b11 * var_a * var_a;
  }
  return std::sqrt(s.process_sd_mm * s.process_sd_mm + s.gauge_sd_mm * s.gauge_sd_mm + force_var);
}

LatheSettings stable_process(LatheSettings s) {
  s.wear_mm_per_part = 0;
  s.thermal_mm = 0;
  return s;
}

LatheOutcome simulate_lathe(const LatheSettings& s, AdjustmentPolicy& policy,
                            const std::function<void(const PartRecord&)>& each_part) {
  validate(s);
  policy.reset();
  LatheNoise noise(s);
  // The set-up absorbs the mean force error, E[y] = y(ā) + b11 s² for a normal allowance.
  const double mean_force_error =
      s.force_model.error_at(s.allowance_mm, s.feed_mm_rev) + s.force_model.b11 * s.allowance_sd_mm * s.allowance_sd_mm;
  LatheOutcome out;
  double offset = 0, abs_sum = 0, square_sum = 0;
  for (std::uint64_t i = 1; i <= s.parts; ++i) {
    PartRecord r;
    r.part = i;
    do r.allowance_mm = s.allowance_mm + noise.allowance.next();
    while (r.allowance_mm <= 0);
    const double force_error =
        s.compensate_force ? 0.0 : s.force_model.error_at(r.allowance_mm, s.feed_mm_rev) - mean_force_error;
    const double drift = s.wear_mm_per_part * static_cast<double>(i) +
                         s.thermal_mm * -std::expm1(-static_cast<double>(i) / s.thermal_parts);
    r.size_mm = s.nominal_mm + offset + drift + force_error + noise.process.next();
    r.measured_mm = r.size_mm + noise.gauge.next();
    const PolicyStep step = policy.observe(r.measured_mm);
    r.alarm = step.alarm;
    r.correction_mm = step.correction;
    r.level_mm = step.level;
    if (step.alarm) ++out.corrections, offset += step.correction;
    r.offset_mm = offset;

    const double deviation = r.size_mm - s.nominal_mm;
    if (r.size_mm >= s.lower_mm && r.size_mm <= s.upper_mm) ++out.in_tolerance;
    abs_sum += std::abs(deviation);
    square_sum += deviation * deviation;
    out.max_abs_deviation_mm = std::max(out.max_abs_deviation_mm, std::abs(deviation));
    if (each_part) each_part(r);
  }
  out.parts = s.parts;
  out.mean_abs_deviation_mm = abs_sum / static_cast<double>(s.parts);
  out.rms_deviation_mm = std::sqrt(square_sum / static_cast<double>(s.parts));
  return out;
}

RunLengthEstimate average_run_length(PolicyKind kind, const SubTuneSettings& subtune, const ChartSettings& charts,
                                     double shift_sigma, double drift_sigma_per_part, std::uint64_t runs,
                                     std::uint64_t seed, std::uint64_t cap) {
  require(runs >= 2, "an ARL estimate needs at least 2 runs");
  require(std::isfinite(shift_sigma) && std::isfinite(drift_sigma_per_part), "the shift and the drift must be finite");
  std::unique_ptr<AdjustmentPolicy> policy = make_policy(kind, subtune, charts);
  sim::GaussianNoise noise(1, seed);
  double sum = 0, square_sum = 0;
  RunLengthEstimate out;
  out.runs = runs;
  for (std::uint64_t r = 0; r < runs; ++r) {
    policy->reset();
    std::uint64_t length = 0;
    bool alarmed = false;
    while (!alarmed && length < cap) {
      ++length;
      const double deviation = shift_sigma + drift_sigma_per_part * static_cast<double>(length) + noise.next();
      alarmed = policy->observe(charts.target + charts.sigma * deviation).alarm;
    }
    if (!alarmed) ++out.censored;
    sum += static_cast<double>(length);
    square_sum += static_cast<double>(length) * static_cast<double>(length);
  }
  const double n = static_cast<double>(runs);
  out.mean = sum / n;
  out.standard_error = std::sqrt(std::max(0.0, (square_sum - sum * sum / n) / (n - 1)) / n);
  return out;
}

}  // namespace tk::quality
