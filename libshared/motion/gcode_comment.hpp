/// @file gcode_comment.hpp
/// @brief Comments that the G-code writers (threadcalc, dxf2region) put in
/// their programs, made safe for any text: LinuxCNC's rs274 and gcode-pulse
/// read them as plain comments, never as an error or a directive.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace tk::motion {

/// Longest comment, parentheses included, that gcode_comment writes. LinuxCNC
/// refuses a line over 252 bytes ("Command too long"); the rest of the room
/// is for the words a comment may follow on its line.
inline constexpr std::size_t kMaxCommentBytes = 200;

/// `text` as an RS274NGC comment, "(" body ")": '(' and ')' become '[' and
/// ']' (LinuxCNC refuses a nested '(' and a ')' would end the comment early),
/// control bytes (newlines, tabs, DEL) become spaces, a body that LinuxCNC
/// would take for a directive (one starting with the word MSG, DEBUG, PRINT,
/// LOG, LOGOPEN, LOGAPPEND, LOGCLOSE, PY, PYRUN, PYRELOAD, ABORT, PROBEOPEN,
/// PROBECLOSE or AXIS, in any case) is put in double quotes, and a body too long for kMaxCommentBytes is cut at a
/// UTF-8 character boundary and ends in "...".
std::string gcode_comment(std::string_view text);

}  // namespace tk::motion
