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
#include <string>
#include <utility>
#include <vector>

#include "bench_common.hpp"
#include "concurrency/ordered_pool.hpp"
#include "control/drive_plant.hpp"
#include "control/feed_drive_sim.hpp"
#include "control/milling_force.hpp"

namespace {

using namespace tk::control;

/// The peer: simulate_feed_drive's own loop, with the plant
/// m ẍ + b ẋ = F − F_d(t) integrated between samples by classical RK4 at the
/// same step, the force held and F_d evaluated where the stages need it, as
/// a Simulink model with the ode4 solver at a fixed step of h would.
/// Generous to the peer: F_d(t) is reused from the previous step's end, so
/// it costs two evaluations per step, not four.
class Rk4Integrator final : public PeriodIntegrator {
 public:
  explicit Rk4Integrator(const FeedDriveConfig& c)
      : cutting_(c.cut), h_(c.period_s / c.substeps), from_n_(1 / c.length_unit_m), substeps_(c.substeps) {}

  void configure(double mass_kg, double damping_kg_s) override { inv_m_ = 1 / mass_kg, damping_ = damping_kg_s; }

  void advance(AxisState& axis, double force, double t) override {
    double x = axis.x, v = axis.v, fd = cutting_.at(t) * from_n_;
    for (int j = 0; j < substeps_; ++j) {
      const double tj = t + j * h_;
      const double fd_mid = cutting_.at(tj + h_ / 2) * from_n_, fd_end = cutting_.at(tj + h_) * from_n_;
      const double k1v = (force - fd - damping_ * v) * inv_m_;
      const double v2 = v + h_ / 2 * k1v, k2v = (force - fd_mid - damping_ * v2) * inv_m_;
      const double v3 = v + h_ / 2 * k2v, k3v = (force - fd_mid - damping_ * v3) * inv_m_;
      const double v4 = v + h_ * k3v, k4v = (force - fd_end - damping_ * v4) * inv_m_;
      x += h_ / 6 * (v + 2 * v2 + 2 * v3 + v4);
      v += h_ / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
      fd = fd_end;
    }
    axis = {x, v};
  }

 private:
  const MillingForce cutting_;
  double h_, from_n_, inv_m_ = 0, damping_ = 0;
  int substeps_;
};

FeedDriveSummary simulate_rk4(const FeedDriveConfig& c) {
  Rk4Integrator rk4(c);
  return simulate_feed_drive(c, rk4);
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
  std::printf(
      "  %s: rms error ours %.6e mm, RK4 %.6e mm (%.3f %% apart); max error %.4e / %.4e mm; chattering %.4e / %.4e "
      "N/s\n",
      name, ours.rms_error_mm, peer.rms_error_mm, 100 * relative, ours.max_error_mm, peer.max_error_mm,
      ours.chattering_n_s, peer.chattering_n_s);
  if (ours.diverged || peer.diverged || ours.plant_steps != peer.plant_steps || !(relative < 0.02))
    bench::fail(std::string(name) +
                ": the exact step and RK4 disagree (rms error more than 2 % apart, or a diverged run)");
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
    Rk4Integrator rk4(c);
    rk4.configure(c.plant.mass_kg, c.plant.damping_kg_s);
    AxisState axis;
    for (std::uint64_t period = 0; period < steps / 10; ++period)
      rk4.advance(axis, force_at(period), static_cast<double>(period) * c.period_s);
    return axis.x;
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
  std::printf("bench_smcsim: the default 10 s feed-drive run (1e6 plant steps), exact step vs RK4 (ode4), %d repeats\n",
              repeats);

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
    std::printf(
        "FIGURE smcsim_loop_%s %.2f million plant steps/s on one core (CPU time, median of %d, range %.2f-%.2f; goal "
        "10; %s)\n",
        name, rate / 1e6, repeats, *std::min_element(rates.begin(), rates.end()) / 1e6,
        *std::max_element(rates.begin(), rates.end()) / 1e6, verdict(rate >= 10e6));
    results.report(1);
  }

  // (b) The bare plant step.
  {
    const BarePlant bare(5'000'000);
    const double x_ours = bare.ours(), x_peer = bare.peer();
    std::printf("  bare plant, %llu steps: x ours %.9e, RK4 %.9e\n", static_cast<unsigned long long>(bare.steps),
                x_ours, x_peer);
    if (!(std::abs(x_ours - x_peer) <= 1e-6 * std::abs(x_peer)))
      bench::fail("the bare exact step and RK4 end in different places");
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
    std::printf(
        "FIGURE smcsim_plant_step %.1f million steps/s on one core (DrivePlant::step + Stepper, median of %d, range "
        "%.1f-%.1f)\n",
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
      std::printf(
          "  %d settings: 1 thread %.2f s wall (%.2f cores), 2 threads %.2f s wall (%.2f cores): speed-up %.2f\n",
          settings, one.wall_s, one.cpu_s / one.wall_s, two.wall_s, cores.back(), speedups.back());
    }
    std::printf(
        "FIGURE smcsim_sweep_speedup_2_threads %.2f (wall, %d settings, median of %d, range %.2f-%.2f; the 2-thread "
        "runs got %.2f cores, median CPU/wall)\n",
        bench::median(speedups), settings, pairs, *std::min_element(speedups.begin(), speedups.end()),
        *std::max_element(speedups.begin(), speedups.end()), bench::median(cores));
  }
  if (sweep_settings > 0) {
    const SweepRun run = sweep(sweep_settings, 2);
    const double goal_s = static_cast<double>(sweep_settings) * 1e6 / (2 * 10e6);  // 10 M steps/s on each of 2 cores
    std::printf(
        "FIGURE smcsim_sweep_%d %.1f s wall on 2 threads (%.1f s CPU, %.2f cores; %.2f million plant steps/s in all, "
        "%.2f per CPU second; goal %.0f s; %s)\n",
        sweep_settings, run.wall_s, run.cpu_s, run.cpu_s / run.wall_s,
        static_cast<double>(run.plant_steps) / run.wall_s / 1e6, static_cast<double>(run.plant_steps) / run.cpu_s / 1e6,
        goal_s, verdict(run.wall_s <= goal_s));
  }
  return 0;
}
