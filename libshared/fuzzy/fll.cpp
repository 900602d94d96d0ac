/// @file fll.cpp
/// @brief FLL reader (line by line, rules parsed once every variable is
/// known) and writer in fuzzylite 6.0's layout; see fll.hpp for the subset.
#include "fuzzy/fll.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <climits>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include "io/error.hpp"
#include "io/input_file.hpp"

namespace tk::fuzzy {
namespace {

constexpr std::array<std::pair<TNorm, std::string_view>, 6> kConjunctions{{{TNorm::minimum, "Minimum"},
                                                                           {TNorm::product, "AlgebraicProduct"},
                                                                           {TNorm::drastic, "DrasticProduct"},
                                                                           {TNorm::lukasiewicz, "BoundedDifference"},
                                                                           {TNorm::hamacher, "HamacherProduct"},
                                                                           {TNorm::trigonometric, "Trigonometric"}}};
constexpr std::array<std::string_view, 9> kSNorms{"Maximum",     "AlgebraicSum",     "BoundedSum",
                                                  "DrasticSum",  "EinsteinSum",      "HamacherSum",
                                                  "NilpotentMaximum", "NormalizedSum", "UnboundedSum"};
// Words a rule gives meaning to: as names they would make rules ambiguous.
constexpr std::array<std::string_view, 6> kKeywords{"if", "is", "and", "or", "then", "with"};
constexpr std::array<std::string_view, 6> kHedges{"not", "any", "very", "somewhat", "extremely", "seldom"};

template <typename List>
bool contains(const List& list, std::string_view word) {
  return std::find(list.begin(), list.end(), word) != list.end();
}

std::string_view trim(std::string_view s) {
  constexpr std::string_view blank = " \t\r\v\f";
  const auto first = s.find_first_not_of(blank);
  if (first == std::string_view::npos) return {};
  return s.substr(first, s.find_last_not_of(blank) - first + 1);
}

std::vector<std::string_view> split(std::string_view s) {
  std::vector<std::string_view> tokens;
  for (std::size_t i = 0; i < s.size();) {
    const std::size_t start = s.find_first_not_of(" \t\v\f", i);
    if (start == std::string_view::npos) break;
    const std::size_t stop = std::min(s.find_first_of(" \t\v\f", start), s.size());
    tokens.push_back(s.substr(start, stop - start));
    i = stop;
  }
  return tokens;
}

/// A finite decimal number, the whole token (a leading '+' allowed).
std::optional<double> parse_number(std::string_view s) {
  if (s.size() > 1 && s[0] == '+' && s[1] != '-') s.remove_prefix(1);
  double value = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value, std::chars_format::general);
  if (ec != std::errc{} || end != s.data() + s.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

/// What fuzzylite keeps of a name (letters, digits, '_', '.'), so that
/// names pass through fuzzylite unchanged; rule words are excluded.
std::string name_problem(std::string_view name) {
  if (name.empty()) return "a name is empty";
  for (const char c : name)
    if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '.'))
      return fmt::format("invalid name '{}' (use letters, digits, '_' and '.')", name);
  if (contains(kKeywords, name) || contains(kHedges, name))
    return fmt::format("'{}' is a rule word and cannot be a name", name);
  return {};
}

enum class Section { none, engine, input, output, rules };

class Reader {
 public:
  explicit Reader(const std::string& file_name) : file_(file_name) {}

  Engine run(std::string_view text) {
    std::size_t number = 0;
    for (std::size_t pos = 0; pos < text.size();) {
      const std::size_t newline = std::min(text.find('\n', pos), text.size());
      std::string_view line = text.substr(pos, newline - pos);
      pos = newline + 1;
      line_ = ++number;
      if (line.find('\0') != std::string_view::npos) fail("NUL byte in the text");
      if (!line.empty() && line.back() == '\r') line.remove_suffix(1);  // CRLF
      if (line.find('\r') != std::string_view::npos) fail("carriage return inside a line");
      line = trim(line.substr(0, line.find('#')));
      if (line.empty()) continue;
      const std::size_t colon = line.find(':');
      if (colon == std::string_view::npos)
        fail(fmt::format("expected 'key: value', found '{}'", line.substr(0, 60)));  // garbage may be long
      entry(trim(line.substr(0, colon)), trim(line.substr(colon + 1)));
    }
    line_ = 0;
    if (section_ == Section::none) fail("no 'Engine:' line (empty input)");
    close_section();
    for (const auto& [at, rule] : rules_) {
      line_ = at;
      parse_rule(rule);
    }
    line_ = 0;
    try {
      validate(engine_);
    } catch (const Error& e) {
      fail(e.what());
    }
    return std::move(engine_);
  }

 private:
  [[noreturn]] void fail(const std::string& message) const { throw Error(message, Location{file_, line_}); }

  void entry(std::string_view key, std::string_view value) {
    if (key == "Engine") {
      if (section_ != Section::none) fail("a second 'Engine:' line");
      engine_.name = value;
      section_ = Section::engine;
      return;
    }
    if (section_ == Section::none) fail(fmt::format("expected 'Engine: NAME' first, found '{}'", key));
    if (key == "InputVariable" || key == "OutputVariable") return open_variable(key == "InputVariable", value);
    if (key == "RuleBlock") {
      close_section();
      if (seen_rule_block_) fail("only one RuleBlock is supported");
      seen_rule_block_ = true;
      engine_.rule_block.name = value;
      section_ = Section::rules;
      return;
    }
    if (key == "description") {
      if (section_ == Section::engine) engine_.description = value;
      if (section_ == Section::input || section_ == Section::output) variable().description = value;
      return;  // a RuleBlock's description has no place in the engine
    }
    if (section_ == Section::input || section_ == Section::output) {
      if (variable_entry(key, value)) return;
    } else if (section_ == Section::rules) {
      if (rule_block_entry(key, value)) return;
    }
    constexpr std::array<std::string_view, 16> known{
        "enabled",     "range",       "lock-range",  "term",        "aggregation",   "accumulation",
        "defuzzifier", "default",     "lock-previous", "lock-valid", "conjunction",  "disjunction",
        "implication", "activation",  "rule",        "description"};
    if (!contains(known, key)) fail(fmt::format("unknown key '{}'", key));
    constexpr std::array<std::string_view, 5> names{"", "Engine", "InputVariable", "OutputVariable", "RuleBlock"};
    fail(fmt::format("key '{}' does not belong in {}", key, names[static_cast<int>(section_)]));
  }

  void open_variable(bool input, std::string_view name) {
    close_section();
    if (seen_rule_block_) fail("variables must come before the RuleBlock");
    const std::string problem = name_problem(name);
    if (!problem.empty()) fail(problem == "a name is empty" ? "a variable without a name" : problem);
    const std::string owned(name);
    if (engine_.input_index(owned) != Variable::npos || engine_.output_index(owned) != Variable::npos)
      fail(fmt::format("variable '{}' defined twice", name));
    if (input) {
      engine_.inputs.emplace_back().name = owned;
    } else {
      engine_.outputs.emplace_back().name = owned;
    }
    section_ = input ? Section::input : Section::output;
    section_line_ = line_;
    have_range_ = false;
  }

  // A variable's problems that only show at its end, reported at its header.
  void close_section() {
    if (section_ != Section::input && section_ != Section::output) return;
    const std::size_t here = line_;
    line_ = section_line_;
    if (!have_range_) fail(fmt::format("variable '{}' has no range", variable().name));
    if (variable().terms.empty()) fail(fmt::format("variable '{}' has no terms", variable().name));
    line_ = here;
  }

  Variable& variable() {
    if (section_ == Section::input) return engine_.inputs.back();
    return engine_.outputs.back();
  }

  bool boolean(std::string_view key, std::string_view value, bool supported) {
    if (value != "true" && value != "false") fail(fmt::format("expected true or false, found '{}'", value));
    if ((value == "true") != supported) fail(fmt::format("'{}: {}' is not supported", key, value));
    return supported;
  }

  double number(std::string_view token, std::string_view what) const {
    const auto value = parse_number(token);
    if (!value) fail(fmt::format("{}: '{}' is not a finite decimal number", what, token));
    return *value;
  }

  bool variable_entry(std::string_view key, std::string_view value) {
    const bool output = section_ == Section::output;
    if (key == "enabled") {
      boolean(key, value, true);
    } else if (key == "lock-range" || (output && (key == "lock-previous" || key == "lock-valid"))) {
      boolean(key, value, false);
    } else if (key == "range") {
      const auto tokens = split(value);
      if (tokens.size() != 2) fail("expected 'range: MIN MAX'");
      variable().min = number(tokens[0], "range");
      variable().max = number(tokens[1], "range");
      if (!(variable().min < variable().max)) fail("range needs MIN < MAX");
      have_range_ = true;
    } else if (key == "term") {
      term(value);
    } else if (output && (key == "aggregation" || key == "accumulation")) {
      if (value != "Maximum") fail(fmt::format("{} '{}' is not supported (only Maximum)", key, value));
    } else if (output && key == "defuzzifier") {
      defuzzifier(value);
    } else if (output && key == "default") {
      double& slot = engine_.outputs.back().default_value;
      if (value == "nan" || value == "NaN" || value == "NAN") {
        slot = std::numeric_limits<double>::quiet_NaN();
      } else if (const auto v = parse_number(value)) {
        slot = *v;
      } else {
        fail(fmt::format("default '{}' is neither a finite decimal number nor nan", value));
      }
    } else {
      return false;
    }
    return true;
  }

  void term(std::string_view value) {
    const auto tokens = split(value);
    if (tokens.size() < 2) fail("expected 'term: NAME Triangle a b c' or 'term: NAME Trapezoid a b c d'");
    const std::string problem = name_problem(tokens[0]);
    if (!problem.empty()) fail(problem);
    const bool triangle = tokens[1] == "Triangle";
    if (!triangle && tokens[1] != "Trapezoid")
      fail(fmt::format("term shape '{}' is not supported (only Triangle and Trapezoid)", tokens[1]));
    const std::size_t vertices = triangle ? 3 : 4;
    if (tokens.size() != 2 + vertices && tokens.size() != 3 + vertices)
      fail(fmt::format("a {} needs {} vertices and an optional height", tokens[1], vertices));
    std::array<double, 4> p{};
    for (std::size_t i = 0; i < vertices; ++i) p[i] = number(tokens[2 + i], "term vertex");
    if (tokens.size() == 3 + vertices && number(tokens.back(), "term height") != 1)
      fail(fmt::format("term '{}': only height 1 is supported", tokens[0]));
    Term t = triangle ? Term::triangle(std::string(tokens[0]), p[0], p[1], p[2])
                      : Term::trapezoid(std::string(tokens[0]), p[0], p[1], p[2], p[3]);
    if (!(t.points.a <= t.points.b && t.points.b <= t.points.c && t.points.c <= t.points.d))
      fail(fmt::format("term '{}' needs its vertices in order", t.name));
    if (variable().term_index(t.name) != Variable::npos)
      fail(fmt::format("term '{}' of variable '{}' defined twice", t.name, variable().name));
    variable().terms.push_back(std::move(t));
  }

  void defuzzifier(std::string_view value) {
    const auto tokens = split(value);
    Defuzzifier& d = engine_.outputs.back().defuzzifier;
    if (tokens.empty()) fail("expected 'defuzzifier: Centroid [RESOLUTION]'");
    if (tokens[0] == "Centroid") {
      d.kind = Defuzzifier::Kind::discrete;
    } else if (tokens[0] == "ExactCentroid") {
      d.kind = Defuzzifier::Kind::exact;
    } else {
      fail(fmt::format("defuzzifier '{}' is not supported (only Centroid)", tokens[0]));
    }
    if (tokens.size() > 2) fail(fmt::format("unexpected '{}' after the resolution", tokens[2]));
    d.resolution = 100;
    if (tokens.size() == 2) {
      const double r = number(tokens[1], "resolution");
      if (r != std::floor(r) || r < 1 || r > INT_MAX) fail("resolution must be a whole number of at least 1");
      d.resolution = static_cast<int>(r);
    }
  }

  bool rule_block_entry(std::string_view key, std::string_view value) {
    RuleBlock& block = engine_.rule_block;
    const auto tnorm = [&](std::string_view name) -> std::optional<TNorm> {
      for (const auto& [t, known] : kConjunctions)
        if (known == name) return t;
      return std::nullopt;
    };
    if (key == "enabled") {
      boolean(key, value, true);
    } else if (key == "conjunction") {
      conjunction_none_ = value == "none";
      const auto t = tnorm(value);
      if (!t && !conjunction_none_)
        fail(fmt::format("conjunction '{}' is not supported (Minimum, AlgebraicProduct, DrasticProduct, "
                         "BoundedDifference, HamacherProduct, Trigonometric or none)", value));
      block.conjunction = t.value_or(TNorm::minimum);
    } else if (key == "disjunction") {
      if (value != "none" && !contains(kSNorms, value)) fail(fmt::format("unknown disjunction '{}'", value));
    } else if (key == "implication" || (key == "activation" && tnorm(value))) {
      // fuzzylite 5 wrote the implication as `activation: <TNorm>`.
      if (value == "Minimum") {
        block.implication = Implication::minimum;
      } else if (value == "AlgebraicProduct") {
        block.implication = Implication::product;
      } else {
        fail(fmt::format("implication '{}' is not supported (Minimum or AlgebraicProduct)", value));
      }
    } else if (key == "activation") {
      if (value != "General" && value != "none")
        fail(fmt::format("activation '{}' is not supported (only General)", value));
    } else if (key == "rule") {
      rules_.emplace_back(line_, value);
    } else {
      return false;
    }
    return true;
  }

  // `VARIABLE is TERM` at tokens[i], for an antecedent (input) or a consequent.
  Proposition proposition(const std::vector<std::string_view>& tokens, std::size_t& i, bool input) {
    if (i + 3 > tokens.size()) fail("the rule ends in the middle of 'VARIABLE is TERM'");
    const std::string name(tokens[i]), term(tokens[i + 2]);
    if (tokens[i + 1] != "is") fail(fmt::format("expected 'is' after '{}', found '{}'", name, tokens[i + 1]));
    if (contains(kHedges, term)) fail(fmt::format("hedge '{}' is not supported", term));
    const std::size_t v = input ? engine_.input_index(name) : engine_.output_index(name);
    if (v == Variable::npos) {
      const bool other = (input ? engine_.output_index(name) : engine_.input_index(name)) != Variable::npos;
      if (other) fail(fmt::format("'{}' is an {} variable and cannot be {}", name, input ? "output" : "input",
                                  input ? "in a rule's if part" : "in a rule's then part"));
      fail(fmt::format("unknown {} variable '{}'", input ? "input" : "output", name));
    }
    const Variable& var = input ? engine_.inputs[v] : static_cast<const Variable&>(engine_.outputs[v]);
    const std::size_t t = var.term_index(term);
    if (t == Variable::npos) fail(fmt::format("unknown term '{}' of variable '{}'", term, name));
    i += 3;
    return Proposition{v, t};
  }

  void parse_rule(std::string_view text) {
    if (text.find_first_of("()") != std::string_view::npos) fail("parentheses are not supported");
    const auto tokens = split(text);
    if (tokens.empty()) fail("empty rule");
    if (tokens[0] != "if") fail(fmt::format("a rule starts with 'if', found '{}'", tokens[0]));
    Rule rule;
    std::size_t i = 1;
    for (bool then = false; !then;) {
      rule.antecedents.push_back(proposition(tokens, i, true));
      if (i == tokens.size()) fail("a rule without 'then'");
      if (tokens[i] == "or") fail("'or' is not supported");
      if (tokens[i] == "and" && conjunction_none_) fail("the rule uses 'and' but the conjunction is none");
      if (tokens[i] != "and" && tokens[i] != "then")
        fail(fmt::format("expected 'and' or 'then', found '{}'", tokens[i]));
      then = tokens[i++] == "then";
    }
    while (true) {
      rule.consequents.push_back(proposition(tokens, i, false));
      if (i == tokens.size()) break;
      if (tokens[i] == "or") fail("'or' is not supported");
      if (tokens[i] == "with") {
        if (i + 2 != tokens.size()) fail("expected one number after 'with'");
        rule.weight = number(tokens[i + 1], "rule weight");
        if (rule.weight < 0 || rule.weight > 1) fail("the rule weight must be in [0, 1]");
        break;
      }
      if (tokens[i++] != "and") fail(fmt::format("expected 'and' or 'with', found '{}'", tokens[i - 1]));
    }
    engine_.rule_block.rules.push_back(std::move(rule));
  }

  std::string file_;
  std::size_t line_ = 0;
  Engine engine_;
  Section section_ = Section::none;
  std::size_t section_line_ = 0;
  bool have_range_ = false;
  bool seen_rule_block_ = false;
  bool conjunction_none_ = false;
  std::vector<std::pair<std::size_t, std::string_view>> rules_;
};

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

Engine read_fll(std::string_view text, const std::string& file_name) { return Reader(file_name).run(text); }

Engine read_fll_file(const std::string& path) {
  io::InputFile input(path);
  std::string text;
  for (std::string_view line; input.next(line);) {
    text += line;
    text += '\n';
  }
  return read_fll(text, input.where().file);
}

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
    out += exact && v.defuzzifier.resolution == 100 ? std::string("ExactCentroid")
                                                    : fmt::format("{} {}", exact ? "ExactCentroid" : "Centroid",
                                                                  v.defuzzifier.resolution);
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
      fmt::format_to(std::back_inserter(out), "{} {} is {}", i ? " and" : "", v.name, v.terms[rule.antecedents[i].term].name);
    }
    out += " then";
    for (std::size_t i = 0; i < rule.consequents.size(); ++i) {
      const Variable& v = engine.outputs[rule.consequents[i].variable];
      fmt::format_to(std::back_inserter(out), "{} {} is {}", i ? " and" : "", v.name, v.terms[rule.consequents[i].term].name);
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
        !same_propositions(p.rules[i].consequents, q.rules[i].consequents) || !same(p.rules[i].weight, q.rules[i].weight))
      return fmt::format("rule {}", i + 1);
  return {};
}

}  // namespace tk::fuzzy
