/// @file fll.cpp
/// @brief The FLL reader: line by line, rules parsed once every variable is
/// known; see fll.hpp for the subset. The writer is fll_write.cpp.
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

#include "fuzzy/fll_names.hpp"
#include "io/error.hpp"
#include "io/input_file.hpp"

namespace tk::fuzzy {
namespace {

using namespace fll_names;

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
    // fuzzylite cannot evaluate a Mamdani block without one; our default would differ silently.
    line_ = rule_block_line_;
    if (seen_rule_block_ && !have_implication_) fail("the RuleBlock has no implication");
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
      rule_block_line_ = line_;
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
    constexpr std::array<std::string_view, 16> known{"enabled",       "range",        "lock-range",  "term",
                                                     "aggregation",   "accumulation", "defuzzifier", "default",
                                                     "lock-previous", "lock-valid",   "conjunction", "disjunction",
                                                     "implication",   "activation",   "rule",        "description"};
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
    have_range_ = have_aggregation_ = have_defuzzifier_ = false;
  }

  // A variable's problems that only show at its end, reported at its header.
  void close_section() {
    if (section_ != Section::input && section_ != Section::output) return;
    const std::size_t here = line_;
    line_ = section_line_;
    if (!have_range_) fail(fmt::format("variable '{}' has no range", variable().name));
    if (variable().terms.empty()) fail(fmt::format("variable '{}' has no terms", variable().name));
    // fuzzylite's defaults (none) cannot evaluate; ours would differ silently.
    if (section_ == Section::output && !have_aggregation_)
      fail(fmt::format("output variable '{}' has no aggregation", variable().name));
    if (section_ == Section::output && !have_defuzzifier_)
      fail(fmt::format("output variable '{}' has no defuzzifier", variable().name));
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
      have_aggregation_ = true;
    } else if (output && key == "defuzzifier") {
      defuzzifier(value);
      have_defuzzifier_ = true;
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
        fail(
            fmt::format("conjunction '{}' is not supported (Minimum, AlgebraicProduct, DrasticProduct, "
                        "BoundedDifference, HamacherProduct, Trigonometric or none)",
                        value));
      block.conjunction = t.value_or(TNorm::minimum);
    } else if (key == "disjunction") {
      if (value != "none" && !contains(kSNorms, value)) fail(fmt::format("unknown disjunction '{}'", value));
    } else if (key == "implication" || (key == "activation" && tnorm(value))) {
      // fuzzylite 5 wrote the implication as `activation: <TNorm>`.
      have_implication_ = true;
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
      if (other)
        fail(fmt::format("'{}' is an {} variable and cannot be {}", name, input ? "output" : "input",
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
  bool have_range_ = false, have_aggregation_ = false, have_defuzzifier_ = false;
  bool seen_rule_block_ = false;
  bool conjunction_none_ = true;  // fuzzylite's default, as for a missing implication
  bool have_implication_ = false;
  std::size_t rule_block_line_ = 0;
  std::vector<std::pair<std::size_t, std::string_view>> rules_;
};

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

}  // namespace tk::fuzzy
