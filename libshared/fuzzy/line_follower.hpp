/// @file line_follower.hpp
/// @brief Könczöl & Gál's line-follower controller: three reflective
/// sensors (left, mid, right; a high reading is dark), terms LIGHT and DARK
/// per sensor, two motors, rules R1-R7 for the left motor mirrored for the
/// right one, consequent terms scaled by a speed factor.
#pragma once

#include <array>
#include <string>

#include "fuzzy/engine.hpp"

namespace tk::fuzzy {

struct LineFollowerOptions {
  int adc_bits = 10;           ///< 10 (Arduino Uno) or 12 (ESP32)
  double speed_factor = 1.92;  ///< the seed's first value; 2.0 in its later runs
  /// BACKWARD_SLOWLY, which the seed's R7 uses without giving its corners:
  /// ours, before scaling, sits between STOP and BACKWARD.
  std::array<double, 4> backward_slowly{-45, -35, -25, -15};
  TNorm conjunction = TNorm::minimum;
  /// Minimum (clipping): Mamdani's own implication, and the one of eFLL, the
  /// Arduino library the seed's controller ran on.
  Implication implication = Implication::minimum;
  Defuzzifier defuzzifier;
  /// The motor command's range: an 8-bit PWM duty with a direction, which is
  /// why the seed scales its +-100-ish terms by about 2.
  double output_min = -255, output_max = 255;
};

/// The rules, for the left motor (sensors left, mid, right; L = LIGHT,
/// D = DARK); the right motor's rules swap the left and right sensors.
///   R1  L D L  FORWARD_MAX      line centred: full ahead
///   R2  D D L  FORWARD          line drifting left: left wheel slows
///   R3  D L L  BACKWARD         line far left: left wheel reverses
///   R4  L D D  FORWARD_MAX      line drifting right: left wheel keeps on
///   R5  L L D  FORWARD_MAX      line far right: left wheel keeps on
///   R6  D D D  STOP             a bar across the line: stop
///   R7  L L L  BACKWARD_SLOWLY  line lost: back up slowly to find it
/// The no-rule-fired default of both motors is 0 (the range's midpoint,
/// motor off); BACKWARD_MAX is defined, as in the seed, but no rule uses it.
Engine line_follower_engine(const LineFollowerOptions& options);

/// "LLD" and the like: each reading's stronger term (L when LIGHT >= DARK),
/// left to right, as the seed names the situations.
std::string sensor_pattern(double left, double mid, double right, int adc_bits);

/// The sensor terms' corners for an ADC of `adc_bits` (10 or 12), as the seed gives them.
Trapezoid light_term(int adc_bits);
Trapezoid dark_term(int adc_bits);

}  // namespace tk::fuzzy
