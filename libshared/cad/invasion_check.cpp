/// @file invasion_check.cpp
/// @brief The streaming guard.
#include "cad/invasion_check.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "cad/path_clearance.hpp"
#include "io/error.hpp"

namespace tk::cad {

InvasionGuard::InvasionGuard(const RegionIndex& index, GuardOptions options, const RegionIndex* contour)
    : index_(index), contour_(contour), options_(options) {
  summary_.closest_mm = std::numeric_limits<double>::infinity();
}

PositionCheck InvasionGuard::check(Point p, std::optional<double> t) {
  PositionCheck result;
  result.answer = guard_query(index_, p, options_.tool_radius, options_.side, contour_);
  const double distance = result.answer.distance;
  ++summary_.positions;
  summary_.closest_mm = std::min(summary_.closest_mm, distance);
  if (distance < 0) {
    ++summary_.invasions;
    if (-distance > summary_.deepest_mm) {
      summary_.deepest_mm = -distance;
      summary_.deepest_at = p;
    }
  }
  if (t) {
    if (last_t_ && *t < *last_t_) throw Error("time goes backwards");
    double approach = 0;
    Point ahead = p;  // where the tool is when a stop ordered now takes effect, at its last velocity
    if (last_t_ && *t > *last_t_) {
      const double dt = *t - *last_t_;
      approach = std::max(0.0, (last_distance_ - distance) / dt);
      const Point velocity{(p.x - last_at_.x) / dt, (p.y - last_at_.y) / dt};
      ahead = {p.x + velocity.x * options_.latency_s, p.y + velocity.y * options_.latency_s};
      if (!std::isfinite(velocity.x) || !std::isfinite(velocity.y) || !std::isfinite(ahead.x) ||
          !std::isfinite(ahead.y))
        throw Error(fmt::format("a move of {:g} mm in {:g} s is too fast to tell where a stop would take effect",
                                std::hypot(p.x - last_at_.x, p.y - last_at_.y), dt));
    }
    result.approach_mm_s = approach;
    const SignedDistance region = [&](Point q) {
      return guard_query(index_, q, options_.tool_radius, options_.side).distance;
    };
    result.stop = first_below(region, p, ahead, options_.margin_mm).has_value();
    if (*result.stop) ++summary_.stops;
    last_t_ = t;
    last_distance_ = distance;
    last_at_ = p;
  }
  return result;
}

}  // namespace tk::cad
