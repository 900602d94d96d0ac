/// @file feed_drive_sim.cpp
#include "control/feed_drive_sim.hpp"

#include <fftw3.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "concurrency/fftw_planner.hpp"
#include "io/error.hpp"

namespace tk::control {

namespace {

/// The coefficient of y += α (u − y) for a first-order low-pass; 1 is no filter.
double low_pass_alpha(double cutoff_hz, double period_s) {
  return cutoff_hz > 0 ? -std::expm1(-2 * std::numbers::pi * cutoff_hz * period_s) : 1.0;
}

/// hf_share is taken over at most this many samples after --settle (128 MB).
constexpr std::uint64_t kSpectrumSamples = 1u << 24;

}  // namespace

void FeedDriveConfig::validate() const {
  const auto positive = [](double v, const char* what) {
    require(v > 0 && std::isfinite(v), fmt::format("{} must be a positive number, not {}", what, v));
  };
  const auto non_negative = [](double v, const char* what) {
    require(v >= 0 && std::isfinite(v), fmt::format("{} must be zero or a positive number, not {}", what, v));
  };
  positive(plant.mass_kg, "the mass"), non_negative(plant.damping_kg_s, "the damping");
  if (plant.mass_end_kg >= 0 || std::isnan(plant.mass_end_kg)) positive(plant.mass_end_kg, "the final mass");
  if (plant.damping_end_kg_s >= 0 || std::isnan(plant.damping_end_kg_s))
    non_negative(plant.damping_end_kg_s, "the final damping");
  positive(mass_estimate_kg, "the mass estimate"), non_negative(damping_estimate_kg_s, "the damping estimate");
  positive(amplifier_a_v, "K_t"), positive(force_constant_n_a, "K_a"), positive(voltage_limit_v, "the voltage limit");
  positive(duration_s, "the duration"), positive(period_s, "the control period");
  require(substeps >= 1 && substeps <= 100000, fmt::format("substeps must be 1 to 100000, not {}", substeps));
  require(duration_s / period_s <= 1e8, "the run is longer than 10^8 control periods");
  non_negative(encoder_mm, "the encoder resolution");
  non_negative(position_filter_hz, "the position filter"), non_negative(velocity_filter_hz, "the velocity filter");
  positive(length_unit_m, "the length unit");
  non_negative(settle_s, "the settling time"), non_negative(hf_cutoff_hz, "the chattering cut-off");
  require(settle_s < duration_s,
          fmt::format("the settling time {} s leaves nothing of a {} s run", settle_s, duration_s));
  require(!std::isinf(initial_position_mm) && !std::isinf(initial_velocity_mm_s), "initial conditions must be finite");
  positive(divergence_mm, "the divergence limit");
  gains.validate();
  cut.validate();
}

std::uint64_t FeedDriveConfig::periods() const {
  return static_cast<std::uint64_t>(std::llround(duration_s / period_s));
}

double high_frequency_share(std::vector<double> samples, double period_s, double cutoff_hz) {
  const std::size_t n = samples.size();
  if (n < 2) return 0;
  std::vector<fftw_complex> spectrum(n / 2 + 1);
  fftw_plan plan;
  {
    std::lock_guard lock(fftw_planner_mutex());
    plan = fftw_plan_dft_r2c_1d(static_cast<int>(n), samples.data(), spectrum.data(), FFTW_ESTIMATE);
  }
  fftw_execute(plan);
  {
    std::lock_guard lock(fftw_planner_mutex());
    fftw_destroy_plan(plan);
  }
  // One-sided periodogram: bins other than DC and Nyquist stand for two.
  double total = 0, above = 0;
  for (std::size_t k = 0; k < spectrum.size(); ++k) {
    const double power = spectrum[k][0] * spectrum[k][0] + spectrum[k][1] * spectrum[k][1];
    const double weight = (k == 0 || 2 * k == n) ? 1 : 2;
    total += weight * power;
    if (static_cast<double>(k) / (n * period_s) > cutoff_hz) above += weight * power;
  }
  return total > 0 ? above / total : 0;
}

namespace {

/// The exact step of drive_plant.hpp, the cutting force linear across each
/// of the period's substeps and walked by rotation.
class ExactIntegrator final : public PeriodIntegrator {
 public:
  explicit ExactIntegrator(const FeedDriveConfig& c)
      : cutting_(c.cut),
        disturbance_(cutting_, c.period_s / c.substeps),
        step_s_(c.period_s / c.substeps),
        from_n_(1 / c.length_unit_m),
        substeps_(c.substeps) {}

  void configure(double mass_kg, double damping_kg_s) override { plant_.configure(mass_kg, damping_kg_s, step_s_); }

  void advance(AxisState& axis, double force, double t_s) override {
    disturbance_.start(t_s);  // re-anchored every period, so the rotation cannot drift
    double fd = disturbance_.value() * from_n_;
    for (int j = 0; j < substeps_; ++j) {
      disturbance_.advance();
      const double fd_next = disturbance_.value() * from_n_;
      plant_.step(axis, force, fd, fd_next);
      fd = fd_next;
    }
  }

 private:
  const MillingForce cutting_;  // before disturbance_, which points at it
  MillingForce::Stepper disturbance_;
  DrivePlant plant_;
  double step_s_, from_n_;
  int substeps_;
};

}  // namespace

FeedDriveSummary simulate_feed_drive(const FeedDriveConfig& c, const FeedDriveSampleSink& on_sample,
                                     std::uint64_t every) {
  ExactIntegrator integrator(c);  // the loop validates c; the cut validates itself first
  return simulate_feed_drive(c, integrator, on_sample, every);
}

FeedDriveSummary simulate_feed_drive(const FeedDriveConfig& c, PeriodIntegrator& integrator,
                                     const FeedDriveSampleSink& on_sample, std::uint64_t every) {
  c.validate();
  const double L = c.length_unit_m, from_mm = 1e-3 / L, to_mm = L / 1e-3, from_n = 1 / L, to_n = L;
  const double T = c.period_s;
  const std::uint64_t periods = c.periods();
  const double force_limit = c.amplifier_a_v * c.force_constant_n_a * c.voltage_limit_v * from_n;
  const double quantum = c.encoder_mm * from_mm;
  const double position_alpha = low_pass_alpha(c.position_filter_hz, T),
               velocity_alpha = low_pass_alpha(c.velocity_filter_hz, T);

  FeedController controller(c.gains, c.mass_estimate_kg, c.damping_estimate_kg_s, T);
  const MillingForce cutting(c.cut);  // F_d for the samples; the integrator has its own
  integrator.configure(c.plant.mass_at(0.5 / periods), c.plant.damping_at(0.5 / periods));

  const ReferenceSample start = c.reference.at(0);
  AxisState axis{(std::isnan(c.initial_position_mm) ? start.x_mm : c.initial_position_mm) * from_mm,
                 (std::isnan(c.initial_velocity_mm_s) ? start.v_mm_s : c.initial_velocity_mm_s) * from_mm};
  const auto measure = [&](double x) { return quantum > 0 ? std::nearbyint(x / quantum) * quantum : x; };
  double previous_reading = measure(axis.x), x_hat = previous_reading, v_hat = axis.v;
  double error_integral = 0;

  FeedDriveSummary sum;
  double sum_e2 = 0, sum_ev2 = 0, sum_s2 = 0, sum_f2 = 0, variation = 0, previous_force_n = 0;
  std::uint64_t measured = 0, saturated = 0;
  std::vector<double> forces;
  const bool want_spectrum = c.hf_cutoff_hz > 0;
  if (want_spectrum) forces.reserve(static_cast<std::size_t>(std::min<std::uint64_t>(periods, kSpectrumSamples)));

  for (std::uint64_t k = 0; k < periods; ++k) {
    const double t = static_cast<double>(k) * T;
    if (c.plant.varies())
      integrator.configure(c.plant.mass_at((k + 0.5) / periods), c.plant.damping_at((k + 0.5) / periods));
    if (k > 0) {  // the encoder, differenced for velocity, each through its filter
      const double reading = measure(axis.x);
      x_hat += position_alpha * (reading - x_hat);
      v_hat += velocity_alpha * ((reading - previous_reading) / T - v_hat);
      previous_reading = reading;
    }
    const ReferenceSample r_mm = c.reference.at(t);
    const double xr = r_mm.x_mm * from_mm, vr = r_mm.v_mm_s * from_mm, ar = r_mm.a_mm_s2 * from_mm;
    const double true_error = xr - axis.x, true_rate = vr - axis.v;
    if (!(std::abs(true_error) * to_mm <= c.divergence_mm)) {
      sum.diverged = true, sum.diverged_at_s = t;
      break;
    }
    const double e = xr - x_hat, e_rate = vr - v_hat;
    const double surface = e_rate + c.gains.mu * e + c.gains.lambda * error_integral;
    double force = controller.force({xr, vr, ar, x_hat, v_hat, e, e_rate, error_integral, surface});
    const bool saturating = !(std::abs(force) <= force_limit);  // also catches NaN
    if (saturating) force = std::isnan(force) ? 0 : std::copysign(force_limit, force);
    const double force_n = force * to_n;
    if (on_sample && k % every == 0)
      on_sample({t, r_mm.x_mm, axis.x * to_mm, true_error * to_mm, true_rate * to_mm, surface * to_mm, force_n,
                 cutting.at(t)});
    if (t >= c.settle_s) {
      const double e_mm = true_error * to_mm, ev_mm = true_rate * to_mm, s_mm = surface * to_mm;
      sum_e2 += e_mm * e_mm, sum_ev2 += ev_mm * ev_mm, sum_s2 += s_mm * s_mm, sum_f2 += force_n * force_n;
      sum.max_error_mm = std::max(sum.max_error_mm, std::abs(e_mm));
      sum.max_force_n = std::max(sum.max_force_n, std::abs(force_n));
      if (measured > 0) variation += std::abs(force_n - previous_force_n);
      previous_force_n = force_n;
      if (want_spectrum && forces.size() < kSpectrumSamples) forces.push_back(force_n);
      saturated += saturating;
      ++measured;
    }
    integrator.advance(axis, force, t);
    sum.plant_steps += static_cast<std::uint64_t>(c.substeps);
    error_integral += e * T;
  }
  if (measured > 0) {
    const double n = static_cast<double>(measured);
    sum.measured_s = n * T;
    sum.rms_error_mm = std::sqrt(sum_e2 / n), sum.rms_velocity_error_mm_s = std::sqrt(sum_ev2 / n);
    sum.rms_s = std::sqrt(sum_s2 / n), sum.effort_rms_n = std::sqrt(sum_f2 / n);
    sum.chattering_n_s = variation / sum.measured_s;
    sum.saturated_share = static_cast<double>(saturated) / n;
    if (want_spectrum) sum.hf_share = high_frequency_share(std::move(forces), T, c.hf_cutoff_hz);
  }
  return sum;
}

}  // namespace tk::control
