/// @file lathe_sim.hpp
/// @brief A simulated lathe making a batch of parts, for comparing the
/// adjustment policies: tool wear and thermal drift move the size, the
/// random allowance moves it through the force-induced error, each part is
/// measured with gauge noise, and the policy's corrections move the set-up.
#pragma once

#include <cstdint>
#include <functional>

#include "machining/force_error_model.hpp"
#include "quality/adjustment_policy.hpp"

namespace tk::quality {

struct LatheSettings {
  double nominal_mm = 40, lower_mm = 39.98, upper_mm = 40.02;  ///< the size and its tolerance band
  std::uint64_t parts = 1000;
  double wear_mm_per_part = 0.0004;                ///< the size grows as the tool's edge wears
  double thermal_mm = 0.008, thermal_parts = 40;   ///< warm-up: thermal_mm (1 − e^(−i/thermal_parts))
  double allowance_mm = 1, allowance_sd_mm = 0.2;  ///< depth of cut per part (normal, redrawn if ≤ 0)
  double feed_mm_rev = 0.2;
  machining::ForceErrorModel force_model{.b1 = 0.01};  ///< y(a, f), mm; the set-up absorbs its mean over the allowance
  double process_sd_mm = 0.002;                        ///< random size variation of the process
  double gauge_sd_mm = 0.001;                          ///< measurement noise
  bool compensate_force = false;  ///< adaptive control: each part's set-up corrected by the model from its allowance
  std::uint64_t seed = 1;
};

/// Errors (tk::Error) for settings no lathe has: a tolerance band that does
/// not contain the nominal, negative spreads, no parts, ...
void validate(const LatheSettings& s);

/// The standard deviation of one measured size of the stable process (no
/// drift): process, gauge and the allowance's spread through the model
/// (exact for a normal allowance: g²s² + 2 b11² s⁴).
double in_control_sigma(const LatheSettings& s);

struct PartRecord {
  std::uint64_t part = 0;  ///< from 1
  double allowance_mm = 0;
  double size_mm = 0;  ///< the part as made
  double measured_mm = 0;
  bool alarm = false;
  double correction_mm = 0;
  double offset_mm = 0;  ///< the sum of the policy's corrections, this part's included
  double level_mm = 0;   ///< the policy's estimate of the size level (NaN: none)
};

struct LatheOutcome {
  std::uint64_t parts = 0, in_tolerance = 0, corrections = 0;
  double mean_abs_deviation_mm = 0, rms_deviation_mm = 0,
         max_abs_deviation_mm = 0;  ///< of the sizes made, from nominal
};

/// Runs the batch under `policy` (reset first). The random draws depend on
/// the seed only, so every policy meets the same allowances and noise.
LatheOutcome simulate_lathe(const LatheSettings& s, AdjustmentPolicy& policy,
                            const std::function<void(const PartRecord&)>& each_part = {});

/// The same lathe with its drifts switched off: every correction is a false alarm.
LatheSettings stable_process(LatheSettings s);

struct RunLengthEstimate {
  double mean = 0, standard_error = 0;
  std::uint64_t runs = 0, censored = 0;  ///< runs cut off at the cap count with the cap
};

/// Average run length of `kind` by simulation: from the first part, the
/// deviation from the target is (shift + drift·i + ε_i) σ with ε ~ N(0, 1);
/// the run length is the part at which the first alarm comes (zero-state,
/// as the published tables give it).
RunLengthEstimate average_run_length(PolicyKind kind, const SubTuneSettings& subtune, const ChartSettings& charts,
                                     double shift_sigma, double drift_sigma_per_part, std::uint64_t runs,
                                     std::uint64_t seed, std::uint64_t cap = 1000000);

}  // namespace tk::quality
