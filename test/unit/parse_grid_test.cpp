/// @file parse_grid_test.cpp
/// @brief parse_grid: one number, FROM:TO:STEP grids (TO included when a
/// step lands on it, even through rounding), and the errors.
#include <gtest/gtest.h>

#include <string>

#include "cli/number_option.hpp"
#include "io/error.hpp"

namespace {

using tk::cli::parse_grid;

TEST(ParseGrid, OneNumber) {
  EXPECT_EQ(parse_grid("40", "--Lambda"), std::vector<double>{40});
  EXPECT_EQ(parse_grid("+2.5e-3", "--Lambda"), std::vector<double>{0.0025});
  EXPECT_EQ(parse_grid("-7", "--Lambda"), std::vector<double>{-7});
}

TEST(ParseGrid, RangesIncludeTheEnd) {
  const std::vector<double> v = parse_grid("10:1000:10", "--Lambda");
  ASSERT_EQ(v.size(), 100u);
  for (std::size_t i = 0; i < v.size(); ++i) EXPECT_DOUBLE_EQ(v[i], 10.0 * (i + 1)) << i;
  EXPECT_EQ(v.back(), 1000);
  // 0.3 / 0.1 is 2.9999999999999996 in binary: the end still counts.
  const std::vector<double> tenths = parse_grid("0:0.3:0.1", "--alpha");
  ASSERT_EQ(tenths.size(), 4u);
  EXPECT_NEAR(tenths.back(), 0.3, 1e-15);
  EXPECT_EQ(parse_grid("0:1:0.1", "--alpha").size(), 11u);
  // A step that does not land on TO stops below it.
  EXPECT_EQ(parse_grid("1:10:4", "--beta"), (std::vector<double>{1, 5, 9}));
  EXPECT_EQ(parse_grid("1:2:5", "--beta"), std::vector<double>{1});
  EXPECT_EQ(parse_grid("3:3:1", "--beta"), std::vector<double>{3});
  EXPECT_EQ(parse_grid("-1:1:1", "--beta"), (std::vector<double>{-1, 0, 1}));
}

void expect_bad(const std::string& text, std::size_t max_values = 1000000) {
  try {
    parse_grid(text, "--Lambda", max_values);
    ADD_FAILURE() << "accepted '" << text << "'";
  } catch (const tk::UsageError& e) {  // a bad option value: exit 2
    EXPECT_NE(std::string(e.what()).find("--Lambda"), std::string::npos) << e.what();
  }
}

TEST(ParseGrid, BadTextAndBadRanges) {
  for (const char* text : {"", "abc", "1:2", "1:2:3:4", "1::2", ":1:1", "1:2:x", "1:2:", "nan", "inf", "1e999", "0x10",
                           "1 ", " 1", "1,2", "1:2:0.5x"})
    expect_bad(text);
  expect_bad("1:10:0");   // step 0
  expect_bad("1:10:-1");  // negative step
  expect_bad("10:1:1");   // TO below FROM
  expect_bad("1:2:nan");
}

TEST(ParseGrid, TooManyValues) {
  EXPECT_EQ(parse_grid("1:10:1", "--Lambda", 10).size(), 10u);
  expect_bad("0:10:1", 10);  // 11 values
  expect_bad("0:1e6:1");     // 1000001 values, default limit 10^6
  expect_bad("0:1:1e-300");  // astronomically many, refused before any allocation
  EXPECT_EQ(parse_grid("1:1e6:1", "--Lambda").size(), 1000000u);
}

}  // namespace
