// Unit tests for sim/svg_marks: plain tick numbers, round scale-bar
// lengths, the legend's rows and the scale bar's drawn length.
#include <gtest/gtest.h>

#include <regex>
#include <string>

#include "sim/svg_marks.hpp"

using namespace tk::sim;

TEST(SvgMarks, PlainNumbersHaveTheStepsDecimalsAndNoExponent) {
  EXPECT_EQ(plain_number(1000, 500), "1000");
  EXPECT_EQ(plain_number(5e6, 1e6), "5000000");
  EXPECT_EQ(plain_number(0.001, 0.001), "0.001");
  EXPECT_EQ(plain_number(40, 0.01), "40.00");
  EXPECT_EQ(plain_number(0.999996, 2e-6), "0.999996");
  EXPECT_EQ(plain_number(0.75, 0.25), "0.75");
  EXPECT_EQ(plain_number(-1e-18, 0.1), "0.0");  // rounding noise at zero, not -0.0
  EXPECT_EQ(plain_number(-0.5, 0.5), "-0.5");
}

TEST(SvgMarks, ScaleBarLengthsAreTheNearestOneTwoOrFive) {
  EXPECT_DOUBLE_EQ(nearest_125(12), 10);
  EXPECT_DOUBLE_EQ(nearest_125(16), 20);
  EXPECT_DOUBLE_EQ(nearest_125(3.3), 5);  // 5/3.3 = 1.52 < 3.3/2 = 1.65
  EXPECT_DOUBLE_EQ(nearest_125(3.1), 2);
  EXPECT_DOUBLE_EQ(nearest_125(0.08), 0.1);
  EXPECT_DOUBLE_EQ(nearest_125(7.0), 5);  // the boundary is sqrt(50) = 7.07
  EXPECT_DOUBLE_EQ(nearest_125(7.2), 10);
  EXPECT_DOUBLE_EQ(nearest_125(7.0 * 1000), 5000);
  EXPECT_DOUBLE_EQ(nearest_125(7.1 * 1.5), 10);
}

TEST(SvgMarks, TheScaleBarIsItsLengthTimesTheScaleAndSaysSo) {
  const std::string bar = svg_scale_bar(20, 2.5, 10, 100, 4, 0.1);
  std::smatch m;
  ASSERT_TRUE(std::regex_search(bar, m, std::regex("<line x1=\"([0-9.]+)\" y1=\"100\" x2=\"([0-9.]+)\" y2=\"100\"/>")));
  EXPECT_DOUBLE_EQ(std::stod(m[2]) - std::stod(m[1]), 50);
  EXPECT_NE(bar.find(">20 mm</text>"), std::string::npos);
}

TEST(SvgMarks, TheLegendHasARowPerEntryWithItsMarkAndEscapedLabel) {
  const std::string legend = svg_legend({{LegendEntry::Mark::line, "stroke=\"red\"", "a & b"},
                                         {LegendEntry::Mark::area, "fill=\"blue\"", "area"},
                                         {LegendEntry::Mark::dot, "fill=\"green\"", "dot"}},
                                        0, 0, 10);
  EXPECT_NE(legend.find("<line"), std::string::npos);
  EXPECT_NE(legend.find("fill=\"blue\"/><text"), std::string::npos);
  EXPECT_NE(legend.find("<circle"), std::string::npos);
  EXPECT_NE(legend.find(">a &amp; b</text>"), std::string::npos);
  EXPECT_DOUBLE_EQ(legend_height(3, 10), 48);
}
