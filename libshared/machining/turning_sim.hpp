/// @file turning_sim.hpp
/// @brief A closed-loop model of longitudinal turning under the fuzzy feed
/// override: Kienzle's cutting force on an allowance profile, the spindle
/// load it puts on the main drive, a first-order lag and Gaussian noise on
/// the load signal, and the override law once per IPO cycle. Every run is
/// compared with the same cut at a fixed 100 % override (the baseline).
#pragma once

#include <cmath>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "machining/feed_override.hpp"

namespace tk::machining {

/// Kienzle's specific cutting force and the tool and drive it acts on.
/// Defaults: E295 (St 50-2) from König & Klocke's Kienzle table, a 95°
/// turning tool, the seed's 9 kW main drive.
struct CuttingModel {
  double kc11_n_mm2 = 1990;     ///< k_c1.1, N/mm² at h = b = 1 mm
  double mc = 0.26;             ///< m_c, the exponent: F_c grows as h^(1 - m_c)
  double kappa_deg = 95;        ///< κ_r, the tool's setting angle
  double rated_power_w = 9000;  ///< the main drive's rated power
  double efficiency = 0.8;      ///< η, spindle power / motor power (belt, gears, bearings)
};

/// F_c = k_c1.1 · b · h^(1 - m_c), h = f sin κ, b = a_p / sin κ (N).
double kienzle_force_n(const CuttingModel& model, double depth_mm, double feed_mm_rev);
/// The spindle load in % of rated: 100 · F_c v_c / (η P_rated).
double spindle_load_pct(const CuttingModel& model, double depth_mm, double feed_mm_rev, double cutting_speed_m_min);

/// The load signal's dynamics: dy/dt = (u - y)/τ, discretised exactly for
/// an input held over each step (y reaches 1 - e^(-t/τ) of a step at the
/// sample times). τ = 0 passes the input through.
class FirstOrderLag {
 public:
  FirstOrderLag(double time_constant_s, double step_s)
      : alpha_(time_constant_s > 0 ? -std::expm1(-step_s / time_constant_s) : 1.0) {}
  void reset(double value) { y_ = value; }
  double update(double input) { return y_ += alpha_ * (input - y_); }
  double value() const { return y_; }

 private:
  double alpha_;
  double y_ = 0;
};

/// A stretch of the cut with a constant allowance (depth of cut a_p).
struct AllowanceSegment {
  double z_from_mm = 0, z_to_mm = 0, depth_mm = 0;
};

/// The default test part, after the seed's: a forged shaft whose three
/// collars leave 3 mm where the rest leaves 1 mm: 3 x (60 mm at 1 mm,
/// 8 mm at 3 mm), 204 mm in all.
std::vector<AllowanceSegment> default_profile();
/// Checks a profile: at least one segment, finite, z increasing without gaps
/// or overlaps, 0 <= depth < 50 mm. Throws tk::Error.
void check_profile(const std::vector<AllowanceSegment>& profile);

struct TurningParams {
  CuttingModel cutting;
  std::vector<AllowanceSegment> profile = default_profile();
  double feed_mm_rev = 0.4;           ///< programmed feed (the seed's)
  double cutting_speed_m_min = 170;   ///< v_c at the diameter below
  double diameter_mm = 80;            ///< sets the constant spindle speed n = v_c / (π D)
  double ipo_s = 0.008;               ///< the interpolation cycle: one control step each
  double lag_s = 0.1;                 ///< τ of the load signal
  double noise_pct = 1.0;             ///< σ of the load signal's noise, % of rated
  std::uint64_t seed = 1;             ///< of the noise
  double above_tolerance = 0.1;       ///< "above M_z" means above (1 + this) M_z
  double max_cycles = 2e8;            ///< a run longer than this is an error
};

/// Throws tk::UsageError naming the option of the first bad parameter.
void validate(const TurningParams& params);
double spindle_speed_rev_s(const TurningParams& params);

/// One IPO cycle as the trace shows it.
struct TraceSample {
  double t_s;              ///< start of the cycle
  double z_mm;             ///< tool position along the cut
  double depth_mm;         ///< allowance under the tool
  double load_true_pct;    ///< the cutting load now (no lag, no noise)
  double load_pct;         ///< the signal the control reads: lagged, noisy, 0-100
  OverrideStep step;       ///< what the control made of it
  double feed_mm_rev;      ///< the feed in effect this cycle (programmed x O_a)
};

struct SegmentStats {
  std::size_t index = 0;
  AllowanceSegment segment;
  double start_s = 0, duration_s = 0;
  double mean_load_pct = 0, max_load_pct = 0;  ///< true load, time-weighted
  double mean_override_pct = 0;                ///< O_n over the whole segment
  /// Over the settled part (the segment's second half in time): half the
  /// peak-to-peak of O_n and its standard deviation, override % points.
  double oscillation_pct = 0, override_sd_pct = 0;
};

struct RunStats {
  double time_s = 0;
  double time_above_mz_s = 0;  ///< true load above (1 + above_tolerance) M_z
  double mean_load_pct = 0, max_load_pct = 0, mean_override_pct = 0;
  double oscillation_pct = 0, override_sd_pct = 0;  ///< the largest over the segments
  std::size_t oscillation_segment = 0;              ///< where oscillation_pct is
  std::uint64_t cycles = 0;
  std::vector<SegmentStats> segments;
};

using TraceSink = std::function<void(const TraceSample&)>;

/// Runs the cut once: under `law`, or at a fixed 100 % override when it is
/// empty. `mz_pct` only sets what counts as "above M_z". `on_sample` (may
/// be empty) sees every cycle.
RunStats simulate_turning(const TurningParams& params, const std::optional<FeedOverrideParams>& law, double mz_pct,
                          const TraceSink& on_sample = {});

/// L / (f n): the cut's time at a fixed 100 % override, in closed form.
double baseline_time_s(const TurningParams& params);

}  // namespace tk::machining
