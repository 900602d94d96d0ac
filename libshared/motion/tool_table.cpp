/// @file tool_table.cpp
#include "motion/tool_table.hpp"

#include <cmath>
#include <string_view>

#include <fmt/format.h>

#include "io/error.hpp"
#include "io/input_file.hpp"

namespace tk::motion {

namespace {

/// One line's tool; false for a line with no words.
bool read_tool(std::string_view text, int& number, Vec3& offsets) {
  const GcodeLine line = lex_gcode_line(text);
  if (line.percent) throw Error("'%' in a tool table");
  if (line.words.empty()) return false;
  bool has_number = false;
  offsets = {};
  for (const GcodeWord& word : line.words) {
    constexpr std::string_view kIgnored = "PDIJQABCUVW";
    if (word.letter == 'T') {
      if (has_number) throw Error("two T words on one line");
      if (word.value < 0 || word.value != std::floor(word.value) || word.value > 1e9)
        throw Error(fmt::format("T{:g}: a tool number is a whole number, 0 or more", word.value));
      number = static_cast<int>(word.value);
      has_number = true;
    } else if (word.letter >= 'X' && word.letter <= 'Z') {
      offsets[word.letter - 'X'] = word.value;
    } else if (kIgnored.find(word.letter) == std::string_view::npos) {
      throw Error(fmt::format("'{}' is no tool table word (T, P, X, Y, Z, D, I, J, Q...)", word.letter));
    }
  }
  if (!has_number) throw Error("a tool without its T word");
  return true;
}

}  // namespace

ToolTable read_tool_table(const std::string& path) {
  io::InputFile input(path);
  ToolTable table;
  std::string_view text;
  while (input.next(text)) {
    try {
      int number = 0;
      Vec3 offsets;
      if (!read_tool(text, number, offsets)) continue;
      if (!table.emplace(number, offsets).second) throw Error(fmt::format("tool T{} given twice", number));
    } catch (const Error& e) {
      throw Error(e.what(), input.where());
    }
  }
  if (table.empty()) throw Error("no tool in the tool table", input.where());
  return table;
}

}  // namespace tk::motion
