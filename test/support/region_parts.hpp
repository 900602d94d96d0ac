/// @file region_parts.hpp
/// @brief Parts the offset tests share: gears of spikes and random stars
/// with arcs and a round hole.
#pragma once

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "cad/loops.hpp"

namespace tk::cad::parts {

/// A closed polyline of `spikes` spikes `height` mm tall, `pitch` mm apart
/// at the root, with each spike's flanks bulged by `bulge` (0: lines).
inline std::vector<Segment> gear(int spikes, double height, double pitch, double bulge) {
  const double root = spikes * pitch / (2 * std::numbers::pi);
  std::vector<Point> v;
  for (int i = 0; i < spikes; ++i) {
    const double a = 2 * std::numbers::pi * i / spikes, b = 2 * std::numbers::pi * (i + 0.5) / spikes;
    v.push_back({root * std::cos(a), root * std::sin(a)});
    v.push_back({(root + height) * std::cos(b), (root + height) * std::sin(b)});
  }
  std::vector<Segment> out;
  for (std::size_t i = 0; i < v.size(); ++i) out.push_back({v[i], v[(i + 1) % v.size()], bulge});
  return out;
}

/// A random star of n corners 20 to 35 mm from the origin, about a third
/// of its sides arcs, and a round hole of radius 2 to 10 mm at the origin.
inline std::vector<Segment> random_star_with_hole(std::mt19937_64& random, int n) {
  std::uniform_real_distribution<double> unit(0, 1);
  std::vector<Point> points;
  for (int i = 0; i < n; ++i) {
    const double angle = 2 * std::numbers::pi * i / n, r = 20 + 15 * unit(random);
    points.push_back({r * std::cos(angle), r * std::sin(angle)});
  }
  std::vector<Segment> part;
  for (std::size_t i = 0; i < points.size(); ++i)
    part.push_back({points[i], points[(i + 1) % points.size()], unit(random) < 0.3 ? 0.4 * (unit(random) - 0.5) : 0});
  const double hole = 2 + 8 * unit(random);
  part.push_back({{hole, 0}, {-hole, 0}, 1});
  part.push_back({{-hole, 0}, {hole, 0}, 1});
  return part;
}

}  // namespace tk::cad::parts
