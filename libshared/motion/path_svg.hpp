/// @file path_svg.hpp
/// @brief An SVG drawing, in the XY plane, of the ideal path (lines and
/// arcs as programmed) against the stepped path (the lattice points the
/// events reach), over a window in mm: for looking at how a method
/// follows the path. Only what falls in the window is kept, up to a cap.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "motion/gcode.hpp"

namespace tk::motion {

struct SvgWindow {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;  ///< mm, x0 < x1 and y0 < y1
};

class PathSvg {
 public:
  static constexpr std::size_t kMaxPoints = 500000;

  explicit PathSvg(SvgWindow window);

  void add_motion(const Motion& motion);     ///< the ideal path of a line or arc
  void add_point(double x_mm, double y_mm);  ///< a lattice point reached
  /// Writes the drawing; throws tk::Error when the file cannot be written.
  void write(const std::string& path) const;
  bool truncated() const { return truncated_; }

 private:
  bool inside(double x, double y) const;
  void keep(std::vector<std::array<double, 2>>& polyline, std::vector<std::size_t>& breaks, double x, double y,
            bool& was_inside);

  SvgWindow window_;
  std::vector<std::array<double, 2>> ideal_, stepped_;
  std::vector<std::size_t> ideal_breaks_, stepped_breaks_;  ///< where a polyline leaves the window
  bool ideal_inside_ = false, stepped_inside_ = false, truncated_ = false;
};

}  // namespace tk::motion
