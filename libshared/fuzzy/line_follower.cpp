/// @file line_follower.cpp
/// @brief The paper's line-follower controller as an Engine, and its
/// published timings and lap times.
#include "fuzzy/line_follower.hpp"

#include <fmt/format.h>

#include "io/error.hpp"

namespace tk::fuzzy {
namespace {

enum Sensor : char { L = 'L', D = 'D' };

struct RuleRow {
  Sensor left, mid, right;
  const char* left_motor;
};

// R1-R7 for the left motor as the paper prints them (seed 000, lines 658-670).
constexpr RuleRow kRules[] = {
    {L, L, L, "STOP"},     {L, L, D, "FORWARD_MAX"},  {L, D, D, "FORWARD"},         {L, D, L, "FORWARD"},
    {D, D, L, "BACKWARD"}, {D, L, L, "BACKWARD_MAX"}, {D, D, D, "BACKWARD_SLOWLY"},
};

Term scaled(const char* name, std::array<double, 4> corners, double factor) {
  return Term::trapezoid(name, corners[0] * factor, corners[1] * factor, corners[2] * factor, corners[3] * factor);
}

}  // namespace

Trapezoid light_term(int adc_bits) {
  if (adc_bits == 10) return {-1, 0, 100, 700};
  if (adc_bits == 12) return {-1, 0, 396, 3135};
  throw Error(fmt::format("the ADC has 10 or 12 bits, not {}", adc_bits));
}

Trapezoid dark_term(int adc_bits) {
  if (adc_bits == 10) return {100, 700, 1024, 1025};
  if (adc_bits == 12) return {396, 3135, 4096, 4097};
  throw Error(fmt::format("the ADC has 10 or 12 bits, not {}", adc_bits));
}

std::string sensor_pattern(double left, double mid, double right, int adc_bits) {
  const Trapezoid light = light_term(adc_bits), dark = dark_term(adc_bits);
  std::string pattern;
  for (double reading : {left, mid, right}) pattern += light(reading) >= dark(reading) ? 'L' : 'D';
  return pattern;
}

Engine line_follower_engine(const LineFollowerOptions& options) {
  if (!(options.speed_factor > 0) || !std::isfinite(options.speed_factor))
    throw Error("the speed factor must be a finite number above 0");
  Engine engine;
  engine.name = "line_follower";
  engine.description =
      fmt::format("Konczol & Gal line follower, {}-bit ADC, speed factor {}", options.adc_bits, options.speed_factor);
  const Trapezoid light = light_term(options.adc_bits), dark = dark_term(options.adc_bits);
  for (const char* name : {"left", "mid", "right"}) {
    Variable v;
    v.name = name;
    v.min = 0;
    v.max = options.adc_bits == 10 ? 1023 : 4095;
    v.terms = {Term{"LIGHT", Term::Shape::trapezoid, light}, Term{"DARK", Term::Shape::trapezoid, dark}};
    engine.inputs.push_back(std::move(v));
  }
  const double k = options.speed_factor;
  for (const char* name : {"left_motor", "right_motor"}) {
    OutputVariable v;
    v.name = name;
    v.min = options.output_min;
    v.max = options.output_max;
    v.defuzzifier = options.defuzzifier;
    v.default_value = 0.5 * (options.output_min + options.output_max);
    v.terms = {scaled("STOP", {-10, 0, 0, 10}, k),
               scaled("FORWARD_MAX", {60, 75, 80, 85}, k),
               scaled("FORWARD", {45, 55, 65, 75}, k),
               scaled("BACKWARD", {-80, -75, -70, -60}, k),
               scaled("BACKWARD_MAX", {-90, -85, -80, -70}, k),
               scaled("BACKWARD_SLOWLY", options.backward_slowly, k)};
    engine.outputs.push_back(std::move(v));
  }
  engine.rule_block.name = "line_following";
  engine.rule_block.conjunction = options.conjunction;
  engine.rule_block.implication = options.implication;
  auto term_of = [](Sensor s) -> std::size_t { return s == L ? 0 : 1; };
  for (std::size_t motor = 0; motor < 2; ++motor) {
    const OutputVariable& out = engine.outputs[motor];
    for (const RuleRow& row : kRules) {
      Rule rule;
      // The right motor mirrors the left: its "left" sensor is the right one.
      const Sensor near = motor == 0 ? row.left : row.right, far = motor == 0 ? row.right : row.left;
      rule.antecedents = {{0, term_of(near)}, {1, term_of(row.mid)}, {2, term_of(far)}};
      rule.consequents = {{motor, out.term_index(row.left_motor)}};
      engine.rule_block.rules.push_back(std::move(rule));
    }
  }
  validate(engine);
  return engine;
}

int board_adc_bits(Board board) { return board == Board::uno ? 10 : 12; }

namespace {

struct BoardFigures {
  TNorm tnorm;
  double uno_ms, esp32_ms;          // Tables 3 and 4, 2 x 1024 inferences
  double uno_laps_s, esp32_laps_s;  // Tables 1 and 2, 3 laps; 0: "-"
};

constexpr BoardFigures kPaperFigures[] = {
    {TNorm::minimum, 3704, 367, 34.23, 32.49},
    {TNorm::product, 3758, 378, 36.95, 28.25},
    {TNorm::drastic, 3756, 321, 0, 0},
    {TNorm::lukasiewicz, 4035, 344, 37.72, 27.35},
    {TNorm::trigonometric, 11665, 1188, 43.99, 27.63},
    {TNorm::hamacher, 4448, 471, 33.41, 30.22},
};

const BoardFigures& figures(TNorm t) {
  for (const BoardFigures& f : kPaperFigures)
    if (f.tnorm == t) return f;
  throw Error("no published figures for this t-norm");
}

}  // namespace

double paper_ms_per_2x1024(Board board, TNorm t) {
  return board == Board::uno ? figures(t).uno_ms : figures(t).esp32_ms;
}

std::optional<double> paper_three_laps_s(Board board, TNorm t) {
  const double s = board == Board::uno ? figures(t).uno_laps_s : figures(t).esp32_laps_s;
  if (s > 0) return s;
  return std::nullopt;
}

}  // namespace tk::fuzzy
