/// @file bench_smcsim.cpp
/// @brief smcsim's feed-drive loop, plant steps per CPU second on one core
/// (goal: 10 million for the single-axis model), against the same sampled
/// loop with the plant integrated the way a general ODE tool does it:
/// classical fixed-step RK4 at the same plant step (Simulink's ode4), the
/// same controller (FeedController), the same cutting force
/// (MillingForce::at), the same encoder, filters and summary. Both must give
/// nearly the same rms error. Then the bare plant step (DrivePlant::step and
/// MillingForce::Stepper) against a bare RK4 step, and a sweep of 1,000
/// settings (smc, Λ = 1..1000) of the 10 s run on 2 threads through
/// tk::OrderedPool, as `smcsim sweep -j 2` runs it, with the speed-up over
/// one thread on 50 settings. Medians of BENCH_SMCSIM_REPEATS (or
/// BENCH_REPEATS, default 5) repeats; the two-thread comparison takes at
/// most 3 and the 1,000-setting sweep runs once (BENCH_SMCSIM_SWEEP sets
/// its size; 0 skips it). RESULT and FIGURE lines for bench/run.sh.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "bench_common.hpp"
#include "concurrency/ordered_pool.hpp"
#include "control/drive_plant.hpp"
#include "control/feed_controllers.hpp"
#include "control/feed_drive_sim.hpp"
#include "control/milling_force.hpp"

namespace {

using namespace tk::control;

/// The peer: simulate_feed_drive's loop line for line, except that between
/// samples the plant m ẍ + b ẋ = F − F_d(t) is integrated by classical RK4
/// with the force held and F_d evaluated where the stages need it, as a
/// Simulink model with the ode4 solver at a fixed step of h would. Generous
/// to the peer: F_d(t) is reused from the previous step's end, so it costs
/// two evaluations per step, not four.
FeedDriveSummary simulate_rk4(const FeedDriveConfig& c) {
  c.validate();
  const double L = c.length_unit_m, from_mm = 1e-3 / L, to_mm = L / 1e-3, from_n = 1 / L, to_n = L;
  const double T = c.period_s, h = T / c.substeps;
  const std::uint64_t periods = c.periods();
  const double force_limit = c.amplifier_a_v * c.force_constant_n_a * c.voltage_limit_v * from_n;
  const double quantum = c.encoder_mm * from_mm;
  const auto low_pass_alpha = [T](double cutoff_hz) { return cutoff_hz > 0 ? -std::expm1(-2 * std::numbers::pi * cutoff_hz * T) : 1.0; };
  const double position_alpha = low_pass_alpha(c.position_filter_hz), velocity_alpha = low_pass_alpha(c.velocity_filter_hz);

  FeedController controller(c.gains, c.mass_estimate_kg, c.damping_estimate_kg_s, T);
  const MillingForce cutting(c.cut);
  double mass = c.plant.mass_at(0.5 / periods), damping = c.plant.damping_at(0.5 / periods);

  const ReferenceSample start = c.reference.at(0);
  double x = (std::isnan(c.initial_position_mm) ? start.x_mm : c.initial_position_mm) * from_mm;
  double v = (std::isnan(c.initial_velocity_mm_s) ? start.v_mm_s : c.initial_velocity_mm_s) * from_mm;
  const auto measure = [&](double position) { return quantum > 0 ? std::nearbyint(position / quantum) * quantum : position; };
  double previous_reading = measure(x), x_hat = previous_reading, v_hat = v;
  double error_integral = 0;

  FeedDriveSummary sum;
  double sum_e2 = 0, sum_ev2 = 0, sum_s2 = 0, sum_f2 = 0, variation = 0, previous_force_n = 0;
  std::uint64_t measured = 0, saturated = 0;
  std::vector<double> forces;
  const bool want_spectrum = c.hf_cutoff_hz > 0;
  if (want_spectrum) forces.reserve(static_cast<std::size_t>(std::min<std::uint64_t>(periods, 1u << 26)));

  for (std::uint64_t k = 0; k < periods; ++k) {
    const double t = static_cast<double>(k) * T;
    if (c.plant.varies()) mass = c.plant.mass_at((k + 0.5) / periods), damping = c.plant.damping_at((k + 0.5) / periods);
    if (k > 0) {
      const double reading = measure(x);
      x_hat += position_alpha * (reading - x_hat);
      v_hat += velocity_alpha * ((reading - previous_reading) / T - v_hat);
      previous_reading = reading;
    }
    const ReferenceSample r_mm = c.reference.at(t);
    const double xr = r_mm.x_mm * from_mm, vr = r_mm.v_mm_s * from_mm, ar = r_mm.a_mm_s2 * from_mm;
    const double e = xr - x_hat, e_rate = vr - v_hat;
    const double surface = e_rate + c.gains.mu * e + c.gains.lambda * error_integral;
    double force = controller.force({xr, vr, ar, x_hat, v_hat, e, e_rate, error_integral, surface});
    if (!(std::abs(force) <= force_limit)) {
      force = std::isnan(force) ? 0 : std::copysign(force_limit, force);
      ++saturated;
    }
    double fd = cutting.at(t) * from_n;
    const double true_error = xr - x, true_rate = vr - v;
    if (!(std::abs(true_error) * to_mm <= c.divergence_mm)) {
      sum.diverged = true, sum.diverged_at_s = t;
      break;
    }
    const double force_n = force * to_n;
    if (t >= c.settle_s) {
      const double e_mm = true_error * to_mm, ev_mm = true_rate * to_mm, s_mm = surface * to_mm;
      sum_e2 += e_mm * e_mm, sum_ev2 += ev_mm * ev_mm, sum_s2 += s_mm * s_mm, sum_f2 += force_n * force_n;
      sum.max_error_mm = std::max(sum.max_error_mm, std::abs(e_mm));
      sum.max_force_n = std::max(sum.max_force_n, std::abs(force_n));
      if (measured > 0) variation += std::abs(force_n - previous_force_n);
      previous_force_n = force_n;
      if (want_spectrum && forces.size() < forces.capacity()) forces.push_back(force_n);
      ++measured;
    }
    // RK4 on (x, v)' = (v, (F − F_d(τ) − b v)/m), F held over the period.
    const double inv_m = 1 / mass;
    for (int j = 0; j < c.substeps; ++j) {
      const double tj = t + j * h;
      const double fd_mid = cutting.at(tj + h / 2) * from_n, fd_end = cutting.at(tj + h) * from_n;
      const double k1x = v, k1v = (force - fd - damping * v) * inv_m;
      const double v2 = v + h / 2 * k1v;
      const double k2x = v2, k2v = (force - fd_mid - damping * v2) * inv_m;
      const double v3 = v + h / 2 * k2v;
      const double k3x = v3, k3v = (force - fd_mid - damping * v3) * inv_m;
      const double v4 = v + h * k3v;
      const double k4x = v4, k4v = (force - fd_end - damping * v4) * inv_m;
      x += h / 6 * (k1x + 2 * k2x + 2 * k3x + k4x);
      v += h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
      fd = fd_end;
    }
    sum.plant_steps += static_cast<std::uint64_t>(c.substeps);
    error_integral += e * T;
  }
  if (measured > 0) {
    const double n = static_cast<double>(measured);
    sum.measured_s = n * T;
    sum.rms_error_mm = std::sqrt(sum_e2 / n), sum.rms_velocity_error_mm_s = std::sqrt(sum_ev2 / n);
    sum.rms_s = std::sqrt(sum_s2 / n), sum.effort_rms_n = std::sqrt(sum_f2 / n);
    sum.chattering_n_s = variation / sum.measured_s;
    sum.saturated_share = static_cast<double>(saturated) / static_cast<double>(std::max<std::uint64_t>(1, sum.plant_steps / c.substeps));
    if (want_spectrum) sum.hf_share = high_frequency_share(forces, T, c.hf_cutoff_hz);
  }
  return sum;
}

FeedDriveConfig default_run(ControllerKind kind) {
  FeedDriveConfig c;  // 10 s, 1e-4 s period, 10 substeps: 1e6 plant steps
  c.gains.kind = kind;
  c.gains.switching = 400;  // Λ (mN with the default millimetre unit); sta keeps α = β = 200
  return c;
}

/// ours / peer agreement on the run's rms error.
void check_agreement(const char* name, const FeedDriveSummary& ours, const FeedDriveSummary& peer) {
  const double relative = std::abs(ours.rms_error_mm - peer.rms_error_mm) / peer.rms_error_mm;
  std::printf("  %s: rms error ours %.6e mm, RK4 %.6e mm (%.3f %% apart); max error %.4e / %.4e mm; chattering %.4e / %.4e N/s\n",
              name, ours.rms_error_mm, peer.rms_error_mm, 100 * relative, ours.max_error_mm, peer.max_error_mm,
              ours.chattering_n_s, peer.chattering_n_s);
  if (ours.diverged || peer.diverged || ours.plant_steps != peer.plant_steps || !(relative < 0.02))
    bench::fail(std::string(name) + ": the exact step and RK4 disagree (rms error more than 2 % apart, or a diverged run)");
}

/// The bare plant, `steps` steps of h = 1e-5 s under the default cut with a
/// force held per 10 steps, ours (exact 2x2 step, rotating Stepper) and the
/// RK4 peer (MillingForce::at at the stages). `steps` is a multiple of 10;
/// each returns its final position.
struct BarePlant {
  FeedDriveConfig c;
  MillingForce cutting{c.cut};
  double h = c.period_s / c.substeps, from_n = 1 / c.length_unit_m;
  std::uint64_t steps;

  explicit BarePlant(std::uint64_t n) : steps(n) {}
  static double force_at(std::uint64_t period) { return 1000.0 * static_cast<double>(period % 7) - 3000.0; }  // mN

  double ours() const {
    DrivePlant plant;
    plant.configure(c.plant.mass_kg, c.plant.damping_kg_s, h);
    MillingForce::Stepper disturbance(cutting, h);
    disturbance.start(0);
    AxisState axis;
    double fd = disturbance.value() * from_n;
    for (std::uint64_t period = 0; period < steps / 10; ++period) {
      const double force = force_at(period);
      for (int j = 0; j < 10; ++j) {
        disturbance.advance();
        const double fd_next = disturbance.value() * from_n;
        plant.step(axis, force, fd, fd_next);
        fd = fd_next;
      }
    }
    return axis.x;
  }

  double peer() const {
    const double m = c.plant.mass_kg, b = c.plant.damping_kg_s, inv_m = 1 / m;
    double x = 0, v = 0, fd = cutting.at(0) * from_n;
    for (std::uint64_t i = 0; i < steps; ++i) {
      const double t = static_cast<double>(i) * h, force = force_at(i / 10);  // a division against the step's ~90 ns
      const double fd_mid = cutting.at(t + h / 2) * from_n, fd_end = cutting.at(t + h) * from_n;
      const double k1v = (force - fd - b * v) * inv_m;
      const double v2 = v + h / 2 * k1v, k2v = (force - fd_mid - b * v2) * inv_m;
      const double v3 = v + h / 2 * k2v, k3v = (force - fd_mid - b * v3) * inv_m;
      const double v4 = v + h * k3v, k4v = (force - fd_end - b * v4) * inv_m;
      x += h / 6 * (v + 2 * v2 + 2 * v3 + v4);
      v += h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
      fd = fd_end;
    }
    return x;
  }
};

double wall_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

/// smc with Λ = 1..settings, each the default 10 s run, through OrderedPool
/// as `smcsim sweep -j threads` does.
struct SweepRun {
  double wall_s, cpu_s;
  std::uint64_t plant_steps;
  std::vector<double> rms;
};

SweepRun sweep(int settings, unsigned threads) {
  SweepRun run{0, 0, 0, {}};
  const double wall0 = wall_seconds(), cpu0 = bench::cpu_seconds();
  {
    tk::OrderedPool<FeedDriveConfig, FeedDriveSummary> pool(
        threads, [](FeedDriveConfig& c) { return simulate_feed_drive(c); },
        [&](FeedDriveSummary& s) {
          run.plant_steps += s.plant_steps;
          run.rms.push_back(s.rms_error_mm);
        });
    FeedDriveConfig c = default_run(ControllerKind::smc);
    for (int lambda = 1; lambda <= settings; ++lambda) {
      c.gains.switching = lambda;
      pool.submit(c);
    }
    pool.finish();
  }
  run.wall_s = wall_seconds() - wall0, run.cpu_s = bench::cpu_seconds() - cpu0;
  return run;
}

const char* verdict(bool met) { return met ? "met" : "NOT met"; }

}  // namespace

int main() {
  const int repeats = bench::repeats({"BENCH_SMCSIM_REPEATS", "BENCH_REPEATS"}, 5);
  const int sweep_settings = [] {
    const char* text = std::getenv("BENCH_SMCSIM_SWEEP");
    return text ? std::max(0, std::atoi(text)) : 1000;
  }();
  std::printf("bench_smcsim: the default 10 s feed-drive run (1e6 plant steps), exact step vs RK4 (ode4), %d repeats\n", repeats);

  // (a) The full loop, one thread, ours against the RK4 loop.
  for (const auto& [name, kind] : {std::pair{"smc", ControllerKind::smc}, std::pair{"sta", ControllerKind::sta}}) {
    const FeedDriveConfig config = default_run(kind);
    FeedDriveSummary ours_summary, peer_summary;
    check_agreement(name, simulate_feed_drive(config), simulate_rk4(config));  // also warms up
    bench::Results results(std::string("smcsim_rk4_") + name);
    std::vector<double> rates;
    for (int r = 0; r < repeats; ++r) {
      const auto [ours, peer] = bench::time_interleaved([&] { ours_summary = simulate_feed_drive(config); },
                                                        [&] { peer_summary = simulate_rk4(config); });
      results.add(ours, peer);
      rates.push_back(static_cast<double>(ours_summary.plant_steps) / ours);
    }
    const double rate = bench::median(rates);
    std::printf("FIGURE smcsim_loop_%s %.2f million plant steps/s on one core (CPU time, median of %d, range %.2f-%.2f; goal 10; %s)\n",
                name, rate / 1e6, repeats, *std::min_element(rates.begin(), rates.end()) / 1e6,
                *std::max_element(rates.begin(), rates.end()) / 1e6, verdict(rate >= 10e6));
    results.report(1);
  }

  // (b) The bare plant step.
  {
    const BarePlant bare(5'000'000);
    const double x_ours = bare.ours(), x_peer = bare.peer();
    std::printf("  bare plant, %llu steps: x ours %.9e, RK4 %.9e\n", static_cast<unsigned long long>(bare.steps), x_ours, x_peer);
    if (!(std::abs(x_ours - x_peer) <= 1e-6 * std::abs(x_peer))) bench::fail("the bare exact step and RK4 end in different places");
    bench::Results results("smcsim_plant_rk4");
    std::vector<double> rates;
    double sink = 0;
    for (int r = 0; r < repeats; ++r) {
      const auto [ours, peer] = bench::time_interleaved([&] { sink += bare.ours(); }, [&] { sink += bare.peer(); });
      results.add(ours, peer);
      rates.push_back(static_cast<double>(bare.steps) / ours);
    }
    if (!std::isfinite(sink)) bench::fail("the bare plant diverged");
    const double rate = bench::median(rates);
    std::printf("FIGURE smcsim_plant_step %.1f million steps/s on one core (DrivePlant::step + Stepper, median of %d, range %.1f-%.1f)\n",
                rate / 1e6, repeats, *std::min_element(rates.begin(), rates.end()) / 1e6,
                *std::max_element(rates.begin(), rates.end()) / 1e6);
    results.report(1);
  }

  // (c) Two threads against one on 50 settings (wall time), then the sweep.
  {
    const int settings = 50, pairs = std::min(repeats, 3);
    // Wall time on a shared machine depends on what else runs; CPU / wall
    // says how many cores each side actually got.
    std::vector<double> speedups, cores;
    SweepRun one{}, two{};
    for (int r = 0; r < pairs; ++r) {
      one = sweep(settings, 1), two = sweep(settings, 2);
      if (one.rms != two.rms) bench::fail("the sweep on 2 threads gave other results than on 1");
      speedups.push_back(one.wall_s / two.wall_s);
      cores.push_back(two.cpu_s / two.wall_s);
      std::printf("  %d settings: 1 thread %.2f s wall (%.2f cores), 2 threads %.2f s wall (%.2f cores): speed-up %.2f\n",
                  settings, one.wall_s, one.cpu_s / one.wall_s, two.wall_s, cores.back(), speedups.back());
    }
    std::printf("FIGURE smcsim_sweep_speedup_2_threads %.2f (wall, %d settings, median of %d, range %.2f-%.2f; the 2-thread "
                "runs got %.2f cores, median CPU/wall)\n",
                bench::median(speedups), settings, pairs, *std::min_element(speedups.begin(), speedups.end()),
                *std::max_element(speedups.begin(), speedups.end()), bench::median(cores));
  }
  if (sweep_settings > 0) {
    const SweepRun run = sweep(sweep_settings, 2);
    const double goal_s = static_cast<double>(sweep_settings) * 1e6 / (2 * 10e6);  // 10 M steps/s on each of 2 cores
    std::printf("FIGURE smcsim_sweep_%d %.1f s wall on 2 threads (%.1f s CPU, %.2f cores; %.2f million plant steps/s in all, "
                "%.2f per CPU second; goal %.0f s; %s)\n",
                sweep_settings, run.wall_s, run.cpu_s, run.cpu_s / run.wall_s, static_cast<double>(run.plant_steps) / run.wall_s / 1e6,
                static_cast<double>(run.plant_steps) / run.cpu_s / 1e6, goal_s, verdict(run.wall_s <= goal_s));
  }
  return 0;
}
