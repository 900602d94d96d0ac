/// @file test_feed_override.cpp
/// @brief The fuzzy feed-override law against values computed by hand from
/// formulas (1)-(7): the rule base's factor at chosen load ratios, the
/// override's clamps and floor, the moving average with its warm-up, the
/// partial gain and the dead band's edge.
#include <gtest/gtest.h>

#include <cmath>
#include <deque>
#include <numeric>
#include <random>

#include "io/error.hpp"
#include "machining/feed_override.hpp"

namespace {

using namespace tk::machining;

TEST(FeedOverride, FuzzyFactorAtHandComputedRatios) {
  // r = 0: LOW 1, OK 0, HIGH 0 -> 2 (speed up).
  EXPECT_DOUBLE_EQ(fuzzy_factor(0), 2.0);
  // r = 0.5: LOW 0.5, OK 0.5 -> (2 * 0.5 + 0.5) / 1 = 1.5.
  EXPECT_DOUBLE_EQ(fuzzy_factor(0.5), 1.5);
  // r = 1: OK 1 -> 1 (hold).
  EXPECT_DOUBLE_EQ(fuzzy_factor(1), 1.0);
  // r = 1.5: OK 0.5, HIGH 0.5 -> (0.5 + 0.25) / 1 = 0.75.
  EXPECT_DOUBLE_EQ(fuzzy_factor(1.5), 0.75);
  // r = 2: HIGH 1 -> 0.5; r = 3: HIGH is capped at 1 -> 0.5.
  EXPECT_DOUBLE_EQ(fuzzy_factor(2), 0.5);
  EXPECT_DOUBLE_EQ(fuzzy_factor(3), 0.5);
  // r = 0.25: LOW 0.75, OK 0.25 -> 1.75; r = 1.2: OK 0.8, HIGH 0.2 -> 0.9.
  EXPECT_DOUBLE_EQ(fuzzy_factor(0.25), 1.75);
  EXPECT_NEAR(fuzzy_factor(1.2), 0.9, 1e-15);
}

TEST(FeedOverride, OriginalLawMultipliesTheOverride) {
  FeedOverrideParams params;  // original, M_z 60 %, O_a 100 %
  FeedOverride law(params);
  OverrideStep s = law.step(30);  // r = 0.5 -> W_k 1.5
  EXPECT_DOUBLE_EQ(s.factor, 1.5);
  EXPECT_DOUBLE_EQ(s.override_pct, 150);
  EXPECT_DOUBLE_EQ(s.load_used, 30);
  s = law.step(90);  // r = 1.5 -> 0.75: 112.5
  EXPECT_DOUBLE_EQ(s.override_pct, 112.5);
  s = law.step(60);  // r = 1: holds
  EXPECT_DOUBLE_EQ(s.factor, 1.0);
  EXPECT_DOUBLE_EQ(s.override_pct, 112.5);
}

TEST(FeedOverride, ClampsAtTwoHundredAndAtTheFloor) {
  FeedOverrideParams params;
  params.initial_override_pct = 150;
  FeedOverride law(params);
  EXPECT_DOUBLE_EQ(law.step(0).override_pct, 200);  // 2 x 150 = 300 -> 200
  EXPECT_DOUBLE_EQ(law.step(0).override_pct, 200);
  // M_a = 100 % against M_z = 60 %: r = 5/3, W_k = 1.5 - 5/6 = 2/3 each cycle:
  // 200 (2/3)^n reaches the 1 % floor after 14 cycles and stays there.
  for (int i = 0; i < 13; ++i) EXPECT_GT(law.step(100).override_pct, 1.0) << i;
  EXPECT_DOUBLE_EQ(law.step(100).override_pct, 1.0);
  EXPECT_DOUBLE_EQ(law.step(100).override_pct, 1.0);
  // From the floor an idle spindle doubles it: 2 %.
  EXPECT_DOUBLE_EQ(law.step(0).override_pct, 2.0);

  params.min_override_pct = 20;
  params.initial_override_pct = 30;
  FeedOverride floored(params);
  EXPECT_DOUBLE_EQ(floored.step(100).override_pct, 20);  // 30 x 2/3 = 20 exactly
  EXPECT_DOUBLE_EQ(floored.step(100).override_pct, 20);
}

TEST(FeedOverride, ModifiedLawByHand) {
  FeedOverrideParams params;
  params.variant = OverrideVariant::modified;
  params.average_d = 4;  // k 0.1, p 0.1, M_z 60: the dead band is 54..66 %
  FeedOverride law(params);
  // Warm-up: the mean of the loads so far. 30 -> r 0.5, W_k 1.5, W_k' 1.05.
  OverrideStep s = law.step(30);
  EXPECT_DOUBLE_EQ(s.load_used, 30);
  EXPECT_NEAR(s.factor, 1.05, 1e-15);
  EXPECT_NEAR(s.override_pct, 105, 1e-12);
  s = law.step(90);  // mean 60: inside the band
  EXPECT_DOUBLE_EQ(s.load_used, 60);
  EXPECT_DOUBLE_EQ(s.factor, 1.0);
  s = law.step(66);  // mean 62: inside
  EXPECT_DOUBLE_EQ(s.load_used, 62);
  EXPECT_DOUBLE_EQ(s.factor, 1.0);
  EXPECT_NEAR(s.override_pct, 105, 1e-12);
  s = law.step(0);  // (30 + 90 + 66 + 0) / 4 = 46.5: r 0.775, W_k 1.225, W_k' 1.0225
  EXPECT_DOUBLE_EQ(s.load_used, 46.5);
  EXPECT_NEAR(s.factor, 1.0225, 1e-14);
  EXPECT_NEAR(s.override_pct, 105 * 1.0225, 1e-11);
  s = law.step(12);  // the 30 leaves: (90 + 66 + 0 + 12) / 4 = 42: r 0.7, W_k' 1.03
  EXPECT_DOUBLE_EQ(s.load_used, 42);
  EXPECT_NEAR(s.factor, 1.03, 1e-14);
  EXPECT_NEAR(s.override_pct, 105 * 1.0225 * 1.03, 1e-11);
}

TEST(FeedOverride, DeadBandEdgeIsInclusive) {
  FeedOverrideParams params;
  params.variant = OverrideVariant::modified;
  params.average_d = 1;
  FeedOverride law(params);
  EXPECT_DOUBLE_EQ(law.step(66).factor, 1.0);  // |66 - 60| = 6 = p M_z: held
  EXPECT_DOUBLE_EQ(law.step(54).factor, 1.0);
  // 66.6: r 1.11, W_k 1.5 - 0.555 = 0.945, W_k' = 1 - 0.1 * 0.055 = 0.9945.
  EXPECT_NEAR(law.step(66.6).factor, 0.9945, 1e-14);
  params.dead_band_p = 0;  // no band: only M_z itself holds
  FeedOverride bare(params);
  EXPECT_DOUBLE_EQ(bare.step(60).factor, 1.0);
  EXPECT_NEAR(bare.step(61.2).factor, 1 - 0.1 * 0.01, 1e-14);  // r 1.02: W_k 0.99
}

TEST(FeedOverride, ModifiedWithFullGainNoBandAndOneSampleIsTheOriginal) {
  FeedOverrideParams original, modified;
  modified.variant = OverrideVariant::modified;
  modified.gain_k = 1, modified.dead_band_p = 0, modified.average_d = 1;
  FeedOverride a(original), b(modified);
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> load(0, 100);
  for (int i = 0; i < 1000; ++i) {
    const double m = load(random);
    ASSERT_DOUBLE_EQ(a.step(m).override_pct, b.step(m).override_pct) << i;
  }
}

TEST(FeedOverride, MovingAverageMatchesADirectMeanOverALongRun) {
  FeedOverrideParams params;
  params.variant = OverrideVariant::modified;
  params.average_d = 25;
  FeedOverride law(params);
  std::deque<double> window;
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> load(0, 100);
  for (int i = 0; i < 200000; ++i) {
    const double m = load(random);
    window.push_back(m);
    if (window.size() > 25) window.pop_front();
    const double mean = std::accumulate(window.begin(), window.end(), 0.0) / static_cast<double>(window.size());
    ASSERT_NEAR(law.step(m).load_used, mean, 1e-11) << i;
  }
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
  rejects([](FeedOverrideParams& p) { p.gain_k = 0; }, "--k");
  rejects([](FeedOverrideParams& p) { p.gain_k = 1.01; }, "--k");
  rejects([](FeedOverrideParams& p) { p.dead_band_p = 1; }, "--p");
  rejects([](FeedOverrideParams& p) { p.dead_band_p = -0.1; }, "--p");
  rejects([](FeedOverrideParams& p) { p.average_d = 0; }, "--d");
  rejects([](FeedOverrideParams& p) { p.initial_override_pct = 0; }, "--initial-override");
  rejects([](FeedOverrideParams& p) { p.initial_override_pct = 201; }, "--initial-override");
  rejects([](FeedOverrideParams& p) { p.min_override_pct = 0; }, "--min-override");
  FeedOverrideParams edge;
  edge.mz_pct = 100, edge.gain_k = 1, edge.dead_band_p = 0, edge.initial_override_pct = 200;
  EXPECT_NO_THROW(validate(edge));
}

}  // namespace
