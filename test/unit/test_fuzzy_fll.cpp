/// @file test_fuzzy_fll.cpp
/// @brief The FLL reader against the values written in hand-made fixtures
/// (test/fixtures/fll), the writer by round trips, and every rejected case
/// with the line it must name.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "fuzzy/fll.hpp"
#include "io/error.hpp"

namespace {

using namespace tk::fuzzy;
using namespace std::string_literals;

std::filesystem::path fixture(const std::string& name) {
  const char* root = std::getenv("TOOLKIT_ROOT");
  const auto base =
      root ? std::filesystem::path(root) : std::filesystem::path(__FILE__).parent_path().parent_path().parent_path();
  return base / "test" / "fixtures" / "fll" / name;
}

std::string slurp(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

const std::vector<std::string> kFixtures{"simple_dimmer.fll", "line_follower.fll", "fuzzylite5_style.fll",
                                         "trigonometric.fll"};

void expect_term(const Term& t, const char* name, Term::Shape shape, double a, double b, double c, double d) {
  EXPECT_EQ(t.name, name);
  EXPECT_EQ(t.shape, shape) << name;
  EXPECT_EQ(t.points.a, a) << name;
  EXPECT_EQ(t.points.b, b) << name;
  EXPECT_EQ(t.points.c, c) << name;
  EXPECT_EQ(t.points.d, d) << name;
}

constexpr auto kTri = Term::Shape::triangle;
constexpr auto kTrap = Term::Shape::trapezoid;

TEST(Fll, SimpleDimmerFields) {
  const Engine e = read_fll_file(fixture("simple_dimmer.fll").string());
  EXPECT_EQ(e.name, "SimpleDimmer");
  EXPECT_EQ(e.description, "");
  ASSERT_EQ(e.inputs.size(), 1u);
  ASSERT_EQ(e.outputs.size(), 1u);
  const Variable& in = e.inputs[0];
  EXPECT_EQ(in.name, "Ambient");
  EXPECT_EQ(in.min, 0);
  EXPECT_EQ(in.max, 1);
  ASSERT_EQ(in.terms.size(), 3u);
  expect_term(in.terms[0], "DARK", kTri, 0, 0.25, 0.25, 0.5);
  expect_term(in.terms[1], "MEDIUM", kTri, 0.25, 0.5, 0.5, 0.75);
  expect_term(in.terms[2], "BRIGHT", kTri, 0.5, 0.75, 0.75, 1);
  const OutputVariable& out = e.outputs[0];
  EXPECT_EQ(out.name, "Power");
  EXPECT_EQ(out.min, 0);
  EXPECT_EQ(out.max, 2);
  EXPECT_EQ(out.defuzzifier.kind, Defuzzifier::Kind::discrete);
  EXPECT_EQ(out.defuzzifier.resolution, 200);
  EXPECT_TRUE(std::isnan(out.default_value));
  ASSERT_EQ(out.terms.size(), 3u);
  expect_term(out.terms[0], "LOW", kTri, 0, 0.5, 0.5, 1);
  expect_term(out.terms[2], "HIGH", kTri, 1, 1.5, 1.5, 2);
  EXPECT_EQ(e.rule_block.name, "");
  EXPECT_EQ(e.rule_block.conjunction, TNorm::minimum);  // `none`: no rule uses `and`
  EXPECT_EQ(e.rule_block.implication, Implication::minimum);
  ASSERT_EQ(e.rule_block.rules.size(), 3u);
  // if Ambient is DARK then Power is HIGH; ... MEDIUM -> MEDIUM; BRIGHT -> LOW
  const std::size_t expected[3][2] = {{0, 2}, {1, 1}, {2, 0}};
  for (std::size_t r = 0; r < 3; ++r) {
    const Rule& rule = e.rule_block.rules[r];
    ASSERT_EQ(rule.antecedents.size(), 1u);
    ASSERT_EQ(rule.consequents.size(), 1u);
    EXPECT_EQ(rule.antecedents[0].variable, 0u);
    EXPECT_EQ(rule.antecedents[0].term, expected[r][0]);
    EXPECT_EQ(rule.consequents[0].variable, 0u);
    EXPECT_EQ(rule.consequents[0].term, expected[r][1]);
    EXPECT_EQ(rule.weight, 1);
  }
}

TEST(Fll, LineFollowerFields) {
  const Engine e = read_fll_file(fixture("line_follower.fll").string());
  EXPECT_EQ(e.name, "LineFollower");
  EXPECT_EQ(e.description, "two reflectance sensors, two wheel speeds");
  ASSERT_EQ(e.inputs.size(), 2u);
  ASSERT_EQ(e.outputs.size(), 2u);
  EXPECT_EQ(e.inputs[0].description, "left sensor reading");
  EXPECT_EQ(e.inputs[1].name, "right");
  EXPECT_EQ(e.inputs[1].min, -1.5);
  EXPECT_EQ(e.inputs[1].max, 1.5);
  expect_term(e.inputs[0].terms[0], "DARK", kTrap, -1.5, -1.5, -0.5, 0);  // comment after the term
  expect_term(e.inputs[0].terms[1], "GREY", kTri, -0.5, 0, 0, 0.5);
  expect_term(e.inputs[0].terms[2], "LIGHT", kTrap, 0, 0.5, 1.5, 1.5);
  EXPECT_EQ(e.outputs[0].name, "speed_left");
  EXPECT_EQ(e.outputs[0].max, 255);
  EXPECT_EQ(e.outputs[0].defuzzifier.resolution, 100);  // `Centroid` alone
  EXPECT_EQ(e.outputs[0].default_value, 127.5);
  EXPECT_EQ(e.outputs[1].defuzzifier.resolution, 1000);
  EXPECT_TRUE(std::isnan(e.outputs[1].default_value));
  expect_term(e.outputs[1].terms[1], "MID", kTri, 63.75, 127.5, 127.5, 191.25);
  expect_term(e.outputs[1].terms[2], "FAST", kTrap, 127.5, 255, 255, 255);
  EXPECT_EQ(e.rule_block.name, "follow");
  EXPECT_EQ(e.rule_block.conjunction, TNorm::hamacher);
  EXPECT_EQ(e.rule_block.implication, Implication::product);
  ASSERT_EQ(e.rule_block.rules.size(), 5u);
  const Rule& first = e.rule_block.rules[0];  // left DARK and right LIGHT -> left SLOW and right FAST
  ASSERT_EQ(first.antecedents.size(), 2u);
  ASSERT_EQ(first.consequents.size(), 2u);
  EXPECT_EQ(first.antecedents[1].variable, 1u);
  EXPECT_EQ(first.antecedents[1].term, 2u);
  EXPECT_EQ(first.consequents[1].variable, 1u);
  EXPECT_EQ(first.consequents[1].term, 2u);
  EXPECT_EQ(e.rule_block.rules[3].weight, 0.5);
  const Rule& last = e.rule_block.rules[4];  // left LIGHT -> right MID with 0.25
  ASSERT_EQ(last.antecedents.size(), 1u);
  EXPECT_EQ(last.consequents[0].variable, 1u);
  EXPECT_EQ(last.consequents[0].term, 1u);
  EXPECT_EQ(last.weight, 0.25);
}

TEST(Fll, OldStyleKeys) {
  const Engine e = read_fll_file(fixture("fuzzylite5_style.fll").string());
  EXPECT_EQ(e.rule_block.implication, Implication::product);  // `activation: AlgebraicProduct`
  EXPECT_EQ(e.outputs[0].default_value, 0);
  expect_term(e.inputs[0].terms[0], "cold", kTrap, 0, 0, 10, 20);  // trailing height 1.000
  expect_term(e.inputs[0].terms[1], "warm", kTri, 10, 20, 20, 30);
}

TEST(Fll, Extensions) {
  const Engine e = read_fll_file(fixture("trigonometric.fll").string());
  EXPECT_EQ(e.rule_block.conjunction, TNorm::trigonometric);
  EXPECT_EQ(e.outputs[0].defuzzifier.kind, Defuzzifier::Kind::exact);
  EXPECT_EQ(e.outputs[0].default_value, 0);
  EXPECT_NE(write_fll(e).find("conjunction: Trigonometric\n"), std::string::npos);
  EXPECT_NE(write_fll(e).find("defuzzifier: ExactCentroid\n"), std::string::npos);
}

TEST(Fll, RoundTripAndFixpoint) {
  for (const std::string& name : kFixtures) {
    const Engine e = read_fll_file(fixture(name).string());
    const std::string text = write_fll(e);
    const Engine again = read_fll(text, "written");
    EXPECT_EQ(engine_difference(e, again), "") << name;
    EXPECT_EQ(write_fll(again), text) << name;
  }
}

TEST(Fll, WriterLayout) {
  const std::string text = write_fll(read_fll_file(fixture("simple_dimmer.fll").string()));
  EXPECT_EQ(text.rfind("Engine: SimpleDimmer\nInputVariable: Ambient\n  enabled: true\n  range: 0 1\n"
                       "  lock-range: false\n  term: DARK Triangle 0 0.25 0.5\n",
                       0),
            0u);
  EXPECT_NE(text.find("  aggregation: Maximum\n  defuzzifier: Centroid 200\n  default: nan\n  lock-previous: false\n"),
            std::string::npos);
  EXPECT_NE(text.find("RuleBlock:\n  enabled: true\n  conjunction: Minimum\n  disjunction: none\n"
                      "  implication: Minimum\n  activation: General\n  rule: if Ambient is DARK then Power is HIGH\n"),
            std::string::npos);
}

TEST(Fll, ShortestRoundTripNumbers) {
  Engine e = read_fll_file(fixture("simple_dimmer.fll").string());
  e.inputs[0].min = -0.1;
  e.inputs[0].max = 1e300;
  e.inputs[0].terms[0] = Term::trapezoid("DARK", 0.1 + 0.2, 1.0 / 3, 2.0 / 3, 0.7);
  e.outputs[0].default_value = 1.0 / 7;
  e.rule_block.rules[1].weight = 0.1;
  const std::string text = write_fll(e);
  EXPECT_NE(text.find("range: -0.1 1e+300\n"), std::string::npos) << text;
  EXPECT_NE(text.find("term: DARK Trapezoid 0.30000000000000004 0.3333333333333333 0.6666666666666666 0.7\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find(" with 0.1\n"), std::string::npos);
  EXPECT_EQ(engine_difference(e, read_fll(text, "t")), "");
}

TEST(Fll, CrlfCommentsAndBlankLines) {
  const std::string lf = slurp(fixture("line_follower.fll"));
  std::string crlf;
  for (char c : lf) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  EXPECT_EQ(engine_difference(read_fll(lf, "lf"), read_fll(crlf, "crlf")), "");
  const std::string commented =
      "# header\n\n  Engine: E # name\n#x\nInputVariable: a\n range: 0 1 # r\n"
      "term: T Triangle 0 0.5 1#t\nOutputVariable: z\nrange: 0 1\naggregation: Maximum\ndefuzzifier: Centroid\nterm: U "
      "Triangle 0 0.5 1\n"
      "\t\nRuleBlock:\nimplication: Minimum\nrule: if a is T then z is U   # the only rule";
  const Engine e = read_fll(commented, "c");
  EXPECT_EQ(e.name, "E");
  EXPECT_EQ(e.inputs[0].max, 1);
  EXPECT_EQ(e.rule_block.rules.size(), 1u);
  EXPECT_EQ(e.outputs[0].defuzzifier.resolution, 100);
}

/// The smallest valid controller; the cases below change one line of it.
const std::vector<std::string> kBase{
    "Engine: E",                          // 1
    "InputVariable: a",                   // 2
    "  range: 0 1",                       // 3
    "  term: LOW Triangle 0 0 1",         // 4
    "  term: HIGH Trapezoid 0 1 1 1",     // 5
    "OutputVariable: z",                  // 6
    "  range: 0 10",                      // 7
    "  aggregation: Maximum",             // 8
    "  defuzzifier: Centroid 100",        // 9
    "  term: OFF Triangle 0 0 10",        // 10
    "RuleBlock: rb",                      // 11
    "  conjunction: Minimum",             // 12
    "  implication: Minimum",             // 13
    "  rule: if a is LOW then z is OFF",  // 14
};

std::string with_line(std::size_t line, const std::string& replacement) {
  std::string text;
  for (std::size_t i = 0; i < kBase.size(); ++i) text += (i + 1 == line ? replacement : kBase[i]) + "\n";
  return text;
}

struct BadCase {
  std::size_t line;
  std::string replacement;
  std::size_t error_line;
  std::string message;
};

TEST(Fll, BaseIsValid) { EXPECT_NO_THROW(read_fll(with_line(0, ""), "base")); }

TEST(Fll, ErrorsNameTheLine) {
  const std::vector<BadCase> cases{
      {8, "", 6, "output variable 'z' has no aggregation"},
      {9, "", 6, "output variable 'z' has no defuzzifier"},
      {14, "  rule: if a is DRK then z is OFF", 14, "unknown term 'DRK' of variable 'a'"},
      {14, "  rule: if b is LOW then z is OFF", 14, "unknown input variable 'b'"},
      {14, "  rule: if a is LOW then y is OFF", 14, "unknown output variable 'y'"},
      {14, "  rule: if z is OFF then z is OFF", 14, "'z' is an output variable and cannot be in a rule's if part"},
      {14, "  rule: if a is LOW or a is HIGH then z is OFF", 14, "'or' is not supported"},
      {14, "  rule: if a is very LOW then z is OFF", 14, "hedge 'very' is not supported"},
      {14, "  rule: if a is not LOW then z is OFF", 14, "hedge 'not' is not supported"},
      {14, "  rule: if a is any then z is OFF", 14, "hedge 'any' is not supported"},
      {14, "  rule: if (a is LOW) then z is OFF", 14, "parentheses are not supported"},
      {14, "  rule: if a is LOW", 14, "a rule without 'then'"},
      {14, "  rule: a is LOW then z is OFF", 14, "a rule starts with 'if', found 'a'"},
      {14, "  rule: if a is LOW then z is OFF with 2", 14, "the rule weight must be in [0, 1]"},
      {14, "  rule: if a is LOW then z is OFF with 0.5 0.5", 14, "expected one number after 'with'"},
      {14, "  rule:", 14, "empty rule"},
      {14, "  rule: if a LOW then z is OFF", 14, "expected 'is' after 'a', found 'LOW'"},
      {12, "  conjunction: none\n  rule: if a is LOW and a is HIGH then z is OFF", 13,
       "the rule uses 'and' but the conjunction is none"},
      {12, "  rule: if a is LOW and a is HIGH then z is OFF", 12,  // no conjunction line means none
       "the rule uses 'and' but the conjunction is none"},
      {13, "", 11, "the RuleBlock has no implication"},
      {13, "  implication: none", 13, "implication 'none' is not supported"},
      {12, "  conjunction: EinsteinProduct", 12, "conjunction 'EinsteinProduct' is not supported"},
      {12, "  disjunction: Foo", 12, "unknown disjunction 'Foo'"},
      {12, "  implication: DrasticProduct", 12, "implication 'DrasticProduct' is not supported"},
      {12, "  activation: Highest", 12, "activation 'Highest' is not supported (only General)"},
      {12, "  enabled: false", 12, "'enabled: false' is not supported"},
      {12, "  enabled: yes", 12, "expected true or false, found 'yes'"},
      {11, "RuleBlock: rb\nRuleBlock: again", 12, "only one RuleBlock is supported"},
      {9, "  defuzzifier: Bisector", 9, "defuzzifier 'Bisector' is not supported (only Centroid)"},
      {9, "  defuzzifier: Centroid 0", 9, "resolution must be a whole number of at least 1"},
      {9, "  defuzzifier: Centroid 2.5", 9, "resolution must be a whole number of at least 1"},
      {9, "  aggregation: AlgebraicSum", 9, "aggregation 'AlgebraicSum' is not supported (only Maximum)"},
      {9, "  lock-previous: true", 9, "'lock-previous: true' is not supported"},
      {9, "  lock-valid: true", 9, "'lock-valid: true' is not supported"},
      {9, "  default: inf", 9, "default 'inf' is neither a finite decimal number nor nan"},
      {9, "  default: 1x", 9, "default '1x' is neither a finite decimal number nor nan"},
      {3, "  lock-range: true", 3, "'lock-range: true' is not supported"},
      {3, "  lock-range: false", 2, "variable 'a' has no range"},
      {3, "  range: 0 nan", 3, "range: 'nan' is not a finite decimal number"},
      {3, "  range: 0 1e999", 3, "range: '1e999' is not a finite decimal number"},
      {3, "  range: 0 0x10", 3, "range: '0x10' is not a finite decimal number"},
      {3, "  range: 1 0", 3, "range needs MIN < MAX"},
      {3, "  range: 0 1 2", 3, "expected 'range: MIN MAX'"},
      {3, "  aggregation: Maximum", 3, "key 'aggregation' does not belong in InputVariable"},
      {3, "  colour: red", 3, "unknown key 'colour'"},
      {3, "  just words", 3, "expected 'key: value', found 'just words'"},
      {4, "  term: LOW Gaussian 0 1", 4, "term shape 'Gaussian' is not supported (only Triangle and Trapezoid)"},
      {4, "  term: LOW Triangle 0 0 1 0.5", 4, "term 'LOW': only height 1 is supported"},
      {4, "  term: LOW Triangle 0 1", 4, "a Triangle needs 3 vertices and an optional height"},
      {4, "  term: LOW Triangle 0 1 0.5", 4, "term 'LOW' needs its vertices in order"},
      {4, "  term: LOW Triangle 0 0 1.5.2", 4, "term vertex: '1.5.2' is not a finite decimal number"},
      {4, "  term: LOW Triangle 0 0 nan", 4, "term vertex: 'nan' is not a finite decimal number"},
      {4, "  term: very Triangle 0 0 1", 4, "'very' is a rule word and cannot be a name"},
      {4, "  term: a-b Triangle 0 0 1", 4, "invalid name 'a-b' (use letters, digits, '_' and '.')"},
      {5, "  term: LOW Trapezoid 0 1 1 1", 5, "term 'LOW' of variable 'a' defined twice"},
      {6, "InputVariable: a", 6, "variable 'a' defined twice"},
      {6, "OutputVariable:", 6, "a variable without a name"},
      {10, "", 6, "variable 'z' has no terms"},
      {1, "InputVariable: x", 1, "expected 'Engine: NAME' first, found 'InputVariable'"},
      {2, "Engine: F", 2, "a second 'Engine:' line"},
      {2, "InputVariable: a\0b"s, 2, "NUL byte in the text"},
      {2, "InputVariable: a\rb", 2, "carriage return inside a line"},
  };
  for (const BadCase& c : cases) {
    std::string text = with_line(c.line, c.replacement);
    try {
      read_fll(text, "bad.fll");
      ADD_FAILURE() << "accepted: " << c.replacement;
    } catch (const tk::Error& e) {
      EXPECT_EQ(e.where().file, "bad.fll");
      EXPECT_EQ(e.where().line, c.error_line) << c.replacement << ": " << e.what();
      EXPECT_EQ(std::string(e.what()).substr(0, c.message.size()), c.message) << c.replacement;
    }
  }
}

TEST(Fll, EmptyGarbageAndValidation) {
  for (const std::string& text : {std::string(), std::string("\n\n# only a comment\n"), std::string("\r\n")}) {
    try {
      read_fll(text, "empty.fll");
      ADD_FAILURE() << "accepted empty input";
    } catch (const tk::Error& e) {
      EXPECT_EQ(e.where().line, 0u);
      EXPECT_EQ(std::string(e.what()), "no 'Engine:' line (empty input)");
    }
  }
  EXPECT_THROW(read_fll(std::string("\x7f"
                                    "ELF\x02\x01\x01\0\0\0:\xff\xfe",
                                    14),
                        "bin"),
               tk::Error);
  // No RuleBlock: validate()'s complaint, with the file name and no line.
  std::string no_rules;
  for (std::size_t i = 0; i < 10; ++i) no_rules += kBase[i] + "\n";
  try {
    read_fll(no_rules, "norules.fll");
    ADD_FAILURE() << "accepted a controller without rules";
  } catch (const tk::Error& e) {
    EXPECT_EQ(e.where().file, "norules.fll");
    EXPECT_EQ(e.where().line, 0u);
    EXPECT_EQ(std::string(e.what()), "the controller has no rules");
  }
}

// fuzzylite's own examples (Debian package fuzzylite): the Mamdani ones in
// our subset read, every other one is refused at a line.
TEST(Fll, FuzzyliteExamplesReadOrFailAtALine) {
  const std::filesystem::path folder = "/usr/share/doc/fuzzylite/examples";
  std::error_code error;
  std::size_t read = 0, refused = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(folder, error)) {
    if (entry.path().extension() != ".fll") continue;
    try {
      read_fll_file(entry.path().string());
      ++read;
    } catch (const tk::Error& e) {
      EXPECT_GT(e.where().line, 0u) << entry.path() << ": " << e.what();
      ++refused;
    }
  }
  if (read + refused == 0) GTEST_SKIP() << "fuzzylite's examples are not installed";
  EXPECT_GE(read, 1u);  // SimpleDimmer.fll
}

TEST(Fll, MissingFileIsAnError) {
  try {
    read_fll_file("/nonexistent/controller.fll");
    ADD_FAILURE();
  } catch (const tk::Error& e) {
    EXPECT_EQ(e.where().file, "/nonexistent/controller.fll");
  }
}

TEST(Fll, WriterRefusesWhatFllCannotSay) {
  const Engine base = read_fll(with_line(0, ""), "base");
  Engine e = base;
  e.inputs[0].name = "two words";
  EXPECT_THROW(write_fll(e), tk::Error);
  e = base;
  e.description = "has # a hash";
  EXPECT_THROW(write_fll(e), tk::Error);
  e = base;
  e.outputs[0].terms[0].name = "and";
  EXPECT_THROW(write_fll(e), tk::Error);
  e = base;
  e.rule_block.rules.clear();
  EXPECT_THROW(write_fll(e), tk::Error);  // validate()
  // A triangle with b != c has no Triangle form: written as a Trapezoid.
  e = base;
  e.inputs[0].terms[0].points = Trapezoid{0, 0.2, 0.4, 1};
  const Engine back = read_fll(write_fll(e), "t");
  expect_term(back.inputs[0].terms[0], "LOW", kTrap, 0, 0.2, 0.4, 1);
}

TEST(Fll, EngineDifferenceSeesEachField) {
  const Engine base = read_fll_file(fixture("line_follower.fll").string());
  EXPECT_EQ(engine_difference(base, base), "");
  Engine e = base;
  e.outputs[1].defuzzifier.resolution = 999;
  EXPECT_NE(engine_difference(base, e), "");
  e = base;
  e.rule_block.rules[2].consequents[1].term = 0;
  EXPECT_NE(engine_difference(base, e), "");
  e = base;
  e.outputs[0].default_value = std::nan("");
  EXPECT_NE(engine_difference(base, e), "");
  e = base;
  e.inputs[1].terms[1].shape = kTrap;
  EXPECT_NE(engine_difference(base, e), "");
}

}  // namespace
