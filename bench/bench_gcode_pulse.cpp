/// @file bench_gcode_pulse.cpp
/// @brief gcode-pulse's pipeline (interpreter, planner, stepper, timing)
/// on a synthetic program of random lines and arcs, in summary mode: the
/// nearest method (the default) against Bresenham in the same run (goal:
/// within 2x, a ratio of at least 0.5) and pulses per second (goal: 30
/// million for the nearest method), plus the paper's direct method, DDA
/// and the nearest method writing CSV. Then maximum and RMS deviation of
/// each method on 10,000 random lines and arcs.
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include "bench_common.hpp"
#include "deviation_study.hpp"
#include "io/record_writer.hpp"
#include "motion/pulse_run.hpp"

namespace {

using namespace tk::motion;

std::string write_program() {
  char path[] = "/tmp/bench_gcode_pulse_XXXXXX";
  const int fd = mkstemp(path);
  if (fd < 0) bench::fail("mkstemp");
  FILE* out = fdopen(fd, "w");
  std::mt19937_64 random(2026);
  std::uniform_real_distribution<double> xy(0, 100), z(0, 10), radius(80, 120);
  std::fprintf(out, "G21 G90 G17 G1 F3000\n");
  for (int i = 0; i < 600; ++i) {
    std::fprintf(out, "G1 X%.4f Y%.4f Z%.4f\n", xy(random), xy(random), z(random));
    std::fprintf(out, "G%d X%.4f Y%.4f R%.4f\n", i % 2 ? 2 : 3, xy(random), xy(random), radius(random));
  }
  std::fclose(out);
  return path;
}

PulseSummary run(const std::string& program, StepMethod method, FILE* csv = nullptr) {
  PulseOptions options;
  options.method = method;
  PulseRun::PulseSink sink;
  tk::io::RecordWriter writer(tk::io::OutputFormat::csv, csv ? csv : stdout);
  writer.declare_fields({"t", "dx", "dy", "dz"});
  if (csv)
    sink = [&](std::span<const Pulse> pulses) {
      for (const Pulse& p : pulses) {
        const double row[4] = {p.t, static_cast<double>(p.delta[0]), static_cast<double>(p.delta[1]),
                               static_cast<double>(p.delta[2])};
        writer.write_numbers(row, 0b1110);
      }
    };
  PulseRun pulse_run(options, sink, [](const std::string&) {});
  pulse_run.run_file(program);
  pulse_run.finish();
  if (csv) writer.flush();
  return pulse_run.summary();
}

std::uint64_t pulses(const PulseSummary& s) { return s.pulses[0] + s.pulses[1] + s.pulses[2]; }

/// Max and RMS deviation of one method over random lines and arcs (mm).
void deviation_study(StepMethod method, const char* name) {
  const auto d = study::deviation_over_random_moves(method, {200, 200, 400}, 10000, 7);
  std::printf(
      "FIGURE deviation_%s max %.5f mm rms %.5f mm over %llu events (5,000 lines, 5,000 arcs, 200/200/400 steps/mm)\n",
      name, d.max_mm, d.rms_mm, static_cast<unsigned long long>(d.events));
}

}  // namespace

int main() {
  const int repeats = bench::repeats({"BENCH_GCODE_PULSE_REPEATS", "BENCH_REPEATS"}, 5);
  const std::string program = write_program();
  std::printf("bench_gcode_pulse: nearest vs bresenham, --summary, 1,200 random lines and arcs, %d repeats\n", repeats);
  bench::Results results("bench_gcode_pulse");
  std::vector<double> nearest_rate, bresenham_rate;
  std::uint64_t count = 0;
  for (int r = 0; r < repeats; ++r) {
    PulseSummary nearest, bresenham;
    const auto [ours, peer] = bench::time_interleaved([&] { nearest = run(program, StepMethod::nearest); },
                                                      [&] { bresenham = run(program, StepMethod::bresenham); });
    for (int axis = 0; axis < 3; ++axis)
      if (nearest.final_mm[axis] != bresenham.final_mm[axis]) bench::fail("the methods end at different points");
    count = pulses(nearest);
    nearest_rate.push_back(static_cast<double>(pulses(nearest)) / ours);
    bresenham_rate.push_back(static_cast<double>(pulses(bresenham)) / peer);
    results.add(ours, peer);
  }
  results.report(0.5);
  std::printf("FIGURE pulses_per_s_nearest %.1f million (goal 30; %llu pulses a run)\n",
              bench::median(nearest_rate) / 1e6, static_cast<unsigned long long>(count));
  std::printf("FIGURE pulses_per_s_bresenham %.1f million\n", bench::median(bresenham_rate) / 1e6);
  const double direct = bench::time_cpu([&] { run(program, StepMethod::direct); });
  std::printf("FIGURE pulses_per_s_direct %.1f million (one run)\n", static_cast<double>(count) / direct / 1e6);
  const double dda = bench::time_cpu([&] { run(program, StepMethod::dda); });
  std::printf("FIGURE pulses_per_s_dda %.1f million (one run)\n", static_cast<double>(count) / dda / 1e6);
  FILE* null = std::fopen("/dev/null", "w");
  const double csv = bench::time_cpu([&] { run(program, StepMethod::nearest, null); });
  std::fclose(null);
  std::printf("FIGURE pulses_per_s_nearest_csv %.1f million (one run, CSV written to /dev/null)\n",
              static_cast<double>(count) / csv / 1e6);
  std::remove(program.c_str());
  for (std::size_t i = 0; i < kStepMethodNames.size(); ++i)
    deviation_study(static_cast<StepMethod>(i), kStepMethodNames[i]);
  return 0;
}
