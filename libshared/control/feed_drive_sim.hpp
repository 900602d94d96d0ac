/// @file feed_drive_sim.hpp
/// @brief One run of the sampled feed-drive loop: encoder and filters, a
/// controller at the control period with the force held (zero-order hold),
/// the plant stepped exactly between samples, the cutting force as the
/// disturbance. Writes a time series through a callback and returns the
/// run's summary figures.
#pragma once

#include <cstdint>
#include <functional>
#include <limits>

#include "control/drive_plant.hpp"
#include "control/feed_controllers.hpp"
#include "control/milling_force.hpp"
#include "control/reference.hpp"

namespace tk::control {

struct FeedDriveConfig {
  DriveMechanics plant;                ///< the real axis (seed: 10 kg, 250 kg/s)
  double mass_estimate_kg = 7;         ///< m̂, what the controller believes
  double damping_estimate_kg_s = 200;  ///< b̂
  double amplifier_a_v = 2;            ///< K_t, current amplifier
  double force_constant_n_a = 50;      ///< K_a, motor
  double voltage_limit_v = 10;         ///< the amplifier input saturates here
  ControllerGains gains;
  MillingCut cut;
  Reference reference = Reference::sine(1, 3);
  double duration_s = 10;
  double period_s = 1e-4;            ///< control period
  int substeps = 10;                 ///< plant steps per control period
  double encoder_mm = 1e-5;          ///< resolution (10 nm, a precision linear scale); 0: none
  double position_filter_hz = 0;     ///< first-order low-pass cut-off; 0: none
  double velocity_filter_hz = 1000;  ///< on the differenced encoder position; 0: none
  double length_unit_m = 1e-3;       ///< the unit the controller's gains are written in
  double settle_s = 0;               ///< summary figures from this time on
  double hf_cutoff_hz = 1000;        ///< chattering share: F's power above this
  double initial_position_mm = std::numeric_limits<double>::quiet_NaN();  ///< NaN: on the reference
  double initial_velocity_mm_s = std::numeric_limits<double>::quiet_NaN();
  double divergence_mm = 1000;  ///< the run stops, marked diverged, beyond this error

  /// Throws tk::Error (no location) for a configuration that cannot run.
  void validate() const;
  std::uint64_t periods() const;
};

/// One sample of the time series (mm, mm/s, N).
struct FeedDriveSample {
  double t_s, x_ref_mm, x_mm, error_mm, error_rate_mm_s, surface_mm_s, force_n, disturbance_n;
};

struct FeedDriveSummary {
  double rms_error_mm = 0, max_error_mm = 0, rms_velocity_error_mm_s = 0, rms_s = 0;
  double chattering_n_s = 0;  ///< total variation of F per second
  double hf_share = 0;        ///< share of F's power above hf_cutoff_hz (periodogram)
  double effort_rms_n = 0, max_force_n = 0, saturated_share = 0;
  double measured_s = 0;  ///< the span the figures cover
  std::uint64_t plant_steps = 0;
  bool diverged = false;
  double diverged_at_s = 0;
};

/// Moves the axis across one control period with the drive force held: the
/// loop's one point of variation (the benchmark puts classical RK4 here to
/// time the same loop against it). Lengths and forces in the model's units.
class PeriodIntegrator {
 public:
  virtual ~PeriodIntegrator() = default;
  /// The plant's m and b from now on.
  virtual void configure(double mass_kg, double damping_kg_s) = 0;
  /// From t to t + period, `force` held, the cutting force acting.
  virtual void advance(AxisState& axis, double force, double t_s) = 0;
};

using FeedDriveSampleSink = std::function<void(const FeedDriveSample&)>;

/// Runs one simulation with the exact plant step; `on_sample` (may be
/// empty) gets every `every`-th control sample.
FeedDriveSummary simulate_feed_drive(const FeedDriveConfig& config, const FeedDriveSampleSink& on_sample = {},
                                     std::uint64_t every = 1);
/// The same loop with another integrator between samples.
FeedDriveSummary simulate_feed_drive(const FeedDriveConfig& config, PeriodIntegrator& integrator,
                                     const FeedDriveSampleSink& on_sample = {}, std::uint64_t every = 1);

/// Share of the power of `samples` (taken every `period_s`) at frequencies
/// above `cutoff_hz`, from the periodogram; 0 for an all-zero signal.
/// By value: FFTW wants a writable input, and the caller is done with it.
double high_frequency_share(std::vector<double> samples, double period_s, double cutoff_hz);

}  // namespace tk::control
