/// @file mamdani.hpp
/// @brief Mamdani inference compiled for speed: fuzzify the inputs, fire the
/// rules with the block's t-norm, aggregate by maximum, defuzzify by centre
/// of gravity (discrete like fuzzylite, or exact).
///
/// Aggregating by maximum lets every consequent term carry one level, the
/// highest activation of the rules that conclude it: max_r min(h_r, mu) =
/// min(max_r h_r, mu), and likewise for the product. The t-norms with a
/// costly outer function (trigonometric: asin; Hamacher: a division) are
/// monotone in an inner value, so the maximum is taken on the inner value
/// and the outer function runs once per consequent term, not per rule.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "fuzzy/centroid.hpp"
#include "fuzzy/engine.hpp"
#include "fuzzy/sample_grid.hpp"

namespace tk::fuzzy {

class Mamdani {
 public:
  /// Validates the engine (Error when it is not usable) and compiles it.
  explicit Mamdani(const Engine& engine);

  /// Overrides every output's defuzzifier.
  void set_defuzzifier(const Defuzzifier& defuzzifier);
  /// A rule fires when its activation is at least this (default: above 0).
  /// fuzzylite fires rules from 1e-6 on; set that to compare number for number.
  void set_fire_threshold(double threshold) { fire_threshold_ = threshold; }

  std::size_t input_count() const { return inputs_.size(); }
  std::size_t output_count() const { return outputs_.size(); }

  /// Evaluates the controller: one value per output, in the engine's order.
  /// An output none of whose rules fired gets its default value (see
  /// OutputVariable::default_value); so does one whose fired terms have no
  /// area inside its range. NaN inputs are an Error.
  void evaluate(std::span<const double> inputs, std::span<double> outputs);

  /// Rules that fired for each output in the last evaluate().
  std::span<const unsigned> fired() const { return fired_; }

 private:
  struct CompiledInput {
    std::vector<Trapezoid> terms;
    std::size_t first_degree = 0;  ///< index of its first term in degrees_
  };
  struct CompiledOutput {
    double min = 0, max = 1, default_value = 0;
    Defuzzifier defuzzifier;
    std::vector<Trapezoid> terms;
    std::size_t first_level = 0;  ///< index of its first term in levels_
    SampleGrid grid{0, 1, 1};
    std::vector<GridTerm> grid_terms;   ///< terms prepared for the grid
    std::vector<std::size_t> by_start;  ///< term indices by first corner, as the exact centroid takes them
  };
  struct CompiledRule {
    std::size_t first_antecedent = 0, antecedent_count = 0;  ///< into antecedents_
    std::size_t first_consequent = 0, consequent_count = 0;  ///< into consequents_
    double weight = 1;
  };

  template <TNorm T>
  void fire_rules();
  void fire_rules_generic();
  /// The output's sample grid and its terms prepared for it, at its resolution.
  static void prepare_grid(CompiledOutput& out);

  TNorm conjunction_;
  Implication implication_;
  bool unit_weights_ = true;
  double fire_threshold_ = 0;
  std::vector<CompiledInput> inputs_;
  std::vector<CompiledOutput> outputs_;
  std::vector<CompiledRule> rules_;
  std::vector<std::size_t> antecedents_;   ///< indices into degrees_
  std::vector<std::size_t> consequents_;   ///< indices into levels_
  std::vector<std::size_t> level_output_;  ///< output of each level
  std::vector<double> degrees_;            ///< membership of each input term (or its inner form)
  std::vector<double> levels_;             ///< activation of each output term
  std::vector<unsigned> fired_;
  std::vector<ImpliedTerm> implied_;
  std::vector<double> rule_degrees_;  ///< scratch of fire_rules_generic
};

}  // namespace tk::fuzzy
