/// @file stepper_line.cpp
/// @brief Lines on the step lattice: one walk, one function per stepping
/// method, all moving through LineWalk::apply.
//
// The state is the current point's offset e from the ideal line
// (perpendicular to it) and its position `along` the line. A move s (a set
// of axes, each one step toward the target) changes them by s - (s.u)u and
// s.u, so the new squared deviation is |e|^2 + 2 e.s + |s_perp|^2: the
// nearest method compares 2 e.s + |s_perp|^2 over at most 7 moves, with
// |s_perp|^2 computed once per line.
#include <algorithm>
#include <bit>
#include <cmath>

#include "io/error.hpp"
#include "motion/stepper.hpp"

namespace tk::motion {

class Stepper::LineWalk {
 public:
  LineWalk(const Stepper& stepper, const Motion& motion, Chunk& out);

  /// The programmed length, mm.
  double length() const { return length_; }
  /// The ends quantise to one lattice point: no step to make.
  bool empty() const { return lattice_length_ == 0; }
  /// The lattice point reached; throws when it is not the target.
  const std::array<std::int64_t, 3>& end() const;

  void walk_direct();
  void walk_nearest();
  void walk_bresenham();
  void walk_dda();

 private:
  /// What an event changes. Each walk keeps it in a local and hands it
  /// back at its end: kept in members, it would be stored and reloaded at
  /// every event, since the compiler cannot tell it from the bytes the
  /// event is stored into (bresenham ran 40 % slower).
  struct Cursor {
    std::array<std::int64_t, 3> at, remaining;
    std::array<double, 3> e;
    double along, last_along;
  };
  Cursor cursor() const { return {at_, remaining_, e_, along_, last_along_}; }
  void settle(const Cursor& c) {
    at_ = c.at, remaining_ = c.remaining, e_ = c.e, along_ = c.along, last_along_ = c.last_along;
  }
  /// Moves the axes of `mask` (bit i = axis i) one step each and emits the event.
  void apply(Cursor& c, int mask) const;
  /// The axes with steps left, as a mask.
  static int moving_axes(const Cursor& c);

  const Motion& motion_;
  Chunk& out_;
  const std::array<double, 3>& step_mm_;
  std::array<std::int64_t, 3> target_, remaining_{};
  std::array<int, 3> sign_{};
  std::array<double, 3> step_{}, u_{}, e_{};
  double length_ = 0, lattice_length_ = 0, along_ = 0, last_along_ = 0, pacing_per_mm_ = 0;
  int pacing_ = 0;
  // Per move (bit i = axis i steps): its component along u, its
  // perpendicular part and that part's squared length.
  std::array<double, 8> move_along_{}, move_perp_sq_{};
  std::array<std::array<double, 3>, 8> move_perp_{};
  /// The lattice point reached, handed back to the stepper at the end.
  std::array<std::int64_t, 3> at_;
};

Stepper::LineWalk::LineWalk(const Stepper& stepper, const Motion& motion, Chunk& out)
    : motion_(motion),
      out_(out),
      step_mm_(stepper.step_mm_),
      target_(stepper.quantise(motion.end)),
      at_(stepper.position_) {
  for (int axis = 0; axis < 3; ++axis) {
    remaining_[axis] = target_[axis] - at_[axis];
    sign_[axis] = (remaining_[axis] > 0) - (remaining_[axis] < 0);
    step_[axis] = sign_[axis] * step_mm_[axis];
    const double d = motion.end[axis] - motion.start[axis];
    length_ += d * d;
    const double lattice_d = static_cast<double>(remaining_[axis]) * step_mm_[axis];
    lattice_length_ += lattice_d * lattice_d;
  }
  length_ = std::sqrt(length_);
  lattice_length_ = std::sqrt(lattice_length_);
  if (lattice_length_ == 0) return;
  // The ideal line is the programmed one; a segment shorter than a step
  // whose ends round apart takes the lattice's direction.
  const bool programmed = length_ > 1e-9 * lattice_length_ && length_ > 1e-12;
  for (int axis = 0; axis < 3; ++axis)
    u_[axis] = programmed ? (motion.end[axis] - motion.start[axis]) / length_
                          : static_cast<double>(remaining_[axis]) * step_mm_[axis] / lattice_length_;
  for (int axis = 0; axis < 3; ++axis) along_ += (at_[axis] * step_mm_[axis] - motion.start[axis]) * u_[axis];
  // When an event comes: a step generator steps an axis as its ideal
  // coordinate crosses the midpoint between two lattice values. The axis
  // that steps most often per mm paces the events: an event that moves it
  // comes at its crossing, so its steps are evenly spaced whatever the
  // method picked; any other event comes at its point's projection on the
  // line (never before the event before it).
  for (int axis = 1; axis < 3; ++axis)
    if (std::fabs(u_[axis]) * stepper.steps_per_mm_[axis] > std::fabs(u_[pacing_]) * stepper.steps_per_mm_[pacing_])
      pacing_ = axis;
  pacing_per_mm_ = 1.0 / u_[pacing_];
  for (int axis = 0; axis < 3; ++axis) e_[axis] = at_[axis] * step_mm_[axis] - motion.start[axis] - along_ * u_[axis];

  for (int mask = 1; mask < 8; ++mask) {
    double su = 0;
    for (int axis = 0; axis < 3; ++axis)
      if (mask >> axis & 1) su += step_[axis] * u_[axis];
    double sq = 0;
    for (int axis = 0; axis < 3; ++axis) {
      move_perp_[mask][axis] = ((mask >> axis & 1) ? step_[axis] : 0.0) - su * u_[axis];
      sq += move_perp_[mask][axis] * move_perp_[mask][axis];
    }
    move_along_[mask] = su;
    move_perp_sq_[mask] = sq;
  }
}

const std::array<std::int64_t, 3>& Stepper::LineWalk::end() const {
  if (at_ != target_) throw Error("internal error: a line did not end on its target");
  return at_;
}

inline void Stepper::LineWalk::apply(Cursor& c, int mask) const {
  StepEvent event;
  double crossing = -INFINITY;
  if (mask >> pacing_ & 1) {
    const double midpoint = (static_cast<double>(c.at[pacing_]) + 0.5 * sign_[pacing_]) * step_mm_[pacing_];
    crossing = (midpoint - motion_.start[pacing_]) * pacing_per_mm_;
  }
  for (int axis = 0; axis < 3; ++axis) {
    if (mask >> axis & 1) {
      c.at[axis] += sign_[axis];
      c.remaining[axis] -= sign_[axis];
      event.delta[axis] = static_cast<std::int8_t>(sign_[axis]);
    }
    c.e[axis] += move_perp_[mask][axis];
  }
  c.along += move_along_[mask];
  if (crossing == -INFINITY) crossing = c.along;
  c.last_along = std::clamp(std::max(c.last_along, crossing), 0.0, length_);
  event.along_mm = c.last_along;
  event.deviation_sq = c.e[0] * c.e[0] + c.e[1] * c.e[1] + c.e[2] * c.e[2];
  out_.push(event);
}

inline int Stepper::LineWalk::moving_axes(const Cursor& c) {
  int mask = 0;
  for (int axis = 0; axis < 3; ++axis)
    if (c.remaining[axis] != 0) mask |= 1 << axis;
  return mask;
}

// Panayotov & Goranov, in lattice units (the box of one step is then a
// cube): from the current point, the line to the target with n steps left
// on each axis leaves the box where the axis with the most left, N, reaches
// its face (t = 1/N), at n_i/N of a step on every other axis. The nearest of
// the 26 points rounds each coordinate to -1, 0 or +1 on its own, so an axis
// steps when |n_i|/N is at least 1/2; a tie ("any matching vector can be
// chosen") goes to the larger stride. Re-origin: n changes, and with it the
// line. N falls by one an event.
void Stepper::LineWalk::walk_direct() {
  Cursor c = cursor();
  for (;;) {
    std::int64_t most = 0;
    for (int axis = 0; axis < 3; ++axis) most = std::max<std::int64_t>(most, std::llabs(c.remaining[axis]));
    if (most == 0) break;
    int mask = 0;
    for (int axis = 0; axis < 3; ++axis)
      if (2 * std::llabs(c.remaining[axis]) >= most) mask |= 1 << axis;
    apply(c, mask);
  }
  settle(c);
}

// Of the moves toward the target, the one whose point lies nearest the
// programmed line.
void Stepper::LineWalk::walk_nearest() {
  Cursor c = cursor();
  // Moves with more axes first, so a tie goes to the larger stride.
  static constexpr int kOrder[7] = {7, 3, 5, 6, 1, 2, 4};
  int allowed = moving_axes(c);
  std::array<int, 7> candidates{};
  int count = 0;
  auto rebuild = [&] {
    count = 0;
    for (int mask : kOrder)
      if ((mask & ~allowed) == 0) candidates[count++] = mask;
  };
  rebuild();
  while (allowed != 0) {
    const double p0 = 2 * c.e[0] * step_[0], p1 = 2 * c.e[1] * step_[1], p2 = 2 * c.e[2] * step_[2];
    const double partial[8] = {0, p0, p1, p0 + p1, p2, p0 + p2, p1 + p2, p0 + p1 + p2};
    int best = candidates[0];
    double best_cost = partial[best] + move_perp_sq_[best];
    // Selects rather than branches: which move wins is data, not pattern.
    for (int i = 1; i < count; ++i) {
      const int mask = candidates[i];
      const double cost = partial[mask] + move_perp_sq_[mask];
      const bool better = cost < best_cost;
      best = better ? mask : best;
      best_cost = better ? cost : best_cost;
    }
    apply(c, best);
    const int now = moving_axes(c);
    if (now != allowed) {
      allowed = now;
      rebuild();
    }
  }
  settle(c);
}

// The major axis steps every event, a minor one when its error term crosses.
void Stepper::LineWalk::walk_bresenham() {
  Cursor c = cursor();
  int major = 0;
  for (int axis = 1; axis < 3; ++axis)
    if (std::llabs(c.remaining[axis]) > std::llabs(c.remaining[major])) major = axis;
  const std::int64_t n = std::llabs(c.remaining[major]);
  std::array<std::int64_t, 3> error{}, rise{};
  for (int axis = 0; axis < 3; ++axis) {
    rise[axis] = 2 * std::llabs(c.remaining[axis]);
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
    apply(c, mask);
  }
  settle(c);
}

// A register of N = 2^k >= the longest axis' steps; every tick adds each
// axis' step count, and an overflow is a step. Starting at N/2 rounds
// instead of truncating.
void Stepper::LineWalk::walk_dda() {
  Cursor c = cursor();
  std::uint64_t longest = 0;
  for (int axis = 0; axis < 3; ++axis) longest = std::max<std::uint64_t>(longest, std::llabs(c.remaining[axis]));
  const std::uint64_t register_size = std::bit_ceil(longest);
  std::array<std::uint64_t, 3> accumulator{register_size / 2, register_size / 2, register_size / 2}, rate{};
  for (int axis = 0; axis < 3; ++axis) rate[axis] = static_cast<std::uint64_t>(std::llabs(c.remaining[axis]));
  for (std::uint64_t tick = 0; tick < register_size; ++tick) {
    int mask = 0;
    for (int axis = 0; axis < 3; ++axis) {
      accumulator[axis] += rate[axis];
      if (accumulator[axis] >= register_size) {
        accumulator[axis] -= register_size;
        mask |= 1 << axis;
      }
    }
    if (mask) apply(c, mask);
  }
  settle(c);
}

double Stepper::run_line(const Motion& motion, Chunk& out) {
  LineWalk walk(*this, motion, out);
  if (walk.empty()) return walk.length();
  switch (method_) {
    case StepMethod::direct: walk.walk_direct(); break;
    case StepMethod::nearest: walk.walk_nearest(); break;
    case StepMethod::bresenham: walk.walk_bresenham(); break;
    case StepMethod::dda: walk.walk_dda(); break;
  }
  position_ = walk.end();
  return walk.length();
}

}  // namespace tk::motion
