/// @file engine.cpp
/// @brief Look-ups and the consistency check of a controller description.
#include "fuzzy/engine.hpp"

#include <fmt/format.h>

#include "io/error.hpp"

namespace tk::fuzzy {
namespace {

template <typename Vars>
std::size_t index_by_name(const Vars& variables, const std::string& name) {
  for (std::size_t i = 0; i < variables.size(); ++i)
    if (variables[i].name == name) return i;
  return Variable::npos;
}

void validate_variable(const Variable& v, const char* kind) {
  if (v.name.empty()) throw Error(fmt::format("{} without a name", kind));
  if (!std::isfinite(v.min) || !std::isfinite(v.max) || !(v.min < v.max))
    throw Error(
        fmt::format("{} '{}': range {} {} is not a finite interval with min < max", kind, v.name, v.min, v.max));
  if (v.terms.empty()) throw Error(fmt::format("{} '{}' has no terms", kind, v.name));
  for (std::size_t i = 0; i < v.terms.size(); ++i) {
    const Term& t = v.terms[i];
    const Trapezoid& p = t.points;
    if (t.name.empty()) throw Error(fmt::format("{} '{}': a term without a name", kind, v.name));
    if (!std::isfinite(p.a) || !std::isfinite(p.b) || !std::isfinite(p.c) || !std::isfinite(p.d))
      throw Error(fmt::format("{} '{}': term '{}' has a vertex that is not a finite number", kind, v.name, t.name));
    if (!(p.a <= p.b && p.b <= p.c && p.c <= p.d))
      throw Error(fmt::format("{} '{}': term '{}' needs vertices in order (a <= b <= c <= d)", kind, v.name, t.name));
    for (std::size_t j = 0; j < i; ++j)
      if (v.terms[j].name == t.name) throw Error(fmt::format("{} '{}': term '{}' defined twice", kind, v.name, t.name));
  }
}

}  // namespace

std::size_t Variable::term_index(const std::string& term_name) const { return index_by_name(terms, term_name); }

std::size_t Engine::input_index(const std::string& variable_name) const { return index_by_name(inputs, variable_name); }

std::size_t Engine::output_index(const std::string& variable_name) const {
  return index_by_name(outputs, variable_name);
}

std::string_view implication_name(Implication implication) {
  return implication == Implication::minimum ? "minimum" : "product";
}

void validate(const Engine& engine) {
  if (engine.inputs.empty()) throw Error("the controller has no input variables");
  if (engine.outputs.empty()) throw Error("the controller has no output variables");
  for (const Variable& v : engine.inputs) validate_variable(v, "input variable");
  for (const OutputVariable& v : engine.outputs) {
    validate_variable(v, "output variable");
    if (v.defuzzifier.resolution < 1)
      throw Error(fmt::format("output variable '{}': resolution must be at least 1", v.name));
  }
  for (std::size_t i = 0; i < engine.inputs.size() + engine.outputs.size(); ++i) {
    const std::string& name =
        i < engine.inputs.size() ? engine.inputs[i].name : engine.outputs[i - engine.inputs.size()].name;
    for (std::size_t j = 0; j < i; ++j) {
      const std::string& other =
          j < engine.inputs.size() ? engine.inputs[j].name : engine.outputs[j - engine.inputs.size()].name;
      if (other == name) throw Error(fmt::format("variable '{}' defined twice", name));
    }
  }
  if (engine.rule_block.rules.empty()) throw Error("the controller has no rules");
  for (std::size_t r = 0; r < engine.rule_block.rules.size(); ++r) {
    const Rule& rule = engine.rule_block.rules[r];
    if (rule.antecedents.empty() || rule.consequents.empty())
      throw Error(fmt::format("rule {} needs at least one antecedent and one consequent", r + 1));
    if (!std::isfinite(rule.weight) || rule.weight < 0 || rule.weight > 1)
      throw Error(fmt::format("rule {}: weight must be in [0, 1]", r + 1));
    for (const Proposition& p : rule.antecedents)
      if (p.variable >= engine.inputs.size() || p.term >= engine.inputs[p.variable].terms.size())
        throw Error(fmt::format("rule {} names an input or term that does not exist", r + 1));
    for (const Proposition& p : rule.consequents)
      if (p.variable >= engine.outputs.size() || p.term >= engine.outputs[p.variable].terms.size())
        throw Error(fmt::format("rule {} names an output or term that does not exist", r + 1));
  }
}

}  // namespace tk::fuzzy
