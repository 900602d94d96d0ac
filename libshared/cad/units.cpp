/// @file units.cpp
/// @brief Millimetres per drawing unit for the DXF $INSUNITS codes, from the
/// exact definitions of the units (international inch, US survey foot of
/// 1200/3937 m, IAU astronomical unit and light year).
#include <array>
#include <numbers>

#include "cad/drawing.hpp"

namespace tk::cad {

namespace {

constexpr double kAstronomicalUnit = 149597870700e3;
constexpr double kSurveyFoot = 1200.0 / 3937.0 * 1000.0;

/// Indexed by $INSUNITS code; 0 where the code names no length. Decimal
/// literals where the value has one, so that 12 inches is exactly 304.8.
constexpr std::array<double, 25> kMillimetres{
    0,                                             // 0 unitless
    25.4,                                          // 1 inch
    304.8,                                         // 2 foot
    1609344,                                       // 3 mile
    1,                                             // 4 millimetre
    10,                                            // 5 centimetre
    1e3,                                           // 6 metre
    1e6,                                           // 7 kilometre
    25.4e-6,                                       // 8 microinch
    0.0254,                                        // 9 mil
    914.4,                                         // 10 yard
    1e-7,                                          // 11 angstrom
    1e-6,                                          // 12 nanometre
    1e-3,                                          // 13 micron
    100,                                           // 14 decimetre
    1e4,                                           // 15 decametre
    1e5,                                           // 16 hectometre
    1e12,                                          // 17 gigametre
    kAstronomicalUnit,                             // 18 astronomical unit
    9460730472580800e3,                            // 19 light year (Julian year of 365.25 days)
    648000 / std::numbers::pi* kAstronomicalUnit,  // 20 parsec
    kSurveyFoot,                                   // 21 US survey foot
    kSurveyFoot / 12,                              // 22 US survey inch
    kSurveyFoot * 3,                               // 23 US survey yard
    kSurveyFoot * 5280,                            // 24 US survey mile
};

}  // namespace

double millimetres_per_unit(int insunits) {
  if (insunits < 0 || insunits >= static_cast<int>(kMillimetres.size())) return 0;
  return kMillimetres[static_cast<std::size_t>(insunits)];
}

}  // namespace tk::cad
