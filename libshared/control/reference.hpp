/// @file reference.hpp
/// @brief The position the axis must follow, with its first two derivatives
/// (the controllers feed them forward): a sinusoid, a step, a ramp, or
/// samples read from records.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace tk::control {

struct ReferenceSample {
  double x_mm = 0, v_mm_s = 0, a_mm_s2 = 0;
};

class Reference {
 public:
  /// A·sin(ω t); the seed's is 1 mm at 3 rad/s.
  static Reference sine(double amplitude_mm, double omega_rad_s);
  /// 0 before `at_s`, then `height_mm` (derivatives 0: a step has none to feed forward).
  static Reference step(double height_mm, double at_s);
  /// `slope_mm_s`·(t − at_s) after `at_s`.
  static Reference ramp(double slope_mm_s, double at_s);
  /// Records with t and x (mm), optionally v and a; missing derivatives are
  /// estimated by finite differences. Between samples x is a cubic Hermite
  /// curve through the sample velocities; after the last it holds.
  /// Throws tk::Error naming the file and line on malformed input.
  static Reference from_records(const std::string& path);

  ReferenceSample at(double t_s) const;
  /// One line for messages and the SVG's title.
  std::string describe() const { return description_; }

 private:
  enum class Kind { sine, step, ramp, samples } kind_ = Kind::sine;
  /// A reference of two finite parameters, described by `description` (a format of both).
  static Reference analytic(Kind kind, std::pair<double, const char*> p1, std::pair<double, const char*> p2,
                            const char* description);
  double p1_ = 0, p2_ = 0;
  std::vector<double> t_, x_, v_, a_;
  std::string description_;
};

}  // namespace tk::control
