/// @file mamdani.cpp
/// @brief The compiled Mamdani controller.
#include "fuzzy/mamdani.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "io/error.hpp"

namespace tk::fuzzy {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// Each t-norm as: the inner value of one membership, how a rule combines
/// inner values, which of two inner values is the higher activation, and the
/// activation an inner value stands for. Where T(mu) = g(combine(f(mu_i)))
/// with g monotone, the rules' maximum is taken on inner values.
template <TNorm T>
struct Kernel;

template <>
struct Kernel<TNorm::minimum> {
  static double inner(double mu) { return mu; }
  static double combine(const double* v, const std::size_t* idx, std::size_t n) {
    if (n == 3) return std::min(std::min(v[idx[0]], v[idx[1]]), v[idx[2]]);  // the seed's rules, unrolled
    double m = v[idx[0]];
    for (std::size_t i = 1; i < n; ++i) m = std::min(m, v[idx[i]]);
    return m;
  }
  static constexpr double none = 0;
  static bool higher(double a, double b) { return a > b; }
  static double activation(double v) { return v; }
  static double inner_of_activation(double a) { return a; }
};

template <>
struct Kernel<TNorm::product> : Kernel<TNorm::minimum> {
  static double combine(const double* v, const std::size_t* idx, std::size_t n) {
    if (n == 3) return v[idx[0]] * v[idx[1]] * v[idx[2]];
    double p = v[idx[0]];
    for (std::size_t i = 1; i < n; ++i) p *= v[idx[i]];
    return p;
  }
};

template <>
struct Kernel<TNorm::lukasiewicz> : Kernel<TNorm::minimum> {
  static double combine(const double* v, const std::size_t* idx, std::size_t n) {
    if (n == 3) return std::max(0.0, v[idx[0]] + v[idx[1]] + v[idx[2]] - 2.0);
    double s = v[idx[0]];
    for (std::size_t i = 1; i < n; ++i) s += v[idx[i]];
    return std::max(0.0, s - static_cast<double>(n - 1));
  }
};

template <>
struct Kernel<TNorm::drastic> : Kernel<TNorm::minimum> {
  static double combine(const double* v, const std::size_t* idx, std::size_t n) {
    if (n == 3) {
      const double a = v[idx[0]], b = v[idx[1]], c = v[idx[2]];
      const int below_one = (a < 1) + (b < 1) + (c < 1);
      return below_one <= 1 ? std::min(std::min(a, b), c) : 0;
    }
    std::size_t below_one = 0;
    double smallest = 1;
    for (std::size_t i = 0; i < n; ++i) {
      const double m = v[idx[i]];
      below_one += m < 1;
      smallest = std::min(smallest, m);
    }
    return below_one <= 1 ? smallest : 0;
  }
};

/// 2/pi asin(prod sin(pi/2 mu)): inner value sin(pi/2 mu), combined by product.
template <>
struct Kernel<TNorm::trigonometric> : Kernel<TNorm::product> {
  static double inner(double mu) { return std::sin(std::numbers::pi / 2 * mu); }
  static double activation(double v) { return 2 / std::numbers::pi * std::asin(std::clamp(v, 0.0, 1.0)); }
  static double inner_of_activation(double a) { return std::sin(std::numbers::pi / 2 * a); }
};

/// 1 / (1 + sum (1/mu - 1)): inner value 1/mu - 1 (inf at mu = 0), combined
/// by sum; the smaller sum is the higher activation.
template <>
struct Kernel<TNorm::hamacher> {
  static double inner(double mu) { return mu > 0 ? 1 / mu - 1 : kInf; }
  static double combine(const double* v, const std::size_t* idx, std::size_t n) {
    if (n == 3) return v[idx[0]] + v[idx[1]] + v[idx[2]];
    double s = v[idx[0]];
    for (std::size_t i = 1; i < n; ++i) s += v[idx[i]];
    return s;
  }
  static constexpr double none = kInf;
  static bool higher(double a, double b) { return a < b; }
  static double activation(double v) { return v < kInf ? 1 / (1 + v) : 0; }
  static double inner_of_activation(double a) { return a > 0 ? 1 / a - 1 : kInf; }
};

}  // namespace

Mamdani::Mamdani(const Engine& engine)
    : conjunction_(engine.rule_block.conjunction), implication_(engine.rule_block.implication) {
  validate(engine);
  std::size_t degree_count = 0;
  for (const Variable& v : engine.inputs) {
    CompiledInput in;
    in.first_degree = degree_count;
    for (const Term& t : v.terms) in.terms.push_back(t.points);
    degree_count += in.terms.size();
    inputs_.push_back(std::move(in));
  }
  std::size_t level_count = 0;
  for (std::size_t o = 0; o < engine.outputs.size(); ++o) {
    const OutputVariable& v = engine.outputs[o];
    CompiledOutput out;
    out.min = v.min;
    out.max = v.max;
    out.default_value = v.default_value;
    out.defuzzifier = v.defuzzifier;
    out.first_level = level_count;
    for (const Term& t : v.terms) out.terms.push_back(t.points);
    prepare_grid(out);
    // The exact centroid takes its terms in the order of their first corner.
    for (std::size_t t = 0; t < out.terms.size(); ++t) out.by_start.push_back(t);
    std::stable_sort(out.by_start.begin(), out.by_start.end(),
                     [&](std::size_t x, std::size_t y) { return out.terms[x].a < out.terms[y].a; });
    level_count += out.terms.size();
    level_output_.insert(level_output_.end(), out.terms.size(), o);
    outputs_.push_back(std::move(out));
  }
  for (const Rule& rule : engine.rule_block.rules) {
    CompiledRule r;
    r.first_antecedent = antecedents_.size();
    r.antecedent_count = rule.antecedents.size();
    for (const Proposition& p : rule.antecedents) antecedents_.push_back(inputs_[p.variable].first_degree + p.term);
    r.first_consequent = consequents_.size();
    r.consequent_count = rule.consequents.size();
    for (const Proposition& p : rule.consequents) consequents_.push_back(outputs_[p.variable].first_level + p.term);
    r.weight = rule.weight;
    unit_weights_ = unit_weights_ && rule.weight == 1;
    rules_.push_back(r);
  }
  degrees_.resize(degree_count);
  levels_.resize(level_count);
  fired_.resize(outputs_.size());
}

void Mamdani::set_defuzzifier(const Defuzzifier& defuzzifier) {
  if (defuzzifier.resolution < 1) throw Error("the centroid's resolution must be at least 1");
  for (CompiledOutput& out : outputs_) {
    out.defuzzifier = defuzzifier;
    prepare_grid(out);
  }
}

void Mamdani::prepare_grid(CompiledOutput& out) {
  out.grid = SampleGrid(out.min, out.max, out.defuzzifier.resolution);
  out.grid_terms.clear();
  for (const Trapezoid& t : out.terms) out.grid_terms.push_back(out.grid.prepare(t));
}

template <TNorm T>
void Mamdani::fire_rules() {
  using K = Kernel<T>;
  for (double& d : degrees_) d = K::inner(d);
  std::fill(levels_.begin(), levels_.end(), K::none);
  std::fill(fired_.begin(), fired_.end(), 0u);
  // A rule fires when its activation is above 0 and at least the threshold.
  const double threshold = K::inner_of_activation(fire_threshold_);
  for (const CompiledRule& r : rules_) {
    const double v = K::combine(degrees_.data(), antecedents_.data() + r.first_antecedent, r.antecedent_count);
    if (!K::higher(v, K::none) || K::higher(threshold, v)) continue;
    for (std::size_t c = 0; c < r.consequent_count; ++c) {
      const std::size_t level = consequents_[r.first_consequent + c];
      if (K::higher(v, levels_[level])) levels_[level] = v;
      ++fired_[level_output_[level]];
    }
  }
  for (double& l : levels_) l = K::higher(l, K::none) ? K::activation(l) : 0;
}

void Mamdani::fire_rules_generic() {
  std::fill(levels_.begin(), levels_.end(), 0.0);
  std::fill(fired_.begin(), fired_.end(), 0u);
  std::vector<double>& mu = rule_degrees_;
  for (const CompiledRule& r : rules_) {
    mu.clear();
    for (std::size_t i = 0; i < r.antecedent_count; ++i) mu.push_back(degrees_[antecedents_[r.first_antecedent + i]]);
    const double a = r.weight * tnorm(conjunction_, mu);
    if (!(a > 0) || a < fire_threshold_) continue;
    for (std::size_t c = 0; c < r.consequent_count; ++c) {
      const std::size_t level = consequents_[r.first_consequent + c];
      levels_[level] = std::max(levels_[level], a);
      ++fired_[level_output_[level]];
    }
  }
}

void Mamdani::evaluate(std::span<const double> inputs, std::span<double> outputs) {
  if (inputs.size() != inputs_.size() || outputs.size() != outputs_.size())
    throw Error("the controller was given the wrong number of inputs or outputs");
  for (std::size_t i = 0; i < inputs_.size(); ++i) {
    const double x = inputs[i];
    if (std::isnan(x)) throw Error("an input is NaN");
    const CompiledInput& in = inputs_[i];
    for (std::size_t t = 0; t < in.terms.size(); ++t) degrees_[in.first_degree + t] = in.terms[t](x);
  }
  if (!unit_weights_) {
    fire_rules_generic();
  } else {
    switch (conjunction_) {
      case TNorm::minimum: fire_rules<TNorm::minimum>(); break;
      case TNorm::product: fire_rules<TNorm::product>(); break;
      case TNorm::drastic: fire_rules<TNorm::drastic>(); break;
      case TNorm::lukasiewicz: fire_rules<TNorm::lukasiewicz>(); break;
      case TNorm::trigonometric: fire_rules<TNorm::trigonometric>(); break;
      case TNorm::hamacher: fire_rules<TNorm::hamacher>(); break;
    }
  }
  for (std::size_t o = 0; o < outputs_.size(); ++o) {
    CompiledOutput& out = outputs_[o];
    const std::span<const double> levels(levels_.data() + out.first_level, out.terms.size());
    CentroidResult c{0, 0};
    if (out.defuzzifier.kind == Defuzzifier::Kind::discrete) {
      c = out.grid.centroid(out.grid_terms, levels, implication_);
    } else {
      implied_.clear();
      for (std::size_t t : out.by_start)
        if (levels[t] > 0) implied_.push_back({out.terms[t], levels[t]});
      if (!implied_.empty()) c = exact_centroid(implied_, implication_, out.min, out.max);
    }
    // No rule fired, or the fired terms have no area inside the range.
    outputs[o] = c.area > 0 ? c.centroid : out.default_value;
  }
}

}  // namespace tk::fuzzy
