/// @file gcode_writer.hpp
/// @brief The one G-code writer, for the programs dxf2region (milling
/// contours) and threadcalc (threading) write: numbers printed one way per
/// program, and comments made safe for any text, so that LinuxCNC's rs274
/// and gcode-pulse read them as plain comments, never as an error or a
/// directive. (The reader is gcode.hpp.)
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace tk::motion {

/// How a program prints its numbers: `decimals` places, rounded to
/// nearest; `trim_zeros` drops trailing zeros (and a bare '.'). Never
/// "-0": a value that prints as zero prints without its sign.
struct GcodeNumberFormat {
  int decimals = 4;
  bool trim_zeros = true;
};

/// dxf2region's contours: micrometres, always six places ("1.500000").
inline constexpr GcodeNumberFormat kFixedMicrons{6, false};
/// threadcalc's programs: to 0.1 µm, trailing zeros dropped ("1.5").
inline constexpr GcodeNumberFormat kTrimmedTenthMicrons{4, true};

std::string gcode_number(double value, GcodeNumberFormat format);

/// A number as written and as a control reads it back.
struct PrintedNumber {
  std::string text;
  double value = 0;
};

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

/// A program built line by line: every number through one format, every
/// comment through gcode_comment.
class GcodeWriter {
 public:
  explicit GcodeWriter(GcodeNumberFormat format) : format_(format) {}

  std::string number(double value) const { return gcode_number(value, format_); }
  PrintedNumber printed(double value) const;

  /// A comment on a line of its own.
  void comment(std::string_view text);
  /// One line: `words` (as given: "G0 X1 Y2"), then the comment if any.
  void line(std::string_view words, std::string_view comment = {});

  const std::string& text() const { return text_; }

 private:
  GcodeNumberFormat format_;
  std::string text_;
};

}  // namespace tk::motion
