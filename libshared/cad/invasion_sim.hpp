/// @file invasion_sim.hpp
/// @brief The seed's experiment, simulated: an operator drives the tool
/// with a joystick straight at the part while a control loop guards the
/// prohibited region (the part grown by the tool radius). The control
/// samples the tool's position every `period_s`, on a clock the operator
/// does not see (each stroke starts at a random phase of it); a stop it
/// orders takes effect `latency_s` later, during which the tool keeps
/// moving at the feed. A stroke succeeds when the tool never enters the
/// region, on the way or where it stops (the seed's "success"); the
/// distance it leaves between its stop and the boundary is the under-cut.
///
/// Two guards, side by side:
/// - fixed tolerance (the seed's): stop as soon as the sampled distance to
///   the region is below T. It fails whenever the distance the tool covers
///   from the crossing of T to the stop (up to a period, then the latency)
///   exceeds T, and leaves the rest of T as under-cut otherwise. The
///   distance it compares is the exact one, or the seed's eq. (2) (see
///   interval_line_distance).
/// - latency-aware (ours): from the last two samples, the tool's velocity;
///   stop when the move from here to where a stop ordered at the next
///   sample would take effect comes closer than a margin to the region
///   (see first_below). On a straight stroke at constant feed the
///   prediction is exact, whatever the region's shape, so the tool never
///   enters and stops within `margin + approach speed x period` of it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "cad/drawing.hpp"
#include "cad/path_clearance.hpp"

namespace tk::cad {

struct InvasionSimOptions {
  double feed_mm_s = 50;         ///< joystick speed (3000 mm/min)
  double latency_s = 0.09;       ///< sample to stop taking effect
  double period_s = 0.001;       ///< control loop period
  double margin_mm = 0.02;       ///< the latency-aware guard's aim
  std::uint32_t strokes = 1000;  ///< approaches per guard and tolerance
  std::uint64_t seed = 1;        ///< for the strokes' start points and angles
  double max_angle_deg = 60;     ///< largest angle between a stroke and the boundary's normal
};

/// One guard's figures over all strokes.
struct InvasionSimResult {
  std::string guard;        ///< "fixed-tolerance" or "latency-aware"
  double tolerance_mm = 0;  ///< T for the fixed guard; the margin for ours
  std::uint32_t strokes = 0;
  std::uint32_t invasions = 0;  ///< strokes that entered the region on the way or where they stopped
  double success_rate = 0;      ///< 1 - invasions / strokes
  double mean_undercut_mm = 0;  ///< over the strokes that stopped outside
  double max_undercut_mm = 0;
  double mean_invasion_mm = 0;  ///< deepest point of the path, over the invading strokes
  double max_invasion_mm = 0;
};

/// The seed's eq. (2): the distance |(P - P1) x (P2 - P1)| / |P2 - P1|
/// from p to the line of each edge P1P2 of `boundary` (closed polylines)
/// whose x interval, or y interval, holds p (its Fig. 4(c) intervals; by
/// x alone a vertical edge would never be checked); the smallest, or
/// infinity when no interval holds p. Unsigned: it cannot tell inside from
/// outside, and it understates the distance beyond a segment's end.
double interval_line_distance(const std::vector<std::vector<Point>>& boundary, Point p);

/// Throws Error when the options or tolerances do not make an experiment
/// (not positive and finite, strokes over a kilometre, or more than 10
/// million readings a stroke),
/// as simulate_invasions would.
void check_invasion_sim(const std::vector<double>& tolerances_mm, const InvasionSimOptions& options);

/// The strokes aim at points of `boundary` (closed polylines of the
/// region's boundary, each oriented with the region on its left: outer
/// boundaries counter-clockwise, holes clockwise), starting outside at
/// `approach_mm` from their target, at a random angle to its normal.
/// Every guard sees the same strokes. The outcome of a stroke is judged
/// by `distance`; the fixed guard compares `fixed_guard_distance` with T
/// (the same function when null). Throws Error on options that are not
/// positive and finite, or a boundary with no usable edge.
std::vector<InvasionSimResult> simulate_invasions(const SignedDistance& distance,
                                                  const std::vector<std::vector<Point>>& boundary,
                                                  const std::vector<double>& tolerances_mm,
                                                  const InvasionSimOptions& options,
                                                  const SignedDistance* fixed_guard_distance = nullptr);

}  // namespace tk::cad
