/// @file stepper.cpp
#include "motion/stepper.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numbers>
#include <string>

#include "io/error.hpp"

namespace tk::motion {

namespace {


int sign_of(std::int64_t value) { return (value > 0) - (value < 0); }

}  // namespace

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

// Lines. The state is the current point's offset e from the ideal line
// (perpendicular to it) and its position `along` the line. A move s (a set
// of axes, each one step toward the target) changes them by s - (s.u)u and
// s.u, so the new squared deviation is |e|^2 + 2 e.s + |s_perp|^2: the
// nearest method compares 2 e.s + |s_perp|^2 over at most 7 moves, with
// |s_perp|^2 computed once per line.
double Stepper::run_line(const Motion& motion, Chunk& out) {
  const auto target = quantise(motion.end);
  std::array<std::int64_t, 3> remaining{};
  std::array<int, 3> sign{};
  std::array<double, 3> step{}, u{}, e{};
  double length = 0, lattice_length = 0;
  for (int axis = 0; axis < 3; ++axis) {
    remaining[axis] = target[axis] - position_[axis];
    sign[axis] = sign_of(remaining[axis]);
    step[axis] = sign[axis] * step_mm_[axis];
    const double d = motion.end[axis] - motion.start[axis];
    length += d * d;
    const double lattice_d = static_cast<double>(remaining[axis]) * step_mm_[axis];
    lattice_length += lattice_d * lattice_d;
  }
  length = std::sqrt(length);
  lattice_length = std::sqrt(lattice_length);
  if (lattice_length == 0) return length;
  // The ideal line is the programmed one; a segment shorter than a step
  // whose ends round apart takes the lattice's direction.
  const bool programmed = length > 1e-9 * lattice_length && length > 1e-12;
  for (int axis = 0; axis < 3; ++axis)
    u[axis] = programmed ? (motion.end[axis] - motion.start[axis]) / length
                         : static_cast<double>(remaining[axis]) * step_mm_[axis] / lattice_length;
  double along = 0;
  for (int axis = 0; axis < 3; ++axis) along += (position_[axis] * step_mm_[axis] - motion.start[axis]) * u[axis];
  // When an event comes: a step generator steps an axis as its ideal
  // coordinate crosses the midpoint between two lattice values. The axis
  // that steps most often per mm paces the events: an event that moves it
  // comes at its crossing, so its steps are evenly spaced whatever the
  // method picked; any other event comes at its point's projection on the
  // line (never before the event before it).
  int pacing = 0;
  for (int axis = 1; axis < 3; ++axis)
    if (std::fabs(u[axis]) * steps_per_mm_[axis] > std::fabs(u[pacing]) * steps_per_mm_[pacing]) pacing = axis;
  const double pacing_per_mm = 1.0 / u[pacing];
  double last_along = 0;
  for (int axis = 0; axis < 3; ++axis) e[axis] = position_[axis] * step_mm_[axis] - motion.start[axis] - along * u[axis];

  // Per move (bit i = axis i steps): its component along u, its
  // perpendicular part and that part's squared length.
  std::array<double, 8> move_along{}, move_perp_sq{};
  std::array<std::array<double, 3>, 8> move_perp{};
  for (int mask = 1; mask < 8; ++mask) {
    double su = 0;
    for (int axis = 0; axis < 3; ++axis)
      if (mask >> axis & 1) su += step[axis] * u[axis];
    double sq = 0;
    for (int axis = 0; axis < 3; ++axis) {
      move_perp[mask][axis] = ((mask >> axis & 1) ? step[axis] : 0.0) - su * u[axis];
      sq += move_perp[mask][axis] * move_perp[mask][axis];
    }
    move_along[mask] = su;
    move_perp_sq[mask] = sq;
  }

  // The lattice point in a local (nothing the event buffer writes can
  // alias it), handed back at the end.
  std::array<std::int64_t, 3> at = position_;
  auto apply = [&](int mask) {
    StepEvent event;
    double crossing = -INFINITY;
    if (mask >> pacing & 1) {
      const double midpoint = (static_cast<double>(at[pacing]) + 0.5 * sign[pacing]) * step_mm_[pacing];
      crossing = (midpoint - motion.start[pacing]) * pacing_per_mm;
    }
    for (int axis = 0; axis < 3; ++axis) {
      if (mask >> axis & 1) {
        at[axis] += sign[axis];
        remaining[axis] -= sign[axis];
        event.delta[axis] = static_cast<std::int8_t>(sign[axis]);
      }
      e[axis] += move_perp[mask][axis];
    }
    along += move_along[mask];
    if (crossing == -INFINITY) crossing = along;
    last_along = std::clamp(std::max(last_along, crossing), 0.0, length);
    event.along_mm = last_along;
    event.deviation_sq = e[0] * e[0] + e[1] * e[1] + e[2] * e[2];
    out.push(event);
  };
  auto moving_axes = [&] {
    int mask = 0;
    for (int axis = 0; axis < 3; ++axis)
      if (remaining[axis] != 0) mask |= 1 << axis;
    return mask;
  };

  if (method_ == StepMethod::direct) {
    // Panayotov & Goranov, in lattice units (the box of one step is then a
    // cube): from the current point, the line to the target with n steps
    // left on each axis leaves the box where the axis with the most left,
    // N, reaches its face (t = 1/N), at n_i/N of a step on every other
    // axis. The nearest of the 26 points rounds each coordinate to -1, 0
    // or +1 on its own, so an axis steps when |n_i|/N is at least 1/2; a
    // tie ("any matching vector can be chosen") goes to the larger stride.
    // Re-origin: n changes, and with it the line. N falls by one an event.
    for (;;) {
      std::int64_t most = 0;
      for (int axis = 0; axis < 3; ++axis) most = std::max<std::int64_t>(most, std::llabs(remaining[axis]));
      if (most == 0) break;
      int mask = 0;
      for (int axis = 0; axis < 3; ++axis)
        if (2 * std::llabs(remaining[axis]) >= most) mask |= 1 << axis;
      apply(mask);
    }
  } else if (method_ == StepMethod::nearest) {
    // Moves with more axes first, so a tie goes to the larger stride.
    static constexpr int kOrder[7] = {7, 3, 5, 6, 1, 2, 4};
    int allowed = moving_axes();
    std::array<int, 7> candidates{};
    int count = 0;
    auto rebuild = [&] {
      count = 0;
      for (int mask : kOrder)
        if ((mask & ~allowed) == 0) candidates[count++] = mask;
    };
    rebuild();
    while (allowed != 0) {
      const double p0 = 2 * e[0] * step[0], p1 = 2 * e[1] * step[1], p2 = 2 * e[2] * step[2];
      const double partial[8] = {0, p0, p1, p0 + p1, p2, p0 + p2, p1 + p2, p0 + p1 + p2};
      int best = candidates[0];
      double best_cost = partial[best] + move_perp_sq[best];
      // Selects rather than branches: which move wins is data, not pattern.
      for (int i = 1; i < count; ++i) {
        const int mask = candidates[i];
        const double cost = partial[mask] + move_perp_sq[mask];
        const bool better = cost < best_cost;
        best = better ? mask : best;
        best_cost = better ? cost : best_cost;
      }
      apply(best);
      const int now = moving_axes();
      if (now != allowed) {
        allowed = now;
        rebuild();
      }
    }
  } else if (method_ == StepMethod::bresenham) {
    int major = 0;
    for (int axis = 1; axis < 3; ++axis)
      if (std::llabs(remaining[axis]) > std::llabs(remaining[major])) major = axis;
    const std::int64_t n = std::llabs(remaining[major]);
    std::array<std::int64_t, 3> error{}, rise{};
    for (int axis = 0; axis < 3; ++axis) {
      rise[axis] = 2 * std::llabs(remaining[axis]);
      error[axis] = rise[axis] - n;
    }
    for (std::int64_t i = 0; i < n; ++i) {
      int mask = 1 << major;
      for (int axis = 0; axis < 3; ++axis) {
        if (axis == major) continue;
        if (error[axis] > 0) {
          mask |= 1 << axis;
          error[axis] -= 2 * n;
        }
        error[axis] += rise[axis];
      }
      apply(mask);
    }
  } else {
    // DDA: a register of N = 2^k >= the longest axis' steps; every tick
    // adds each axis' step count, and an overflow is a step. Starting at
    // N/2 rounds instead of truncating.
    std::uint64_t longest = 0;
    for (int axis = 0; axis < 3; ++axis) longest = std::max<std::uint64_t>(longest, std::llabs(remaining[axis]));
    const std::uint64_t register_size = std::bit_ceil(longest);
    std::array<std::uint64_t, 3> accumulator{register_size / 2, register_size / 2, register_size / 2}, rate{};
    for (int axis = 0; axis < 3; ++axis) rate[axis] = static_cast<std::uint64_t>(std::llabs(remaining[axis]));
    for (std::uint64_t tick = 0; tick < register_size; ++tick) {
      int mask = 0;
      for (int axis = 0; axis < 3; ++axis) {
        accumulator[axis] += rate[axis];
        if (accumulator[axis] >= register_size) {
          accumulator[axis] -= register_size;
          mask |= 1 << axis;
        }
      }
      if (mask) apply(mask);
    }
  }
  position_ = at;
  if (position_ != target) throw Error("internal error: a line did not end on its target");
  return length;
}

}  // namespace tk::motion
