/// @file turning_sim.cpp
/// @brief The turning model and the closed-loop run, cycle by cycle.
#include "machining/turning_sim.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <numbers>

#include "cli/option_checks.hpp"
#include "io/error.hpp"
#include "sim/gaussian_noise.hpp"

namespace tk::machining {

namespace {

/// The override samples of one segment, summarised when the tool leaves it.
class SegmentRecorder {
 public:
  void start(std::size_t index, const AllowanceSegment& segment, double t_s, double load_at_100) {
    stats_ = {};
    stats_.index = index;
    stats_.segment = segment;
    stats_.start_s = t_s;
    stats_.load_at_100_pct = load_at_100;
    samples_.clear();
  }
  void add(double t_s, double dt_s, double load_true, double override_pct) {
    samples_.push_back({t_s, override_pct});
    stats_.duration_s += dt_s;
    stats_.mean_load_pct += load_true * dt_s;
    stats_.max_load_pct = std::max(stats_.max_load_pct, load_true);
    stats_.mean_override_pct += override_pct;
  }
  bool empty() const { return samples_.empty(); }

  SegmentStats finish() {
    SegmentStats s = stats_;
    if (samples_.empty()) return s;
    if (s.duration_s > 0) s.mean_load_pct /= s.duration_s;
    s.mean_override_pct /= static_cast<double>(samples_.size());
    // The settled part: the second half of the segment's time, so that the
    // swing of the override after a step in the allowance does not count.
    // The swing is taken about the least-squares line through it, so that
    // a slow drift (the override still creeping towards 200 %) is not
    // counted as oscillation.
    const double settled_from = s.start_s + s.duration_s / 2;
    double n = 0, st = 0, so = 0, stt = 0, sto = 0;
    for (const auto& [t, o] : samples_)
      if (t >= settled_from) n += 1, st += t, so += o, stt += t * t, sto += t * o;
    if (n == 0) return s;
    s.settled_override_pct = so / n;
    const double spread = stt - st * st / n;
    const double slope = spread > 0 ? (sto - st * so / n) / spread : 0;
    double low = kMaxOverridePct, high = -kMaxOverridePct, squares = 0;
    for (const auto& [t, o] : samples_) {
      if (t < settled_from) continue;
      const double r = o - s.settled_override_pct - slope * (t - st / n);
      low = std::min(low, r), high = std::max(high, r), squares += r * r;
    }
    s.oscillation_pct = (high - low) / 2;
    s.override_sd_pct = std::sqrt(squares / n);
    return s;
  }

 private:
  SegmentStats stats_;
  std::vector<std::pair<double, double>> samples_;
};

}  // namespace

RevolutionHistory::RevolutionHistory(double revolution_cycles, double z_now, double step_before_mm)
    : back_(static_cast<std::size_t>(revolution_cycles)),
      fraction_(revolution_cycles - static_cast<double>(back_)),
      ring_(back_ + 2) {
  for (std::size_t j = 0; j < ring_.size(); ++j)
    ring_[(ring_.size() - j) % ring_.size()] = z_now - static_cast<double>(j) * step_before_mm;
}

double kienzle_force_n(const CuttingModel& model, double depth_mm, double feed_mm_rev) {
  const double sin_kappa = std::sin(model.kappa_deg * std::numbers::pi / 180);
  const double h = feed_mm_rev * sin_kappa;  // chip thickness
  const double b = depth_mm / sin_kappa;     // chip width
  return model.kc11_n_mm2 * b * std::pow(h, 1 - model.mc);
}

double spindle_load_pct(const CuttingModel& model, double depth_mm, double feed_mm_rev, double cutting_speed_m_min) {
  const double power_w = kienzle_force_n(model, depth_mm, feed_mm_rev) * cutting_speed_m_min / 60;
  return 100 * power_w / (model.efficiency * model.rated_power_w);
}

std::vector<AllowanceSegment> default_profile() {
  std::vector<AllowanceSegment> profile;
  double z = 0;
  for (int collar = 0; collar < 3; ++collar) {
    profile.push_back({z, z + 60, 1});
    profile.push_back({z + 60, z + 68, 3});
    z += 68;
  }
  return profile;
}

void check_profile(const std::vector<AllowanceSegment>& profile) {
  if (profile.empty()) throw Error("the allowance profile is empty");
  for (std::size_t i = 0; i < profile.size(); ++i) {
    const AllowanceSegment& s = profile[i];
    if (!std::isfinite(s.z_from_mm) || !std::isfinite(s.z_to_mm) || !(s.z_from_mm < s.z_to_mm))
      throw Error(fmt::format("profile segment {}: z must increase (from {} to {})", i + 1, s.z_from_mm, s.z_to_mm));
    if (!(s.depth_mm >= 0 && s.depth_mm < 50))
      throw Error(fmt::format("profile segment {}: depth {} mm is outside [0, 50)", i + 1, s.depth_mm));
    if (i > 0 && s.z_from_mm != profile[i - 1].z_to_mm)
      throw Error(fmt::format("profile segment {} starts at z = {}, not where the one before ends ({})", i + 1,
                              s.z_from_mm, profile[i - 1].z_to_mm));
  }
}

void validate(const TurningParams& p) {
  // Ranges wide enough for any lathe and material (fuzzyfeed(1), OPTIONS);
  // the bounds keep a run's cycle count and the revolution history finite.
  using cli::require_range, cli::ZeroAllowed;
  require_range(p.cutting.kc11_n_mm2, 100, 10000, "--kc11");
  require_range(p.cutting.mc, 0, 0.9, "--mc");
  require_range(p.cutting.kappa_deg, 1, 179, "--kappa");
  require_range(p.cutting.rated_power_w / 1000, 0.1, 1000, "--power");
  require_range(p.cutting.efficiency, 0.05, 1, "--efficiency");
  require_range(p.feed_mm_rev, 0.001, 5, "--feed");
  require_range(p.cutting_speed_m_min, 1, 5000, "--cutting-speed");
  require_range(p.diameter_mm, 0.5, 5000, "--diameter");
  require_range(p.ipo_s, 1e-4, 1, "--ipo");
  require_range(p.kv, 0.01, 1000, "--kv");
  require_range(p.load_smoothing_s, 0, 10, "--lag");
  require_range(p.noise_pct, 0, 100, "--noise");
  require_range(p.above_tolerance, 0, 10, "--above-tol");
  // The revolution history holds one position per IPO cycle of a revolution.
  if (!(1 / (spindle_speed_rev_s(p) * p.ipo_s) <= 1e6))
    throw UsageError(
        "a spindle revolution lasts more than 10^6 IPO cycles: raise --cutting-speed or --ipo, or lower --diameter");
}

double spindle_speed_rev_s(const TurningParams& params) {
  return params.cutting_speed_m_min * 1000 / (std::numbers::pi * params.diameter_mm) / 60;
}

double axis_lag_s(const TurningParams& params) { return 60.0 / (1000.0 * params.kv); }

double baseline_time_s(const TurningParams& params) {
  const double length = params.profile.back().z_to_mm - params.profile.front().z_from_mm;
  return length / (params.feed_mm_rev * spindle_speed_rev_s(params));
}

RunStats simulate_turning(const TurningParams& params, const std::optional<FeedOverrideParams>& law, double mz_pct,
                          const TraceSink& on_sample) {
  validate(params);
  check_profile(params.profile);
  std::optional<FeedOverride> control;
  if (law) control.emplace(*law);
  const double n_rev_s = spindle_speed_rev_s(params);
  const double above = mz_pct * (1 + params.above_tolerance);
  const double z_end = params.profile.back().z_to_mm;
  const double T = params.ipo_s;
  const auto load_of_chip = [&](double depth, double chip_mm) {
    return spindle_load_pct(params.cutting, depth, chip_mm, params.cutting_speed_m_min);
  };
  const auto load_at_100 = [&](std::size_t i) { return load_of_chip(params.profile[i].depth_mm, params.feed_mm_rev); };

  // A law that keeps the feed near 0 would otherwise run for ever.
  const double baseline_cycles = baseline_time_s(params) / T;
  cli::require_run_size(baseline_cycles, params.max_cycles,
                        "IPO cycles for the cut at 100 % (raise --feed or --ipo, or shorten the profile)",
                        "--feed, --cutting-speed, --diameter, --ipo and the profile's length");
  const double cycle_limit = std::min(params.max_cycles, std::max(1e6, 1000 * baseline_cycles));

  RunStats run;
  sim::GaussianNoise noise(params.noise_pct, params.seed);
  FirstOrderLag signal(params.load_smoothing_s, T);
  // The law is switched on with the tool already cutting at the initial
  // override: axis, chip and signal start settled.
  double override_pct = control ? control->override_pct() : 100;
  const double feed_rate_at_100 = params.feed_mm_rev * n_rev_s;  // mm/s
  FeedAxis axis(axis_lag_s(params), T, feed_rate_at_100 * override_pct / 100);
  double z = params.profile.front().z_from_mm;
  RevolutionHistory history(1 / (n_rev_s * T), z, axis.velocity() * T);
  std::size_t segment = 0;
  SegmentRecorder recorder;
  recorder.start(0, params.profile[0], 0, load_at_100(0));
  signal.reset(load_of_chip(params.profile[0].depth_mm, history.travel_over_revolution()));
  double weighted_load = 0, override_sum = 0;
  for (std::uint64_t cycle = 0;; ++cycle) {
    if (static_cast<double>(cycle) > cycle_limit)
      throw Error(
          fmt::format("the cut takes more than {:g} IPO cycles ({:g} times the cut at 100 %){}", cycle_limit,
                      cycle_limit / baseline_cycles,
                      cycle_limit == params.max_cycles ? ", the simulation's limit" : ": the override stays near 0"));
    const double t = static_cast<double>(cycle) * T;
    while (segment + 1 < params.profile.size() && z >= params.profile[segment].z_to_mm) {
      if (!recorder.empty()) run.segments.push_back(recorder.finish());
      ++segment;
      recorder.start(segment, params.profile[segment], t, load_at_100(segment));
    }
    const double depth = params.profile[segment].depth_mm;
    const double chip = history.travel_over_revolution();
    const double load_true = load_of_chip(depth, chip);
    const double load = std::clamp(signal.update(load_true) + noise.next(), 0.0, 100.0);
    const OverrideStep step = control ? control->step(load) : OverrideStep{1, 100};

    // This cycle the axis is commanded at the override in force (O_a).
    const double travel = axis.advance(feed_rate_at_100 * override_pct / 100);
    double dt = T;
    const bool last = z + travel >= z_end;
    if (last) dt = T * (z_end - z) / travel;  // the cut ends inside this cycle
    if (on_sample) on_sample({t, z, depth, chip, load_true, load, step});
    recorder.add(t, dt, load_true, step.override_pct);
    weighted_load += load_true * dt;
    override_sum += step.override_pct;
    run.max_load_pct = std::max(run.max_load_pct, load_true);
    if (load_true > above) run.time_above_mz_s += dt;
    run.cycles = cycle + 1;
    if (last) {
      run.time_s = t + dt;
      break;
    }
    z += travel;
    history.push(z);
    override_pct = step.override_pct;  // O_n is in force from the next cycle
  }
  run.segments.push_back(recorder.finish());
  run.mean_load_pct = run.time_s > 0 ? weighted_load / run.time_s : 0;
  run.mean_override_pct = override_sum / static_cast<double>(run.cycles);
  for (const SegmentStats& s : run.segments)
    if (s.oscillation_pct > run.oscillation_pct) {
      run.oscillation_pct = s.oscillation_pct;
      run.oscillation_segment = s.index;
    }
  for (const SegmentStats& s : run.segments) run.override_sd_pct = std::max(run.override_sd_pct, s.override_sd_pct);
  return run;
}

}  // namespace tk::machining
