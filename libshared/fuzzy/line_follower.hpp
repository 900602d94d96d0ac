/// @file line_follower.hpp
/// @brief Könczöl & Gál's line-follower controller: three reflective
/// sensors (left, mid, right; a high reading is dark), terms LIGHT and DARK
/// per sensor, two motors, rules R1-R7 for the left motor mirrored for the
/// right one, consequent terms scaled by a speed factor.
#pragma once

#include <array>
#include <optional>
#include <string>

#include "fuzzy/engine.hpp"

namespace tk::fuzzy {

struct LineFollowerOptions {
  int adc_bits = 10;          ///< 10 (Arduino Uno) or 12 (ESP32)
  double speed_factor = 2.0;  ///< the paper's Tables 1-2 (1.92 in its first measurements)
  /// BACKWARD_SLOWLY, which the paper's R7 uses without giving its corners:
  /// ours, before scaling, sits between STOP and BACKWARD.
  std::array<double, 4> backward_slowly{-45, -35, -25, -15};
  TNorm conjunction = TNorm::minimum;
  /// Minimum (clipping): Mamdani's own implication (the paper: "A Mamdani
  /// type fuzzy interference system", no more detail).
  Implication implication = Implication::minimum;
  Defuzzifier defuzzifier;
  /// The motor command's range: an 8-bit PWM duty ("0-255") with a
  /// direction (the paper's BACKWARD terms are negative).
  double output_min = -255, output_max = 255;
};

/// The rules as the paper prints them, for the left motor (sensors left,
/// mid, right; L = LIGHT, D = DARK, a dark line on a light floor); the
/// right motor's rules swap the left and right sensors:
///   R1  L L L  STOP             line lost: stop
///   R2  L L D  FORWARD_MAX      line under the right sensor: pivot right
///   R3  L D D  FORWARD          line right of centre: pivot right
///   R4  L D L  FORWARD          line centred: ahead
///   R5  D D L  BACKWARD         line left of centre: pivot left
///   R6  D L L  BACKWARD_MAX     line under the left sensor: pivot left
///   R7  D D D  BACKWARD_SLOWLY  all dark: back up slowly
/// D L D has no rule. The no-rule-fired default of both motors is 0 (the
/// range's midpoint, motor off).
Engine line_follower_engine(const LineFollowerOptions& options);

/// "LLD" and the like: each reading's stronger term (L when LIGHT >= DARK),
/// left to right, as the paper names the situations.
std::string sensor_pattern(double left, double mid, double right, int adc_bits);

/// The sensor terms' corners for an ADC of `adc_bits` (10 or 12), as the paper gives them.
Trapezoid light_term(int adc_bits);
Trapezoid dark_term(int adc_bits);

/// The paper's two boards: the Arduino Uno (10-bit ADC) and the ESP32 (12-bit).
enum class Board { uno, esp32 };
int board_adc_bits(Board board);

/// The paper's Tables 3 and 4: ms for 2 x 1024 inferences (both motors for
/// 1024 sensor triples) on `board`, measured with millis().
double paper_ms_per_2x1024(Board board, TNorm t);

/// The paper's Tables 1 and 2: three laps' time in s (median of three runs,
/// speed factor 2.0), none for the drastic t-norm, which did not finish.
std::optional<double> paper_three_laps_s(Board board, TNorm t);

}  // namespace tk::fuzzy
