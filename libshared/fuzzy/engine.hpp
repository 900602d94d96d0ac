/// @file engine.hpp
/// @brief A Mamdani controller as data: input and output variables with
/// their terms, and one block of rules `if A is X and B is Y then Z is W`.
/// This is what the FLL reader builds and the writer prints; Mamdani
/// (mamdani.hpp) compiles it for fast evaluation.
#pragma once

#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "fuzzy/membership.hpp"
#include "fuzzy/tnorm.hpp"

namespace tk::fuzzy {

/// A named term. Every shape here is piecewise linear and held as a
/// trapezoid (a triangle has b == c), which is what makes the exact centroid
/// possible; `shape` remembers how the user wrote it.
struct Term {
  enum class Shape { triangle, trapezoid };
  std::string name;
  Shape shape = Shape::trapezoid;
  Trapezoid points;

  static Term triangle(std::string name, double a, double b, double c) {
    return Term{std::move(name), Shape::triangle, Trapezoid{a, b, b, c}};
  }
  static Term trapezoid(std::string name, double a, double b, double c, double d) {
    return Term{std::move(name), Shape::trapezoid, Trapezoid{a, b, c, d}};
  }
  double membership(double x) const { return points(x); }
};

struct Variable {
  std::string name;
  std::string description;
  double min = 0, max = 1;
  std::vector<Term> terms;

  /// Index of the term called `term_name`, or npos.
  std::size_t term_index(const std::string& term_name) const;
  static constexpr std::size_t npos = static_cast<std::size_t>(-1);
};

/// How an output's centre of gravity is taken.
struct Defuzzifier {
  enum class Kind { discrete, exact };
  Kind kind = Kind::discrete;
  /// Discrete only: fuzzylite's Centroid samples the range at `resolution`
  /// midpoints, x_i = min + (i + 0.5) (max - min) / resolution.
  int resolution = 100;
};

struct OutputVariable : Variable {
  Defuzzifier defuzzifier;
  /// The value when no rule fires (or the fired terms have no area inside
  /// the range). NaN unless the controller says otherwise, as in fuzzylite.
  double default_value = std::numeric_limits<double>::quiet_NaN();
};

/// How a fired rule shapes its consequent term: clip it at the rule's
/// activation (minimum, Mamdani's original) or scale it (product, Larsen).
enum class Implication { minimum, product };

/// (variable, term) by index into Engine::inputs or Engine::outputs.
struct Proposition {
  std::size_t variable = 0;
  std::size_t term = 0;
};

/// if every antecedent holds (joined by the block's conjunction) then each
/// consequent; activation = weight x conjunction of the antecedents.
struct Rule {
  std::vector<Proposition> antecedents;
  std::vector<Proposition> consequents;
  double weight = 1;
};

struct RuleBlock {
  std::string name;
  TNorm conjunction = TNorm::minimum;
  Implication implication = Implication::minimum;
  /// Aggregation of the implied terms is always the maximum.
  std::vector<Rule> rules;
};

struct Engine {
  std::string name;
  std::string description;
  std::vector<Variable> inputs;
  std::vector<OutputVariable> outputs;
  RuleBlock rule_block;

  std::size_t input_index(const std::string& variable_name) const;
  std::size_t output_index(const std::string& variable_name) const;
};

/// Checks what evaluation relies on: finite ranges with min < max, terms
/// with finite vertices a <= b <= c <= d, rules that name existing
/// variables and terms, each rule with at least one antecedent and one
/// consequent, resolution >= 1. Throws Error naming the problem.
void validate(const Engine& engine);

std::string_view implication_name(Implication implication);

}  // namespace tk::fuzzy
