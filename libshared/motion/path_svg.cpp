/// @file path_svg.cpp
#include "motion/path_svg.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "io/atomic_file.hpp"
#include "io/error.hpp"
#include "motion/arc_geometry.hpp"

namespace tk::motion {

PathSvg::PathSvg(SvgWindow window) : window_(window) {}

bool PathSvg::inside(double x, double y) const {
  return x >= window_.x0 && x <= window_.x1 && y >= window_.y0 && y <= window_.y1;
}

void PathSvg::keep(std::vector<std::array<double, 2>>& polyline, std::vector<std::size_t>& breaks, double x, double y,
                   bool& was_inside) {
  const bool now_inside = inside(x, y);
  if (now_inside) {
    if (!was_inside && !polyline.empty()) breaks.push_back(polyline.size());
    if (polyline.size() < kMaxPoints) polyline.push_back({x, y});
    else truncated_ = true;
  }
  was_inside = now_inside;
}

void PathSvg::add_motion(const Motion& motion) {
  if (motion.kind == MotionKind::dwell) return;
  // Pieces short against the window (1/400 of it), so the drawn path is
  // smooth at the window's scale and enters it where the path does.
  const double piece = std::min(window_.x1 - window_.x0, window_.y1 - window_.y0) / 400;
  auto pieces_for = [&](double length) { return static_cast<int>(std::clamp(length / piece, 8.0, 200000.0)); };
  if (motion.kind != MotionKind::arc) {
    const int pieces = pieces_for(std::hypot(motion.end.x - motion.start.x, motion.end.y - motion.start.y));
    for (int i = 0; i <= pieces; ++i) {
      const double f = static_cast<double>(i) / pieces;
      keep(ideal_, ideal_breaks_, motion.start.x + f * (motion.end.x - motion.start.x),
           motion.start.y + f * (motion.end.y - motion.start.y), ideal_inside_);
    }
    return;
  }
  const ArcGeometry g = arc_geometry(motion);
  const int pieces = pieces_for(std::max(g.r_start, g.r_end) * g.sweep);
  for (int i = 0; i <= pieces; ++i) {
    const double phi = g.sweep * i / pieces, angle = g.start_angle + g.turn * phi;
    Vec3 p;
    p[g.a0] = g.c0 + g.radius(phi) * std::cos(angle);
    p[g.a1] = g.c1 + g.radius(phi) * std::sin(angle);
    p[g.a2] = g.height(phi);
    keep(ideal_, ideal_breaks_, p.x, p.y, ideal_inside_);
  }
}

void PathSvg::add_point(double x_mm, double y_mm) { keep(stepped_, stepped_breaks_, x_mm, y_mm, stepped_inside_); }

namespace {

// SVG's y grows downward: mirror so the drawing reads as the machine's XY.
std::string path_data(const std::vector<std::array<double, 2>>& points, const std::vector<std::size_t>& breaks,
                      const SvgWindow& w) {
  std::string d;
  std::size_t next_break = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const bool move = i == 0 || (next_break < breaks.size() && breaks[next_break] == i);
    if (move && i != 0) ++next_break;
    d += fmt::format("{}{:.6g} {:.6g}", move ? (i ? " M" : "M") : " L", points[i][0] - w.x0, w.y1 - points[i][1]);
  }
  return d;
}

}  // namespace

void PathSvg::write(const std::string& path) const {
  const double width = window_.x1 - window_.x0, height = window_.y1 - window_.y0;
  const double stroke = std::max(width, height) / 1500;
  std::string svg = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"1000\" height=\"{:.0f}\" viewBox=\"0 0 {:.6g} {:.6g}\">\n"
      "<title>gcode-pulse: ideal path (blue) and stepped path (red), X {:.6g} to {:.6g} mm, Y {:.6g} to {:.6g} "
      "mm</title>\n"
      "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n",
      1000 * height / width, width, height, window_.x0, window_.x1, window_.y0, window_.y1);
  svg += fmt::format("<path d=\"{}\" fill=\"none\" stroke=\"#1f5fbf\" stroke-width=\"{:.6g}\"/>\n",
                     path_data(ideal_, ideal_breaks_, window_), 2 * stroke);
  svg += fmt::format("<path d=\"{}\" fill=\"none\" stroke=\"#c8281e\" stroke-width=\"{:.6g}\"/>\n",
                     path_data(stepped_, stepped_breaks_, window_), stroke);
  svg += "</svg>\n";
  io::write_file_atomically(path, svg);
}

}  // namespace tk::motion
