/// @file gcode_block.cpp
/// @brief The G code table (LinuxCNC's modal groups and what this
/// interpreter does with each code), M code groups and arguments, and the
/// checks made while a line's words are sorted out.
#include "motion/gcode_block.hpp"

#include <cmath>

#include <fmt/format.h>

#include "io/error.hpp"

namespace tk::motion {

namespace {

const char* group_name(GcodeGroup group) {
  switch (group) {
    case GcodeGroup::non_modal: return "non-modal";
    case GcodeGroup::motion: return "motion";
    case GcodeGroup::plane: return "plane";
    case GcodeGroup::distance: return "distance mode";
    case GcodeGroup::arc_distance: return "arc distance mode";
    case GcodeGroup::feed_mode: return "feed rate mode";
    case GcodeGroup::units: return "units";
    case GcodeGroup::cutter_compensation: return "cutter compensation";
    case GcodeGroup::tool_length: return "tool length offset";
    case GcodeGroup::coordinate_system: return "coordinate system";
    case GcodeGroup::path_control: return "path control";
    case GcodeGroup::return_mode: return "canned cycle return mode";
    case GcodeGroup::spindle_mode: return "spindle speed mode";
    case GcodeGroup::lathe_mode: return "lathe diameter mode";
  }
  return "?";
}

/// LinuxCNC's G codes (and G70/G71, which Mach3 and older Fanuc controls
/// use for inch/mm; in LinuxCNC they are lathe cycles).
constexpr GcodeInfo kGcodes[] = {
    {0, GcodeGroup::motion, GcodeUse::act},
    {10, GcodeGroup::motion, GcodeUse::act},
    {20, GcodeGroup::motion, GcodeUse::act},
    {30, GcodeGroup::motion, GcodeUse::act},
    {40, GcodeGroup::non_modal, GcodeUse::act},
    {50, GcodeGroup::motion, GcodeUse::unsupported, "cubic spline"},
    {51, GcodeGroup::motion, GcodeUse::unsupported, "quadratic spline"},
    {52, GcodeGroup::motion, GcodeUse::unsupported, "NURBS"},
    {70, GcodeGroup::lathe_mode, GcodeUse::act},
    {80, GcodeGroup::lathe_mode, GcodeUse::act},
    {100, GcodeGroup::non_modal, GcodeUse::unsupported, "setting offsets and tool data", true},
    {170, GcodeGroup::plane, GcodeUse::act},
    {171, GcodeGroup::plane, GcodeUse::unsupported, "UV plane"},
    {180, GcodeGroup::plane, GcodeUse::act},
    {181, GcodeGroup::plane, GcodeUse::unsupported, "WU plane"},
    {190, GcodeGroup::plane, GcodeUse::act},
    {191, GcodeGroup::plane, GcodeUse::unsupported, "VW plane"},
    {200, GcodeGroup::units, GcodeUse::act},
    {210, GcodeGroup::units, GcodeUse::act},
    {280, GcodeGroup::non_modal, GcodeUse::unsupported, "return to home", true},
    {281, GcodeGroup::non_modal, GcodeUse::unsupported, "storing the home position"},
    {300, GcodeGroup::non_modal, GcodeUse::unsupported, "return to the second home", true},
    {301, GcodeGroup::non_modal, GcodeUse::unsupported, "storing the second home position"},
    {330, GcodeGroup::motion, GcodeUse::act},
    {331, GcodeGroup::motion, GcodeUse::unsupported, "rigid tapping"},
    {382, GcodeGroup::motion, GcodeUse::unsupported, "probing"},
    {383, GcodeGroup::motion, GcodeUse::unsupported, "probing"},
    {384, GcodeGroup::motion, GcodeUse::unsupported, "probing"},
    {385, GcodeGroup::motion, GcodeUse::unsupported, "probing"},
    {400, GcodeGroup::cutter_compensation, GcodeUse::record},
    {410, GcodeGroup::cutter_compensation, GcodeUse::unsupported, "cutter radius compensation"},
    {411, GcodeGroup::cutter_compensation, GcodeUse::unsupported, "cutter radius compensation"},
    {420, GcodeGroup::cutter_compensation, GcodeUse::unsupported, "cutter radius compensation"},
    {421, GcodeGroup::cutter_compensation, GcodeUse::unsupported, "cutter radius compensation"},
    {430, GcodeGroup::tool_length, GcodeUse::act},
    {431, GcodeGroup::tool_length, GcodeUse::act, "", true},
    {432, GcodeGroup::tool_length, GcodeUse::unsupported, "added tool length offset"},
    {490, GcodeGroup::tool_length, GcodeUse::act},
    {520, GcodeGroup::non_modal, GcodeUse::unsupported, "local coordinate offset", true},
    // Machine coordinates: without work offsets they are the program's.
    {530, GcodeGroup::non_modal, GcodeUse::act},
    {540, GcodeGroup::coordinate_system, GcodeUse::record},
    {550, GcodeGroup::coordinate_system, GcodeUse::record},
    {560, GcodeGroup::coordinate_system, GcodeUse::record},
    {570, GcodeGroup::coordinate_system, GcodeUse::record},
    {580, GcodeGroup::coordinate_system, GcodeUse::record},
    {590, GcodeGroup::coordinate_system, GcodeUse::record},
    {591, GcodeGroup::coordinate_system, GcodeUse::record},
    {592, GcodeGroup::coordinate_system, GcodeUse::record},
    {593, GcodeGroup::coordinate_system, GcodeUse::record},
    {610, GcodeGroup::path_control, GcodeUse::record},
    {611, GcodeGroup::path_control, GcodeUse::record},
    {640, GcodeGroup::path_control, GcodeUse::record},
    {700, GcodeGroup::units, GcodeUse::act},
    {710, GcodeGroup::units, GcodeUse::act},
    {730, GcodeGroup::motion, GcodeUse::unsupported, "canned cycle"},
    {740, GcodeGroup::motion, GcodeUse::unsupported, "canned cycle"},
    {760, GcodeGroup::motion, GcodeUse::unsupported, "threading cycle"},
    {800, GcodeGroup::motion, GcodeUse::act},
    {810, GcodeGroup::motion, GcodeUse::unsupported, "canned cycle"},
    {820, GcodeGroup::motion, GcodeUse::unsupported, "canned cycle"},
    {830, GcodeGroup::motion, GcodeUse::unsupported, "canned cycle"},
    {840, GcodeGroup::motion, GcodeUse::unsupported, "canned cycle"},
    {850, GcodeGroup::motion, GcodeUse::unsupported, "canned cycle"},
    {860, GcodeGroup::motion, GcodeUse::unsupported, "canned cycle"},
    {870, GcodeGroup::motion, GcodeUse::unsupported, "canned cycle"},
    {880, GcodeGroup::motion, GcodeUse::unsupported, "canned cycle"},
    {890, GcodeGroup::motion, GcodeUse::unsupported, "canned cycle"},
    {900, GcodeGroup::distance, GcodeUse::act},
    {901, GcodeGroup::arc_distance, GcodeUse::act},
    {910, GcodeGroup::distance, GcodeUse::act},
    {911, GcodeGroup::arc_distance, GcodeUse::act},
    {920, GcodeGroup::non_modal, GcodeUse::unsupported, "coordinate system offset", true},
    {921, GcodeGroup::non_modal, GcodeUse::unsupported, "coordinate system offset"},
    {922, GcodeGroup::non_modal, GcodeUse::unsupported, "coordinate system offset"},
    {923, GcodeGroup::non_modal, GcodeUse::unsupported, "coordinate system offset"},
    {930, GcodeGroup::feed_mode, GcodeUse::act},
    {940, GcodeGroup::feed_mode, GcodeUse::act},
    {950, GcodeGroup::feed_mode, GcodeUse::unsupported, "feed per revolution"},
    {960, GcodeGroup::spindle_mode, GcodeUse::record},
    {970, GcodeGroup::spindle_mode, GcodeUse::record},
    {980, GcodeGroup::return_mode, GcodeUse::record},
    {990, GcodeGroup::return_mode, GcodeUse::record},
};

const GcodeInfo* find_gcode(int code) {
  for (const GcodeInfo& info : kGcodes)
    if (info.code == code) return &info;
  return nullptr;
}

/// LinuxCNC's M code groups; empty for codes in none.
std::string_view m_group(int m) {
  switch (m) {
    case 0:
    case 1:
    case 2:
    case 30:
    case 60: return "stopping";
    case 3:
    case 4:
    case 5: return "spindle";
    case 6: return "tool change";
    case 7:
    case 8:
    case 9: return "coolant";
    case 48:
    case 49:
    case 50:
    case 51:
    case 52:
    case 53: return "override";
    case 62:
    case 63:
    case 64:
    case 65:
    case 66:
    case 67:
    case 68: return "input/output";
    default: return {};
  }
}

}  // namespace

std::string gcode_name(int code) {
  return code % 10 ? fmt::format("G{}.{}", code / 10, code % 10) : fmt::format("G{}", code / 10);
}

std::string_view mcode_arguments(int m) {
  if (m == 19) return "RQP";
  if (m >= 50 && m <= 53) return "P";
  if (m == 61) return "Q";
  if (m >= 62 && m <= 65) return "P";
  if (m == 66) return "PELQ";
  if (m == 67 || m == 68) return "EQ";
  if (m >= 100 && m <= 199) return "PQ";  // user M codes
  return {};
}

void GcodeBlock::add_gcode(double number) {
  const double tenths = std::round(number * 10);
  if (number < 0 || std::abs(number * 10 - tenths) > 1e-6 || tenths > 10000)
    throw Error(fmt::format("bad G code G{:g}", number));
  const int code = static_cast<int>(tenths);
  const GcodeInfo* info = find_gcode(code);
  if (!info) throw Error(fmt::format("unknown G code {}", gcode_name(code)));
  for (const GcodeInfo*& other : gcodes) {
    if (other->group != info->group) continue;
    // Mach3 and Fanuc keep G80 (cancel canned cycles) apart from G0-G3:
    // "G00 G90 G80" is a rapid move, and G80 has nothing to cancel here.
    const bool straight_or_arc = (info->code <= 30) != (other->code <= 30);
    if (info->group == GcodeGroup::motion && (info->code == 800 || other->code == 800) && straight_or_arc) {
      if (info->code != 800) other = info;
      ignored_g80 = true;
      return;
    }
    throw Error(fmt::format("{} and {} are both in the {} group", gcode_name(other->code), gcode_name(code),
                            group_name(info->group)));
  }
  gcodes.push_back(info);
}

void GcodeBlock::add_mcode(double number) {
  if (number < 0 || number != std::floor(number) || number > 1e6) throw Error(fmt::format("bad M code M{:g}", number));
  const int m = static_cast<int>(number);
  for (const int other : mcodes) {
    if ((m == 7 && other == 8) || (m == 8 && other == 7)) continue;  // mist and flood together
    if (other == m && m_group(m).empty()) throw Error(fmt::format("two M{} words on one line", m));
    if (other == m || (!m_group(m).empty() && m_group(other) == m_group(m)))
      throw Error(fmt::format("M{} and M{} are both in the {} group", other, m, m_group(m)));
  }
  mcodes.push_back(m);
  if (mcode_arguments(m).find('P') != std::string_view::npos) m_takes_p = true;
}

void GcodeBlock::add(const GcodeWord& word) {
  if (!std::isfinite(word.value)) throw Error(fmt::format("bad number in the {} word", word.letter));
  if (word.letter == 'G') return add_gcode(word.value);
  if (word.letter == 'M') return add_mcode(word.value);
  if (word.letter == 'N') return;  // line numbers mean nothing here
  if (word.letter < 'A' || word.letter > 'Z') throw Error(fmt::format("bad word letter '{}'", word.letter));
  if (has(word.letter)) throw Error(fmt::format("two {} words on one line", word.letter));
  present.set(index(word.letter));
  value[index(word.letter)] = word.value;
}

}  // namespace tk::motion
