/// @file stepper.cpp
/// @brief The stepper's lattice and its dispatch: lines walk in
/// stepper_line.cpp, arcs in stepper_arc.cpp.
#include "motion/stepper.hpp"

#include <cmath>
#include <string>

#include "io/error.hpp"

namespace tk::motion {

StepMethod step_method_named(std::string_view name) {
  for (std::size_t i = 0; i < kStepMethodNames.size(); ++i)
    if (name == kStepMethodNames[i]) return static_cast<StepMethod>(i);
  throw Error("unknown stepping method '" + std::string(name) + "'");
}

Stepper::Stepper(StepMethod method, std::array<double, 3> steps_per_mm) : method_(method), steps_per_mm_(steps_per_mm) {
  for (int axis = 0; axis < 3; ++axis) {
    if (!(steps_per_mm[axis] > 0) || !std::isfinite(steps_per_mm[axis]))
      throw Error("steps per mm must be positive and finite");
    step_mm_[axis] = 1.0 / steps_per_mm[axis];
  }
}

std::array<std::int64_t, 3> Stepper::quantise(const Vec3& mm) const {
  std::array<std::int64_t, 3> lattice{};
  for (int axis = 0; axis < 3; ++axis) {
    const double steps = std::round(mm[axis] * steps_per_mm_[axis]);
    if (!(std::fabs(steps) < 9e15)) throw Error("coordinate beyond the step counters' range");
    lattice[axis] = static_cast<std::int64_t>(steps);
  }
  return lattice;
}

double Stepper::run(const Motion& motion, const std::function<void(std::span<const StepEvent>)>& sink) {
  if (motion.kind == MotionKind::dwell) return 0;
  Chunk out(sink);
  const double length = motion.kind == MotionKind::arc ? run_arc(motion, out) : run_line(motion, out);
  out.flush();
  return length;
}

}  // namespace tk::motion
