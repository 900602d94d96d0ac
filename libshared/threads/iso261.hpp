/// @file iso261.hpp
/// @brief The general plan of ISO 261:1998 for metric screw threads: nominal
/// diameters 1 to 300 mm, their choice series, coarse pitch and fine pitches.
///
/// The data and its sources are in iso261.cpp. Every diameter the standard's
/// Table 1 lists has exactly one row; a diameter it does not list has none.
#pragma once

#include <optional>
#include <span>

namespace tk::threads {

struct Iso261Size {
  double diameter_mm;
  int choice;              ///< 1, 2 or 3: ISO 261's column (1 preferred, then 2, then 3)
  double coarse_pitch_mm;  ///< 0 where ISO 261 gives no coarse pitch (column-3 sizes such
                           ///< as M5.5, M15, M25, and every diameter above 68 mm)
  /// The fine pitches of the row in ascending order (smallest first), each once.
  /// Above 68 mm ISO 261 has no coarse pitch and all its pitches, 6 mm and 8 mm
  /// included, are listed here. Never empty.
  std::span<const double> fine_pitches_mm;
};

/// Every row of ISO 261's table, in strictly increasing diameter.
std::span<const Iso261Size> iso261_sizes();

/// The row for this nominal diameter (matched within 1e-9 mm), or nullopt
/// when ISO 261 has none.
std::optional<Iso261Size> iso261_size(double diameter_mm);

/// True when ISO 261 lists this diameter-pitch combination, as its coarse or
/// one of its fine pitches (both matched within 1e-9 mm).
bool iso261_has_pitch(double diameter_mm, double pitch_mm);

/// ISO 261's footnote on a listed combination, or nullptr when it has none:
/// M14x1.25 is for spark plugs only, M35x1.5 for rolling-bearing locknuts
/// only, and the 3 mm pitch of M30 and M33 is printed in parentheses (to be
/// avoided where possible).
const char* iso261_pitch_note(double diameter_mm, double pitch_mm);

}  // namespace tk::threads
