/// @file tool_table.hpp
/// @brief LinuxCNC's tool table (`T1 P1 Z12.98 D6 ;comment`, one tool a
/// line): the offsets G43 applies.
#pragma once

#include <map>
#include <string>

#include "motion/gcode.hpp"

namespace tk::motion {

/// Tool number to its X, Y, Z offsets in mm (the table's numbers are
/// millimetres here; LinuxCNC reads them in the machine's units).
using ToolTable = std::map<int, Vec3>;

/// Reads a table: words as in G-code, `;` and `(...)` comments. T (a whole
/// number ≥ 0) is required; X, Y and Z are the offsets (0 when absent);
/// P, D, I, J, Q and the offsets of A, B, C, U, V, W are accepted and
/// ignored. Throws tk::Error at the file and line of a bad line, a tool
/// given twice, or a table with no tool.
ToolTable read_tool_table(const std::string& path);

}  // namespace tk::motion
