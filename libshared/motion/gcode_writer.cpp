/// @file gcode_writer.cpp
/// @brief Numbers and safe comment text for the G-code programs we write.
#include "motion/gcode_writer.hpp"

#include <fmt/format.h>

#include <cctype>
#include <cstdlib>

namespace tk::motion {
namespace {

/// LinuxCNC 2.8 looks at a comment's start, blanks skipped and case
/// ignored, for directives: "msg,", "debug,", "print,", "log,", "logopen,",
/// "logappend,", "logclose", "py,", "pyrun,", "pyreload", "abort,",
/// "probeopen", "probeclose", and its AXIS screen for "axis,". A body that
/// starts with one of these words, whatever follows the word (unless more of
/// a longer word), counts as one.
bool reads_as_directive(std::string_view body) {
  std::size_t i = 0;
  while (i < body.size() && body[i] == ' ') ++i;
  body.remove_prefix(i);
  std::size_t word = 0;
  while (word < body.size() && (std::isalnum(static_cast<unsigned char>(body[word])) != 0 || body[word] == '_')) ++word;
  std::string first(body.substr(0, word));
  for (char& c : first) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (std::string_view directive : {"msg", "debug", "print", "log", "logopen", "logappend", "logclose", "py", "pyrun",
                                     "pyreload", "abort", "probeopen", "probeclose", "axis"})
    if (first == directive) return true;
  return false;
}

/// Cuts `body` to at most `bytes` bytes, not inside a UTF-8 character.
void cut_to(std::string& body, std::size_t bytes) {
  if (body.size() <= bytes) return;
  std::size_t end = bytes;
  while (end > 0 && (static_cast<unsigned char>(body[end]) & 0xC0) == 0x80) --end;
  body.resize(end);
}

}  // namespace

std::string gcode_comment(std::string_view text) {
  std::string body;
  body.reserve(text.size());
  for (char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '(') body += '[';
    else if (c == ')') body += ']';
    else if (byte < 0x20 || byte == 0x7f) body += ' ';
    else body += c;
  }
  const bool quoted = reads_as_directive(body);
  const std::size_t room = kMaxCommentBytes - 2 - (quoted ? 2 : 0);
  if (body.size() > room) {
    cut_to(body, room - 3);
    body += "...";
  }
  return quoted ? "(\"" + body + "\")" : "(" + body + ")";
}

std::string gcode_number(double value, GcodeNumberFormat format) {
  std::string text = fmt::format("{:.{}f}", value, format.decimals);
  if (text.starts_with('-') && text.find_first_not_of("0.", 1) == std::string::npos) text.erase(0, 1);
  if (format.trim_zeros && text.find('.') != std::string::npos) {
    while (text.back() == '0') text.pop_back();
    if (text.back() == '.') text.pop_back();
  }
  return text;
}

PrintedNumber GcodeWriter::printed(double value) const {
  std::string text = number(value);
  const double read_back = std::strtod(text.c_str(), nullptr);
  return {std::move(text), read_back};
}

void GcodeWriter::comment(std::string_view text) {
  text_ += gcode_comment(text);
  text_ += '\n';
}

void GcodeWriter::line(std::string_view words, std::string_view comment) {
  text_ += words;
  if (!comment.empty()) {
    text_ += ' ';
    text_ += gcode_comment(comment);
  }
  text_ += '\n';
}

}  // namespace tk::motion
