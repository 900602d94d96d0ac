/// @file turning_sim.hpp
/// @brief A closed-loop model of a longitudinal roughing pass under the feed
/// override law, IPO cycle by IPO cycle: the override written in one cycle
/// commands the feed axis in the next; the axis follows with its position
/// loop's lag; the chip the edge cuts is the axial travel over the last
/// spindle revolution; Kienzle's force on it loads the spindle drive; the
/// drive's smoothed load, with noise, is what the law reads. Every run is
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
/// Defaults: E295 (St 50-2), a 95° holder for the seed's WNMG insert, the
/// seed's 9 kW main drive.
struct CuttingModel {
  double kc11_n_mm2 = 1990;     ///< k_c1.1, N/mm² at h = b = 1 mm
  double mc = 0.26;             ///< m_c, the exponent: F_c grows as h^(1 - m_c)
  double kappa_deg = 95;        ///< κ_r, the tool's setting angle
  double rated_power_w = 9000;  ///< the main drive's rated power
  double efficiency = 0.8;      ///< η, spindle power / motor power (belt, gears, bearings)
};

/// F_c = k_c1.1 · b · h^(1 - m_c), h = f sin κ, b = a_p / sin κ (N), f the feed per revolution.
double kienzle_force_n(const CuttingModel& model, double depth_mm, double feed_mm_rev);
/// The spindle load in % of rated: 100 · F_c v_c / (η P_rated).
double spindle_load_pct(const CuttingModel& model, double depth_mm, double feed_mm_rev, double cutting_speed_m_min);

/// dy/dt = (u - y)/τ, discretised exactly for an input held over each step
/// (y reaches 1 - e^(-t/τ) of a step at the sample times). τ = 0 passes
/// the input through.
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

/// The feed axis under its position loop: with a servo gain K_v the
/// velocity follows the commanded one as a first-order lag of τ = 1/K_v
/// (a following error of v τ: K_v = 1 (m/min)/mm lags 1 mm at 1 m/min).
class FeedAxis {
 public:
  // 1 - e^(-T/τ) by expm1: for a lag of many steps (a tiny K_v) 1 - exp
  // rounds to 0 and the axis would follow without lag.
  FeedAxis(double lag_s, double step_s, double velocity_mm_s)
      : lag_s_(lag_s),
        step_s_(step_s),
        decay_(std::exp(-step_s / lag_s)),
        response_(-std::expm1(-step_s / lag_s)),
        velocity_(velocity_mm_s) {}
  /// Moves one step with the command held; returns the distance, mm (exact).
  double advance(double command_mm_s) {
    const double travel = command_mm_s * step_s_ + (velocity_ - command_mm_s) * lag_s_ * response_;
    velocity_ = command_mm_s + (velocity_ - command_mm_s) * decay_;
    return travel;
  }
  double velocity() const { return velocity_; }

 private:
  double lag_s_, step_s_, decay_, response_, velocity_;
};

/// The tool's axial positions at the last cycle starts, enough to reach one
/// spindle revolution back: the feed per revolution the edge cuts now (the
/// chip) is the travel since it last passed this point of the
/// circumference, z(t) - z(t - 60/n), linear between cycle starts.
class RevolutionHistory {
 public:
  /// `revolution_cycles` = T_rev / T_ipo; before the start the tool moved
  /// `step_before_mm` per cycle (the cut was already running).
  RevolutionHistory(double revolution_cycles, double z_now, double step_before_mm);
  /// z(t) - z(t - T_rev), z(t) the newest position.
  double travel_over_revolution() const {
    const double newer = at(back_), older = at(back_ + 1);
    return at(0) - (newer + fraction_ * (older - newer));
  }
  void push(double z) {
    newest_ = (newest_ + 1) % ring_.size();
    ring_[newest_] = z;
  }

 private:
  double at(std::size_t cycles_ago) const { return ring_[(newest_ + ring_.size() - cycles_ago) % ring_.size()]; }

  std::size_t back_;
  double fraction_;
  std::vector<double> ring_;
  std::size_t newest_ = 0;
};

/// A stretch of the cut with a constant allowance (depth of cut a_p).
struct AllowanceSegment {
  double z_from_mm = 0, z_to_mm = 0, depth_mm = 0;
};

/// The default test part: the seed's 1 mm allowance with 3 mm stretches;
/// the seed gives no lengths, these are ours: 3 x (60 mm at 1 mm, 8 mm at
/// 3 mm), 204 mm in all.
std::vector<AllowanceSegment> default_profile();
/// Checks a profile: at least one segment, finite, z increasing without gaps
/// or overlaps, 0 <= depth < 50 mm. Throws tk::Error.
void check_profile(const std::vector<AllowanceSegment>& profile);

struct TurningParams {
  CuttingModel cutting;
  std::vector<AllowanceSegment> profile = default_profile();
  double feed_mm_rev = 0.4;          ///< programmed feed (the seed's)
  double cutting_speed_m_min = 140;  ///< v_c: the 3 mm cut at 100 % within the 9 kW drive
  double diameter_mm = 80;           ///< sets the constant spindle speed n = v_c / (π D)
  double ipo_s = 0.008;              ///< the interpolation cycle: one step of the law each
  double kv = 1;                     ///< the feed axis's servo gain K_v, (m/min)/mm: lag 1/K_v
  double load_smoothing_s = 0.04;    ///< τ of the drive's smoothed load signal
  double noise_pct = 1.0;            ///< σ of the load signal's noise, % of rated
  std::uint64_t seed = 1;            ///< of the noise
  double above_tolerance = 0.1;      ///< "above M_z" means above (1 + this) M_z
  /// A run longer than this, or than 1000 baselines (at least 10^6), is an
  /// error; so is a baseline longer than this (a usage error). Each cycle
  /// keeps 16 bytes for its segment's statistics: 2e7 cycles, 320 MB.
  double max_cycles = 2e7;
};

/// Throws tk::UsageError naming the option of the first bad parameter.
void validate(const TurningParams& params);
double spindle_speed_rev_s(const TurningParams& params);
/// The feed axis's time constant 1/K_v, s (K_v in (m/min)/mm: 1 is 16.7/s).
double axis_lag_s(const TurningParams& params);

/// One IPO cycle as the trace shows it.
struct TraceSample {
  double t_s;            ///< start of the cycle
  double z_mm;           ///< tool position along the cut
  double depth_mm;       ///< allowance under the tool
  double chip_mm;        ///< the feed per revolution being cut: z(t) - z(t - one revolution)
  double load_true_pct;  ///< the cutting load now (no smoothing, no noise)
  double load_pct;       ///< M_a, the signal the law reads: smoothed, noisy, 0-100
  OverrideStep step;     ///< what the law made of it
};

struct SegmentStats {
  std::size_t index = 0;
  AllowanceSegment segment;
  double start_s = 0, duration_s = 0;
  double load_at_100_pct = 0;                  ///< the true load at 100 % override (closed form)
  double mean_load_pct = 0, max_load_pct = 0;  ///< true load, time-weighted
  double mean_override_pct = 0;                ///< O_n over the whole segment
  /// Over the settled part (the segment's second half in time): the mean of
  /// O_n; half the peak-to-peak and the standard deviation of O_n about its
  /// least-squares line there (a drift is not an oscillation), % points.
  double settled_override_pct = 0, oscillation_pct = 0, override_sd_pct = 0;
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
