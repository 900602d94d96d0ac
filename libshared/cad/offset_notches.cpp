/// @file offset_notches.cpp
/// @brief Filling the notches a round tool cannot enter (see offset_notches.hpp).
#include "cad/offset_notches.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>

#include "cad/region_union.hpp"

namespace tk::cad {
namespace {

using ClipperLib::cInt;
using ClipperLib::IntPoint;
using ClipperLib::Path;
__extension__ typedef __int128 WideInt;  // products of coordinate differences (< 2^63 each) fit

WideInt dot_exact(const IntPoint& from, const IntPoint& to, const IntPoint& from2, const IntPoint& to2) {
  return WideInt(to.X - from.X) * WideInt(to2.X - from2.X) + WideInt(to.Y - from.Y) * WideInt(to2.Y - from2.Y);
}

double distance(const IntPoint& a, const IntPoint& b) { return std::hypot(double(b.X - a.X), double(b.Y - a.Y)); }

cInt round_half_away(double v) { return static_cast<cInt>(v < 0 ? v - 0.5 : v + 0.5); }

/// The angle turned at b on the way a -> b -> c, in [0, pi].
double turn_angle(const IntPoint& a, const IntPoint& b, const IntPoint& c) {
  const double ux = double(b.X - a.X), uy = double(b.Y - a.Y), vx = double(c.X - b.X), vy = double(c.Y - b.Y);
  return std::abs(std::atan2(ux * vy - uy * vx, ux * vx + uy * vy));
}

/// One path's notches, filled into `out` as the path is walked.
class NotchFiller {
 public:
  NotchFiller(const Path& path, double delta, double join_tolerance, double worth)
      : path_(path),
        radius_(std::abs(delta)),
        notch_turn_(delta > 0 ? -1 : 1),
        margin_(2.5 * join_tolerance + 2),
        worth_(worth) {}

  Path fill(std::size_t& filled) {
    const std::size_t n = path_.size();
    if (n < 4 || radius_ == 0) return path_;
    std::vector<char> notch(n);
    for (std::size_t i = 0; i < n; ++i)
      notch[i] = orient_exact(path_[(i + n - 1) % n], path_[i], path_[(i + 1) % n]) == notch_turn_;
    std::size_t start = 0;
    while (start < n && notch[start]) ++start;
    if (start == n) return path_;         // all one way: a convex hole, nothing between two mouth corners
    std::size_t here = 0, first_out = 0;  // notches filled; where vertex 0 (or what took its place) went
    for (std::size_t step = 0; step < n;) {
      const std::size_t i = (start + step) % n;
      if (!notch[i]) {
        if (i == 0) first_out = out_.size();
        out_.push_back(path_[i]);
        ++step;
        continue;
      }
      std::size_t run = 0;  // the notch's corners, i ... i + run - 1, end before a vertex that is not one
      while (notch[(i + run) % n]) ++run;
      if (i == 0 || i + run > n) first_out = out_.size();
      if (fill_run(i, run)) {
        ++here;
      } else {
        for (std::size_t k = 0; k < run; ++k) {
          if ((i + k) % n == 0) first_out = out_.size();
          out_.push_back(corner(i, k));
        }
      }
      step += run;
    }
    if (here == 0) return path_;
    filled += here;
    // From where the path started, so that the offset's polygons start where they would unfilled.
    std::rotate(out_.begin(), out_.begin() + std::ptrdiff_t(first_out), out_.end());
    return out_;
  }

 private:
  const IntPoint& corner(std::size_t first, std::size_t k) const { return path_[(first + k) % path_.size()]; }

  /// Fills the notch of corners first ... first + run - 1 if it qualifies (see the header).
  bool fill_run(std::size_t first, std::size_t run) {
    const std::size_t n = path_.size();
    const IntPoint& a = path_[(first + n - 1) % n];
    const IntPoint& b = path_[(first + run) % n];
    const double width = distance(a, b);
    if (!(width < 2 * radius_ * (1 - 1e-9)) || width == 0) return false;
    // M convex: turning the same way at the mouth's corners, once round in all.
    const IntPoint &v1 = corner(first, 0), &vk = corner(first, run - 1);
    if (orient_exact(vk, b, a) != notch_turn_ || orient_exact(b, a, v1) != notch_turn_) return false;
    const auto m_corner = [&](std::size_t k) -> const IntPoint& {  // M's corners: a, v1 ... vk, b
      return k == 0 ? a : k <= run ? corner(first, k - 1) : b;
    };
    double turned = 0;
    for (std::size_t k = 0; k < run + 2; ++k)
      turned += turn_angle(m_corner((k + run + 1) % (run + 2)), m_corner(k), m_corner((k + 1) % (run + 2)));
    if (turned > 3 * std::numbers::pi) return false;
    // At most 90 degrees at a and b: M lies in the strip across the mouth.
    if (dot_exact(a, v1, a, b) < 0 || dot_exact(b, vk, b, a) < 0) return false;
    const double ux = double(b.X - a.X) / width, uy = double(b.Y - a.Y) / width;
    const auto depth = [&](const IntPoint& p) { return ux * double(p.Y - a.Y) - uy * double(p.X - a.X); };
    double deepest = 0;  // signed: the corners all lie on one side of the mouth (M is convex)
    for (std::size_t k = 0; k < run; ++k) {
      const double d = depth(corner(first, k));
      if (std::abs(d) > std::abs(deepest)) deepest = d;
    }
    // The new corner t under the mouth's middle, where a -> t and t -> b
    // dip at angle g: at sin g = W / 2R they are the tangents to the disc
    // resting on a and b. Steeper, so that the offset of a -> t starts
    // inside b's circle by the margin (it starts at a + R n, whose distance
    // from b is sqrt(W^2 - 2 W R sin g + R^2)), and a unit for rounding t.
    const double sin_dip = (width * width + 2 * radius_ * margin_ - margin_ * margin_) / (2 * width * radius_);
    if (!(sin_dip < 1)) return false;
    const double below = width / 2 * sin_dip / std::sqrt(1 - sin_dip * sin_dip) + 1;
    if (std::abs(deepest) < below + worth_) return false;
    const double inward = deepest > 0 ? 1 : -1;
    const IntPoint t{round_half_away(double(a.X + b.X) / 2 - inward * uy * below),
                     round_half_away(double(a.Y + b.Y) / 2 + inward * ux * below)};
    // t inside M (strictly), so that a -> t -> b stays in the notch.
    if (orient_exact(b, a, t) != notch_turn_) return false;
    for (std::size_t k = 0; k <= run; ++k)
      if (orient_exact(m_corner(k), m_corner(k + 1), t) != notch_turn_) return false;
    out_.push_back(t);
    return true;
  }

  const Path& path_;
  const double radius_;
  const int notch_turn_;
  const double margin_, worth_;
  Path out_;
};

}  // namespace

Path fill_notches(const Path& path, double delta, double join_tolerance, double worth, std::size_t& filled) {
  return NotchFiller(path, delta, join_tolerance, worth).fill(filled);
}

}  // namespace tk::cad
