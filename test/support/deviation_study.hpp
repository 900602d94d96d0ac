/// @file deviation_study.hpp
/// @brief How closely a stepping method follows the path: its largest and
/// RMS distance from the ideal path over random moves (lines of up to 10 mm per
/// axis in XY and 1 mm in Z, alternating with arcs of radius 0.2 to 10.2 mm
/// and 0.1 to 6.1 radians, every other one a helix). Shared by the unit
/// test that compares the methods and the benchmark that reports them.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <random>

#include "motion/stepper.hpp"

namespace tk::motion::study {

struct Deviation {
  double max_mm = 0, rms_mm = 0;
  std::uint64_t events = 0;
};

inline Deviation deviation_over_random_moves(StepMethod method, std::array<double, 3> steps_per_mm, int moves,
                                             std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> unit(0, 1);
  Stepper stepper(method, steps_per_mm);
  double worst = 0, sum_sq = 0;
  std::uint64_t events = 0;
  Vec3 at{};
  for (int i = 0; i < moves; ++i) {
    Motion m;
    m.start = at;
    if (i % 2 == 0) {
      m.end = {at.x + 20 * unit(random) - 10, at.y + 20 * unit(random) - 10, at.z + 2 * unit(random) - 1};
    } else {
      m.kind = MotionKind::arc;
      const double r = 0.2 + 10 * unit(random), a = 6.283 * unit(random), sweep = 0.1 + 6 * unit(random);
      m.clockwise = unit(random) < 0.5;
      m.center = {at.x - r * std::cos(a), at.y - r * std::sin(a), at.z};
      const double e = a + (m.clockwise ? -sweep : sweep);
      m.end = {m.center.x + r * std::cos(e), m.center.y + r * std::sin(e), at.z + (i % 4 == 1 ? unit(random) - 0.5 : 0)};
    }
    stepper.run(m, [&](std::span<const StepEvent> chunk) {
      for (const StepEvent& event : chunk) {
        worst = std::max(worst, event.deviation_sq);
        sum_sq += event.deviation_sq;
      }
      events += chunk.size();
    });
    at = m.end;
  }
  return {std::sqrt(worst), events ? std::sqrt(sum_sq / static_cast<double>(events)) : 0.0, events};
}

}  // namespace tk::motion::study
