/// @file invasion_sim.cpp
#include "cad/invasion_sim.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <random>

#include "io/error.hpp"

namespace tk::cad {

namespace {

struct Stroke {
  Point start, direction;  ///< direction: unit, toward the boundary
  double phase = 0;        ///< of the control's clock at the start, in periods: [0, 1)
};

void check_positive(double value, const char* name) {
  if (!(value > 0) || !std::isfinite(value)) throw Error(std::string(name) + " must be a positive number");
}

/// Targets spread over the boundary by length; each stroke starts outside,
/// `approach` from its target along the normal turned by a random angle.
std::vector<Stroke> make_strokes(const SignedDistance& distance, const std::vector<std::vector<Point>>& boundary,
                                 double approach, const InvasionSimOptions& options) {
  struct Edge {
    Point a, b;
    double length;
  };
  std::vector<Edge> edges;
  std::vector<double> cumulative;
  double total = 0;
  for (const auto& loop : boundary)
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const Point a = loop[i], b = loop[(i + 1) % loop.size()];
      const double length = std::hypot(b.x - a.x, b.y - a.y);
      if (!(length > 0) || !std::isfinite(length)) continue;
      edges.push_back({a, b, length});
      total += length;
      cumulative.push_back(total);
    }
  if (edges.empty()) throw Error("the region has no boundary to approach");
  std::mt19937_64 random(options.seed);
  std::uniform_real_distribution<double> unit(0, 1);
  const double max_angle = options.max_angle_deg * std::numbers::pi / 180;
  std::vector<Stroke> strokes;
  // A start can land inside the region (across a narrow part): draw again.
  for (std::uint64_t tries = 0; strokes.size() < options.strokes && tries < 100ull * options.strokes + 1000; ++tries) {
    const double at = unit(random) * total;
    const std::size_t i = std::min<std::size_t>(
        std::lower_bound(cumulative.begin(), cumulative.end(), at) - cumulative.begin(), edges.size() - 1);
    const Edge& e = edges[i];
    const double f = unit(random);
    const Point target{e.a.x + f * (e.b.x - e.a.x), e.a.y + f * (e.b.y - e.a.y)};
    // The region lies on the edge's left: outward is its right.
    const double nx = (e.b.y - e.a.y) / e.length, ny = -(e.b.x - e.a.x) / e.length;
    const double angle = (2 * unit(random) - 1) * max_angle;
    const double ox = nx * std::cos(angle) - ny * std::sin(angle), oy = nx * std::sin(angle) + ny * std::cos(angle);
    const Point start{target.x + approach * ox, target.y + approach * oy};
    if (!(distance(start) > 0.5 * approach * std::cos(max_angle))) continue;
    strokes.push_back({start, {-ox, -oy}, unit(random)});
  }
  if (strokes.empty()) throw Error("no stroke could start outside the region");
  return strokes;
}

/// One reading of the control: where the tool is and its distance to the region.
struct Sample {
  Point at;
  double distance = 0;
};

/// Runs every stroke under one guard. `order_stop(now, before)` says
/// whether the control orders a stop at a reading (`before`: the reading
/// one period earlier, null at the stroke's first).
template <typename Guard>
InvasionSimResult run(const SignedDistance& distance, const std::vector<Stroke>& strokes, double travel_limit,
                      const InvasionSimOptions& options, Guard order_stop) {
  InvasionSimResult result;
  result.strokes = static_cast<std::uint32_t>(strokes.size());
  const double v = options.feed_mm_s;
  double undercut_sum = 0, invasion_sum = 0;
  for (const Stroke& s : strokes) {
    auto at = [&](double t) { return Point{s.start.x + v * t * s.direction.x, s.start.y + v * t * s.direction.y}; };
    // With no stop ordered, the stroke ends where the operator lets go.
    double stop_time = travel_limit / v;
    std::optional<Sample> before;
    for (std::uint64_t k = 0;; ++k) {
      const double t = (static_cast<double>(k) + s.phase) * options.period_s;
      if (t + options.latency_s >= stop_time) break;
      const Sample now{at(t), distance(at(t))};
      if (order_stop(now, before ? &*before : nullptr)) {
        stop_time = t + options.latency_s;
        break;
      }
      before = now;
    }
    // The seed's success: "the prohibited region is not trespassed", on the
    // way as well as where the tool stops (a stroke can clip a sharp
    // corner and stop beyond it).
    const double depth = deepest_on_move(distance, s.start, at(stop_time));
    const double final_distance = distance(at(stop_time));
    if (depth > 0) {
      ++result.invasions;
      invasion_sum += depth;
      result.max_invasion_mm = std::max(result.max_invasion_mm, depth);
    } else {
      undercut_sum += final_distance;
      result.max_undercut_mm = std::max(result.max_undercut_mm, final_distance);
    }
  }
  const std::uint32_t outside = result.strokes - result.invasions;
  result.success_rate = static_cast<double>(outside) / result.strokes;
  result.mean_undercut_mm = outside ? undercut_sum / outside : 0;
  result.mean_invasion_mm = result.invasions ? invasion_sum / result.invasions : 0;
  return result;
}

}  // namespace

double interval_line_distance(const std::vector<std::vector<Point>>& boundary, Point p) {
  double nearest = std::numeric_limits<double>::infinity();
  for (const auto& loop : boundary)
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const Point a = loop[i], b = loop[(i + 1) % loop.size()];
      const bool in_x = std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x);
      const bool in_y = std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y);
      const double length = std::hypot(b.x - a.x, b.y - a.y);
      if (!(in_x || in_y) || !(length > 0)) continue;
      nearest = std::min(nearest, std::abs((p.x - a.x) * (b.y - a.y) - (p.y - a.y) * (b.x - a.x)) / length);
    }
  return nearest;
}

namespace {

struct StrokeLengths {
  double approach;      ///< from a stroke's start to its target
  double travel_limit;  ///< where the operator lets go when no stop comes
};

StrokeLengths stroke_lengths(const std::vector<double>& tolerances_mm, const InvasionSimOptions& options) {
  check_positive(options.feed_mm_s, "the feed");
  check_positive(options.period_s, "the control period");
  if (!(options.latency_s >= 0) || !std::isfinite(options.latency_s)) throw Error("the latency must not be negative");
  if (!(options.margin_mm >= 0) || !std::isfinite(options.margin_mm)) throw Error("the margin must not be negative");
  if (options.strokes == 0 || options.strokes > 10'000'000) throw Error("strokes must be between 1 and 10000000");
  if (!(options.max_angle_deg >= 0 && options.max_angle_deg < 90))
    throw Error("the stroke angle must be in [0, 90) degrees");
  double largest = options.margin_mm;
  for (double t : tolerances_mm) {
    if (!(t >= 0) || !std::isfinite(t) || t > 1e6) throw Error("tolerances must be numbers of mm from 0 to 1e6");
    largest = std::max(largest, t);
  }
  // Far enough out that every guard sees a few samples before it acts, and
  // a stroke that is never stopped ends well inside.
  const double coast = options.feed_mm_s * (options.latency_s + 2 * options.period_s);
  const double approach = largest + 3 * coast + 10;
  const double travel_limit = approach + coast + 10;
  if (!(travel_limit <= 1e6))
    throw Error("strokes of more than a kilometre: the feed, the latency, a tolerance or the margin is too large");
  if (!(travel_limit / (options.feed_mm_s * options.period_s) <= 1e7))
    throw Error(
        "more than 10 million control readings a stroke: the period is too short for the feed, or the latency too "
        "long");
  return {approach, travel_limit};
}

}  // namespace

void check_invasion_sim(const std::vector<double>& tolerances_mm, const InvasionSimOptions& options) {
  stroke_lengths(tolerances_mm, options);
}

std::vector<InvasionSimResult> simulate_invasions(const SignedDistance& distance,
                                                  const std::vector<std::vector<Point>>& boundary,
                                                  const std::vector<double>& tolerances_mm,
                                                  const InvasionSimOptions& options,
                                                  const SignedDistance* fixed_guard_distance) {
  const auto [approach, travel_limit] = stroke_lengths(tolerances_mm, options);
  const std::vector<Stroke> strokes = make_strokes(distance, boundary, approach, options);

  std::vector<InvasionSimResult> results;
  for (double tolerance : tolerances_mm) {
    InvasionSimResult r = run(distance, strokes, travel_limit, options, [&](const Sample& now, const Sample*) {
      return (fixed_guard_distance ? (*fixed_guard_distance)(now.at) : now.distance) < tolerance;
    });
    r.guard = "fixed-tolerance";
    r.tolerance_mm = tolerance;
    results.push_back(r);
  }
  // Ours: stop now unless waiting one more period could still stop in
  // time, judged on the move from here to where the tool would be when
  // that stop took effect, extrapolated from the last two readings.
  const double horizon = (options.period_s + options.latency_s) / options.period_s;
  InvasionSimResult ours = run(distance, strokes, travel_limit, options, [&](const Sample& now, const Sample* before) {
    if (!before) return now.distance < options.margin_mm;
    const Point ahead{now.at.x + horizon * (now.at.x - before->at.x), now.at.y + horizon * (now.at.y - before->at.y)};
    return first_below(distance, now.at, ahead, options.margin_mm).has_value();
  });
  ours.guard = "latency-aware";
  ours.tolerance_mm = options.margin_mm;
  results.push_back(ours);
  return results;
}

}  // namespace tk::cad
