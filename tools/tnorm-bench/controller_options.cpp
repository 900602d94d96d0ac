/// @file controller_options.cpp
/// @brief The controller options every tnorm-bench mode shares: the
/// t-norms, the paper's controller or an FLL file's, its defuzzifier.
#include <algorithm>
#include <iterator>

#include "cli/number_option.hpp"
#include "cli/option_checks.hpp"
#include "fuzzy/fll.hpp"
#include "fuzzy/line_follower.hpp"
#include "io/error.hpp"
#include "modes.hpp"

namespace tnorm_bench {

using namespace tk;

namespace {

constexpr TNorm kAllTNorms[] = {TNorm::minimum,     TNorm::product,       TNorm::drastic,
                                TNorm::lukasiewicz, TNorm::trigonometric, TNorm::hamacher};

}  // namespace

void ControllerOptions::add_to(CLI::App& sub, bool many_tnorms) {
  auto* t =
      sub.add_option("--tnorm", tnorms,
                     many_tnorms ? "t-norm(s): minimum, product, drastic, lukasiewicz, trigonometric, hamacher, all"
                                 : "the rules' t-norm: minimum, product, drastic, lukasiewicz, trigonometric, hamacher")
          ->type_name("NAME");
  if (!many_tnorms) t->expected(1);
  adc_option = sub.add_option("--adc", adc_bits, "the sensors' ADC: 10 (Arduino Uno) or 12 bits (ESP32)")
                   ->check(CLI::IsMember({10, 12}))
                   ->capture_default_str();
  sub.add_option("--centroid", centroid, "exact, or discrete[:N] (fuzzylite's, N samples, default 100)")
      ->type_name("KIND");
  sub.add_option("--speed-factor", speed_factor,
                 "scales the motor terms (the paper: 1.92 first, 2.0 in its Tables 1-2)")
      ->check(cli::range_check(0.1, 10))
      ->capture_default_str();
  sub.add_option("--backward-slowly", backward_slowly, "BACKWARD_SLOWLY's corners before scaling")
      ->capture_default_str()
      ->type_name("A,B,C,D");
  sub.add_option("--implication", implication, "minimum (clip) or product (scale)")
      ->check(CLI::IsMember({"minimum", "product"}))
      ->capture_default_str();
  sub.add_option("--fll", fll_path, "use this fuzzylite FLL controller instead of the paper's")->type_name("FILE");
  sub.add_option("--fire-threshold", fire_threshold, "rules fire from this activation on (fuzzylite: 1e-6)")
      ->check(cli::range_check(0, 1))
      ->capture_default_str()
      ->type_name("X");
}

std::vector<TNorm> ControllerOptions::chosen_tnorms(bool default_all) const {
  std::vector<TNorm> chosen;
  for (const std::string& name : tnorms) {
    if (name == "all") {
      chosen.assign(std::begin(kAllTNorms), std::end(kAllTNorms));
      continue;
    }
    const auto t = fuzzy::tnorm_from_name(name);
    if (!t) throw UsageError("--tnorm: unknown t-norm '" + name + "'");
    chosen.push_back(*t);
  }
  if (chosen.empty()) {
    if (default_all) return {std::begin(kAllTNorms), std::end(kAllTNorms)};
    if (fll_path.empty()) chosen.push_back(TNorm::minimum);
  }
  return chosen;
}

fuzzy::Defuzzifier ControllerOptions::defuzzifier(const fuzzy::Defuzzifier& fallback) const {
  if (centroid.empty()) return fallback;
  fuzzy::Defuzzifier d;
  if (centroid == "exact") {
    d.kind = fuzzy::Defuzzifier::Kind::exact;
  } else if (centroid.rfind("discrete", 0) == 0) {
    d.kind = fuzzy::Defuzzifier::Kind::discrete;
    if (centroid.size() > 8) {
      if (centroid[8] != ':') throw UsageError("--centroid: use exact, discrete or discrete:N");
      const std::uint64_t n = cli::parse_count(centroid.substr(9), "--centroid");
      if (n < 1 || n > 10'000'000) throw UsageError("--centroid: N must be from 1 to 10000000");
      d.resolution = static_cast<int>(n);
    }
  } else {
    throw UsageError("--centroid: use exact, discrete or discrete:N");
  }
  return d;
}

fuzzy::Engine ControllerOptions::engine(std::optional<TNorm> t) const {
  fuzzy::Engine e;
  if (!fll_path.empty()) {
    e = fuzzy::read_fll_file(fll_path);
    if (t) e.rule_block.conjunction = *t;
  } else {
    fuzzy::LineFollowerOptions o;
    o.adc_bits = adc_bits;
    o.speed_factor = speed_factor;
    o.implication = implication == "product" ? fuzzy::Implication::product : fuzzy::Implication::minimum;
    o.conjunction = t.value_or(TNorm::minimum);
    const std::vector<double> c = cli::parse_numbers(backward_slowly, "--backward-slowly", 4);
    if (!std::is_sorted(c.begin(), c.end()))
      throw UsageError("--backward-slowly " + backward_slowly +
                       ": the term needs its corners in order (A <= B <= C <= D)");
    o.backward_slowly = {c[0], c[1], c[2], c[3]};
    e = fuzzy::line_follower_engine(o);
  }
  for (auto& out : e.outputs) out.defuzzifier = defuzzifier(out.defuzzifier);
  return e;
}

fuzzy::Mamdani ControllerOptions::controller(const fuzzy::Engine& e) const {
  fuzzy::Mamdani m(e);
  m.set_fire_threshold(fire_threshold);
  return m;
}

std::string tnorm_label(const fuzzy::Engine& e) { return std::string(fuzzy::tnorm_name(e.rule_block.conjunction)); }

}  // namespace tnorm_bench
