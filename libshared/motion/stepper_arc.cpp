/// @file stepper_arc.cpp
/// @brief Arcs and helices on the step lattice, along the path that
/// ArcGeometry parametrises by the swept angle phi. Every method tracks
/// phi of the current lattice point
/// exactly (atan2 of the turn since the last point), and hands the last
/// couple of steps to the line stepper, aimed at the end quantised.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "io/error.hpp"
#include "motion/arc_geometry.hpp"
#include "motion/stepper.hpp"

namespace tk::motion {

double Stepper::run_arc(const Motion& motion, Chunk& out) {
  const ArcGeometry g = arc_geometry(motion);
  if (!(g.r_start > 0) || !(g.r_end > 0)) throw Error("arc of zero radius");
  const int a0 = g.a0, a1 = g.a1, a2 = g.a2;
  const double h0 = step_mm_[a0], h1 = step_mm_[a1], h2 = step_mm_[a2];
  const auto target = quantise(motion.end);
  const int rise_sign = target[a2] > position_[a2] ? 1 : target[a2] < position_[a2] ? -1 : 0;
  // The walk keeps the lattice point in locals (nothing the event buffer
  // writes can alias them), and hands it back before the last steps.
  std::int64_t at0 = position_[a0], at1 = position_[a1], at2 = position_[a2];

  // The current point relative to the centre, and its angle phi so far.
  auto offset0 = [&] { return static_cast<double>(at0) * h0 - g.c0; };
  auto offset1 = [&] { return static_cast<double>(at1) * h1 - g.c1; };
  double phi = 0;
  {
    const double angle = std::atan2(offset1(), offset0());
    double d = g.turn * (angle - g.start_angle);
    d = std::remainder(d, kTwoPi);  // the start point rounds to a lattice point next to it
    phi = d;
  }
  // The last steps go straight to the end: within about two steps of it.
  const double end_zone = 2.5 * std::max(h0, h1) / std::max(std::min(g.r_start, g.r_end), 1e-300);

  // How far along the helix a lattice point lies: unrolled, the helix is
  // a straight line in (arc length, height); project the point's (R phi,
  // height) onto it, so a step of the normal axis alone advances too.
  const double mean_radius = 0.5 * (g.r_start + g.r_end);
  const double unrolled = mean_radius * g.sweep;
  const double inv_length = 1.0 / g.length;
  auto projection = [&](double phi_now) {
    const double rise_done = static_cast<double>(at2) * h2 - g.z_start;
    return (mean_radius * phi_now * unrolled + rise_done * g.z_rise) * inv_length;
  };
  // The start's lattice point projects a little before or after 0: map
  // [that, length] onto [0, length] (the last steps are mapped below).
  const double projection_start = projection(phi);
  const double along_scale = projection_start < g.length ? g.length / (g.length - projection_start) : 1.0;
  auto along_of = [&](double phi_now) {
    return std::clamp((projection(phi_now) - projection_start) * along_scale, 0.0, g.length);
  };
  // Distance from the helix, to first order: the radial error, and the
  // height error at the point's own angle times the cosine of the helix's
  // slope (unrolled, the helix is a line; a point above it by dz lies
  // dz * cos(slope) from it). On a flat arc the factor is 1.
  const double axial_to_normal = unrolled / g.length;
  // phi advances by the turn between successive points, taken as
  // cross / R^2 with R the ideal radius (the sine of the turn, with the
  // points' radii, which stay within a step of R, put to R: no square root
  // or division on the chain from one event to the next); every 256
  // events phi is set to the point's exact angle, so the small errors
  // never add up.
  std::uint32_t since_exact = 0;
  double last_along = 0;
  const double inv_r_sq = 1.0 / (g.r_start * g.r_end);
  auto emit = [&](int d0, int d1, int d2) {
    const double v0 = offset0(), v1 = offset1();
    at0 += d0;
    at1 += d1;
    at2 += d2;
    const double w0 = offset0(), w1 = offset1();
    phi += g.turn * (v0 * w1 - v1 * w0) * inv_r_sq;
    if (++since_exact == 256) {
      // The exact angle of the point, unwrapped next to the running value.
      since_exact = 0;
      const double exact = g.turn * (std::atan2(w1, w0) - g.start_angle);
      phi += std::remainder(exact - phi, kTwoPi);
    }
    const double rho = std::sqrt(w0 * w0 + w1 * w1);
    StepEvent event;
    event.delta[a0] = static_cast<std::int8_t>(d0);
    event.delta[a1] = static_cast<std::int8_t>(d1);
    event.delta[a2] = static_cast<std::int8_t>(d2);
    last_along = std::max(last_along, along_of(phi));  // a resync of phi may step back a hair
    event.along_mm = last_along;
    const double radial = rho - g.radius(phi);
    const double axial = (static_cast<double>(at2) * h2 - g.height(phi)) * axial_to_normal;
    event.deviation_sq = radial * radial + axial * axial;
    out.push(event);
  };
  // The paper prints no rule for arcs: its direct method walks them as the
  // nearest method does, by the neighbour nearest the helix.
  const bool nearest_walk = method_ == StepMethod::nearest || method_ == StepMethod::direct;
  // Cost of a candidate point: its squared distance from the ideal helix,
  // to first order (no square roots: only the ranking matters), with phi
  // advanced by the small-angle estimate of its turn. Bresenham's midpoint
  // decision is in the plane alone (the normal axis follows on its own),
  // so it weighs the radial error only.
  // Per event (`prepare`): the current point, and the ideal radius there
  // (its change over one step is far below the errors being ranked).
  double b0 = 0, b1 = 0, r_sq = 0;
  const double inv_2r = 1.0 / (g.r_start + g.r_end), inv_b_sq = inv_r_sq;
  auto prepare = [&] {
    b0 = offset0();
    b1 = offset1();
    const double r = g.radius(phi);
    r_sq = r * r;
  };
  auto cost_of = [&](int d0, int d1, int d2, double& turn_out) {
    const double w0 = b0 + d0 * h0, w1 = b1 + d1 * h1;
    const double rho_sq = w0 * w0 + w1 * w1;
    const double turn = g.turn * (b0 * w1 - b1 * w0) * inv_b_sq;
    turn_out = turn;
    const double phi_new = phi + turn;
    const double radial = (rho_sq - r_sq) * inv_2r;
    const double axial =
        nearest_walk ? (static_cast<double>(at2 + d2) * h2 - g.height(phi_new)) * axial_to_normal : 0.0;
    return radial * radial + axial * axial;
  };

  if (method_ == StepMethod::dda) {
    // Sample the ideal path finely enough that no axis moves more than half
    // a step between samples; step wherever a rounded coordinate changes.
    const double planar_steps = std::max(g.r_start, g.r_end) * g.sweep / std::min(h0, h1);
    const double rise_steps = std::fabs(g.z_rise) / h2;
    const auto samples = static_cast<std::uint64_t>(std::ceil(2.0 * std::max(planar_steps, rise_steps))) + 1;
    for (std::uint64_t i = 1; i <= samples; ++i) {
      const double phi_i = g.sweep * static_cast<double>(i) / static_cast<double>(samples);
      if (g.sweep - phi_i < end_zone) break;
      const double angle = g.start_angle + g.turn * phi_i, r = g.radius(phi_i);
      const auto sample0 = static_cast<std::int64_t>(std::llround((g.c0 + r * std::cos(angle)) / h0));
      const auto sample1 = static_cast<std::int64_t>(std::llround((g.c1 + r * std::sin(angle)) / h1));
      const auto sample2 = static_cast<std::int64_t>(std::llround(g.height(phi_i) / h2));
      const auto d0 = std::clamp<std::int64_t>(sample0 - at0, -1, 1);
      const auto d1 = std::clamp<std::int64_t>(sample1 - at1, -1, 1);
      const auto d2 = std::clamp<std::int64_t>(sample2 - at2, -1, 1);
      if (d0 || d1 || d2) emit(static_cast<int>(d0), static_cast<int>(d1), static_cast<int>(d2));
    }
  } else {
    // A safety bound: the walk advances phi at every in-plane step and
    // rises at most |rise| times, so it never needs this many events.
    const double planar_steps = std::max(g.r_start, g.r_end) * g.sweep / std::min(h0, h1);
    const double bound = 4.0 * (planar_steps + std::fabs(g.z_rise) / h2) + 16.0;
    // An in-plane axis may reverse only once the path has turned on it
    // (its tangent component changed sign since that axis last stepped):
    // near an extreme of a steep helix the nearest point would otherwise
    // dither back and forth, a burst of pulses microseconds apart.
    int last_sign0 = 0, last_sign1 = 0, tangent_sign0 = 0, tangent_sign1 = 0;
    for (double events = 0; g.sweep - phi > end_zone && events < bound; ++events) {
      prepare();
      // Tangent: which in-plane moves advance along the arc.
      const double t0 = -g.turn * b1, t1 = g.turn * b0;
      const int now_sign0 = t0 > 0 ? 1 : -1, now_sign1 = t1 > 0 ? 1 : -1;
      auto reverses = [&](int d0, int d1) {
        return (d0 != 0 && d0 == -last_sign0 && now_sign0 == tangent_sign0) ||
               (d1 != 0 && d1 == -last_sign1 && now_sign1 == tangent_sign1);
      };
      const int rise = at2 != target[a2] ? rise_sign : 0;
      int best0 = 0, best1 = 0, best2 = 0;
      double best_cost = INFINITY, turn = 0;
      auto consider = [&](int d0, int d1, int d2) {
        double candidate_turn = 0;
        const double cost = cost_of(d0, d1, d2, candidate_turn);
        if (cost < best_cost) {
          best_cost = cost;
          best0 = d0;
          best1 = d1;
          best2 = d2;
          turn = candidate_turn;
        }
      };
      if (nearest_walk && !rise) {
        // The common case, no rise to make: the three in-plane neighbours
        // the tangent's way, ranked without branches (which of them wins
        // is what a branch predictor cannot guess). Same order and ties as
        // the general loop below.
        const bool blocked0 = now_sign0 == -last_sign0 && now_sign0 == tangent_sign0;
        const bool blocked1 = now_sign1 == -last_sign1 && now_sign1 == tangent_sign1;
        double turn_a = 0, turn_b = 0, turn_c = 0;
        const double cost_a = blocked1 ? INFINITY : cost_of(0, now_sign1, 0, turn_a);
        const double cost_b = blocked0 ? INFINITY : cost_of(now_sign0, 0, 0, turn_b);
        const double cost_c = blocked0 || blocked1 ? INFINITY : cost_of(now_sign0, now_sign1, 0, turn_c);
        const bool b_beats_a = cost_b < cost_a;
        const double best_ab = b_beats_a ? cost_b : cost_a;
        const bool c_wins = cost_c < best_ab;
        if (c_wins || best_ab < INFINITY) {
          best0 = c_wins || b_beats_a ? now_sign0 : 0;
          best1 = c_wins || !b_beats_a ? now_sign1 : 0;
          turn = c_wins ? turn_c : b_beats_a ? turn_b : turn_a;
        }
      } else if (nearest_walk) {
        // The neighbours around the tangent: each in-plane axis still or one
        // step the tangent's way (a move against the tangent on an axis never
        // lies nearer an arc that turns less than 90 degrees in one step).
        for (int d0 = 0; d0 != 2 * now_sign0; d0 += now_sign0)
          for (int d1 = 0; d1 != 2 * now_sign1; d1 += now_sign1) {
            if (!d0 && !d1) continue;
            if (reverses(d0, d1)) continue;
            consider(d0, d1, 0);
            if (rise) consider(d0, d1, rise);
          }
        if (rise) consider(0, 0, rise);  // a steep helix may need a rise alone
      } else {
        // Bresenham (midpoint): the in-plane axis with the larger tangent
        // component steps; the other joins when that lands nearer the arc.
        const int s0 = t0 > 0 ? 1 : -1, s1 = t1 > 0 ? 1 : -1;
        const bool major0 = std::fabs(t0) / h0 >= std::fabs(t1) / h1;
        consider(major0 ? s0 : 0, major0 ? 0 : s1, 0);
        consider(s0, s1, 0);
        // The normal axis joins when it lags half a step or more.
        const double lag = (g.height(phi + turn) - static_cast<double>(at2) * h2) * rise;
        if (rise && lag >= 0.5 * h2) best2 = rise;
      }
      if ((best0 || best1) && turn <= 0) break;  // radius below a step: finish straight
      if (!best0 && !best1 && !best2) break;
      emit(best0, best1, best2);
      if (best0) {
        last_sign0 = best0;
        tangent_sign0 = now_sign0;
      }
      if (best1) {
        last_sign1 = best1;
        tangent_sign1 = now_sign1;
      }
      // Bresenham on a steep helix: the rise alone while it lags a step.
      if (method_ == StepMethod::bresenham && rise)
        while ((g.height(phi) - static_cast<double>(at2) * h2) * rise >= 1.5 * h2 && at2 != target[a2])
          emit(0, 0, rise);
    }
  }
  position_[a0] = at0;
  position_[a1] = at1;
  position_[a2] = at2;
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
  const double done = std::max(last_along, along_of(phi)), left = g.length - done;
  const std::function<void(std::span<const StepEvent>)> shift_along = [&](std::span<const StepEvent> events) {
    for (StepEvent event : events) {
      event.along_mm = straight > 0 ? std::min(done + left * event.along_mm / straight, g.length) : g.length;
      out.push(event);
    }
  };
  Chunk tail_out(shift_along);
  run_line(rest, tail_out);
  tail_out.flush();
  return g.length;
}

}  // namespace tk::motion
