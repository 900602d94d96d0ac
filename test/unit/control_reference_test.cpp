/// @file control_reference_test.cpp
/// @brief The reference trajectories: the sine, step and ramp against their
/// formulas; samples read from records: the cubic Hermite curve passes
/// through the samples with their velocities, reproduces a cubic exactly,
/// and its velocity is the derivative of its position (central differences);
/// finite-difference derivatives where columns are missing (exact for
/// lines, and for parabolas in the interior); malformed files give tk::Error
/// naming the file and line.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "control/reference.hpp"
#include "io/error.hpp"
#include "temp_file.hpp"

namespace {

using namespace tk::control;
using tk::test::TempFile;

TEST(Reference, SineStepAndRampFollowTheirFormulas) {
  const Reference sine = Reference::sine(1.5, 3);
  for (const double t : {0.0, 0.1, 0.77, 2.0, 10.0}) {
    const ReferenceSample r = sine.at(t);
    EXPECT_NEAR(r.x_mm, 1.5 * std::sin(3 * t), 1e-15);
    EXPECT_NEAR(r.v_mm_s, 4.5 * std::cos(3 * t), 1e-14);
    EXPECT_NEAR(r.a_mm_s2, -13.5 * std::sin(3 * t), 1e-13);
    // The derivatives are derivatives: central differences of x and v.
    const double d = 1e-5;
    EXPECT_NEAR((sine.at(t + d).x_mm - sine.at(t - d).x_mm) / (2 * d), r.v_mm_s, 1e-8);
    EXPECT_NEAR((sine.at(t + d).v_mm_s - sine.at(t - d).v_mm_s) / (2 * d), r.a_mm_s2, 1e-8);
  }
  const Reference step = Reference::step(2, 0.5);
  EXPECT_EQ(step.at(0.49).x_mm, 0);
  EXPECT_EQ(step.at(0.5).x_mm, 2);
  EXPECT_EQ(step.at(3).x_mm, 2);
  EXPECT_EQ(step.at(3).v_mm_s, 0);
  const Reference ramp = Reference::ramp(-4, 1);
  EXPECT_EQ(ramp.at(0.5).x_mm, 0);
  EXPECT_EQ(ramp.at(0.5).v_mm_s, 0);
  EXPECT_DOUBLE_EQ(ramp.at(1.25).x_mm, -1);
  EXPECT_EQ(ramp.at(1.25).v_mm_s, -4);
  EXPECT_THROW(Reference::sine(NAN, 1), tk::Error);
  EXPECT_THROW(Reference::step(1, INFINITY), tk::Error);
  EXPECT_THROW(Reference::ramp(NAN, 0), tk::Error);
}

/// p(t) = 0.5 − t + 2 t² − 0.75 t³ sampled at uneven times with p' given: the
/// cubic Hermite interpolant of a cubic is the cubic itself.
double cubic(double t) { return 0.5 - t + 2 * t * t - 0.75 * t * t * t; }
double cubic_rate(double t) { return -1 + 4 * t - 2.25 * t * t; }

TEST(Reference, HermiteReproducesACubicAndPassesThroughSamples) {
  const double times[] = {0, 0.1, 0.35, 0.4, 1.0, 1.7, 2.0};
  std::string csv = "t,x,v\n";
  for (const double t : times) {
    char line[128];
    std::snprintf(line, sizeof line, "%.17g,%.17g,%.17g\n", t, cubic(t), cubic_rate(t));
    csv += line;
  }
  const TempFile file(csv, ".csv");
  const Reference r = Reference::from_records(file.path());
  for (const double t : times) {
    EXPECT_NEAR(r.at(t).x_mm, cubic(t), 1e-15) << t;
    if (t > 0 && t < 2) {
      EXPECT_NEAR(r.at(t).v_mm_s, cubic_rate(t), 1e-14) << t;
    }
  }
  for (double t = 0.003; t < 2; t += 0.0173) {
    EXPECT_NEAR(r.at(t).x_mm, cubic(t), 1e-14) << t;
    EXPECT_NEAR(r.at(t).v_mm_s, cubic_rate(t), 1e-13) << t;
    // v is the derivative of x (central difference, h = 1e-6).
    const double d = 1e-6;
    EXPECT_NEAR((r.at(t + d).x_mm - r.at(t - d).x_mm) / (2 * d), r.at(t).v_mm_s, 1e-8) << t;
  }
  // Before the first and after the last sample the position holds still.
  EXPECT_EQ(r.at(-1).x_mm, cubic(0));
  EXPECT_EQ(r.at(-1).v_mm_s, 0);
  EXPECT_NEAR(r.at(5).x_mm, cubic(2), 1e-15);
  EXPECT_EQ(r.at(5).v_mm_s, 0);
}

/// Without v: a smooth, non-polynomial curve still passes through every
/// sample and its velocity is continuous across the samples (Hermite with
/// shared slopes) and is the derivative of x inside each interval.
TEST(Reference, HermiteThroughSamplesOfASine) {
  std::string json;
  for (int i = 0; i <= 40; ++i) {
    const double t = 0.05 * i + 0.01 * std::sin(i);  // uneven spacing
    char line[128];
    std::snprintf(line, sizeof line, "{\"t\": %.17g, \"x\": %.17g}\n", t, std::sin(3 * t));
    json += line;
  }
  const TempFile file(json, ".jsonl");
  const Reference r = Reference::from_records(file.path());
  for (int i = 1; i < 40; ++i) {
    const double t = 0.05 * i + 0.01 * std::sin(i);
    EXPECT_NEAR(r.at(t).x_mm, std::sin(3 * t), 1e-15) << i;
    const double d = 1e-9;
    EXPECT_NEAR(r.at(t - d).v_mm_s, r.at(t + d).v_mm_s, 1e-6) << "continuous velocity at sample " << i;
    const double mid = t + 0.02, e = 1e-6;
    EXPECT_NEAR((r.at(mid + e).x_mm - r.at(mid - e).x_mm) / (2 * e), r.at(mid).v_mm_s, 1e-7) << i;
    // Close to the true curve: slopes from central differences on a 0.05 s grid.
    EXPECT_NEAR(r.at(mid).x_mm, std::sin(3 * mid), 2e-3) << i;
  }
}

TEST(Reference, FiniteDifferenceDerivatives) {
  // A line: every difference (central inside, one-sided at the ends) is the slope.
  std::string line_csv = "t,x\n";
  for (int i = 0; i < 6; ++i) line_csv += std::to_string(0.25 * i) + "," + std::to_string(1 + 3 * 0.25 * i) + "\n";
  const TempFile line_file(line_csv, ".csv");
  const Reference line = Reference::from_records(line_file.path());
  for (int i = 0; i < 5; ++i) {  // just after each sample but the last (after it the reference holds)
    const double t = 0.25 * i;
    EXPECT_NEAR(line.at(t + 1e-12).v_mm_s, 3, 1e-9) << i;
    EXPECT_NEAR(line.at(t + 1e-12).a_mm_s2, 0, 1e-9) << i;
  }
  // A parabola x = t² on a uniform grid (h = 0.5): the central difference of
  // x is exact (2 t) at interior samples, and the difference of those
  // velocities is exact (2) where both neighbours are interior.
  std::string para = "t,x\n";
  for (int i = 0; i <= 10; ++i) para += std::to_string(0.5 * i) + "," + std::to_string(0.25 * i * i) + "\n";
  const TempFile para_file(para, ".csv");
  const Reference p = Reference::from_records(para_file.path());
  for (int i = 1; i < 10; ++i) EXPECT_NEAR(p.at(0.5 * i).v_mm_s, 2 * 0.5 * i, 1e-12) << i;
  for (int i = 2; i < 9; ++i) EXPECT_NEAR(p.at(0.5 * i).a_mm_s2, 2, 1e-12) << i;
  // One-sided at the first sample: (x1 − x0)/h = 0.25/0.5; seen just after t0
  // (at t0 itself the reference is "before the samples" and holds still).
  EXPECT_NEAR(p.at(1e-12).v_mm_s, 0.5, 1e-9);
  // The acceleration between samples is linear: halfway from 2 to 3 s it is 2.
  EXPECT_NEAR(p.at(2.25).a_mm_s2, 2, 1e-12);
  // Given columns are used as they are.
  const TempFile given("t,x,v,a\n0,0,7,9\n1,1,7,9\n2,2,7,9\n", ".csv");
  const Reference g = Reference::from_records(given.path());
  EXPECT_NEAR(g.at(1).v_mm_s, 7, 1e-12);
  EXPECT_NEAR(g.at(1.5).a_mm_s2, 9, 1e-12);
}

/// The error's file and line: "path:line: message".
void expect_error_at(const std::string& content, const std::string& suffix, std::size_t line,
                     const std::string& fragment) {
  const TempFile file(content, suffix);
  try {
    Reference::from_records(file.path());
    ADD_FAILURE() << "no error for: " << content;
  } catch (const tk::Error& e) {
    EXPECT_EQ(e.where().file, file.path()) << e.located_message();
    EXPECT_EQ(e.where().line, line) << e.located_message();
    EXPECT_NE(e.located_message().find(file.path() + ":" + std::to_string(line) + ":"), std::string::npos)
        << e.located_message();
    EXPECT_NE(e.located_message().find(fragment), std::string::npos) << e.located_message();
  }
}

TEST(Reference, MalformedFilesNameFileAndLine) {
  expect_error_at("t,x\n0,0\n1,1\n1,2\n", ".csv", 4, "increase");           // t repeats
  expect_error_at("t,x\n0,0\n2,1\n1,2\n", ".csv", 4, "increase");           // t goes back
  expect_error_at("t,x\n0,0\n1,abc\n", ".csv", 3, "x");                     // not a number
  expect_error_at("t,y\n0,0\n1,1\n", ".csv", 1, "x");                       // no x column: the header says so
  expect_error_at("{\"t\": 0, \"x\": 0}\n{\"x\": 1}\n", ".jsonl", 2, "t");  // no t
  expect_error_at("t,x,v\n0,0,1\n1,1,nan\n", ".csv", 3, "finite");          // a NaN velocity
  expect_error_at("t,x\n0,0\n1,inf\n", ".csv", 3, "finite");
  // Too few samples: named by file (there is no line to point at).
  const TempFile one("t,x\n0,1\n", ".csv");
  try {
    Reference::from_records(one.path());
    ADD_FAILURE() << "one sample accepted";
  } catch (const tk::Error& e) {
    EXPECT_NE(e.located_message().find(one.path()), std::string::npos) << e.located_message();
  }
  EXPECT_THROW(Reference::from_records("/nonexistent/reference.csv"), tk::Error);
}

}  // namespace
