/// @file fll_write.cpp
/// @brief The FLL writer, in fuzzylite 6.0's layout, and the field-by-field
/// comparison of engines the tests and the fuzzer use.
#include <fmt/format.h>

#include <cmath>
#include <iterator>
#include <string>

#include "fuzzy/fll.hpp"
#include "fuzzy/fll_names.hpp"
#include "io/error.hpp"

namespace tk::fuzzy {
namespace {

using namespace fll_names;

void check_text(std::string_view text, std::string_view what) {
  if (text.find_first_of("#\n\r") != std::string_view::npos || text.find('\0') != std::string_view::npos ||
      trim(text) != text)
    throw Error(fmt::format("{} '{}' cannot be written to FLL", what, text));
}

void check_name(std::string_view name) {
  const std::string problem = name_problem(name);
  if (!problem.empty()) throw Error(fmt::format("cannot write FLL: {}", problem));
}

void write_variable(std::string& out, const Variable& v, const char* kind) {
  check_name(v.name);
  check_text(v.description, "description");
  fmt::format_to(std::back_inserter(out), "{}: {}\n", kind, v.name);
  if (!v.description.empty()) fmt::format_to(std::back_inserter(out), "  description: {}\n", v.description);
  fmt::format_to(std::back_inserter(out), "  enabled: true\n  range: {} {}\n  lock-range: false\n", v.min, v.max);
}

void write_terms(std::string& out, const Variable& v) {
  for (const Term& t : v.terms) {
    check_name(t.name);
    const Trapezoid& p = t.points;
    if (t.shape == Term::Shape::triangle && p.b == p.c) {
      fmt::format_to(std::back_inserter(out), "  term: {} Triangle {} {} {}\n", t.name, p.a, p.b, p.d);
    } else {
      fmt::format_to(std::back_inserter(out), "  term: {} Trapezoid {} {} {} {}\n", t.name, p.a, p.b, p.c, p.d);
    }
  }
}

}  // namespace

std::string write_fll(const Engine& engine) {
  validate(engine);
  check_text(engine.name, "engine name");
  check_text(engine.description, "description");
  check_text(engine.rule_block.name, "rule block name");
  std::string out = engine.name.empty() ? "Engine:\n" : fmt::format("Engine: {}\n", engine.name);
  if (!engine.description.empty()) out += fmt::format("  description: {}\n", engine.description);
  for (const Variable& v : engine.inputs) {
    write_variable(out, v, "InputVariable");
    write_terms(out, v);
  }
  for (const OutputVariable& v : engine.outputs) {
    write_variable(out, v, "OutputVariable");
    const bool exact = v.defuzzifier.kind == Defuzzifier::Kind::exact;
    out += "  aggregation: Maximum\n  defuzzifier: ";
    out += exact && v.defuzzifier.resolution == 100
               ? std::string("ExactCentroid")
               : fmt::format("{} {}", exact ? "ExactCentroid" : "Centroid", v.defuzzifier.resolution);
    out += std::isnan(v.default_value) ? std::string("\n  default: nan\n")
                                       : fmt::format("\n  default: {}\n", v.default_value);
    out += "  lock-previous: false\n";
    write_terms(out, v);
  }
  const RuleBlock& block = engine.rule_block;
  out += block.name.empty() ? "RuleBlock:\n" : fmt::format("RuleBlock: {}\n", block.name);
  std::string_view conjunction;
  for (const auto& [t, name] : kConjunctions)
    if (t == block.conjunction) conjunction = name;
  fmt::format_to(std::back_inserter(out),
                 "  enabled: true\n  conjunction: {}\n  disjunction: none\n  implication: {}\n  activation: General\n",
                 conjunction, block.implication == Implication::minimum ? "Minimum" : "AlgebraicProduct");
  for (const Rule& rule : block.rules) {
    out += "  rule: if";
    for (std::size_t i = 0; i < rule.antecedents.size(); ++i) {
      const Variable& v = engine.inputs[rule.antecedents[i].variable];
      fmt::format_to(std::back_inserter(out), "{} {} is {}", i ? " and" : "", v.name,
                     v.terms[rule.antecedents[i].term].name);
    }
    out += " then";
    for (std::size_t i = 0; i < rule.consequents.size(); ++i) {
      const Variable& v = engine.outputs[rule.consequents[i].variable];
      fmt::format_to(std::back_inserter(out), "{} {} is {}", i ? " and" : "", v.name,
                     v.terms[rule.consequents[i].term].name);
    }
    if (rule.weight != 1) fmt::format_to(std::back_inserter(out), " with {}", rule.weight);
    out += '\n';
  }
  return out;
}

namespace {

bool same(double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); }

std::string variable_difference(const Variable& a, const Variable& b) {
  if (a.name != b.name) return fmt::format("variable name '{}' vs '{}'", a.name, b.name);
  if (a.description != b.description) return fmt::format("variable '{}': description", a.name);
  if (!same(a.min, b.min) || !same(a.max, b.max)) return fmt::format("variable '{}': range", a.name);
  if (a.terms.size() != b.terms.size()) return fmt::format("variable '{}': number of terms", a.name);
  for (std::size_t i = 0; i < a.terms.size(); ++i) {
    const Term &s = a.terms[i], &t = b.terms[i];
    if (s.name != t.name || s.shape != t.shape || !same(s.points.a, t.points.a) || !same(s.points.b, t.points.b) ||
        !same(s.points.c, t.points.c) || !same(s.points.d, t.points.d))
      return fmt::format("variable '{}': term {} ('{}')", a.name, i + 1, s.name);
  }
  return {};
}

bool same_propositions(const std::vector<Proposition>& a, const std::vector<Proposition>& b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](const Proposition& p, const Proposition& q) {
    return p.variable == q.variable && p.term == q.term;
  });
}

}  // namespace

std::string engine_difference(const Engine& a, const Engine& b) {
  if (a.name != b.name) return "engine name";
  if (a.description != b.description) return "engine description";
  if (a.inputs.size() != b.inputs.size() || a.outputs.size() != b.outputs.size()) return "number of variables";
  for (std::size_t i = 0; i < a.inputs.size(); ++i)
    if (auto d = variable_difference(a.inputs[i], b.inputs[i]); !d.empty()) return d;
  for (std::size_t i = 0; i < a.outputs.size(); ++i) {
    const OutputVariable &s = a.outputs[i], &t = b.outputs[i];
    if (auto d = variable_difference(s, t); !d.empty()) return d;
    if (s.defuzzifier.kind != t.defuzzifier.kind || s.defuzzifier.resolution != t.defuzzifier.resolution)
      return fmt::format("variable '{}': defuzzifier", s.name);
    if (!same(s.default_value, t.default_value)) return fmt::format("variable '{}': default", s.name);
  }
  const RuleBlock &p = a.rule_block, &q = b.rule_block;
  if (p.name != q.name) return "rule block name";
  if (p.conjunction != q.conjunction) return "conjunction";
  if (p.implication != q.implication) return "implication";
  if (p.rules.size() != q.rules.size()) return "number of rules";
  for (std::size_t i = 0; i < p.rules.size(); ++i)
    if (!same_propositions(p.rules[i].antecedents, q.rules[i].antecedents) ||
        !same_propositions(p.rules[i].consequents, q.rules[i].consequents) ||
        !same(p.rules[i].weight, q.rules[i].weight))
      return fmt::format("rule {}", i + 1);
  return {};
}

}  // namespace tk::fuzzy
