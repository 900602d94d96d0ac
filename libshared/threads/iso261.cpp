/// @file iso261.cpp
/// @brief ISO 261:1998 Table 1 (general plan of diameter-pitch combinations)
/// as constant data.
///
/// Transcribed from the text of GB/T 193-2003 "General purpose metric screw
/// threads - General plan", the Chinese national standard that reproduces
/// ISO 261:1998 identically (same diameters 1-300 mm, same coarse and fine
/// pitches, same footnotes on M14x1.25 and M35x1.5 and the bracketed pitch 3
/// of M30 and M33):
///   https://m.docduoduo.com/p-8483904.html
/// cross-checked row by row against a second, independent transcription of
/// ISO 261 that also records the choice column of every combination:
///   https://github.com/martinproks/cosmeticthread3d (MetricCoarse1st/2nd/3th.py,
///   MetricFine1st/2nd/3th.py)
/// and, for the first and second choice sizes up to M64, against the ISO 262
/// subset on Wikipedia's "ISO metric screw thread" (Preferred sizes):
///   https://en.wikipedia.org/wiki/ISO_metric_screw_thread
///   (mirror: https://www.liquisearch.com/iso_metric_screw_thread/preferred_sizes)
/// and the first/second choice columns of the BIS (IS 4218) diameter-pitch
/// table reproduced in a Machine Drawing textbook, Table 5.1:
///   https://issuhub.com/view/index/5590?pageIndex=103
///
/// Where the sources disagreed, the standard's text (GB/T 193) was followed:
///   - cosmeticthread3d gives M1.4 a coarse pitch of 0.25 mm; GB/T 193,
///     Wikipedia and Mastik's ISO 965 table all give 0.3 mm.
///   - cosmeticthread3d omits M30x1; GB/T 193 lists 1 among M30's fine pitches
///     (M33, by contrast, really has no 1 mm pitch).
/// The choice column (1/2/3) is not recoverable from the flattened GB/T text;
/// it is taken from cosmeticthread3d and agrees with Wikipedia/ISO 262 and
/// IS 4218 wherever those give it (up to M100).
///
/// Conventions:
///   - fine pitches are stored in ascending order, each once;
///   - above 68 mm ISO 261 has no coarse pitch (coarse_pitch_mm = 0) and every
///     pitch of the row, including 6 and 8 mm, is a fine pitch;
///   - column-3 sizes M5.5, M15, M17, M25, M26, M28, M32, M35, M38, M40, M50,
///     M55, M58, M62, M65 have no coarse pitch either; M9 and M11 do.
#include "threads/iso261.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace tk::threads {

namespace {

constexpr double kTolerance = 1e-9;

bool same(double a, double b) { return std::fabs(a - b) <= kTolerance; }

// Fine pitches of each row, ascending.
constexpr double k1[] = {0.2};
constexpr double k1_1[] = {0.2};
constexpr double k1_2[] = {0.2};
constexpr double k1_4[] = {0.2};
constexpr double k1_6[] = {0.2};
constexpr double k1_8[] = {0.2};
constexpr double k2[] = {0.25};
constexpr double k2_2[] = {0.25};
constexpr double k2_5[] = {0.35};
constexpr double k3[] = {0.35};
constexpr double k3_5[] = {0.35};
constexpr double k4[] = {0.5};
constexpr double k4_5[] = {0.5};
constexpr double k5[] = {0.5};
constexpr double k5_5[] = {0.5};
constexpr double k6[] = {0.75};
constexpr double k7[] = {0.75};
constexpr double k8[] = {0.75, 1};
constexpr double k9[] = {0.75, 1};
constexpr double k10[] = {0.75, 1, 1.25};
constexpr double k11[] = {0.75, 1};
constexpr double k12[] = {1, 1.25, 1.5};
constexpr double k14[] = {1, 1.25, 1.5};
constexpr double k15[] = {1, 1.5};
constexpr double k16[] = {1, 1.5};
constexpr double k17[] = {1, 1.5};
constexpr double k18[] = {1, 1.5, 2};
constexpr double k20[] = {1, 1.5, 2};
constexpr double k22[] = {1, 1.5, 2};
constexpr double k24[] = {1, 1.5, 2};
constexpr double k25[] = {1, 1.5, 2};
constexpr double k26[] = {1.5};
constexpr double k27[] = {1, 1.5, 2};
constexpr double k28[] = {1, 1.5, 2};
constexpr double k30[] = {1, 1.5, 2, 3};
constexpr double k32[] = {1.5, 2};
constexpr double k33[] = {1.5, 2, 3};
constexpr double k35[] = {1.5};
constexpr double k36[] = {1.5, 2, 3};
constexpr double k38[] = {1.5};
constexpr double k39[] = {1.5, 2, 3};
constexpr double k40[] = {1.5, 2, 3};
constexpr double k42[] = {1.5, 2, 3, 4};
constexpr double k45[] = {1.5, 2, 3, 4};
constexpr double k48[] = {1.5, 2, 3, 4};
constexpr double k50[] = {1.5, 2, 3};
constexpr double k52[] = {1.5, 2, 3, 4};
constexpr double k55[] = {1.5, 2, 3, 4};
constexpr double k56[] = {1.5, 2, 3, 4};
constexpr double k58[] = {1.5, 2, 3, 4};
constexpr double k60[] = {1.5, 2, 3, 4};
constexpr double k62[] = {1.5, 2, 3, 4};
constexpr double k64[] = {1.5, 2, 3, 4};
constexpr double k65[] = {1.5, 2, 3, 4};
constexpr double k68[] = {1.5, 2, 3, 4};
constexpr double k70[] = {1.5, 2, 3, 4, 6};
constexpr double k72[] = {1.5, 2, 3, 4, 6};
constexpr double k75[] = {1.5, 2, 3, 4};
constexpr double k76[] = {1.5, 2, 3, 4, 6};
constexpr double k78[] = {2};
constexpr double k80[] = {1.5, 2, 3, 4, 6};
constexpr double k82[] = {2};
constexpr double k85[] = {2, 3, 4, 6};
constexpr double k90[] = {2, 3, 4, 6};
constexpr double k95[] = {2, 3, 4, 6};
constexpr double k100[] = {2, 3, 4, 6};
constexpr double k105[] = {2, 3, 4, 6};
constexpr double k110[] = {2, 3, 4, 6};
constexpr double k115[] = {2, 3, 4, 6};
constexpr double k120[] = {2, 3, 4, 6};
constexpr double k125[] = {2, 3, 4, 6, 8};
constexpr double k130[] = {2, 3, 4, 6, 8};
constexpr double k135[] = {2, 3, 4, 6};
constexpr double k140[] = {2, 3, 4, 6, 8};
constexpr double k145[] = {2, 3, 4, 6};
constexpr double k150[] = {2, 3, 4, 6, 8};
constexpr double k155[] = {3, 4, 6};
constexpr double k160[] = {3, 4, 6, 8};
constexpr double k165[] = {3, 4, 6};
constexpr double k170[] = {3, 4, 6, 8};
constexpr double k175[] = {3, 4, 6};
constexpr double k180[] = {3, 4, 6, 8};
constexpr double k185[] = {3, 4, 6};
constexpr double k190[] = {3, 4, 6, 8};
constexpr double k195[] = {3, 4, 6};
constexpr double k200[] = {3, 4, 6, 8};
constexpr double k205[] = {3, 4, 6};
constexpr double k210[] = {3, 4, 6, 8};
constexpr double k215[] = {3, 4, 6};
constexpr double k220[] = {3, 4, 6, 8};
constexpr double k225[] = {3, 4, 6};
constexpr double k230[] = {3, 4, 6, 8};
constexpr double k235[] = {3, 4, 6};
constexpr double k240[] = {3, 4, 6, 8};
constexpr double k245[] = {3, 4, 6};
constexpr double k250[] = {3, 4, 6, 8};
constexpr double k255[] = {4, 6};
constexpr double k260[] = {4, 6, 8};
constexpr double k265[] = {4, 6};
constexpr double k270[] = {4, 6, 8};
constexpr double k275[] = {4, 6};
constexpr double k280[] = {4, 6, 8};
constexpr double k285[] = {4, 6};
constexpr double k290[] = {4, 6, 8};
constexpr double k295[] = {4, 6};
constexpr double k300[] = {4, 6, 8};

// One entry per row of ISO 261 Table 1, in increasing diameter:
// {nominal diameter, choice column, coarse pitch (0: none), fine pitches}.
const Iso261Size kSizes[] = {
    {1, 1, 0.25, k1},     {1.1, 2, 0.25, k1_1}, {1.2, 1, 0.25, k1_2}, {1.4, 2, 0.3, k1_4},  {1.6, 1, 0.35, k1_6},
    {1.8, 2, 0.35, k1_8}, {2, 1, 0.4, k2},      {2.2, 2, 0.45, k2_2}, {2.5, 1, 0.45, k2_5}, {3, 1, 0.5, k3},
    {3.5, 2, 0.6, k3_5},  {4, 1, 0.7, k4},      {4.5, 2, 0.75, k4_5}, {5, 1, 0.8, k5},      {5.5, 3, 0, k5_5},
    {6, 1, 1, k6},        {7, 2, 1, k7},        {8, 1, 1.25, k8},     {9, 3, 1.25, k9},     {10, 1, 1.5, k10},
    {11, 3, 1.5, k11},    {12, 1, 1.75, k12},   {14, 2, 2, k14},      {15, 3, 0, k15},      {16, 1, 2, k16},
    {17, 3, 0, k17},      {18, 2, 2.5, k18},    {20, 1, 2.5, k20},    {22, 2, 2.5, k22},    {24, 1, 3, k24},
    {25, 3, 0, k25},      {26, 3, 0, k26},      {27, 2, 3, k27},      {28, 3, 0, k28},      {30, 1, 3.5, k30},
    {32, 3, 0, k32},      {33, 2, 3.5, k33},    {35, 3, 0, k35},      {36, 1, 4, k36},      {38, 3, 0, k38},
    {39, 2, 4, k39},      {40, 3, 0, k40},      {42, 1, 4.5, k42},    {45, 2, 4.5, k45},    {48, 1, 5, k48},
    {50, 3, 0, k50},      {52, 2, 5, k52},      {55, 3, 0, k55},      {56, 1, 5.5, k56},    {58, 3, 0, k58},
    {60, 2, 5.5, k60},    {62, 3, 0, k62},      {64, 1, 6, k64},      {65, 3, 0, k65},      {68, 2, 6, k68},
    {70, 3, 0, k70},      {72, 1, 0, k72},      {75, 3, 0, k75},      {76, 2, 0, k76},      {78, 3, 0, k78},
    {80, 1, 0, k80},      {82, 3, 0, k82},      {85, 2, 0, k85},      {90, 1, 0, k90},      {95, 2, 0, k95},
    {100, 1, 0, k100},    {105, 2, 0, k105},    {110, 1, 0, k110},    {115, 2, 0, k115},    {120, 2, 0, k120},
    {125, 1, 0, k125},    {130, 2, 0, k130},    {135, 3, 0, k135},    {140, 1, 0, k140},    {145, 3, 0, k145},
    {150, 2, 0, k150},    {155, 3, 0, k155},    {160, 1, 0, k160},    {165, 3, 0, k165},    {170, 2, 0, k170},
    {175, 3, 0, k175},    {180, 1, 0, k180},    {185, 3, 0, k185},    {190, 2, 0, k190},    {195, 3, 0, k195},
    {200, 1, 0, k200},    {205, 3, 0, k205},    {210, 2, 0, k210},    {215, 3, 0, k215},    {220, 1, 0, k220},
    {225, 3, 0, k225},    {230, 3, 0, k230},    {235, 3, 0, k235},    {240, 2, 0, k240},    {245, 3, 0, k245},
    {250, 1, 0, k250},    {255, 3, 0, k255},    {260, 2, 0, k260},    {265, 3, 0, k265},    {270, 3, 0, k270},
    {275, 3, 0, k275},    {280, 1, 0, k280},    {285, 3, 0, k285},    {290, 3, 0, k290},    {295, 3, 0, k295},
    {300, 2, 0, k300},
};

}  // namespace

std::span<const Iso261Size> iso261_sizes() { return {std::begin(kSizes), std::end(kSizes)}; }

std::optional<Iso261Size> iso261_size(double diameter_mm) {
  // The table is sorted: find the first row not below d - tolerance.
  const auto sizes = iso261_sizes();
  const auto it = std::lower_bound(sizes.begin(), sizes.end(), diameter_mm - kTolerance,
                                   [](const Iso261Size& row, double d) { return row.diameter_mm < d; });
  if (it == sizes.end() || !same(it->diameter_mm, diameter_mm)) return std::nullopt;
  return *it;
}

bool iso261_has_pitch(double diameter_mm, double pitch_mm) {
  const auto row = iso261_size(diameter_mm);
  if (!row) return false;
  if (row->coarse_pitch_mm > 0 && same(row->coarse_pitch_mm, pitch_mm)) return true;
  return std::any_of(row->fine_pitches_mm.begin(), row->fine_pitches_mm.end(),
                     [pitch_mm](double p) { return same(p, pitch_mm); });
}

const char* iso261_pitch_note(double diameter_mm, double pitch_mm) {
  if (same(diameter_mm, 14) && same(pitch_mm, 1.25)) return "ISO 261: only for spark plugs";
  if (same(diameter_mm, 35) && same(pitch_mm, 1.5)) return "ISO 261: only for locknuts for bearings";
  if ((same(diameter_mm, 30) || same(diameter_mm, 33)) && same(pitch_mm, 3))
    return "ISO 261: pitch in parentheses, to be avoided as far as possible";
  return nullptr;
}

}  // namespace tk::threads
