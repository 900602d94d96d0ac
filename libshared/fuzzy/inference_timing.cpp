/// @file inference_timing.cpp
/// @brief CPU-time measurement of inferences, medians over rounds.
#include "fuzzy/inference_timing.hpp"

#include <time.h>

#include <algorithm>
#include <cstdint>
#include <random>

namespace tk::fuzzy {
namespace {

double cpu_seconds() {
  timespec now{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + static_cast<double>(now.tv_nsec) * 1e-9;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

}  // namespace

std::vector<std::array<double, 3>> protocol_triples(int adc_bits) {
  const std::uint64_t scale = (std::uint64_t{1} << adc_bits);
  std::vector<std::array<double, 3>> triples(1024);
  std::mt19937_64 random(2020);  // its output is fixed by the standard: the same triples everywhere
  auto next = [&] { return static_cast<double>(random() % scale); };
  for (auto& t : triples) t = {next(), next(), next()};
  return triples;
}

InferenceTiming time_inferences(Mamdani& controller, std::span<const std::array<double, 3>> triples, double seconds) {
  std::vector<double> outputs(controller.output_count());
  volatile double sink = 0;
  auto block = [&] {
    for (const auto& t : triples) {
      controller.evaluate(t, outputs);
      sink = sink + outputs[0];
    }
  };
  const double per_block = static_cast<double>(triples.size() * outputs.size());
  block();  // warm caches and scratch buffers
  InferenceTiming timing;
  std::vector<double> single, per_inference;
  const double start = cpu_seconds();
  // Rounds of 16 blocks, at least 9 of them, until the time is used.
  while (per_inference.size() < 9 || cpu_seconds() - start < seconds) {
    const double t0 = cpu_seconds();
    block();
    const double t1 = cpu_seconds();
    for (int k = 1; k < 16; ++k) block();
    const double t2 = cpu_seconds();
    single.push_back((t1 - t0) * 1e3);
    per_inference.push_back((t2 - t0) / (16 * per_block) * 1e9);
    timing.inferences += static_cast<std::uint64_t>(16 * per_block);
    if (per_inference.size() >= 100000) break;
  }
  timing.ns_per_inference = median(per_inference);
  timing.ms_per_2x1024 = median(single) * 2048 / per_block;
  return timing;
}

}  // namespace tk::fuzzy
