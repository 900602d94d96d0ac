/// @file iso965_tables.hpp
/// @brief ISO 965-1:2013 tolerance data for ISO general purpose metric
/// screw threads, as the standard tabulates it (micrometres), with the
/// standard's formulas for what the tables do not cover.
#pragma once

#include <optional>
#include <span>

namespace tk::threads {

/// Table numbers are those of ISO 965-1:2013 (Table 1 fundamental deviations,
/// 2 TD1, 3 Td, 4 TD2, 5 Td2); the 1998 edition holds the same values. Where a
/// table has no entry, the value comes from the standard's formulas (clause
/// 10), rounded the way the tables are (see iso965_tables.cpp).

/// A tabulated or computed value, micrometres. `computed` is true when no
/// table of ISO 965-1 holds the case and the value comes from the standard's
/// formula (rounded as the table would be, see the .cpp), so callers can say so.
struct Micrometres {
  int value = 0;
  bool computed = false;
  const char* source = "";  ///< e.g. "ISO 965-1:2013 Table 3" or "ISO 965-1 formula (8)"
};

/// Fundamental deviation of a tolerance position: es for the external
/// positions 'e' 'f' 'g' 'h' (zero or negative), EI for the internal 'G' 'H'
/// (zero or positive). nullopt when the standard defines no value for the
/// pitch (e.g. 'e' below P = 0.5 mm, 'f' below 0.35 mm) or the position is
/// not one of these six.
std::optional<Micrometres> fundamental_deviation(char position, double pitch_mm);

/// Td, tolerance of the external major diameter d, grades 4, 6, 8.
std::optional<Micrometres> major_diameter_tolerance(int grade, double pitch_mm);

/// TD1, tolerance of the internal minor diameter D1, grades 4 to 8.
std::optional<Micrometres> minor_diameter_tolerance(int grade, double pitch_mm);

/// Td2, tolerance of the external pitch diameter, grades 3 to 9; the row is
/// chosen by the basic major diameter d's range in the table.
std::optional<Micrometres> external_pitch_diameter_tolerance(int grade, double major_mm, double pitch_mm);

/// TD2, tolerance of the internal pitch diameter, grades 4 to 8.
std::optional<Micrometres> internal_pitch_diameter_tolerance(int grade, double major_mm, double pitch_mm);

/// The pitches Tables 1 to 3 list (0.2 to 8 mm), ascending.
std::span<const double> iso965_pitches();

/// One row of the pitch diameter tables (Tables 4 and 5): a basic major
/// diameter range, over `over_mm` up to and including `up_to_mm`, and a pitch
/// tabulated for it.
struct Iso965DiameterPitch {
  double over_mm;
  double up_to_mm;
  double pitch_mm;
};

/// Every (diameter range, pitch) row of Tables 4 and 5, in table order.
std::span<const Iso965DiameterPitch> iso965_pitch_diameter_rows();

}  // namespace tk::threads
