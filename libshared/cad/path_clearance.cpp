/// @file path_clearance.cpp
#include "cad/path_clearance.hpp"

#include <algorithm>
#include <cmath>

namespace tk::cad {

namespace {

constexpr double kMinStepMm = 1e-4;
/// 100 mm of a move within 0.1 um of the level; more is not resolved.
constexpr int kMaxSteps = 1'000'000;

Point along(Point from, Point to, double f) { return {from.x + f * (to.x - from.x), from.y + f * (to.y - from.y)}; }

}  // namespace

std::optional<double> first_below(const SignedDistance& distance, Point from, Point to, double level) {
  const double length = std::hypot(to.x - from.x, to.y - from.y);
  double f = 0;
  for (int steps = 0;; ++steps) {
    const double d = distance(along(from, to, f));
    if (!(d >= level)) return f;  // NaN counts as below: refuse rather than pass
    if (f >= 1 || !(length > 0)) return std::nullopt;
    const double next = std::min(1.0, f + std::max(d - level, kMinStepMm) / length);
    // A step lost in rounding (a move of 10^12 mm) or a very long graze:
    // not resolved, so refused rather than passed.
    if (!(next > f) || steps == kMaxSteps) return f;
    f = next;
  }
}

double deepest_on_move(const SignedDistance& distance, Point from, Point to) {
  const std::optional<double> entry = first_below(distance, from, to, 0);
  if (!entry) return 0;
  const double length = std::hypot(to.x - from.x, to.y - from.y);
  const double step = length > 0 ? 0.01 / length : 1;
  double deepest = 0;
  for (double f = *entry;; f = std::min(1.0, f + step)) {
    deepest = std::max(deepest, -distance(along(from, to, f)));
    if (f >= 1) return deepest;
  }
}

}  // namespace tk::cad
