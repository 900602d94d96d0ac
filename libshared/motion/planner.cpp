/// @file planner.cpp
#include "motion/planner.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "io/error.hpp"
#include "motion/arc_geometry.hpp"

namespace tk::motion {

namespace {

constexpr double kUnlimited = std::numeric_limits<double>::infinity();

double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

/// Path length and unit directions at both ends; 0 length for a motion
/// that goes nowhere. `radius` is the smallest radius of an arc (else 0).
/// `share` is the largest |component| of a unit tangent on each axis.
void shape_of(const Motion& m, double& length, Vec3& entry, Vec3& exit, double& radius, Vec3& share) {
  radius = 0;
  if (m.kind == MotionKind::arc) {
    const ArcGeometry g = arc_geometry(m);
    length = g.length;
    entry = g.tangent(0);
    exit = g.tangent(g.sweep);
    radius = std::min(g.r_start, g.r_end);
    const double rise = length > 0 ? std::fabs(g.z_rise) / length : 0;
    share[g.a0] = share[g.a1] = std::sqrt(std::max(0.0, 1 - rise * rise));
    share[g.a2] = rise;
    return;
  }
  Vec3 d{m.end.x - m.start.x, m.end.y - m.start.y, m.end.z - m.start.z};
  length = std::sqrt(dot(d, d));
  if (length > 0) d = Vec3{d.x / length, d.y / length, d.z / length};
  entry = exit = d;
  share = Vec3{std::fabs(d.x), std::fabs(d.y), std::fabs(d.z)};
}

/// The largest path value (speed or acceleration) whose share on every
/// axis stays within that axis' limit.
double limit_by_axes(double path_limit, const std::array<double, 3>& axis_limit, const Vec3& share) {
  for (int axis = 0; axis < 3; ++axis)
    if (share[axis] > 1e-12) path_limit = std::min(path_limit, axis_limit[axis] / share[axis]);
  return path_limit;
}

/// The feed cap along a motion of this shape: --rapid for G0, --max-feed
/// otherwise, lowered so that no axis' share exceeds its own speed limit.
double speed_cap(const MachineLimits& limits, const Motion& motion, const Vec3& share) {
  return limit_by_axes(motion.kind == MotionKind::rapid ? limits.rapid_speed : limits.max_speed, limits.axis_speed,
                       share);
}

}  // namespace

double machine_speed_cap(const MachineLimits& limits, const Motion& motion) {
  double length = 0, radius = 0;
  Vec3 entry, exit, share;
  shape_of(motion, length, entry, exit, radius, share);
  return speed_cap(limits, motion, share);
}

double PlannedBlock::time_at(double along) const {
  const double s = std::clamp(along, 0.0, length);
  const double a = acceleration;
  if (s < cruise_from) return (std::sqrt(entry_speed * entry_speed + 2 * a * s) - entry_speed) / a;
  if (s <= cruise_to) return cruise_starts + (s - cruise_from) / cruise_speed;
  const double into = s - cruise_to;
  return cruise_ends + (cruise_speed - std::sqrt(std::max(0.0, cruise_speed * cruise_speed - 2 * a * into))) / a;
}

void complete_profile(PlannedBlock& block, double nominal) {
  const double a = block.acceleration, v0 = block.entry_speed, v1 = block.exit_speed, length = block.length;
  // The highest speed reachable between the two ends, capped by the feed.
  const double peak = std::sqrt((2 * a * length + v0 * v0 + v1 * v1) / 2);
  const double vc = std::max({std::min(nominal, peak), v0, v1});
  block.cruise_speed = vc;
  if (!(vc > 0)) {
    block.duration = 0;
    return;
  }
  const double s_accel = (vc * vc - v0 * v0) / (2 * a), s_decel = (vc * vc - v1 * v1) / (2 * a);
  const double s_cruise = std::max(0.0, length - s_accel - s_decel);
  block.cruise_from = std::min(s_accel, length);
  block.cruise_to = std::min(s_accel + s_cruise, length);
  block.cruise_starts = (vc - v0) / a;
  block.cruise_ends = block.cruise_starts + s_cruise / vc;
  block.duration = block.cruise_ends + (vc - v1) / a;
}

Planner::Planner(MachineLimits limits) : limits_(limits) {
  if (!(limits_.acceleration > 0) || !std::isfinite(limits_.acceleration)) throw Error("acceleration must be positive");
  if (!(limits_.rapid_speed > 0) || !(limits_.max_speed > 0)) throw Error("speeds must be positive");
  if (!(limits_.junction_deviation >= 0)) throw Error("junction deviation must not be negative");
  for (int axis = 0; axis < 3; ++axis)
    if (!(limits_.axis_speed[axis] > 0) || !(limits_.axis_acceleration[axis] > 0))
      throw Error("axis speeds and accelerations must be positive");
  limits_.lookahead = std::max<std::size_t>(limits_.lookahead, 1);
}

void Planner::add(const Motion& motion, const Sink& ready) {
  if (motion.kind == MotionKind::dwell) {
    finish(ready);
    PlannedBlock dwell;
    dwell.motion = motion;
    dwell.duration = motion.duration;
    ready(dwell);
    return;
  }
  Pending next;
  double radius = 0;
  Vec3 share;
  shape_of(motion, next.block.length, next.entry_direction, next.exit_direction, radius, share);
  if (!(next.block.length > 0)) return;
  next.block.motion = motion;
  const double a = limit_by_axes(limits_.acceleration, limits_.axis_acceleration, share);
  next.block.acceleration = a;
  double nominal = motion.kind == MotionKind::rapid ? limits_.rapid_speed
                   : motion.inverse_time            ? next.block.length / motion.duration
                                                    : motion.feed;
  // G0 runs as fast as the slowest axis it needs allows; a feed above
  // what the machine can do is capped (and counted).
  const double machine_speed = speed_cap(limits_, motion, share);
  if (nominal > machine_speed) {
    nominal = machine_speed;
    next.block.feed_capped = motion.kind != MotionKind::rapid;
  }
  if (radius > 0) nominal = std::min(nominal, std::sqrt(a * radius));  // centripetal limit
  next.nominal = nominal;

  // The corner with the previous block, by junction deviation (grbl).
  double junction = 0;
  if (have_previous_) {
    const double cos_turn = dot(previous_exit_direction_, next.entry_direction);  // 1: straight on
    if (cos_turn > 0.999999) {
      junction = kUnlimited;
    } else if (cos_turn > -0.999999) {
      const double sin_half = std::sqrt(0.5 * (1 - cos_turn));
      const double corner_a = std::min(a, previous_acceleration_);
      junction = std::sqrt(corner_a * limits_.junction_deviation * sin_half / (1 - sin_half));
    }
    junction = std::min({junction, nominal, previous_nominal_});
  }
  // A G33 after a motion that does not follow the spindle starts from rest:
  // the control stops there and waits for the spindle's index pulse, so
  // that every pass of a thread starts at the same angle (LinuxCNC), then
  // accelerates into it. G33 after G33 stays locked and joins as usual.
  if (motion.spindle_synchronised && !previous_synchronised_) junction = 0;
  next.max_entry = junction;
  have_previous_ = true;
  previous_synchronised_ = motion.spindle_synchronised;
  previous_exit_direction_ = next.exit_direction;
  previous_nominal_ = nominal;
  previous_acceleration_ = a;
  if (pending_.empty()) locked_entry_ = junction;
  pending_.push_back(next);
  // Planning costs the window's length: plan once it is full, then hand
  // out its first half, so each block costs a constant on average and
  // every block went out with at least half a window planned behind it.
  if (pending_.size() > limits_.lookahead) {
    plan();
    while (pending_.size() > limits_.lookahead / 2) emit_front(ready);
  }
}

void Planner::finish(const Sink& ready) {
  plan();
  while (!pending_.empty()) emit_front(ready);
  have_previous_ = false;
  locked_entry_ = 0;
}

// Backward from a stop at the window's end, then forward from the front
// block's fixed entry: every entry speed is the highest that both its
// junction allows and the accelerations on either side can reach.
void Planner::plan() {
  if (pending_.empty()) return;
  double exit = 0;
  for (std::size_t i = pending_.size(); i-- > 0;) {
    PlannedBlock& b = pending_[i].block;
    b.exit_speed = exit;
    b.entry_speed = std::min(pending_[i].max_entry, std::sqrt(exit * exit + 2 * b.acceleration * b.length));
    exit = b.entry_speed;
  }
  pending_.front().block.entry_speed = std::min(pending_.front().block.entry_speed, locked_entry_);
  for (std::size_t i = 0; i < pending_.size(); ++i) {
    PlannedBlock& b = pending_[i].block;
    if (i > 0) {
      const PlannedBlock& before = pending_[i - 1].block;
      b.entry_speed = std::min(
          b.entry_speed, std::sqrt(before.entry_speed * before.entry_speed + 2 * before.acceleration * before.length));
      pending_[i - 1].block.exit_speed = b.entry_speed;
    }
  }
  pending_.back().block.exit_speed = 0;
}

void Planner::emit_front(const Sink& ready) {
  Pending front = pending_.front();
  pending_.pop_front();
  complete_profile(front.block, front.nominal);
  locked_entry_ = front.block.exit_speed;
  if (!pending_.empty()) pending_.front().block.entry_speed = locked_entry_;
  ready(front.block);
}

}  // namespace tk::motion
