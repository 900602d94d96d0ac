/// @file bench_tnorm.cpp
/// @brief The paper's line-follower controller in our Mamdani engine against
/// the same controller built in fuzzylite 6.0 (Debian libfuzzylite-dev), per
/// t-norm, on the same 1024 sensor triples: the outputs must agree within
/// 1e-9 at the same resolution, and the times give ns per inference (one
/// motor's value for one triple: the paper's protocol is 2 x 1024 of them).
/// fuzzylite has no trigonometric t-norm; the benchmark supplies one.
#include <fl/Headers.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "bench_common.hpp"
#include "fuzzy/line_follower.hpp"
#include "fuzzy/mamdani.hpp"

namespace {

using tk::fuzzy::TNorm;

/// 2/pi asin(sin(pi/2 a) sin(pi/2 b)); folded over three inputs it equals
/// the paper's three-input form.
class Trigonometric : public fl::TNorm {
 public:
  std::string className() const override { return "Trigonometric"; }
  fl::Complexity complexity() const override { return fl::Complexity().function(4); }
  fl::scalar compute(fl::scalar a, fl::scalar b) const override {
    return 2 / std::numbers::pi * std::asin(std::sin(std::numbers::pi / 2 * a) * std::sin(std::numbers::pi / 2 * b));
  }
  fl::TNorm* clone() const override { return new Trigonometric(*this); }
};

fl::TNorm* fuzzylite_tnorm(TNorm t) {
  switch (t) {
    case TNorm::minimum: return new fl::Minimum;
    case TNorm::product: return new fl::AlgebraicProduct;
    case TNorm::drastic: return new fl::DrasticProduct;
    case TNorm::lukasiewicz: return new fl::BoundedDifference;
    case TNorm::trigonometric: return new Trigonometric;
    case TNorm::hamacher: return new fl::HamacherProduct;
  }
  return nullptr;
}

/// Our Engine, rebuilt term by term and rule by rule in fuzzylite.
fl::Engine* fuzzylite_engine(const tk::fuzzy::Engine& ours, int resolution) {
  auto* engine = new fl::Engine(ours.name);
  for (const auto& v : ours.inputs) {
    auto* in = new fl::InputVariable(v.name, v.min, v.max);
    for (const auto& t : v.terms)
      in->addTerm(new fl::Trapezoid(t.name, t.points.a, t.points.b, t.points.c, t.points.d));
    engine->addInputVariable(in);
  }
  for (const auto& v : ours.outputs) {
    auto* out = new fl::OutputVariable(v.name, v.min, v.max);
    for (const auto& t : v.terms)
      out->addTerm(new fl::Trapezoid(t.name, t.points.a, t.points.b, t.points.c, t.points.d));
    out->setAggregation(new fl::Maximum);
    out->setDefuzzifier(new fl::Centroid(resolution));
    out->setDefaultValue(v.default_value);
    engine->addOutputVariable(out);
  }
  auto* block = new fl::RuleBlock(ours.rule_block.name);
  block->setConjunction(fuzzylite_tnorm(ours.rule_block.conjunction));
  block->setImplication(new fl::Minimum);
  block->setActivation(new fl::General);
  for (const auto& rule : ours.rule_block.rules) {
    std::string text = "if ";
    for (std::size_t i = 0; i < rule.antecedents.size(); ++i) {
      const auto& p = rule.antecedents[i];
      text += (i ? " and " : "") + ours.inputs[p.variable].name + " is " + ours.inputs[p.variable].terms[p.term].name;
    }
    const auto& c = rule.consequents[0];
    text += " then " + ours.outputs[c.variable].name + " is " + ours.outputs[c.variable].terms[c.term].name;
    block->addRule(fl::Rule::parse(text, engine));
  }
  engine->addRuleBlock(block);
  std::string status;
  if (!engine->isReady(&status)) bench::fail("fuzzylite engine not ready: " + status);
  return engine;
}

}  // namespace

int main() {
  // fuzzylite compares with a tolerance of 1e-6 (rules below it do not fire,
  // terms' edges blur by it); 0 makes its arithmetic the plain one ours is.
  fl::fuzzylite::setMachEps(0);
  const int repeats = bench::repeats({"BENCH_TNORM_REPEATS", "BENCH_REPEATS"}, 5);
  const int resolution = 100;
  std::mt19937_64 rng(2020);
  std::uniform_int_distribution<int> reading(0, 1023);
  std::vector<std::array<double, 3>> triples(1024);
  for (auto& t : triples) t = {double(reading(rng)), double(reading(rng)), double(reading(rng))};
  const int rounds = 200;  // 200 x 2 x 1024 inferences a timing

  std::printf("bench_tnorm: line follower, 1024 random 10-bit triples x 2 motors, resolution %d, %d repeats\n",
              resolution, repeats);
  std::printf("%-14s %12s %12s %12s %10s %10s %12s\n", "tnorm", "ours ns", "exact ns", "fuzzylite ns", "ratio",
              "exact/fl", "max |diff|");
  std::vector<double> worst_ratio, worst_exact_ratio, ours_2048, exact_2048, peer_2048;
  for (TNorm t :
       {TNorm::minimum, TNorm::product, TNorm::drastic, TNorm::lukasiewicz, TNorm::trigonometric, TNorm::hamacher}) {
    tk::fuzzy::LineFollowerOptions options;
    options.conjunction = t;
    options.defuzzifier.resolution = resolution;
    const tk::fuzzy::Engine engine = tk::fuzzy::line_follower_engine(options);
    tk::fuzzy::Mamdani ours(engine), exact(engine);
    exact.set_defuzzifier({tk::fuzzy::Defuzzifier::Kind::exact, resolution});
    std::unique_ptr<fl::Engine> peer(fuzzylite_engine(engine, resolution));
    fl::InputVariable* in[3] = {peer->getInputVariable(0), peer->getInputVariable(1), peer->getInputVariable(2)};
    fl::OutputVariable* out[2] = {peer->getOutputVariable(0), peer->getOutputVariable(1)};

    // Agreement first, on every triple.
    double max_diff = 0;
    for (const auto& triple : triples) {
      double mine[2];
      ours.evaluate(triple, mine);
      for (int i = 0; i < 3; ++i) in[i]->setValue(triple[i]);
      peer->process();
      for (int m = 0; m < 2; ++m) {
        const double theirs = out[m]->getValue();
        const double diff = std::abs(mine[m] - theirs);
        if (!(diff <= 1e-9))
          bench::fail(std::string(tk::fuzzy::tnorm_name(t)) + ": outputs differ at (" + std::to_string(triple[0]) +
                      ", " + std::to_string(triple[1]) + ", " + std::to_string(triple[2]) + "): ours " +
                      std::to_string(mine[m]) + ", fuzzylite " + std::to_string(theirs));
        max_diff = std::max(max_diff, diff);
      }
    }

    double sink = 0;
    auto run_ours = [&](tk::fuzzy::Mamdani& m) {
      return [&] {
        double o[2];
        for (int r = 0; r < rounds; ++r)
          for (const auto& triple : triples) {
            m.evaluate(triple, o);
            sink += o[0] + o[1];
          }
      };
    };
    auto run_peer = [&] {
      for (int r = 0; r < rounds / 10; ++r)  // fuzzylite is slower: fewer rounds, scaled below
        for (const auto& triple : triples) {
          for (int i = 0; i < 3; ++i) in[i]->setValue(triple[i]);
          peer->process();
          sink += out[0]->getValue() + out[1]->getValue();
        }
    };
    std::vector<double> ours_ns, exact_ns, peer_ns, ratio, exact_ratio;
    const double inferences = 2.0 * triples.size() * rounds;
    for (int k = 0; k < repeats; ++k) {
      auto [a, p] = bench::time_interleaved(run_ours(ours), run_peer);
      const double e = bench::time_cpu(run_ours(exact));
      ours_ns.push_back(a / inferences * 1e9);
      exact_ns.push_back(e / inferences * 1e9);
      peer_ns.push_back(p * 10 / inferences * 1e9);
      ratio.push_back(peer_ns.back() / ours_ns.back());
      exact_ratio.push_back(peer_ns.back() / exact_ns.back());
    }
    if (sink == 12345.678) std::printf(" ");  // keeps the work
    std::printf("%-14s %12.1f %12.1f %12.1f %10.1f %10.1f %12.2e\n", std::string(tk::fuzzy::tnorm_name(t)).c_str(),
                bench::median(ours_ns), bench::median(exact_ns), bench::median(peer_ns), bench::median(ratio),
                bench::median(exact_ratio), max_diff);
    std::printf("FIGURE tnorm_%s_ns_per_inference %.1f ns (exact %.1f, fuzzylite %.1f; ratio %.1f, exact %.1f)\n",
                std::string(tk::fuzzy::tnorm_name(t)).c_str(), bench::median(ours_ns), bench::median(exact_ns),
                bench::median(peer_ns), bench::median(ratio), bench::median(exact_ratio));
    ours_2048.push_back(bench::median(ours_ns) * 2048e-9);
    exact_2048.push_back(bench::median(exact_ns) * 2048e-9);
    peer_2048.push_back(bench::median(peer_ns) * 2048e-9);
    worst_ratio.push_back(bench::median(ratio));
    worst_exact_ratio.push_back(bench::median(exact_ratio));
  }
  // run.sh's RESULT lines: the t-norm with the smallest ratio, its seconds
  // per 2 x 1024 inferences (the paper's protocol) for ours and fuzzylite.
  const std::size_t w = std::min_element(worst_ratio.begin(), worst_ratio.end()) - worst_ratio.begin();
  const std::size_t we =
      std::min_element(worst_exact_ratio.begin(), worst_exact_ratio.end()) - worst_exact_ratio.begin();
  std::printf("RESULT tnorm_discrete %.6f %.6f %.4f 20 %d\n", ours_2048[w], peer_2048[w], worst_ratio[w], repeats);
  std::printf("RESULT tnorm_exact %.6f %.6f %.4f 20 %d\n", exact_2048[we], peer_2048[we], worst_exact_ratio[we],
              repeats);
  return 0;
}
