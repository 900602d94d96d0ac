/// @file stepper_arc.cpp
/// @brief Arcs and helices on the step lattice, along the path that
/// ArcGeometry parametrises by the swept angle phi: one walk, one function
/// per stepping method. Every method tracks phi of the current lattice
/// point exactly (atan2 of the turn since the last point), and hands the
/// last couple of steps to the line stepper, aimed at the end quantised.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "io/error.hpp"
#include "motion/arc_geometry.hpp"
#include "motion/stepper.hpp"

namespace tk::motion {

namespace {

/// The arc's geometry; an Error for an arc of zero radius (before its end
/// is quantised).
ArcGeometry arc_of_some_radius(const Motion& motion) {
  ArcGeometry g = arc_geometry(motion);
  if (!(g.r_start > 0) || !(g.r_end > 0)) throw Error("arc of zero radius");
  return g;
}

}  // namespace

class Stepper::ArcWalk {
 public:
  ArcWalk(const Stepper& stepper, const Motion& motion, Chunk& out);

  /// Walks until the end is about two steps away, by the method's rule.
  void walk_nearest();
  void walk_bresenham();
  void walk_dda();

  /// The lattice point reached (axes in the stepper's order).
  std::array<std::int64_t, 3> at() const;
  /// How far along the helix the walk has come, mm.
  double done() const { return std::max(last_along_, along_of(phi_)); }
  const ArcGeometry& geometry() const { return g_; }

 private:
  /// One event's unit moves (in-plane axes a0, a1, normal axis a2) and the
  /// turn it makes.
  struct Move {
    int d0 = 0, d1 = 0, d2 = 0;
    double turn = 0;
  };
  /// The tangent at the current point and, per in-plane axis, the way it points.
  struct Heading {
    double t0 = 0, t1 = 0;
    int sign0 = 0, sign1 = 0;
  };

  // The current point relative to the centre.
  double offset0() const { return static_cast<double>(at0_) * h0_ - g_.c0; }
  double offset1() const { return static_cast<double>(at1_) * h1_ - g_.c1; }
  double projection(double phi_now) const;
  double along_of(double phi_now) const;
  void emit(int d0, int d1, int d2);
  void prepare();
  template <bool kAxial>
  double cost_of(int d0, int d1, int d2, double& turn_out) const;
  /// `best` becomes the candidate (d0, d1, d2) when it costs less than `best_cost`.
  template <bool kAxial>
  void keep_cheaper(Move& best, double& best_cost, int d0, int d1, int d2) const;
  /// The nearest and the Bresenham walk share the loop; `choose` picks each
  /// event's move, `after` runs after it is made.
  template <class Choose, class After>
  void walk_planar(Choose choose, After after);
  Move nearest_move(const Heading& heading, int rise) const;
  Move bresenham_move(const Heading& heading, int rise) const;

  const ArcGeometry g_;
  Chunk& out_;
  const int a0_, a1_, a2_;
  const double h0_, h1_, h2_;
  const std::array<std::int64_t, 3> target_;
  int rise_sign_ = 0;
  // The walk keeps the lattice point itself, and hands it back before the
  // last steps.
  std::int64_t at0_, at1_, at2_;
  double phi_ = 0;  ///< the angle swept so far
  double end_zone_ = 0, mean_radius_ = 0, unrolled_ = 0, inv_length_ = 0, projection_start_ = 0, along_scale_ = 0;
  double axial_to_normal_ = 0, last_along_ = 0, inv_r_sq_ = 0, inv_2r_ = 0, inv_b_sq_ = 0;
  std::uint32_t since_exact_ = 0;
  // Per event (`prepare`): the current point, and the ideal radius there
  // (its change over one step is far below the errors being ranked).
  double b0_ = 0, b1_ = 0, r_sq_ = 0;
  // An in-plane axis may reverse only once the path has turned on it (its
  // tangent component changed sign since that axis last stepped).
  int last_sign0_ = 0, last_sign1_ = 0, tangent_sign0_ = 0, tangent_sign1_ = 0;
};

Stepper::ArcWalk::ArcWalk(const Stepper& stepper, const Motion& motion, Chunk& out)
    : g_(arc_of_some_radius(motion)),
      out_(out),
      a0_(g_.a0),
      a1_(g_.a1),
      a2_(g_.a2),
      h0_(stepper.step_mm_[a0_]),
      h1_(stepper.step_mm_[a1_]),
      h2_(stepper.step_mm_[a2_]),
      target_(stepper.quantise(motion.end)),
      at0_(stepper.position_[a0_]),
      at1_(stepper.position_[a1_]),
      at2_(stepper.position_[a2_]) {
  rise_sign_ = target_[a2_] > at2_ ? 1 : target_[a2_] < at2_ ? -1 : 0;
  {
    const double angle = std::atan2(offset1(), offset0());
    double d = g_.turn * (angle - g_.start_angle);
    d = std::remainder(d, kTwoPi);  // the start point rounds to a lattice point next to it
    phi_ = d;
  }
  // The last steps go straight to the end: within about two steps of it.
  end_zone_ = 2.5 * std::max(h0_, h1_) / std::max(std::min(g_.r_start, g_.r_end), 1e-300);
  // How far along the helix a lattice point lies: unrolled, the helix is
  // a straight line in (arc length, height); project the point's (R phi,
  // height) onto it, so a step of the normal axis alone advances too.
  mean_radius_ = 0.5 * (g_.r_start + g_.r_end);
  unrolled_ = mean_radius_ * g_.sweep;
  inv_length_ = 1.0 / g_.length;
  // The start's lattice point projects a little before or after 0: map
  // [that, length] onto [0, length] (the last steps are mapped below).
  projection_start_ = projection(phi_);
  along_scale_ = projection_start_ < g_.length ? g_.length / (g_.length - projection_start_) : 1.0;
  // Distance from the helix, to first order: the radial error, and the
  // height error at the point's own angle times the cosine of the helix's
  // slope (unrolled, the helix is a line; a point above it by dz lies
  // dz * cos(slope) from it). On a flat arc the factor is 1.
  axial_to_normal_ = unrolled_ / g_.length;
  inv_r_sq_ = 1.0 / (g_.r_start * g_.r_end);
  inv_2r_ = 1.0 / (g_.r_start + g_.r_end);
  inv_b_sq_ = inv_r_sq_;
}

std::array<std::int64_t, 3> Stepper::ArcWalk::at() const {
  std::array<std::int64_t, 3> point{};
  point[a0_] = at0_;
  point[a1_] = at1_;
  point[a2_] = at2_;
  return point;
}

double Stepper::ArcWalk::projection(double phi_now) const {
  const double rise_done = static_cast<double>(at2_) * h2_ - g_.z_start;
  return (mean_radius_ * phi_now * unrolled_ + rise_done * g_.z_rise) * inv_length_;
}

double Stepper::ArcWalk::along_of(double phi_now) const {
  return std::clamp((projection(phi_now) - projection_start_) * along_scale_, 0.0, g_.length);
}

// phi advances by the turn between successive points, taken as cross / R^2
// with R the ideal radius (the sine of the turn, with the points' radii,
// which stay within a step of R, put to R: no square root or division on
// the chain from one event to the next); every 256 events phi is set to
// the point's exact angle, so the small errors never add up.
inline void Stepper::ArcWalk::emit(int d0, int d1, int d2) {
  const double v0 = offset0(), v1 = offset1();
  at0_ += d0;
  at1_ += d1;
  at2_ += d2;
  const double w0 = offset0(), w1 = offset1();
  phi_ += g_.turn * (v0 * w1 - v1 * w0) * inv_r_sq_;
  if (++since_exact_ == 256) {
    // The exact angle of the point, unwrapped next to the running value.
    since_exact_ = 0;
    const double exact = g_.turn * (std::atan2(w1, w0) - g_.start_angle);
    phi_ += std::remainder(exact - phi_, kTwoPi);
  }
  const double rho = std::sqrt(w0 * w0 + w1 * w1);
  StepEvent event;
  event.delta[a0_] = static_cast<std::int8_t>(d0);
  event.delta[a1_] = static_cast<std::int8_t>(d1);
  event.delta[a2_] = static_cast<std::int8_t>(d2);
  last_along_ = std::max(last_along_, along_of(phi_));  // a resync of phi may step back a hair
  event.along_mm = last_along_;
  const double radial = rho - g_.radius(phi_);
  const double axial = (static_cast<double>(at2_) * h2_ - g_.height(phi_)) * axial_to_normal_;
  event.deviation_sq = radial * radial + axial * axial;
  out_.push(event);
}

inline void Stepper::ArcWalk::prepare() {
  b0_ = offset0();
  b1_ = offset1();
  const double r = g_.radius(phi_);
  r_sq_ = r * r;
}

// Cost of a candidate point: its squared distance from the ideal helix, to
// first order (no square roots: only the ranking matters), with phi
// advanced by the small-angle estimate of its turn. Bresenham's midpoint
// decision is in the plane alone (the normal axis follows on its own), so
// it weighs the radial error only (kAxial false).
template <bool kAxial>
inline double Stepper::ArcWalk::cost_of(int d0, int d1, int d2, double& turn_out) const {
  const double w0 = b0_ + d0 * h0_, w1 = b1_ + d1 * h1_;
  const double rho_sq = w0 * w0 + w1 * w1;
  const double turn = g_.turn * (b0_ * w1 - b1_ * w0) * inv_b_sq_;
  turn_out = turn;
  const double phi_new = phi_ + turn;
  const double radial = (rho_sq - r_sq_) * inv_2r_;
  const double axial = kAxial ? (static_cast<double>(at2_ + d2) * h2_ - g_.height(phi_new)) * axial_to_normal_ : 0.0;
  return radial * radial + axial * axial;
}

template <bool kAxial>
inline void Stepper::ArcWalk::keep_cheaper(Move& best, double& best_cost, int d0, int d1, int d2) const {
  double turn = 0;
  const double cost = cost_of<kAxial>(d0, d1, d2, turn);
  if (cost < best_cost) {
    best_cost = cost;
    best = {d0, d1, d2, turn};
  }
}

template <class Choose, class After>
void Stepper::ArcWalk::walk_planar(Choose choose, After after) {
  // A safety bound: the walk advances phi at every in-plane step and
  // rises at most |rise| times, so it never needs this many events.
  const double planar_steps = std::max(g_.r_start, g_.r_end) * g_.sweep / std::min(h0_, h1_);
  const double bound = 4.0 * (planar_steps + std::fabs(g_.z_rise) / h2_) + 16.0;
  for (double events = 0; g_.sweep - phi_ > end_zone_ && events < bound; ++events) {
    prepare();
    // Tangent: which in-plane moves advance along the arc.
    Heading heading;
    heading.t0 = -g_.turn * b1_;
    heading.t1 = g_.turn * b0_;
    heading.sign0 = heading.t0 > 0 ? 1 : -1;
    heading.sign1 = heading.t1 > 0 ? 1 : -1;
    const int rise = at2_ != target_[a2_] ? rise_sign_ : 0;
    const Move best = choose(heading, rise);
    if ((best.d0 || best.d1) && best.turn <= 0) break;  // radius below a step: finish straight
    if (!best.d0 && !best.d1 && !best.d2) break;
    emit(best.d0, best.d1, best.d2);
    if (best.d0) {
      last_sign0_ = best.d0;
      tangent_sign0_ = heading.sign0;
    }
    if (best.d1) {
      last_sign1_ = best.d1;
      tangent_sign1_ = heading.sign1;
    }
    after(rise);
  }
}

// The neighbour nearest the helix. The paper prints no rule for arcs: its
// direct method walks them this way too. The reversal rule keeps a steep
// helix near an extreme from dithering back and forth, a burst of pulses
// microseconds apart.
Stepper::ArcWalk::Move Stepper::ArcWalk::nearest_move(const Heading& h, int rise) const {
  Move best;
  if (!rise) {
    // The common case, no rise to make: the three in-plane neighbours the
    // tangent's way, ranked without branches (which of them wins is what a
    // branch predictor cannot guess). Same order and ties as the general
    // search below.
    const bool blocked0 = h.sign0 == -last_sign0_ && h.sign0 == tangent_sign0_;
    const bool blocked1 = h.sign1 == -last_sign1_ && h.sign1 == tangent_sign1_;
    double turn_a = 0, turn_b = 0, turn_c = 0;
    const double cost_a = blocked1 ? INFINITY : cost_of<true>(0, h.sign1, 0, turn_a);
    const double cost_b = blocked0 ? INFINITY : cost_of<true>(h.sign0, 0, 0, turn_b);
    const double cost_c = blocked0 || blocked1 ? INFINITY : cost_of<true>(h.sign0, h.sign1, 0, turn_c);
    const bool b_beats_a = cost_b < cost_a;
    const double best_ab = b_beats_a ? cost_b : cost_a;
    const bool c_wins = cost_c < best_ab;
    if (c_wins || best_ab < INFINITY) {
      best.d0 = c_wins || b_beats_a ? h.sign0 : 0;
      best.d1 = c_wins || !b_beats_a ? h.sign1 : 0;
      best.turn = c_wins ? turn_c : b_beats_a ? turn_b : turn_a;
    }
    return best;
  }
  double best_cost = INFINITY;
  auto consider = [&](int d0, int d1, int d2) { keep_cheaper<true>(best, best_cost, d0, d1, d2); };
  auto reverses = [&](int d0, int d1) {
    return (d0 != 0 && d0 == -last_sign0_ && h.sign0 == tangent_sign0_) ||
           (d1 != 0 && d1 == -last_sign1_ && h.sign1 == tangent_sign1_);
  };
  // The neighbours around the tangent: each in-plane axis still or one
  // step the tangent's way (a move against the tangent on an axis never
  // lies nearer an arc that turns less than 90 degrees in one step).
  for (int d0 = 0; d0 != 2 * h.sign0; d0 += h.sign0)
    for (int d1 = 0; d1 != 2 * h.sign1; d1 += h.sign1) {
      if (!d0 && !d1) continue;
      if (reverses(d0, d1)) continue;
      consider(d0, d1, 0);
      consider(d0, d1, rise);
    }
  consider(0, 0, rise);  // a steep helix may need a rise alone
  return best;
}

// Bresenham (midpoint): the in-plane axis with the larger tangent component
// steps; the other joins when that lands nearer the arc. The normal axis
// joins when it lags half a step or more.
inline Stepper::ArcWalk::Move Stepper::ArcWalk::bresenham_move(const Heading& h, int rise) const {
  Move best;
  double best_cost = INFINITY;
  auto consider = [&](int d0, int d1, int d2) { keep_cheaper<false>(best, best_cost, d0, d1, d2); };
  const bool major0 = std::fabs(h.t0) / h0_ >= std::fabs(h.t1) / h1_;
  consider(major0 ? h.sign0 : 0, major0 ? 0 : h.sign1, 0);
  consider(h.sign0, h.sign1, 0);
  const double lag = (g_.height(phi_ + best.turn) - static_cast<double>(at2_) * h2_) * rise;
  if (rise && lag >= 0.5 * h2_) best.d2 = rise;
  return best;
}

void Stepper::ArcWalk::walk_nearest() {
  walk_planar([this](const Heading& h, int rise) { return nearest_move(h, rise); }, [](int) {});
}

void Stepper::ArcWalk::walk_bresenham() {
  walk_planar(
      [this](const Heading& h, int rise) { return bresenham_move(h, rise); },
      [this](int rise) {
        // On a steep helix: the rise alone while it lags a step.
        if (rise)
          while ((g_.height(phi_) - static_cast<double>(at2_) * h2_) * rise >= 1.5 * h2_ && at2_ != target_[a2_])
            emit(0, 0, rise);
      });
}

// Sample the ideal path finely enough that no axis moves more than half a
// step between samples; step wherever a rounded coordinate changes.
void Stepper::ArcWalk::walk_dda() {
  const double planar_steps = std::max(g_.r_start, g_.r_end) * g_.sweep / std::min(h0_, h1_);
  const double rise_steps = std::fabs(g_.z_rise) / h2_;
  const auto samples = static_cast<std::uint64_t>(std::ceil(2.0 * std::max(planar_steps, rise_steps))) + 1;
  for (std::uint64_t i = 1; i <= samples; ++i) {
    const double phi_i = g_.sweep * static_cast<double>(i) / static_cast<double>(samples);
    if (g_.sweep - phi_i < end_zone_) break;
    const double angle = g_.start_angle + g_.turn * phi_i, r = g_.radius(phi_i);
    const auto sample0 = static_cast<std::int64_t>(std::llround((g_.c0 + r * std::cos(angle)) / h0_));
    const auto sample1 = static_cast<std::int64_t>(std::llround((g_.c1 + r * std::sin(angle)) / h1_));
    const auto sample2 = static_cast<std::int64_t>(std::llround(g_.height(phi_i) / h2_));
    const auto d0 = std::clamp<std::int64_t>(sample0 - at0_, -1, 1);
    const auto d1 = std::clamp<std::int64_t>(sample1 - at1_, -1, 1);
    const auto d2 = std::clamp<std::int64_t>(sample2 - at2_, -1, 1);
    if (d0 || d1 || d2) emit(static_cast<int>(d0), static_cast<int>(d1), static_cast<int>(d2));
  }
}

double Stepper::run_arc(const Motion& motion, Chunk& out) {
  ArcWalk walk(*this, motion, out);
  switch (method_) {
    case StepMethod::direct:
    case StepMethod::nearest: walk.walk_nearest(); break;
    case StepMethod::bresenham: walk.walk_bresenham(); break;
    case StepMethod::dda: walk.walk_dda(); break;
  }
  position_ = walk.at();
  const double length = walk.geometry().length;
  // The last steps: straight to the end quantised, as a short line.
  Motion rest = motion;
  rest.kind = MotionKind::linear;
  for (int axis = 0; axis < 3; ++axis) rest.start[axis] = static_cast<double>(position_[axis]) * step_mm_[axis];
  // The last steps share out what is left of the path in proportion to
  // their own progress, ending exactly at its end.
  double straight = 0;
  for (int axis = 0; axis < 3; ++axis) {
    const double d = motion.end[axis] - rest.start[axis];
    straight += d * d;
  }
  straight = std::sqrt(straight);
  const double done = walk.done(), left = length - done;
  const std::function<void(std::span<const StepEvent>)> shift_along = [&](std::span<const StepEvent> events) {
    for (StepEvent event : events) {
      event.along_mm = straight > 0 ? std::min(done + left * event.along_mm / straight, length) : length;
      out.push(event);
    }
  };
  Chunk tail_out(shift_along);
  run_line(rest, tail_out);
  tail_out.flush();
  return length;
}

}  // namespace tk::motion
