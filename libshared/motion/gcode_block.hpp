/// @file gcode_block.hpp
/// @brief Internal to the G-code interpreter: the table of G codes with
/// LinuxCNC's modal groups, M code groups, and one line's words sorted out
/// and checked (two codes of one group, a letter twice).
#pragma once

#include <algorithm>
#include <array>
#include <bitset>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "motion/gcode.hpp"

namespace tk::motion {

enum class GcodeGroup : std::uint8_t {
  non_modal,
  motion,
  plane,
  distance,
  arc_distance,
  feed_mode,
  units,
  cutter_compensation,
  tool_length,
  coordinate_system,
  path_control,
  return_mode,
  spindle_mode,
  lathe_mode,
};

/// What the interpreter does with a code: executes it, counts it in
/// unused_words() (no effect on the tool path here), or refuses it.
enum class GcodeUse : std::uint8_t { act, record, unsupported };

struct GcodeInfo {
  int code;  ///< the G number times ten: 591 is G59.1
  GcodeGroup group;
  GcodeUse use;
  const char* what = "";          ///< for unsupported codes, what they do
  bool takes_axis_words = false;  ///< its X/Y/Z are no move (G28, G92...)
};

/// "G1", "G59.1" for a code in tenths.
std::string gcode_name(int code);

/// The argument words an M code takes ("P" for M62: output number).
std::string_view mcode_arguments(int m);

/// One line's words: G and M codes checked against their groups, the
/// other letters' values, and which of those something used.
struct GcodeBlock {
  std::vector<const GcodeInfo*> gcodes;
  std::vector<int> mcodes;
  std::array<double, 26> value{};
  std::bitset<26> present, used;
  bool ignored_g80 = false;  ///< G80 beside G0-G3 (Mach3 style)
  bool m_takes_p = false;    ///< an M code owns the P word

  /// Adds a word; throws tk::Error for a bad or unknown code, two codes of
  /// one group and a letter given twice. N words are dropped.
  void add(const GcodeWord& word);

  static std::size_t index(char letter) { return static_cast<std::size_t>(letter - 'A'); }
  bool empty() const { return gcodes.empty() && mcodes.empty() && present.none() && !ignored_g80; }
  bool has(char letter) const { return present[index(letter)]; }
  /// The letter's value, marked as used.
  double take(char letter) {
    used.set(index(letter));
    return value[index(letter)];
  }
  void consume(char letter) {
    if (has(letter)) take(letter);
  }
  bool has_g(int code) const {
    return std::any_of(gcodes.begin(), gcodes.end(), [code](const GcodeInfo* g) { return g->code == code; });
  }
  bool has_m(int m) const { return std::find(mcodes.begin(), mcodes.end(), m) != mcodes.end(); }
  const GcodeInfo* in_group(GcodeGroup group) const {
    for (const GcodeInfo* g : gcodes)
      if (g->group == group) return g;
    return nullptr;
  }

 private:
  void add_gcode(double number);
  void add_mcode(double number);
};

}  // namespace tk::motion
