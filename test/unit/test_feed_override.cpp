/// @file test_feed_override.cpp
/// @brief The feed-override law against values worked by hand from the
/// paper's formulas (1)-(7) (exponents chosen to come out round: e^-1.25,
/// e^-1, e^-4), the hold at M_a = M_z, the identity of the modified law
/// with k = p = 1, d = 0 and the original, the range (0, 200] the paper
/// states for O_n; and one step on a grid of (M_a, M_z, O_a) against
/// test/oracle/fuzzyfeed_law.py, a Python law written from the paper's text.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <vector>

#include "io/error.hpp"
#include "machining/feed_override.hpp"
#include "project_paths.hpp"

namespace {

using namespace tk::machining;

FeedOverrideParams modified_law() {
  FeedOverrideParams law;  // k = p = 0.1, d = 25, M_z = 60
  law.variant = OverrideVariant::modified;
  return law;
}

TEST(FeedOverride, CorrectionCoefficientByHand) {
  const FeedOverrideParams law;  // M_z = 60
  // (1): -5/3600 * 30^2 = -1.25; M_a = 0 gives e^0 = 1.
  EXPECT_NEAR(correction_coefficient(law, 30), std::exp(-1.25), 1e-15);
  EXPECT_DOUBLE_EQ(correction_coefficient(law, 0), 1);
  // (2): -10/(1 - 0.6) * (0.8 - 0.6)^2 = -25 * 0.04 = -1; at 100 %: -25 * 0.16 = -4.
  EXPECT_NEAR(correction_coefficient(law, 80), std::exp(-1.0), 1e-15);
  EXPECT_NEAR(correction_coefficient(law, 100), std::exp(-4.0), 1e-15);
  // M_z = 50, M_a = 75: -10/0.5 * 0.25^2 = -1.25.
  FeedOverrideParams half = law;
  half.mz_pct = 50;
  EXPECT_NEAR(correction_coefficient(half, 75), std::exp(-1.25), 1e-15);
  // Just below M_z (1) gives about e^-5; at M_z the override holds (W_k = 1).
  EXPECT_NEAR(correction_coefficient(law, 60 - 1e-9), std::exp(-5.0), 1e-9);
  EXPECT_DOUBLE_EQ(correction_coefficient(law, 60), 1);
  // (5) and (6): k e^-1.25; p e^-1 + 0.9.
  const FeedOverrideParams mod = modified_law();
  EXPECT_NEAR(correction_coefficient(mod, 30), 0.1 * std::exp(-1.25), 1e-15);
  EXPECT_NEAR(correction_coefficient(mod, 80), 0.1 * std::exp(-1.0) + 0.9, 1e-15);
  EXPECT_DOUBLE_EQ(correction_coefficient(mod, 60), 1);
}

TEST(FeedOverride, OriginalLawStepsByHand) {
  FeedOverride law(FeedOverrideParams{});  // O_a = 100
  // (3) at 30 %: 200 (0.5 + w - 0.5 w) = 100 + 100 w.
  OverrideStep s = law.step(30);
  EXPECT_NEAR(s.override_pct, 100 + 100 * std::exp(-1.25), 1e-12);
  const double after_30 = s.override_pct;
  // (4) at 80 %: e^-1 times that.
  s = law.step(80);
  EXPECT_NEAR(s.override_pct, after_30 * std::exp(-1.0), 1e-12);
  // At M_z: held exactly.
  const double held = s.override_pct;
  s = law.step(60);
  EXPECT_EQ(s.wk, 1);
  EXPECT_EQ(s.override_pct, held);
  // An idle spindle (M_a = 0, W_k = 1): (3) gives 200 whatever O_a is.
  EXPECT_DOUBLE_EQ(law.step(0).override_pct, 200);
  EXPECT_DOUBLE_EQ(law.step(0).override_pct, 200);
}

TEST(FeedOverride, ModifiedLawStepsByHand) {
  FeedOverride law(modified_law());
  // (5) + (3) at 30 %: 100 + 100 * 0.1 e^-1.25 = 102.865...
  EXPECT_NEAR(law.step(30).override_pct, 100 + 10 * std::exp(-1.25), 1e-12);
  FeedOverride again(modified_law());
  // (6) + (7) at 80 %: (0.1 e^-1 + 0.9)(100 - 25) + 25.
  EXPECT_NEAR(again.step(80).override_pct, (0.1 * std::exp(-1.0) + 0.9) * 75 + 25, 1e-12);
  // Below d an overload pulls the override up to d, as (7) prints:
  // 10 % at 100 % load -> (0.1 e^-4 + 0.9)(10 - 25) + 25 = 11.47...
  FeedOverrideParams low = modified_law();
  low.initial_override_pct = 10;
  FeedOverride below_d(low);
  EXPECT_NEAR(below_d.step(100).override_pct, (0.1 * std::exp(-4.0) + 0.9) * -15 + 25, 1e-12);
  // A persistent overload takes the override towards d and never below it.
  FeedOverride overloaded(modified_law());
  double o = 0;
  for (int i = 0; i < 2000; ++i) o = overloaded.step(100).override_pct;
  EXPECT_GT(o, 25);
  EXPECT_NEAR(o, 25, 1e-9);
}

TEST(FeedOverride, ModifiedWithUnitWeightsAndNoOffsetIsTheOriginal) {
  FeedOverrideParams original, modified = modified_law();
  modified.k = 1, modified.p = 1, modified.d_pct = 0;
  FeedOverride a(original), b(modified);
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> load(0, 100);
  for (int i = 0; i < 10000; ++i) {
    const double m = load(random);
    const OverrideStep x = a.step(m), y = b.step(m);
    ASSERT_DOUBLE_EQ(x.wk, y.wk) << i;
    ASSERT_DOUBLE_EQ(x.override_pct, y.override_pct) << i;
  }
}

TEST(FeedOverride, OverrideStaysInsideTheStatedRange) {
  // The paper: "the value set O_n = (0,200%]". (3) only raises the override,
  // (4) only lowers it; over random loads, both variants, several M_z.
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> load(0, 100);
  for (const double mz : {5.0, 35.0, 60.0, 95.0, 100.0})
    for (const OverrideVariant variant : {OverrideVariant::original, OverrideVariant::modified}) {
      FeedOverrideParams params;
      params.variant = variant, params.mz_pct = mz;
      FeedOverride law(params);
      double previous = law.override_pct();
      for (int i = 0; i < 20000; ++i) {
        const double m = load(random);
        const double o = law.step(m).override_pct;
        ASSERT_GT(o, 0) << mz << " " << i;
        ASSERT_LE(o, 200) << mz << " " << i;
        if (m < mz) {
          ASSERT_GE(o, previous) << mz << " " << i;
        }
        if (m > mz && variant == OverrideVariant::original) {
          ASSERT_LE(o, previous) << mz << " " << i;
        }
        previous = o;
      }
    }
}

/// One step from O_a at each (M_a, M_z, O_a) of a grid, ours and the oracle's.
void compare_grid_with_oracle(const FeedOverrideParams& base, const std::string& options) {
  struct Point {
    double ma, mz, oa;
  };
  std::vector<Point> grid;
  for (const double mz : {1.0, 10.0, 35.0, 60.0, 85.0, 99.0, 100.0}) {
    std::set<double> loads{0, 5, 20, 40, 59.99, 60, 60.01, 70, 90, 99.5, 100, mz, std::nextafter(mz, 0.0)};
    if (mz < 100) loads.insert(std::nextafter(mz, 100.0));
    for (const double oa : {1e-3, 1.0, 24.9, 25.0, 100.0, 145.0, 199.0, 200.0})
      for (const double ma : loads) grid.push_back({ma, mz, oa});
  }
  const auto input = std::filesystem::temp_directory_path() / ("fuzzyfeed_grid_" + std::to_string(::getpid()) + ".txt");
  {
    std::ofstream out(input);
    char line[128];
    for (const Point& g : grid) {
      std::snprintf(line, sizeof line, "%.17g %.17g %.17g\n", g.ma, g.mz, g.oa);
      out << line;
    }
  }
  const std::string command = "/usr/bin/python3 '" +
                              (tk::test::project_root() / "test" / "oracle" / "fuzzyfeed_law.py").string() + "' grid " +
                              options + " < '" + input.string() + "'";
  FILE* pipe = popen(command.c_str(), "r");
  ASSERT_NE(pipe, nullptr) << command;
  std::size_t i = 0;
  double wk = 0, on = 0;
  while (std::fscanf(pipe, "%lf %lf", &wk, &on) == 2 && i < grid.size()) {
    const Point& g = grid[i++];
    FeedOverrideParams law = base;
    law.mz_pct = g.mz;
    const double ours = correction_coefficient(law, g.ma);
    EXPECT_NEAR(ours, wk, 1e-13 * wk) << options << " at " << g.ma << " " << g.mz << " " << g.oa;
    EXPECT_NEAR(aggregate_override(law, g.ma < g.mz, ours, g.oa), on, 1e-13 * on)
        << options << " at " << g.ma << " " << g.mz << " " << g.oa;
  }
  EXPECT_EQ(pclose(pipe), 0) << command;
  std::filesystem::remove(input);
  EXPECT_EQ(i, grid.size()) << command;
}

TEST(FeedOverride, GridAgreesWithThePythonLawWrittenFromThePaper) {
  compare_grid_with_oracle(FeedOverrideParams{}, "--variant original");
  compare_grid_with_oracle(modified_law(), "--variant modified");
  FeedOverrideParams other = modified_law();
  other.k = 0.4, other.p = 0.7, other.d_pct = 60;
  compare_grid_with_oracle(other, "--variant modified --k 0.4 --p 0.7 --d 60");
}

TEST(FeedOverride, OptionalFloor) {
  FeedOverrideParams params;
  params.min_override_pct = 20;
  params.initial_override_pct = 30;
  FeedOverride law(params);
  EXPECT_DOUBLE_EQ(law.step(100).override_pct, 20);  // 30 e^-4 = 0.55 -> 20
  FeedOverrideParams none;
  none.initial_override_pct = 30;
  FeedOverride free_law(none);
  EXPECT_NEAR(free_law.step(100).override_pct, 30 * std::exp(-4.0), 1e-12);
}

TEST(FeedOverride, RejectsParametersOutOfRange) {
  const auto rejects = [](auto change, const char* option) {
    FeedOverrideParams params;
    change(params);
    try {
      validate(params);
      ADD_FAILURE() << option << " accepted";
    } catch (const tk::UsageError& e) {
      EXPECT_NE(std::string(e.what()).find(option), std::string::npos) << e.what();
    }
  };
  rejects([](FeedOverrideParams& p) { p.mz_pct = 0; }, "--mz");
  rejects([](FeedOverrideParams& p) { p.mz_pct = 100.5; }, "--mz");
  rejects([](FeedOverrideParams& p) { p.mz_pct = std::nan(""); }, "--mz");
  rejects([](FeedOverrideParams& p) { p.k = 0; }, "--k");
  rejects([](FeedOverrideParams& p) { p.k = 1.01; }, "--k");
  rejects([](FeedOverrideParams& p) { p.p = 1.01; }, "--p");
  rejects([](FeedOverrideParams& p) { p.p = -0.1; }, "--p");
  rejects([](FeedOverrideParams& p) { p.d_pct = -1; }, "--d");
  rejects([](FeedOverrideParams& p) { p.d_pct = 100.5; }, "--d");
  rejects([](FeedOverrideParams& p) { p.initial_override_pct = 0; }, "--initial-override");
  rejects([](FeedOverrideParams& p) { p.initial_override_pct = 201; }, "--initial-override");
  rejects([](FeedOverrideParams& p) { p.min_override_pct = 200; }, "--min-override");
  FeedOverrideParams edge;
  edge.mz_pct = 100, edge.k = 1, edge.p = 0, edge.d_pct = 100, edge.initial_override_pct = 200;
  EXPECT_NO_THROW(validate(edge));
  FeedOverride at_full(edge);  // M_z = 100: only M_a = M_z reaches (2), and holds
  EXPECT_EQ(at_full.step(100).override_pct, 200);
}

}  // namespace
