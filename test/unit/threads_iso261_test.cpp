/// @file threads_iso261_test.cpp
/// @brief Unit tests for the ISO 261 general plan table: well-known rows,
/// the table's ordering and internal consistency, and lookups of diameters
/// the standard does not list.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "project_paths.hpp"
#include "threads/iso261.hpp"

using namespace tk::threads;

namespace {

std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream in(line);
  std::string cell;
  while (std::getline(in, cell, ',')) cells.push_back(cell);
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}

std::vector<double> fine_of(double d) {
  const auto row = iso261_size(d);
  if (!row) return {};
  return {row->fine_pitches_mm.begin(), row->fine_pitches_mm.end()};
}

}  // namespace

TEST(Iso261Table, WellKnownCoarsePitches) {
  struct Case {
    double d;
    double coarse;
  };
  for (const Case c :
       {Case{1, 0.25}, Case{6, 1}, Case{8, 1.25}, Case{10, 1.5}, Case{12, 1.75}, Case{16, 2}, Case{20, 2.5},
        Case{24, 3}, Case{30, 3.5}, Case{36, 4}, Case{42, 4.5}, Case{48, 5}, Case{56, 5.5}, Case{64, 6}, Case{68, 6}}) {
    const auto row = iso261_size(c.d);
    ASSERT_TRUE(row.has_value()) << "M" << c.d;
    EXPECT_DOUBLE_EQ(row->diameter_mm, c.d);
    EXPECT_DOUBLE_EQ(row->coarse_pitch_mm, c.coarse) << "M" << c.d;
  }
}

TEST(Iso261Table, SmallAndSecondChoiceSizes) {
  EXPECT_DOUBLE_EQ(iso261_size(1.1)->coarse_pitch_mm, 0.25);
  EXPECT_DOUBLE_EQ(iso261_size(1.4)->coarse_pitch_mm, 0.3);
  EXPECT_DOUBLE_EQ(iso261_size(2.2)->coarse_pitch_mm, 0.45);
  EXPECT_DOUBLE_EQ(iso261_size(3.5)->coarse_pitch_mm, 0.6);
  EXPECT_DOUBLE_EQ(iso261_size(4.5)->coarse_pitch_mm, 0.75);
  EXPECT_EQ(iso261_size(1.1)->choice, 2);
  EXPECT_EQ(iso261_size(14)->choice, 2);
  EXPECT_EQ(iso261_size(5.5)->choice, 3);
  EXPECT_EQ(iso261_size(10)->choice, 1);
}

TEST(Iso261Table, FinePitchesAscendingForKnownRows) {
  EXPECT_EQ(fine_of(1), (std::vector<double>{0.2}));
  EXPECT_EQ(fine_of(8), (std::vector<double>{0.75, 1}));
  EXPECT_EQ(fine_of(10), (std::vector<double>{0.75, 1, 1.25}));
  EXPECT_EQ(fine_of(12), (std::vector<double>{1, 1.25, 1.5}));
  EXPECT_EQ(fine_of(14), (std::vector<double>{1, 1.25, 1.5}));
  EXPECT_EQ(fine_of(20), (std::vector<double>{1, 1.5, 2}));
  EXPECT_EQ(fine_of(30), (std::vector<double>{1, 1.5, 2, 3}));
  EXPECT_EQ(fine_of(33), (std::vector<double>{1.5, 2, 3}));
  EXPECT_EQ(fine_of(42), (std::vector<double>{1.5, 2, 3, 4}));
  EXPECT_EQ(fine_of(68), (std::vector<double>{1.5, 2, 3, 4}));
  EXPECT_EQ(fine_of(300), (std::vector<double>{4, 6, 8}));
}

TEST(Iso261Table, SizesWithoutCoarsePitch) {
  for (double d : {5.5, 15.0, 17.0, 25.0, 26.0, 28.0, 32.0, 35.0, 38.0, 40.0, 50.0, 55.0, 58.0, 62.0, 65.0}) {
    EXPECT_EQ(iso261_size(d)->coarse_pitch_mm, 0.0) << "M" << d;
  }
  EXPECT_DOUBLE_EQ(iso261_size(9)->coarse_pitch_mm, 1.25);
  EXPECT_DOUBLE_EQ(iso261_size(11)->coarse_pitch_mm, 1.5);
  // ISO 261 gives coarse pitches only up to 68 mm.
  for (const auto& row : iso261_sizes()) {
    if (row.diameter_mm > 68) {
      EXPECT_EQ(row.coarse_pitch_mm, 0.0) << "M" << row.diameter_mm;
    }
  }
}

TEST(Iso261Table, RangeAndOrdering) {
  const auto sizes = iso261_sizes();
  ASSERT_FALSE(sizes.empty());
  EXPECT_DOUBLE_EQ(sizes.front().diameter_mm, 1);
  EXPECT_DOUBLE_EQ(sizes.back().diameter_mm, 300);
  for (std::size_t i = 1; i < sizes.size(); ++i) {
    EXPECT_LT(sizes[i - 1].diameter_mm, sizes[i].diameter_mm) << "row " << i;
  }
}

TEST(Iso261Table, EveryRowIsConsistent) {
  for (const auto& row : iso261_sizes()) {
    SCOPED_TRACE(testing::Message() << "M" << row.diameter_mm);
    EXPECT_GE(row.choice, 1);
    EXPECT_LE(row.choice, 3);
    ASSERT_FALSE(row.fine_pitches_mm.empty());
    EXPECT_TRUE(std::is_sorted(row.fine_pitches_mm.begin(), row.fine_pitches_mm.end()));
    EXPECT_EQ(std::adjacent_find(row.fine_pitches_mm.begin(), row.fine_pitches_mm.end()), row.fine_pitches_mm.end());
    for (double p : row.fine_pitches_mm) {
      EXPECT_GT(p, 0.0);
      if (row.coarse_pitch_mm > 0) {
        EXPECT_LT(p, row.coarse_pitch_mm);
      }
    }
    const auto found = iso261_size(row.diameter_mm);
    ASSERT_TRUE(found.has_value());
    EXPECT_EQ(found->fine_pitches_mm.data(), row.fine_pitches_mm.data());
  }
}

TEST(Iso261Lookup, UnknownDiametersAreNullopt) {
  for (double d : {0.0, 0.9, 1.3, 1.7, 2.3, 2.6, 13.0, 19.0, 21.0, 23.0, 34.0, 66.0, 67.0, 77.0, 301.0, 1000.0, -6.0,
                   std::nan("")}) {
    EXPECT_FALSE(iso261_size(d).has_value()) << d;
  }
}

TEST(Iso261Lookup, ToleranceIsTight) {
  EXPECT_TRUE(iso261_size(6.0 + 5e-10).has_value());
  EXPECT_TRUE(iso261_size(6.0 - 5e-10).has_value());
  EXPECT_FALSE(iso261_size(6.0 + 1e-6).has_value());
  EXPECT_FALSE(iso261_size(6.0 - 1e-6).has_value());
  EXPECT_TRUE(iso261_size(1.1 + 2e-10).has_value());
}

TEST(Iso261Lookup, HasPitch) {
  EXPECT_TRUE(iso261_has_pitch(10, 1.5));
  EXPECT_TRUE(iso261_has_pitch(10, 1.25));
  EXPECT_TRUE(iso261_has_pitch(10, 0.75));
  EXPECT_FALSE(iso261_has_pitch(10, 0.5));
  EXPECT_FALSE(iso261_has_pitch(6, 0.5));
  EXPECT_TRUE(iso261_has_pitch(30, 1));
  EXPECT_FALSE(iso261_has_pitch(33, 1));
  EXPECT_TRUE(iso261_has_pitch(72, 6));
  EXPECT_FALSE(iso261_has_pitch(13, 1));
  EXPECT_FALSE(iso261_has_pitch(5.5, 0));  // "no coarse pitch" is not a pitch
}

TEST(Iso261Lookup, PitchNotes) {
  EXPECT_NE(iso261_pitch_note(14, 1.25), nullptr);
  EXPECT_NE(iso261_pitch_note(35, 1.5), nullptr);
  EXPECT_NE(iso261_pitch_note(30, 3), nullptr);
  EXPECT_NE(iso261_pitch_note(33, 3), nullptr);
  EXPECT_EQ(iso261_pitch_note(14, 1.5), nullptr);
  EXPECT_EQ(iso261_pitch_note(36, 3), nullptr);
}

// The ISO 965-2 oracle fixture names its rows by ISO 261 designations ("M6" for
// the coarse pitch, "M8x1" for a fine one): every row must be a combination
// this table lists, and its basic-size columns must agree with the pitch.
TEST(Iso261Fixture, LimitsFixtureUsesIso261Combinations) {
  const auto path = tk::test::project_root() / "test/fixtures/threads/iso965-2_limits.csv";
  std::ifstream in(path);
  ASSERT_TRUE(in) << path;
  std::string line;
  ASSERT_TRUE(std::getline(in, line));
  const auto header = split_csv(line);
  const std::vector<std::string> expected{"designation", "d_max",          "d_min",         "d2_max", "d2_min",
                                          "d3_max",      "D1_min",         "D1_max",        "D2_min", "D2_max",
                                          "source",      "external_class", "internal_class"};
  ASSERT_EQ(header, expected);
  int rows = 0;
  std::set<std::pair<long, long>> covered;  // (d, P) in micrometres
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    ++rows;
    const auto cells = split_csv(line);
    ASSERT_EQ(cells.size(), expected.size()) << line;
    SCOPED_TRACE(cells[0]);
    ASSERT_EQ(cells[0].rfind("M", 0), 0u);
    const std::string body = cells[0].substr(1);
    const auto x = body.find('x');
    const double d = std::stod(body.substr(0, x));
    const auto row = iso261_size(d);
    ASSERT_TRUE(row.has_value());
    const double p = x == std::string::npos ? row->coarse_pitch_mm : std::stod(body.substr(x + 1));
    if (x == std::string::npos) {
      EXPECT_GT(p, 0.0) << "a designation without pitch needs a coarse pitch";
    } else {
      EXPECT_NE(p, row->coarse_pitch_mm) << "the coarse pitch is written without 'x'";
    }
    EXPECT_TRUE(iso261_has_pitch(d, p));
    covered.insert({std::lround(d * 1000), std::lround(p * 1000)});
    auto value = [&](std::size_t i) { return cells[i].empty() ? std::nan("") : std::stod(cells[i]); };
    for (std::size_t i = 1; i <= 9; ++i) {
      if (!cells[i].empty()) {
        EXPECT_EQ(cells[i].size() - cells[i].find('.'), 4u) << header[i] << " needs 3 decimals";
      }
    }
    // max above min where both are given
    for (auto [hi, lo] : {std::pair{1, 2}, std::pair{3, 4}, std::pair{7, 6}, std::pair{9, 8}}) {
      if (!cells[hi].empty() && !cells[lo].empty()) {
        EXPECT_GT(value(hi), value(lo)) << header[hi];
      }
    }
    // H-position minima are the basic sizes (ISO 724), rounded to 0.001 mm
    if (!cells[8].empty()) {
      EXPECT_NEAR(value(8), d - 0.649519053 * p, 0.0006);
    }
    if (!cells[6].empty()) {
      EXPECT_NEAR(value(6), d - 1.082531755 * p, 0.0006);
    }
    const bool external = !cells[1].empty() || !cells[2].empty() || !cells[3].empty() || !cells[4].empty();
    const bool internal = !cells[6].empty() || !cells[7].empty() || !cells[8].empty() || !cells[9].empty();
    EXPECT_TRUE(external || internal);
    EXPECT_EQ(cells[11].empty(), !external);
    EXPECT_EQ(cells[12], internal ? "6H" : "");
    EXPECT_FALSE(cells[10].empty());
  }
  EXPECT_GE(rows, 100);
  // The issue asks for every ISO 261 size from M1 to M68, coarse and fine.
  for (const Iso261Size& size : iso261_sizes()) {
    if (size.diameter_mm > 68) break;
    std::vector<double> pitches(size.fine_pitches_mm.begin(), size.fine_pitches_mm.end());
    if (size.coarse_pitch_mm > 0) pitches.push_back(size.coarse_pitch_mm);
    for (double p : pitches)
      EXPECT_TRUE(covered.count({std::lround(size.diameter_mm * 1000), std::lround(p * 1000)}))
          << "M" << size.diameter_mm << "x" << p << " has no published row";
  }
}
