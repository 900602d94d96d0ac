/// @file test_pulse_estimate.cpp
/// @brief The pulses a motion implies (gcode-pulse --max-pulses) against the
/// pulses the stepper makes on random lines and arcs: equal on lines, and
/// on arcs within the rounding of the lattice at the circle's extremes
/// (an axis' travel is counted in mm, the stepper's in whole steps).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "motion/pulse_estimate.hpp"
#include "motion/stepper.hpp"

namespace {

using namespace tk::motion;

constexpr std::array<double, 3> kEstimateStepsPerMm{200, 160, 400};

double pulses_made(Stepper& stepper, const Motion& motion) {
  double pulses = 0;
  stepper.run(motion, [&](std::span<const StepEvent> events) {
    for (const StepEvent& event : events)
      for (int axis = 0; axis < 3; ++axis) pulses += std::abs(event.delta[axis]);
  });
  return pulses;
}

TEST(PulseEstimate, LinesImplyTheStepsBetweenTheirQuantisedEnds) {
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> coordinate(-50, 50);
  for (StepMethod method : {StepMethod::nearest, StepMethod::bresenham, StepMethod::dda}) {
    Stepper stepper(method, kEstimateStepsPerMm);
    Vec3 from{};
    for (int line = 0; line < 200; ++line) {
      Motion motion;
      motion.start = from;
      motion.end = Vec3{coordinate(random), coordinate(random), line % 3 == 0 ? coordinate(random) : from.z};
      EXPECT_EQ(implied_pulses(motion, kEstimateStepsPerMm), pulses_made(stepper, motion)) << "line " << line;
      from = motion.end;
    }
  }
}

TEST(PulseEstimate, ArcsImplyTheTravelOfEachAxisWithinTheRoundingAtTheExtremes) {
  std::mt19937_64 random(13);
  std::uniform_real_distribution<double> unit(0, 1);
  for (StepMethod method : {StepMethod::nearest, StepMethod::bresenham}) {
    Stepper stepper(method, kEstimateStepsPerMm);
    Vec3 from{};
    for (int arc = 0; arc < 150; ++arc) {
      Motion motion;
      motion.kind = MotionKind::arc;
      motion.clockwise = arc % 2 == 0;
      motion.turns = arc % 5 == 0 ? 3 : 0;
      const double radius = 0.1 + 20 * unit(random), start_angle = 2 * std::numbers::pi * unit(random);
      const double sweep = 6 * unit(random) + 0.05;
      motion.start = from;
      motion.center = Vec3{from.x - radius * std::cos(start_angle), from.y - radius * std::sin(start_angle), from.z};
      const double end_angle = start_angle + (motion.clockwise ? -sweep : sweep);
      motion.end = Vec3{motion.center.x + radius * std::cos(end_angle), motion.center.y + radius * std::sin(end_angle),
                        from.z + (arc % 3 == 0 ? 4 * unit(random) - 2 : 0)};
      const double made = pulses_made(stepper, motion), implied = implied_pulses(motion, kEstimateStepsPerMm);
      // A step of rounding at each end and at each extreme of each plane axis.
      const double turns = (sweep + 2 * std::numbers::pi * static_cast<double>(motion.turns)) / std::numbers::pi;
      EXPECT_NEAR(implied, made, 2 * (turns + 3)) << "arc " << arc << " radius " << radius << " sweep " << sweep;
      from = motion.end;
    }
  }
}

TEST(PulseEstimate, DwellsImplyNone) {
  Motion dwell;
  dwell.kind = MotionKind::dwell;
  dwell.duration = 5;
  EXPECT_EQ(implied_pulses(dwell, kEstimateStepsPerMm), 0);
}

}  // namespace
