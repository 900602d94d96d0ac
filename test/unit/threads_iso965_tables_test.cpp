// Unit tests for the ISO 965-1 tables (libshared/threads/iso965_tables.cpp):
// every tabulated entry against the standard's clause 10 formulas, published
// anchors and limits of size from independent sources, monotonicity, the
// formula fallback and the refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "threads/iso965_tables.hpp"

using namespace tk::threads;

namespace {

// The clause 10 formulas, unrounded, written out again here (not taken from
// the library) so that a transcription typo in the tables shows against them.
double td6(double p) { return 180 * std::pow(p, 2.0 / 3) - 3.15 / std::sqrt(p); }
double td1_6(double p) { return p <= 0.8 ? 433 * p - 190 * std::pow(p, 1.22) : 230 * std::pow(p, 0.7); }
double td2_6(double p, double over, double up_to) {
  return 90 * std::pow(p, 0.4) * std::pow(std::sqrt(over * up_to), 0.1);  // d: the range's geometric mean
}
double major_factor(int g) { return g == 4 ? 0.63 : g == 6 ? 1.0 : 1.6; }
double minor_factor(int g) { return std::vector<double>{0.63, 0.8, 1.0, 1.25, 1.6}[g - 4]; }
double external_factor(int g) { return std::vector<double>{0.5, 0.63, 0.8, 1.0, 1.25, 1.6, 2.0}[g - 3]; }
double internal_factor(int g) { return std::vector<double>{0.85, 1.06, 1.32, 1.7, 2.12}[g - 4]; }  // x Td2(6)

// One tabulated tolerance, with the formula value it rounds.
struct Entry {
  std::string what;
  int grade;
  int value;
  double formula;
  double row_grade6;  // the same row's grade 6 entry (for TD2: the row's Td2(6))
  double factor;      // the clause 10 factor of this grade relative to row_grade6
};

std::vector<Entry> all_entries() {
  std::vector<Entry> out;
  for (double p : iso965_pitches()) {
    const std::string at = " P " + std::to_string(p);
    for (int g : {4, 6, 8})
      if (auto v = major_diameter_tolerance(g, p))
        out.push_back({"Td" + at, g, v->value, major_factor(g) * td6(p), double(major_diameter_tolerance(6, p)->value),
                       major_factor(g)});
    for (int g = 4; g <= 8; ++g)
      if (auto v = minor_diameter_tolerance(g, p)) {
        auto six = minor_diameter_tolerance(6, p);
        if (!six) continue;  // rows without grade 6 (P 0.2, 0.25) are checked against the formula only
        out.push_back({"TD1" + at, g, v->value, minor_factor(g) * td1_6(p), double(six->value), minor_factor(g)});
      }
  }
  // rows of TD1 without grade 6 still count against the formula
  for (double p : {0.2, 0.25})
    for (int g = 4; g <= 5; ++g)
      if (auto v = minor_diameter_tolerance(g, p))
        out.push_back({"TD1 P " + std::to_string(p), g, v->value, minor_factor(g) * td1_6(p), 0, 0});
  for (const Iso965DiameterPitch& r : iso965_pitch_diameter_rows()) {
    const double d = (r.over_mm + r.up_to_mm) / 2;  // any diameter inside the range
    const std::string at =
        " d " + std::to_string(r.over_mm) + "-" + std::to_string(r.up_to_mm) + " P " + std::to_string(r.pitch_mm);
    const double raw = td2_6(r.pitch_mm, r.over_mm, r.up_to_mm);
    const double six = external_pitch_diameter_tolerance(6, d, r.pitch_mm)->value;
    for (int g = 3; g <= 9; ++g)
      if (auto v = external_pitch_diameter_tolerance(g, d, r.pitch_mm))
        out.push_back({"Td2" + at, g, v->value, external_factor(g) * raw, six, external_factor(g)});
    for (int g = 4; g <= 8; ++g)
      if (auto v = internal_pitch_diameter_tolerance(g, d, r.pitch_mm))
        out.push_back({"TD2" + at, g, v->value, internal_factor(g) * raw, six, internal_factor(g)});
  }
  return out;
}

int count_of(const std::vector<Entry>& entries, const std::string& prefix) {
  int n = 0;
  for (const Entry& e : entries) n += e.what.rfind(prefix, 0) == 0 && e.what[prefix.size()] == ' ';
  return n;
}

// Whole-micrometre values of the R40 series (ISO 3), as the tables print them
// (under 100 um the rounded series R'40: 26, 32, 34, 36, 38, 42, 48).
bool is_r40(int v) {
  static const std::vector<int> mantissa = {100, 106, 112, 118, 125, 132, 140, 150, 160, 170, 180, 190, 200, 212,
                                            224, 236, 250, 265, 280, 300, 315, 335, 355, 375, 400, 425, 450, 475,
                                            500, 530, 560, 600, 630, 670, 710, 750, 800, 850, 900, 950};
  static const std::vector<int> two_digit = {17, 18, 19, 20, 21, 22, 24, 25, 26, 28, 30, 32, 34, 36, 38, 40,
                                             42, 45, 48, 50, 53, 56, 60, 63, 67, 71, 75, 80, 85, 90, 95};
  for (int m : mantissa)
    if (v == m || v == 10 * m) return true;
  for (int m : two_digit)
    if (v == m) return true;
  return false;
}

int um(double mm_difference) { return static_cast<int>(std::lround(mm_difference * 1000)); }
int value_or_zero(const std::optional<Micrometres>& v) { return v ? v->value : 0; }

}  // namespace

// ---------------------------------------------------------------- the tables as a whole

// Catches dropped or blanked cells: the tables hold 65 Td, 106 TD1, 296 Td2, 205 TD2 entries.
TEST(Iso965Tables, EntryCounts) {
  const std::vector<Entry> entries = all_entries();
  EXPECT_EQ(count_of(entries, "Td"), 65);
  EXPECT_EQ(count_of(entries, "TD1"), 106);
  EXPECT_EQ(count_of(entries, "Td2"), 296);
  EXPECT_EQ(count_of(entries, "TD2"), 205);
  EXPECT_EQ(iso965_pitches().size(), 25u);
  EXPECT_EQ(iso965_pitch_diameter_rows().size(), 47u);
}

// Every tabulated tolerance within 7 % of the unrounded clause 10 formula. Why 7 %:
// R40 numbers lie 5.9 % apart, so rounding alone moves a value up to 2.9 %, the
// grade 6 value is rounded before it is scaled (up to 2.9 % more), and the
// hand-smoothed entries reach 6.7 % (TD1(7) at P 0.5 is 180, the formula 168.7).
// A digit typo (365 for 265, 198 for 180) is 10 % or more off.
TEST(Iso965Tables, EveryToleranceNearFormula) {
  for (const Entry& e : all_entries())
    EXPECT_NEAR(e.value / e.formula, 1.0, 0.07)
        << e.what << " grade " << e.grade << ": " << e.value << " against formula " << e.formula;
}

// Within a row the grades follow the clause 10 factors: every entry within 4.5 % of
// factor x the row's own grade 6 entry (rounding one value to R40 is 2.9 % at most;
// the largest seen is 3.9 %, Td(8) at P 8). This catches a swap of neighbouring R40
// numbers the 7 % check lets through (TD2(8) 22.4-45/P 2 as 335 instead of 355 is 7 % off).
TEST(Iso965Tables, GradesFollowFactorsWithinRow) {
  for (const Entry& e : all_entries()) {
    if (e.factor == 0) continue;
    EXPECT_NEAR(e.value / (e.factor * e.row_grade6), 1.0, 0.045) << e.what << " grade " << e.grade;
  }
}

// Every tabulated tolerance is an R40 number (a typo like 198 or 263 is not).
TEST(Iso965Tables, EveryToleranceIsAnR40Number) {
  for (const Entry& e : all_entries()) {
    EXPECT_TRUE(is_r40(e.value)) << e.what << " grade " << e.grade << ": " << e.value;
  }
}

// ---------------------------------------------------------------- Table 1

// g and G within 6 % of 15 + 11P (the largest, 5.4 %, is P 0.75: 22 against 23.25);
// f within 5 % of 30 + 11P (largest 4 %, P 1.25: 42 against 43.75); e within 6.5 %
// of 50 + 11P from P 0.7 (largest 3.9 %) - below, the table departs from the formula
// on purpose and all sources agree: P 0.5 is 50 (formula 55.5), P 0.6 is 53 (56.6).
TEST(Iso965Deviations, EveryEntryNearFormula) {
  int g_count = 0, e_count = 0, f_count = 0;
  for (double p : iso965_pitches()) {
    const auto G = fundamental_deviation('G', p), g = fundamental_deviation('g', p);
    ASSERT_TRUE(G && g) << p;
    EXPECT_EQ(G->value, -g->value) << p;
    EXPECT_NEAR(G->value / (15 + 11 * p), 1.0, 0.06) << p;
    EXPECT_TRUE(is_r40(G->value)) << p;
    ++g_count;
    if (auto f = fundamental_deviation('f', p)) {
      EXPECT_NEAR(-f->value / (30 + 11 * p), 1.0, 0.05) << p;
      ++f_count;
    }
    if (auto e = fundamental_deviation('e', p)) {
      EXPECT_TRUE(is_r40(-e->value)) << p;
      EXPECT_TRUE(p < 0.7 || std::fabs(-e->value / (50 + 11 * p) - 1) <= 0.065) << p;
      ++e_count;
    }
    EXPECT_EQ(fundamental_deviation('H', p)->value, 0);
    EXPECT_EQ(fundamental_deviation('h', p)->value, 0);
  }
  EXPECT_EQ(g_count, 25);
  EXPECT_EQ(e_count, 19);  // from P 0.5
  EXPECT_EQ(f_count, 22);  // from P 0.35
  EXPECT_EQ(fundamental_deviation('e', 0.5)->value, -50);
  EXPECT_EQ(fundamental_deviation('e', 0.6)->value, -53);
}

TEST(Iso965Deviations, SignsSourcesAndUndefinedPositions) {
  const auto g = fundamental_deviation('g', 2.0);
  ASSERT_TRUE(g);
  EXPECT_EQ(g->value, -38);  // the formula gives 37; the table says 38
  EXPECT_FALSE(g->computed);
  EXPECT_STREQ(g->source, "ISO 965-1:2013 Table 1");
  EXPECT_EQ(fundamental_deviation('G', 2.0)->value, 38);
  EXPECT_EQ(fundamental_deviation('f', 2.0)->value, -52);
  EXPECT_EQ(fundamental_deviation('e', 2.0)->value, -71);
  EXPECT_EQ(fundamental_deviation('g', 4.0)->value, -60);
  EXPECT_FALSE(fundamental_deviation('e', 0.45));
  EXPECT_FALSE(fundamental_deviation('e', 0.2));
  EXPECT_FALSE(fundamental_deviation('f', 0.3));
  EXPECT_TRUE(fundamental_deviation('f', 0.35));
  for (char c : {'a', 'b', 'c', 'd', 'E', 'F', 'x', '6', '\0'}) EXPECT_FALSE(fundamental_deviation(c, 1.0)) << c;
}

// ---------------------------------------------------------------- published anchors

TEST(Iso965Anchors, PublishedValues) {
  EXPECT_EQ(external_pitch_diameter_tolerance(6, 8, 1.0)->value, 112);   // M8x1 6g
  EXPECT_EQ(external_pitch_diameter_tolerance(6, 10, 1.5)->value, 132);  // M10 6g
  EXPECT_EQ(external_pitch_diameter_tolerance(6, 30, 2.0)->value, 170);  // 22.4-45, P 2
  EXPECT_EQ(internal_pitch_diameter_tolerance(6, 30, 2.0)->value, 224);
  EXPECT_EQ(major_diameter_tolerance(6, 1.0)->value, 180);
  EXPECT_EQ(major_diameter_tolerance(6, 1.5)->value, 236);
  EXPECT_EQ(major_diameter_tolerance(6, 2.0)->value, 280);
  EXPECT_EQ(minor_diameter_tolerance(6, 2.0)->value, 375);
  // entries the tables smooth away from the formula (kept as printed)
  EXPECT_EQ(major_diameter_tolerance(6, 4.0)->value, 475);             // formula 452
  EXPECT_EQ(external_pitch_diameter_tolerance(6, 3, 0.5)->value, 75);  // formula 78.3
  EXPECT_EQ(minor_diameter_tolerance(7, 0.5)->value, 180);             // formula 168.7
  // the four cells where source B disagrees with A, C and the formula
  EXPECT_EQ(external_pitch_diameter_tolerance(9, 16, 1.25)->value, 265);
  EXPECT_EQ(external_pitch_diameter_tolerance(9, 60, 2.0)->value, 355);
  EXPECT_EQ(external_pitch_diameter_tolerance(4, 200, 4.0)->value, 180);
  EXPECT_EQ(internal_pitch_diameter_tolerance(8, 30, 2.0)->value, 355);
}

// ISO 965-2 limits of size (mm) as published independently of the tables' sources:
// M1-M4 from Fabory "Screw threads" (5H/6h up to M1.4, 6H/6g above; M4's D1 and
// M5-M30 from threadlib's metric_thread.csv). The differences are es, Td, Td2, TD1, TD2.
TEST(Iso965Anchors, Iso965Part2Limits) {
  struct Limits {
    double d, p;
    char position;
    int internal_grade;
    double d_max, d_min, d2_max, d2_min, D1_min, D1_max, D2_min, D2_max;
  };
  const std::vector<Limits> rows = {
      {1.0, 0.25, 'h', 5, 1.000, 0.933, 0.838, 0.785, 0.729, 0.785, 0.838, 0.894},
      {1.2, 0.25, 'h', 5, 1.200, 1.133, 1.038, 0.985, 0.929, 0.985, 1.038, 1.094},
      {1.4, 0.3, 'h', 5, 1.400, 1.325, 1.205, 1.149, 1.075, 1.142, 1.205, 1.265},
      {1.6, 0.35, 'g', 6, 1.581, 1.496, 1.354, 1.291, 1.221, 1.321, 1.373, 1.458},
      {2.0, 0.4, 'g', 6, 1.981, 1.886, 1.721, 1.654, 1.567, 1.679, 1.740, 1.830},
      {2.5, 0.45, 'g', 6, 2.480, 2.380, 2.188, 2.117, 2.013, 2.138, 2.208, 2.303},
      {3.0, 0.5, 'g', 6, 2.980, 2.874, 2.655, 2.580, 2.459, 2.599, 2.675, 2.775},
      {3.5, 0.6, 'g', 6, 3.479, 3.354, 3.089, 3.004, 2.850, 3.010, 3.110, 3.222},
      {4.0, 0.7, 'g', 6, 3.978, 3.838, 3.523, 3.433, 3.242, 3.422, 3.545, 3.663},
      {5.0, 0.8, 'g', 6, 4.976, 4.826, 4.456, 4.361, 4.134, 4.334, 4.480, 4.605},
      {6.0, 1.0, 'g', 6, 5.974, 5.794, 5.324, 5.212, 4.917, 5.153, 5.350, 5.500},
      {8.0, 1.25, 'g', 6, 7.972, 7.760, 7.160, 7.042, 6.647, 6.912, 7.188, 7.348},
      {10.0, 1.5, 'g', 6, 9.968, 9.732, 8.994, 8.862, 8.376, 8.676, 9.026, 9.206},
  };
  for (const Limits& r : rows) {
    SCOPED_TRACE(testing::Message() << "M" << r.d << "x" << r.p);
    EXPECT_EQ(fundamental_deviation(r.position, r.p)->value, um(r.d_max - r.d));
    EXPECT_EQ(major_diameter_tolerance(6, r.p)->value, um(r.d_max - r.d_min));
    EXPECT_EQ(external_pitch_diameter_tolerance(6, r.d, r.p)->value, um(r.d2_max - r.d2_min));
    EXPECT_EQ(minor_diameter_tolerance(r.internal_grade, r.p)->value, um(r.D1_max - r.D1_min));
    EXPECT_EQ(internal_pitch_diameter_tolerance(r.internal_grade, r.d, r.p)->value, um(r.D2_max - r.D2_min));
  }
  // larger coarse sizes, internal thread 6H only (threadlib gives the external to 0.01 mm there)
  struct Internal {
    double d, p, D1_min, D1_max, D2_min, D2_max;
  };
  for (const Internal& r : std::vector<Internal>{{12, 1.75, 10.106, 10.441, 10.863, 11.063},
                                                 {14, 2.0, 11.835, 12.210, 12.701, 12.913},
                                                 {20, 2.5, 17.294, 17.744, 18.376, 18.600},
                                                 {24, 3.0, 20.752, 21.252, 22.051, 22.316},
                                                 {30, 3.5, 26.211, 26.771, 27.727, 28.007}}) {
    EXPECT_EQ(minor_diameter_tolerance(6, r.p)->value, um(r.D1_max - r.D1_min)) << r.d;
    EXPECT_EQ(internal_pitch_diameter_tolerance(6, r.d, r.p)->value, um(r.D2_max - r.D2_min)) << r.d;
  }
}

// Yamawa tap catalogue: TD2 of 4H, 5H, 6H and EI of G for coarse threads M1 to M8.
TEST(Iso965Anchors, YamawaTapCatalogue) {
  struct Row {
    double d, p;
    int td2[3];  // 4H 5H 6H, 0 = not listed (the standard has no 6H at P 0.25)
    int G;       // 0 = not listed
  };
  for (const Row& r : std::vector<Row>{{1.0, 0.25, {45, 56, 0}, 0},
                                       {1.4, 0.3, {48, 60, 75}, 0},
                                       {1.6, 0.35, {53, 67, 85}, 0},
                                       {2.0, 0.4, {56, 71, 90}, 0},
                                       {2.5, 0.45, {60, 75, 95}, 0},
                                       {3.0, 0.5, {63, 80, 100}, 20},
                                       {3.5, 0.6, {71, 90, 112}, 21},
                                       {4.0, 0.7, {75, 95, 118}, 22},
                                       {5.0, 0.8, {80, 100, 125}, 24},
                                       {6.0, 1.0, {95, 118, 150}, 26},
                                       {8.0, 1.25, {100, 125, 160}, 28}}) {
    for (int i = 0; i < 3; ++i) EXPECT_EQ(value_or_zero(internal_pitch_diameter_tolerance(4 + i, r.d, r.p)), r.td2[i]);
    if (r.G) {
      EXPECT_EQ(fundamental_deviation('G', r.p)->value, r.G) << r.d;
    }
  }
}

// ---------------------------------------------------------------- monotonicity

TEST(Iso965Monotonic, GrowsWithGradePitchAndDiameter) {
  using Values = std::vector<std::optional<Micrometres>>;
  // The values that exist grow along the sequence (strictly: never tie).
  const auto expect_growing = [](const Values& values, bool strictly, const std::string& what) {
    std::optional<int> last;
    for (const auto& v : values) {
      if (!v) continue;
      if (last) {
        EXPECT_TRUE(strictly ? v->value > *last : v->value >= *last) << what << ": " << v->value;
      }
      last = v->value;
    }
  };
  const auto pitches = iso965_pitches();
  for (double p : pitches) {  // with grade
    expect_growing({major_diameter_tolerance(4, p), major_diameter_tolerance(6, p), major_diameter_tolerance(8, p)},
                   true, "Td P " + std::to_string(p));
    Values td1;
    for (int g = 4; g <= 8; ++g) td1.push_back(minor_diameter_tolerance(g, p));
    expect_growing(td1, true, "TD1 P " + std::to_string(p));
  }
  for (int g = 4; g <= 8; ++g) {  // with pitch (0.7 and 0.75 tie)
    Values td, td1;
    for (double p : pitches) {
      td.push_back(major_diameter_tolerance(g, p));
      td1.push_back(minor_diameter_tolerance(g, p));
    }
    expect_growing(td, false, "Td grade " + std::to_string(g));
    expect_growing(td1, false, "TD1 grade " + std::to_string(g));
  }
  for (char c : {'e', 'f', 'g'}) {  // |es| with pitch
    Values magnitudes;
    for (double p : pitches) {
      auto v = fundamental_deviation(c, p);
      if (v) v->value = -v->value;
      magnitudes.push_back(v);
    }
    expect_growing(magnitudes, false, std::string("es ") + c);
  }
  const auto rows = iso965_pitch_diameter_rows();  // in table order: by range, then by pitch
  for (auto [name, lookup, lowest, highest] : {std::tuple{"Td2", &external_pitch_diameter_tolerance, 3, 9},
                                               std::tuple{"TD2", &internal_pitch_diameter_tolerance, 4, 8}})
    for (const Iso965DiameterPitch& r : rows) {
      const std::string at = name + (" d " + std::to_string(r.up_to_mm)) + " P " + std::to_string(r.pitch_mm);
      Values by_grade;
      for (int g = lowest; g <= highest; ++g) by_grade.push_back(lookup(g, r.up_to_mm, r.pitch_mm));
      expect_growing(by_grade, true, at);
      for (int g = lowest; g <= highest; ++g) {
        Values by_pitch, by_diameter;  // the pitches of r's range; r's pitch in every range listing it
        for (const Iso965DiameterPitch& s : rows) {
          if (s.over_mm == r.over_mm) by_pitch.push_back(lookup(g, s.up_to_mm, s.pitch_mm));
          if (s.pitch_mm == r.pitch_mm) by_diameter.push_back(lookup(g, s.up_to_mm, s.pitch_mm));
        }
        expect_growing(by_pitch, false, at + " grade " + std::to_string(g) + ", by pitch");
        expect_growing(by_diameter, false, at + " grade " + std::to_string(g) + ", by diameter");
      }
    }
}

// The formula fallback keeps the order too: a sweep over untabulated pitches.
TEST(Iso965Monotonic, ComputedValuesNeverShrinkWithPitch) {
  int last_td = 0, last_td1 = 0, last_td2 = 0, last_g = 0;
  for (double p = 0.83; p < 8; p += 0.1) {
    const auto td = major_diameter_tolerance(6, p), td1 = minor_diameter_tolerance(6, p);
    const auto td2 = external_pitch_diameter_tolerance(6, 1000, p), g = fundamental_deviation('g', p);
    ASSERT_TRUE(td && td1 && td2 && g) << p;
    EXPECT_TRUE(td->computed && td1->computed && td2->computed && g->computed) << p;
    EXPECT_GE(td->value, last_td) << p;
    EXPECT_GE(td1->value, last_td1) << p;
    EXPECT_GE(td2->value, last_td2) << p;
    EXPECT_GE(-g->value, last_g) << p;
    last_td = td->value, last_td1 = td1->value, last_td2 = td2->value, last_g = -g->value;
  }
}

// ---------------------------------------------------------------- lookups

TEST(Iso965Lookup, DiameterRangesAreOverUpToAndIncluding) {
  EXPECT_EQ(external_pitch_diameter_tolerance(6, 1.4, 0.3)->value, 56);  // 1.4 is in 0.99-1.4
  EXPECT_FALSE(external_pitch_diameter_tolerance(6, 1.4, 0.3)->computed);
  EXPECT_TRUE(external_pitch_diameter_tolerance(6, 1.41, 0.3)->computed);  // 1.4-2.8 lists no 0.3
  EXPECT_EQ(external_pitch_diameter_tolerance(6, 5.6, 0.8)->value, 95);    // 2.8-5.6
  EXPECT_EQ(external_pitch_diameter_tolerance(6, 5.61, 1.0)->value, 112);  // 5.6-11.2
  EXPECT_EQ(external_pitch_diameter_tolerance(6, 355, 8.0)->value, 355);
  EXPECT_TRUE(external_pitch_diameter_tolerance(6, 355.1, 8.0)->computed);
  EXPECT_TRUE(external_pitch_diameter_tolerance(6, 0.99, 0.2)->computed);  // 0.99 itself is below the first range
  EXPECT_STREQ(external_pitch_diameter_tolerance(6, 10, 1.5)->source, "ISO 965-1:2013 Table 5");
  EXPECT_STREQ(internal_pitch_diameter_tolerance(6, 10, 1.5)->source, "ISO 965-1:2013 Table 4");
  EXPECT_STREQ(minor_diameter_tolerance(6, 1.5)->source, "ISO 965-1:2013 Table 2");
  EXPECT_STREQ(major_diameter_tolerance(6, 1.5)->source, "ISO 965-1:2013 Table 3");
}

TEST(Iso965Lookup, PitchMatchesWithinOneNanometre) {
  EXPECT_FALSE(major_diameter_tolerance(6, 1.0 + 5e-10)->computed);
  EXPECT_FALSE(major_diameter_tolerance(6, 1.0 - 5e-10)->computed);
  EXPECT_TRUE(major_diameter_tolerance(6, 1.0 + 1e-6)->computed);
  EXPECT_FALSE(fundamental_deviation('g', 1.25 + 1e-10)->computed);
}

// Cases the tables do not hold: the formula, rounded to R40, flagged computed.
TEST(Iso965Computed, UntabulatedPitchOrDiameter) {
  // M10x2: 5.6-11.2 lists no P 2; Td2(6) = 90 * 2^0.4 * 7.92^0.1 = 146.1 -> 150, TD2(6) = 1.32 * 150 = 198 -> 200
  const auto td2 = external_pitch_diameter_tolerance(6, 10, 2.0);
  ASSERT_TRUE(td2);
  EXPECT_TRUE(td2->computed);
  EXPECT_EQ(td2->value, 150);
  EXPECT_NE(std::string(td2->source).find("formula"), std::string::npos);
  EXPECT_EQ(internal_pitch_diameter_tolerance(6, 10, 2.0)->value, 200);
  EXPECT_EQ(external_pitch_diameter_tolerance(8, 10, 2.0)->value, 236);  // 1.6 * 150 = 240 -> 236
  // beyond 355 mm, d itself: 90 * 6^0.4 * 400^0.1 = 335.5 -> 335
  EXPECT_EQ(external_pitch_diameter_tolerance(6, 400, 6.0)->value, 335);
  EXPECT_TRUE(external_pitch_diameter_tolerance(6, 400, 6.0)->computed);
  // P 0.9 is in no table: Td(6) = 164.5 -> 160, TD1(6) = 213.7 -> 212, g 24.9 -> 25
  EXPECT_EQ(major_diameter_tolerance(6, 0.9)->value, 160);
  EXPECT_EQ(minor_diameter_tolerance(6, 0.9)->value, 212);
  EXPECT_EQ(fundamental_deviation('g', 0.9)->value, -25);
  EXPECT_TRUE(fundamental_deviation('g', 0.9)->computed);
  EXPECT_EQ(fundamental_deviation('h', 0.9)->value, 0);
  EXPECT_FALSE(fundamental_deviation('h', 0.9)->computed);  // zero by definition at every pitch
  // R40 values under 100 um go to whole micrometres with halves to even, as the tables print them:
  EXPECT_EQ(fundamental_deviation('G', 1.1)->value, 26);    // 27.1 -> R40 26.5 -> 26
  EXPECT_EQ(fundamental_deviation('g', 1.45)->value, -32);  // 30.95 -> R40 31.5 -> 32
  // beyond the tables' 8 mm
  EXPECT_EQ(major_diameter_tolerance(6, 10)->value, 850);  // 180 * 10^(2/3) - 3.15 / sqrt(10) = 834.5 -> 850
}

// A grade the tables leave empty stays empty, tabulated or not.
TEST(Iso965Computed, EmptyCellsAndFinePitchesGiveNothing) {
  EXPECT_FALSE(major_diameter_tolerance(8, 0.5));   // Td(8) starts at P 0.8
  EXPECT_FALSE(major_diameter_tolerance(8, 0.55));  // not tabulated, still below 0.8
  EXPECT_TRUE(major_diameter_tolerance(8, 0.9));
  EXPECT_FALSE(minor_diameter_tolerance(8, 0.75));
  EXPECT_FALSE(minor_diameter_tolerance(6, 0.25));
  EXPECT_FALSE(internal_pitch_diameter_tolerance(8, 30, 1.0));  // the one TD2(8) hole above P 0.8
  EXPECT_FALSE(external_pitch_diameter_tolerance(8, 8, 0.75));
  EXPECT_FALSE(external_pitch_diameter_tolerance(7, 1.2, 0.3));
  EXPECT_FALSE(fundamental_deviation('e', 0.42));  // untabulated, below e's 0.5
  EXPECT_FALSE(fundamental_deviation('f', 0.32));
  EXPECT_TRUE(fundamental_deviation('e', 0.55));
}

TEST(Iso965Lookup, InvalidInputsGiveNothing) {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  for (double p : {0.0, -1.0, nan, inf, -inf}) {
    EXPECT_FALSE(fundamental_deviation('g', p)) << p;
    EXPECT_FALSE(fundamental_deviation('h', p)) << p;
    EXPECT_FALSE(major_diameter_tolerance(6, p)) << p;
    EXPECT_FALSE(minor_diameter_tolerance(6, p)) << p;
    EXPECT_FALSE(external_pitch_diameter_tolerance(6, 10, p)) << p;
    EXPECT_FALSE(internal_pitch_diameter_tolerance(6, 10, p)) << p;
    EXPECT_FALSE(external_pitch_diameter_tolerance(6, p, 1.0)) << p;
    EXPECT_FALSE(internal_pitch_diameter_tolerance(6, p, 1.0)) << p;
  }
  for (int g : {-1, 0, 3, 5, 7, 9}) EXPECT_FALSE(major_diameter_tolerance(g, 1.0)) << g;
  for (int g : {3, 9}) EXPECT_FALSE(minor_diameter_tolerance(g, 1.0)) << g;
  for (int g : {2, 10}) EXPECT_FALSE(external_pitch_diameter_tolerance(g, 10, 1.0)) << g;
  for (int g : {3, 9}) EXPECT_FALSE(internal_pitch_diameter_tolerance(g, 10, 1.0)) << g;
  EXPECT_FALSE(major_diameter_tolerance(6, 1e-4));  // the formula goes negative
}
