// Unit tests for sim::time_panels_svg, the stacked time panels that
// fuzzyfeed and smcsim draw with: well-formed XML, the per-column
// reduction of long series, the y ranges, and errors naming the file.
#include <gtest/gtest.h>

#include <array>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

#include "control/feed_drive_plot.hpp"
#include "io/error.hpp"
#include "sim/time_panels_svg.hpp"
#include "temp_file.hpp"

using namespace tk::sim;

namespace {

/// Whether `xml` is well-formed for what an SVG writer emits: nested
/// elements with double-quoted attributes, text and attribute values
/// using only the predefined entities. (No comments, CDATA or DTD.)
testing::AssertionResult well_formed(const std::string& xml) {
  std::vector<std::string> open;
  bool had_root = false;
  std::size_t i = 0;
  const auto name_at = [&](std::size_t& at) {
    const std::size_t from = at;
    while (at < xml.size() && (std::isalnum(static_cast<unsigned char>(xml[at])) || std::strchr(":-_.", xml[at]))) ++at;
    return xml.substr(from, at - from);
  };
  const auto skip_space = [&] {
    while (i < xml.size() && std::isspace(static_cast<unsigned char>(xml[i]))) ++i;
  };
  const auto entity_ok = [&](std::size_t at) {
    for (const char* entity : {"&amp;", "&lt;", "&gt;", "&quot;", "&apos;"})
      if (xml.compare(at, std::strlen(entity), entity) == 0) return true;
    return false;
  };
  const auto failure = [&](const std::string& what) { return testing::AssertionFailure() << what << " at byte " << i; };
  while (i < xml.size()) {
    if (xml[i] == '&' && !entity_ok(i)) return failure("a bare &");
    if (xml[i] != '<') {
      if (open.empty() && !std::isspace(static_cast<unsigned char>(xml[i]))) return failure("text outside the root");
      ++i;
      continue;
    }
    const bool closing = xml[++i] == '/';
    if (closing) ++i;
    const std::string name = name_at(i);
    if (name.empty()) return failure("a tag without a name");
    if (closing) {
      skip_space();
      if (open.empty() || open.back() != name || xml[i] != '>') return failure("</" + name + "> closes nothing open");
      open.pop_back(), ++i;
      continue;
    }
    if (open.empty() && had_root) return failure("a second root");
    had_root = true;
    for (;;) {
      skip_space();
      if (xml.compare(i, 2, "/>") == 0) {
        i += 2;
        break;
      }
      if (xml[i] == '>') {
        open.push_back(name), ++i;
        break;
      }
      if (name_at(i).empty() || xml.compare(i, 2, "=\"") != 0)
        return failure("a malformed attribute in <" + name + ">");
      for (i += 2; i < xml.size() && xml[i] != '"'; ++i)
        if (xml[i] == '<' || (xml[i] == '&' && !entity_ok(i))) return failure("a bad character in an attribute");
      if (i++ == xml.size()) return failure("an unterminated attribute");
    }
  }
  if (!open.empty()) return failure("<" + open.back() + "> never closed");
  if (!had_root) return failure("no element");
  return testing::AssertionSuccess();
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

/// The points of each polyline, in order.
std::vector<std::vector<std::array<double, 2>>> polylines(const std::string& svg) {
  std::vector<std::vector<std::array<double, 2>>> out;
  for (std::size_t at = svg.find("<polyline "); at != std::string::npos; at = svg.find("<polyline ", at + 1)) {
    const std::size_t from = svg.find("points=\"", at) + 8;
    std::istringstream points(svg.substr(from, svg.find('"', from) - from));
    out.emplace_back();
    double x, y;
    char comma;
    while (points >> x >> comma >> y) out.back().push_back({x, y});
  }
  return out;
}

/// A one-series plot of `value` at `samples` times spread over [0, 1).
TimePanelsPlot one_series(std::size_t samples, SampleValue value,
                          TimePanel::Range range = TimePanel::Range::from_data) {
  TimePanelsPlot plot{
      .title = "test", .samples = samples, .time_s = [samples](std::size_t i) { return double(i) / samples; }};
  plot.panels.push_back({.y_label = "v", .series = {{std::move(value)}}, .range = range});
  return plot;
}

// Panel geometry of the writer: the first panel's frame spans y 50..300.
constexpr double kPanelTop = 50, kPanelBottom = 300;

TEST(TimePanelsSvg, IsWellFormedXmlWithOnePolylinePerSeriesAndAnEscapedTitle) {
  const auto sine = [](std::size_t i) { return std::sin(i * 0.01); };
  TimePanelsPlot plot{
      .title = "a <title> & \"quotes\"", .samples = 1000, .time_s = [](std::size_t i) { return i * 1e-3; }};
  plot.panels.push_back({.y_label = "x & y, mm",
                         .series = {{sine, "#1f5fbf", 1.2, "x<ref>"}, {sine, "#c8281e", 2, ""}},
                         .levels = {{0.5, 0.5, "#c8281e", "limit & more"}, {-0.2, 0.2, "#2a9d3a", ""}}});
  plot.panels.push_back({.y_label = "z", .series = {{sine}}, .range = TimePanel::Range::fixed, .y_min = 0, .y_max = 2});
  const std::string svg = time_panels_svg(plot);
  EXPECT_TRUE(well_formed(svg)) << svg;
  EXPECT_EQ(count(svg, "<polyline "), 3u);
  EXPECT_EQ(count(svg, "<rect class=\"panel\""), 2u);
  EXPECT_NE(svg.find("<title>a &lt;title&gt; &amp; &quot;quotes&quot;</title>"), std::string::npos);
  EXPECT_NE(svg.find(">x&lt;ref&gt;</tspan>"), std::string::npos);
  EXPECT_NE(svg.find(">limit &amp; more</text>"), std::string::npos);
  EXPECT_NE(svg.find("stroke-dasharray"), std::string::npos);  // the level line
  EXPECT_TRUE(well_formed(time_panels_svg({.title = "empty", .samples = 0, .time_s = {}, .panels = {TimePanel{}}})));
}

TEST(TimePanelsSvg, AMillionSamplesOfASineKeepTheirEnvelopeInTwoPointsPerColumn) {
  constexpr std::size_t kSamples = 1000000;
  const std::string svg =
      time_panels_svg(one_series(kSamples, [](std::size_t i) { return std::sin(2 * std::numbers::pi * 1e-3 * i); }));
  ASSERT_TRUE(well_formed(svg));
  const auto lines = polylines(svg);
  ASSERT_EQ(lines.size(), 1u);
  const auto& points = lines[0];
  EXPECT_LE(points.size(), 2 * 880u);
  EXPECT_GE(points.size(), 2 * 880u - 10);  // 1000 periods: every column sees both extremes
  double top = INFINITY, bottom = -INFINITY;
  for (std::size_t k = 0; k < points.size(); ++k) {
    top = std::min(top, points[k][1]), bottom = std::max(bottom, points[k][1]);
    if (k > 0) {
      EXPECT_GE(points[k][0], points[k - 1][0]) << "x goes back at point " << k;
    }
  }
  // From the data, ±1 fills the frame exactly.
  EXPECT_NEAR(top, kPanelTop, 0.11);
  EXPECT_NEAR(bottom, kPanelBottom, 0.11);
}

TEST(TimePanelsSvg, ShortSeriesAreDrawnSampleBySampleSkippingNonFiniteValues) {
  const auto lines =
      polylines(time_panels_svg(one_series(100, [](std::size_t i) { return i == 7 ? NAN : double(i); })));
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0].size(), 99u);
}

TEST(TimePanelsSvg, RangesFromTheDataSymmetricOrFixed) {
  const auto ramp = [](std::size_t i) { return -0.2 + 1.2 * i / 99.0; };  // -0.2 .. 1
  const std::string from_data = time_panels_svg(one_series(100, ramp));
  EXPECT_NE(from_data.find(">-0.2</text>"), std::string::npos);
  EXPECT_EQ(from_data.find(">-1</text>"), std::string::npos);
  const std::string symmetric = time_panels_svg(one_series(100, ramp, TimePanel::Range::symmetric));
  EXPECT_NE(symmetric.find(">-1.0</text>"), std::string::npos);
  EXPECT_NE(symmetric.find(">1.0</text>"), std::string::npos);
  EXPECT_NE(symmetric.find(">0.0</text>"), std::string::npos);  // not 5.55e-17; the step's decimals

  TimePanelsPlot fixed = one_series(
      100, [](std::size_t) { return 500.0; }, TimePanel::Range::fixed);
  fixed.panels[0].y_min = 0, fixed.panels[0].y_max = 200;
  const std::string svg = time_panels_svg(fixed);
  EXPECT_NE(svg.find(">200</text>"), std::string::npos);
  const auto lines = polylines(svg);
  ASSERT_EQ(lines.size(), 1u);
  for (const auto& point : lines[0]) EXPECT_NEAR(point[1], kPanelTop, 1e-9);  // beyond the range: at the edge
}

TEST(TimePanelsSvg, NiceStepsAreOneTwoOrFiveTimesAPowerOfTen) {
  EXPECT_DOUBLE_EQ(nice_step(100, 6), 20);
  EXPECT_DOUBLE_EQ(nice_step(3, 10), 0.5);
  EXPECT_DOUBLE_EQ(nice_step(2, 6), 0.5);
  EXPECT_DOUBLE_EQ(nice_step(0.006, 6), 0.001);
  EXPECT_DOUBLE_EQ(nice_step(900, 10), 100);
}

TEST(TimePanelsSvg, ARunEndingOnePeriodShortOfATickEndsOnThatTick) {
  TimePanelsPlot plot = one_series(30000, [](std::size_t) { return 0.0; });
  plot.time_s = [](std::size_t i) { return i * 1e-4; };  // 0 .. 2.9999 s
  EXPECT_NE(time_panels_svg(plot).find(">3.0</text>"), std::string::npos);
}

TEST(TimePanelsSvg, WritesAtomicallyAndNamesAnUnwritablePath) {
  tk::test::TempFile file("", ".svg");
  write_time_panels_svg(file.path(), one_series(10, [](std::size_t i) { return double(i); }));
  std::ifstream in(file.path());
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_TRUE(well_formed(text));
  EXPECT_FALSE(std::filesystem::exists(file.path() + ".tmp"));

  const std::string bad = "/nonexistent-dir/plot.svg";
  try {
    write_time_panels_svg(bad, one_series(10, [](std::size_t i) { return double(i); }));
    FAIL() << "no error";
  } catch (const tk::Error& e) {
    EXPECT_EQ(e.where().file, bad);
    EXPECT_EQ(e.located_message().rfind(bad + ": ", 0), 0u) << e.located_message();
  }
}

TEST(FeedDrivePlot, DrawsTheFourPanelsWithTheCuttingForceInTheLast) {
  tk::control::FeedDrivePlot plot;
  for (int i = 0; i < 5000; ++i) {
    const double t = i * 1e-3, x_ref = std::sin(3 * t), x = x_ref - 0.01 * std::sin(40 * t);
    plot.add({t, x_ref, x, x_ref - x, 0.4 * std::cos(40 * t), 0, 30 * std::sin(200 * t), -5 + 2 * std::sin(50 * t)});
  }
  tk::test::TempFile file("", ".svg");
  plot.write(file.path(), "smcsim <smc>");
  std::ifstream in(file.path());
  const std::string svg((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_TRUE(well_formed(svg));
  EXPECT_EQ(count(svg, "<rect class=\"panel\""), 4u);
  EXPECT_EQ(count(svg, "<polyline "), 6u);  // x_ref and x, e, e_dot, F and F_d
  EXPECT_NE(svg.find(">cutting force F_d</tspan>"), std::string::npos);
  EXPECT_NE(svg.find(">-30</text>"), std::string::npos);  // the force's signed range
  EXPECT_NE(svg.find("smcsim &lt;smc&gt;"), std::string::npos);
}

}  // namespace
