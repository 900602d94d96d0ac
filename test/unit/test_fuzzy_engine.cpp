/// @file test_fuzzy_engine.cpp
/// @brief Mamdani inference and both centroids against hand-computed values,
/// closed forms, a naive re-evaluation written here from the definitions,
/// and dense numerical integration.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "fuzzy/centroid.hpp"
#include "fuzzy/line_follower.hpp"
#include "fuzzy/mamdani.hpp"
#include "io/error.hpp"
#include "test_volume.hpp"

namespace tk::fuzzy {
namespace {

/// Centroid of a full-height trapezoid (a, b, c, d) as a polygon (closed form).
double trapezoid_centroid(double a, double b, double c, double d) {
  return (c * c + c * d + d * d - a * a - a * b - b * b) / (3 * (c + d - a - b));
}

/// Membership straight from the definition, independent of Trapezoid.
double mu_def(double a, double b, double c, double d, double x) {
  if (x < a || x > d) return 0;
  if (x < b) return (x - a) / (b - a);
  if (x <= c) return 1;
  if (x < d) return (d - x) / (d - c);
  return c == d ? 1 : 0;
}

Engine one_input_engine() {
  Engine e;
  e.name = "hand";
  Variable x;
  x.name = "x";
  x.min = 0;
  x.max = 2;
  x.terms = {Term::triangle("A", 0, 1, 2), Term::trapezoid("B", 1, 2, 2, 2)};
  e.inputs.push_back(x);
  OutputVariable y;
  y.name = "y";
  y.min = 0;
  y.max = 10;
  y.terms = {Term::trapezoid("LOW", 0, 0, 2, 4), Term::triangle("HIGH", 4, 7, 10)};
  e.outputs.push_back(y);
  e.rule_block.rules = {Rule{{{0, 0}}, {{0, 1}}, 1}, Rule{{{0, 1}}, {{0, 0}}, 1}};
  return e;
}

TEST(FuzzyCentroid, SymmetricClippedTriangleCentresOnItsApex) {
  const ImpliedTerm t{Trapezoid{4, 7, 7, 10}, 0.5};
  for (Implication imp : {Implication::minimum, Implication::product}) {
    EXPECT_NEAR(exact_centroid({&t, 1}, imp, 0, 10).centroid, 7.0, 1e-12);
    EXPECT_NEAR(discrete_centroid({&t, 1}, imp, 0, 10, 100).centroid, 7.0, 1e-12);
  }
  // Area by hand: clipped at 0.5 the triangle is a trapezoid of bases 6 and 3.
  EXPECT_NEAR(exact_centroid({&t, 1}, Implication::minimum, 0, 10).area, 0.5 * (6 + 3) / 2, 1e-12);
  EXPECT_NEAR(exact_centroid({&t, 1}, Implication::product, 0, 10).area, 0.5 * 6 / 2, 1e-12);
}

TEST(FuzzyCentroid, TwoTermsByHand) {
  // LOW (0,0,2,4) at 1: area 3, centroid 14/9; HIGH (4,7,7,10) clipped at
  // 0.5: area 2.25, centroid 7; together (3 * 14/9 + 2.25 * 7) / 5.25 = 35/9.
  const ImpliedTerm terms[] = {{Trapezoid{0, 0, 2, 4}, 1}, {Trapezoid{4, 7, 7, 10}, 0.5}};
  const CentroidResult r = exact_centroid(terms, Implication::minimum, 0, 10);
  EXPECT_NEAR(r.centroid, 35.0 / 9, 1e-12);
  EXPECT_NEAR(r.area, 5.25, 1e-12);
}

TEST(FuzzyCentroid, DiscreteIsFuzzyliteMidpointRule) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<ImpliedTerm> terms;
    for (int k = 0, n = 1 + trial % 4; k < n; ++k) {
      double v[4];
      for (double& x : v) x = -50 + 100 * u(rng);
      std::sort(v, v + 4);
      if (trial % 5 == 0) v[1] = v[0];  // vertical edges too
      terms.push_back({Trapezoid{v[0], v[1], v[2], v[3]}, 0.05 + 0.95 * u(rng)});
    }
    const Implication imp = trial % 2 ? Implication::minimum : Implication::product;
    const int resolution = 1 + trial % 250;
    // fuzzylite's Centroid::defuzzify, written out.
    const double min = -40, max = 45, dx = (max - min) / resolution;
    double area = 0, xc = 0;
    for (int i = 0; i < resolution; ++i) {
      const double x = min + (i + 0.5) * dx;
      double y = 0;
      for (const ImpliedTerm& t : terms) {
        const double mu = mu_def(t.shape.a, t.shape.b, t.shape.c, t.shape.d, x);
        y = std::max(y, imp == Implication::minimum ? std::min(mu, t.level) : mu * t.level);
      }
      xc += y * x;
      area += y;
    }
    const CentroidResult r = discrete_centroid(terms, imp, min, max, resolution);
    if (area == 0) {
      EXPECT_TRUE(std::isnan(r.centroid));
    } else {
      EXPECT_NEAR(r.centroid, xc / area, 1e-12 * (1 + std::abs(xc / area))) << "trial " << trial;
      EXPECT_NEAR(r.area, area * dx, 1e-9 * area * dx);
    }
  }
}

TEST(FuzzyCentroid, ExactAgreesWithDenseIntegration) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0, 1);
  for (int trial = 0, trials = test_volume(200, 30); trial < trials; ++trial) {
    std::vector<ImpliedTerm> terms;
    for (int k = 0, n = 1 + trial % 5; k < n; ++k) {
      double v[4];
      for (double& x : v) x = 100 * u(rng);
      std::sort(v, v + 4);
      terms.push_back({Trapezoid{v[0], v[1], v[2], v[3]}, 0.05 + 0.95 * u(rng)});
    }
    const Implication imp = trial % 2 ? Implication::minimum : Implication::product;
    const double min = 10, max = 90;
    // Composite Simpson on a fine grid, from the definitions: O(h^2) at kinks.
    const int n = 100000;
    const double h = (max - min) / n;
    double area = 0, moment = 0;
    for (int i = 0; i <= n; ++i) {
      const double x = min + i * h;
      double y = 0;
      for (const ImpliedTerm& t : terms) {
        const double mu = mu_def(t.shape.a, t.shape.b, t.shape.c, t.shape.d, x);
        y = std::max(y, imp == Implication::minimum ? std::min(mu, t.level) : mu * t.level);
      }
      const double w = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
      area += w * y;
      moment += w * x * y;
    }
    area *= h / 3;
    moment *= h / 3;
    const CentroidResult r = exact_centroid(terms, imp, min, max);
    if (area < 1e-9) continue;
    EXPECT_NEAR(r.area, area, 1e-6 * (max - min)) << "trial " << trial;
    EXPECT_NEAR(r.centroid, moment / area, 1e-6 * (max - min)) << "trial " << trial;
  }
}

TEST(FuzzyCentroid, ExactWithVerticalEdgesAndEqualTerms) {
  // Pairs (the fast two-term path) and triples with steps and coinciding
  // terms, against a dense midpoint sum (O(h) near a step: looser bound).
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0, 1);
  for (int trial = 0, trials = test_volume(120, 60); trial < trials; ++trial) {
    std::vector<ImpliedTerm> terms;
    for (int k = 0, n = 2 + trial % 2; k < n; ++k) {
      double v[4];
      for (double& x : v) x = 100 * u(rng);
      std::sort(v, v + 4);
      if (trial % 3 == 0) v[1] = v[0];
      if (trial % 4 == 0) v[3] = v[2];
      terms.push_back({Trapezoid{v[0], v[1], v[2], v[3]}, 0.05 + 0.95 * u(rng)});
    }
    if (trial % 5 == 0) terms[1] = terms[0];  // the same term twice
    const Implication imp = trial % 2 ? Implication::minimum : Implication::product;
    const int n = 400000;
    const double min = 0, max = 100, h = (max - min) / n;
    double area = 0, moment = 0;
    for (int i = 0; i < n; ++i) {
      const double x = min + (i + 0.5) * h;
      double y = 0;
      for (const ImpliedTerm& t : terms) {
        const double mu = mu_def(t.shape.a, t.shape.b, t.shape.c, t.shape.d, x);
        y = std::max(y, imp == Implication::minimum ? std::min(mu, t.level) : mu * t.level);
      }
      area += y * h;
      moment += x * y * h;
    }
    if (area < 1e-6) continue;
    const CentroidResult r = exact_centroid(terms, imp, min, max);
    EXPECT_NEAR(r.area, area, 1e-3) << "trial " << trial;
    EXPECT_NEAR(r.centroid, moment / area, 1e-3 * (1 + 1 / area)) << "trial " << trial;
  }
}

TEST(FuzzyCentroid, DiscreteConvergesToExact) {
  const ImpliedTerm terms[] = {
      {Trapezoid{0, 0, 2, 4}, 0.8}, {Trapezoid{3, 6, 6, 9}, 0.6}, {Trapezoid{5, 8, 9, 10}, 0.3}};
  const double exact = exact_centroid(terms, Implication::minimum, 0, 10).centroid;
  double previous_error = 1e9;
  for (int resolution : {10, 100, 1000, 10000}) {
    const double error = std::abs(discrete_centroid(terms, Implication::minimum, 0, 10, resolution).centroid - exact);
    EXPECT_LT(error, previous_error + 1e-15);
    previous_error = error;
  }
  EXPECT_LT(previous_error, 1e-6);
}

TEST(FuzzyMamdani, OneInputByHand) {
  Engine e = one_input_engine();
  for (Defuzzifier::Kind kind : {Defuzzifier::Kind::discrete, Defuzzifier::Kind::exact}) {
    e.outputs[0].defuzzifier.kind = kind;
    Mamdani m(e);
    double y = 0;
    const double x = 0.5;  // A = 0.5, B = 0: only HIGH, clipped at 0.5
    m.evaluate({&x, 1}, {&y, 1});
    EXPECT_NEAR(y, 7.0, 1e-12);
    EXPECT_EQ(m.fired()[0], 1u);
  }
  e.outputs[0].defuzzifier.kind = Defuzzifier::Kind::exact;
  // x = 1.5: A = 0.5 (HIGH at 0.5), B = 0.5 (LOW at 0.5). LOW clipped at 0.5
  // is (0,0,3,4) at height 0.5: area 1.75, moment 0.5 (4.5 + 7/6 * 0.5)...
  // written out: rectangle [0,3] area 1.5 centroid 1.5, triangle [3,4]
  // area 0.25 centroid 10/3; HIGH clipped: area 2.25 centroid 7.
  Mamdani m(e);
  double y = 0;
  const double x = 1.5;
  m.evaluate({&x, 1}, {&y, 1});
  const double expected = (1.5 * 1.5 + 0.25 * 10.0 / 3 + 2.25 * 7) / (1.5 + 0.25 + 2.25);
  EXPECT_NEAR(y, expected, 1e-12);
}

TEST(FuzzyMamdani, NoRuleFiredGivesTheDefault) {
  Engine e = one_input_engine();
  e.inputs[0].terms = {Term::triangle("A", 0, 0.5, 1), Term::triangle("B", 1.5, 2, 2)};
  {
    Mamdani m(e);
    double y = 0;
    const double x = 1.25;  // neither A nor B
    m.evaluate({&x, 1}, {&y, 1});
    EXPECT_TRUE(std::isnan(y));  // the default default, as in fuzzylite
    EXPECT_EQ(m.fired()[0], 0u);
  }
  e.outputs[0].default_value = 5;
  Mamdani m(e);
  double y = 0;
  const double x = 1.25;
  m.evaluate({&x, 1}, {&y, 1});
  EXPECT_EQ(y, 5);
  const double nan_input = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(m.evaluate({&nan_input, 1}, {&y, 1}), Error);
}

TEST(FuzzyMamdani, FastKernelsMatchTheNaiveDefinition) {
  // Random 3-input engines; every t-norm's fast path against rule-by-rule
  // evaluation with tnorm() and the definitions.
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  for (TNorm t :
       {TNorm::minimum, TNorm::product, TNorm::drastic, TNorm::lukasiewicz, TNorm::trigonometric, TNorm::hamacher}) {
    for (int trial = 0; trial < 60; ++trial) {
      Engine e;
      for (const char* name : {"a", "b", "c"}) {
        Variable v;
        v.name = name;
        v.min = 0;
        v.max = 1;
        v.terms = {Term::trapezoid("LO", -1, 0, 0.2 + 0.2 * u(rng), 0.7), Term::trapezoid("HI", 0.3, 0.8, 1, 2)};
        e.inputs.push_back(v);
      }
      OutputVariable out;
      out.name = "y";
      out.min = -10;
      out.max = 10;
      for (int k = 0; k < 4; ++k)
        out.terms.push_back(Term::triangle("T" + std::to_string(k), -10 + 5 * k, -7 + 5 * k, -3 + 5 * k));
      e.outputs.push_back(out);
      e.rule_block.conjunction = t;
      e.rule_block.implication = trial % 2 ? Implication::minimum : Implication::product;
      for (int r = 0; r < 8; ++r)
        e.rule_block.rules.push_back(
            Rule{{{0, std::size_t(r & 1)}, {1, std::size_t(r >> 1 & 1)}, {2, std::size_t(r >> 2 & 1)}},
                 {{0, std::size_t(r % 4)}},
                 1});
      Mamdani m(e);
      const double in[3] = {u(rng), u(rng), trial % 3 ? u(rng) : 0.9};
      double y = 0;
      m.evaluate(in, {&y, 1});
      // Naive: levels per term, then the fuzzylite midpoint sums.
      double level[4] = {0, 0, 0, 0};
      for (const Rule& r : e.rule_block.rules) {
        double mu[3];
        for (int i = 0; i < 3; ++i) {
          const Trapezoid& p = e.inputs[i].terms[r.antecedents[i].term].points;
          mu[i] = mu_def(p.a, p.b, p.c, p.d, in[i]);
        }
        level[r.consequents[0].term] = std::max(level[r.consequents[0].term], tnorm(t, mu));
      }
      std::vector<ImpliedTerm> implied;
      for (int k = 0; k < 4; ++k)
        if (level[k] > 0) implied.push_back({e.outputs[0].terms[k].points, level[k]});
      if (implied.empty()) {
        EXPECT_TRUE(std::isnan(y));
        continue;
      }
      const double expected = discrete_centroid(implied, e.rule_block.implication, -10, 10, 100).centroid;
      EXPECT_NEAR(y, expected, 1e-12) << tnorm_name(t) << " trial " << trial;
    }
  }
}

TEST(FuzzyLineFollower, CentredLineDrivesStraightAtForward) {
  for (Defuzzifier::Kind kind : {Defuzzifier::Kind::discrete, Defuzzifier::Kind::exact}) {
    LineFollowerOptions options;
    options.defuzzifier.kind = kind;
    Mamdani m(line_follower_engine(options));
    const double in[3] = {50, 900, 50};
    double out[2];
    m.evaluate(in, out);
    // Only R4 (L D L) fires, at 1: FORWARD {45, 55, 65, 75} x 2.0, a full trapezoid.
    const double k = 2.0, expected = trapezoid_centroid(45 * k, 55 * k, 65 * k, 75 * k);
    EXPECT_NEAR(out[0], expected, kind == Defuzzifier::Kind::exact ? 1e-12 : 0.5);
    EXPECT_EQ(out[0], out[1]);
  }
}

TEST(FuzzyLineFollower, MirroredAndPivotingTowardTheLine) {
  LineFollowerOptions options;
  options.defuzzifier.kind = Defuzzifier::Kind::exact;
  Mamdani m(line_follower_engine(options));
  const double left_dark[3] = {900, 50, 50}, right_dark[3] = {50, 50, 900};
  double a[2], b[2];
  m.evaluate(left_dark, a);
  m.evaluate(right_dark, b);
  EXPECT_NEAR(a[0], b[1], 1e-12);  // mirror image
  EXPECT_NEAR(a[1], b[0], 1e-12);
  // D L L: R6 sends the left wheel BACKWARD_MAX, the right one (mirrored R2) FORWARD_MAX.
  EXPECT_NEAR(a[0], trapezoid_centroid(-90 * 2.0, -85 * 2.0, -80 * 2.0, -70 * 2.0), 1e-12);
  EXPECT_NEAR(a[1], trapezoid_centroid(60 * 2.0, 75 * 2.0, 80 * 2.0, 85 * 2.0), 1e-12);
  // D D L: R5, BACKWARD; the right wheel (mirrored R3) FORWARD.
  const double left_and_mid[3] = {900, 900, 50};
  m.evaluate(left_and_mid, a);
  EXPECT_NEAR(a[0], trapezoid_centroid(-80 * 2.0, -75 * 2.0, -70 * 2.0, -60 * 2.0), 1e-12);
  EXPECT_NEAR(a[1], trapezoid_centroid(45 * 2.0, 55 * 2.0, 65 * 2.0, 75 * 2.0), 1e-12);
  // All light: R1, STOP (a triangle about 0); all dark: R7, our BACKWARD_SLOWLY.
  const double lost[3] = {20, 20, 20}, all_dark[3] = {1000, 1000, 1000};
  m.evaluate(lost, a);
  EXPECT_NEAR(a[0], 0, 1e-12);
  EXPECT_NEAR(a[1], 0, 1e-12);
  m.evaluate(all_dark, a);
  EXPECT_NEAR(a[0], trapezoid_centroid(-45 * 2.0, -35 * 2.0, -25 * 2.0, -15 * 2.0), 1e-12);
  // D L D has no rule: both motors get the default, 0.
  const double both_sides[3] = {900, 50, 900};
  m.evaluate(both_sides, a);
  EXPECT_EQ(a[0], 0);
  EXPECT_EQ(m.fired()[0], 0u);
}

TEST(FuzzyLineFollower, DrasticFiresNothingWhenTwoSensorsAreUnsure) {
  // Two memberships below 1 in every rule: the drastic t-norm gives 0
  // everywhere and both motors get the default, 0; the minimum still acts,
  // turning toward the line on the right (R1 at 0.95 with R2-R4 at 0.05).
  const double unsure[3] = {30, 130, 130};
  for (TNorm t : {TNorm::drastic, TNorm::minimum}) {
    LineFollowerOptions options;
    options.conjunction = t;
    Mamdani m(line_follower_engine(options));
    double out[2];
    m.evaluate(unsure, out);
    if (t == TNorm::drastic) {
      EXPECT_EQ(out[0], 0);
      EXPECT_EQ(out[1], 0);
      EXPECT_EQ(m.fired()[0], 0u);
    } else {
      EXPECT_GT(out[0], out[1]);
      EXPECT_EQ(m.fired()[0], 4u);
    }
  }
}

TEST(FuzzyLineFollower, TwelveBitTermsAndBadOptions) {
  EXPECT_EQ(light_term(12).d, 3135);
  EXPECT_EQ(dark_term(12).a, 396);
  LineFollowerOptions options;
  options.adc_bits = 11;
  EXPECT_THROW(line_follower_engine(options), Error);
  options.adc_bits = 10;
  options.backward_slowly = {-10, -30, -20, -5};  // out of order
  EXPECT_THROW(line_follower_engine(options), Error);
  options.backward_slowly = {-45, -35, -25, -15};
  options.speed_factor = 0;
  EXPECT_THROW(line_follower_engine(options), Error);
}

}  // namespace
}  // namespace tk::fuzzy
