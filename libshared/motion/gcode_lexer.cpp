/// @file gcode_lexer.cpp
/// @brief Splits one G-code line into words: comments, "(MSG,...)", block
/// delete, '%' tape markers and numbers as LinuxCNC reads them.
#include <cctype>
#include <charconv>
#include <cmath>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "io/error.hpp"
#include "motion/gcode.hpp"

namespace tk::motion {

namespace {

/// Where our subset stops, LinuxCNC's own interpreter takes over.
constexpr std::string_view kCanonHint = " (rs274 -g FILE | gcode-pulse --canon runs the whole language)";

/// Longest number accepted: more digits carry no precision and only serve
/// to build huge values.
constexpr std::size_t kMaxNumberLength = 64;

bool is_blank(unsigned char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v'; }

/// Control characters and DEL; 0x80 and above too outside comments.
bool is_bad_byte(unsigned char c, bool in_comment) {
  if (is_blank(c)) return false;
  return c < 0x20 || c == 0x7f || (c >= 0x80 && !in_comment);
}

[[noreturn]] void bad_byte(unsigned char c) { throw Error(fmt::format("unexpected byte 0x{:02x}", c)); }

bool is_number_char(char c) { return std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == '+' || c == '-'; }

bool starts_with_nocase(std::string_view text, std::string_view prefix) {
  if (text.size() < prefix.size()) return false;
  for (std::size_t i = 0; i < prefix.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(text[i])) != prefix[i]) return false;
  return true;
}

/// The message of a "(MSG, text)" comment, if `comment` (between the
/// parentheses) is one.
std::optional<std::string_view> message_of(std::string_view comment) {
  std::size_t i = 0;
  while (i < comment.size() && is_blank(static_cast<unsigned char>(comment[i]))) ++i;
  if (!starts_with_nocase(comment.substr(i), "msg")) return std::nullopt;
  i += 3;
  while (i < comment.size() && is_blank(static_cast<unsigned char>(comment[i]))) ++i;
  if (i == comment.size() || comment[i] != ',') return std::nullopt;
  ++i;
  while (i < comment.size() && is_blank(static_cast<unsigned char>(comment[i]))) ++i;
  std::size_t end = comment.size();
  while (end > i && is_blank(static_cast<unsigned char>(comment[end - 1]))) --end;
  return comment.substr(i, end - i);
}

/// Reads the comment opening at text[open]; returns the index after it.
std::size_t read_comment(std::string_view text, std::size_t open, GcodeLine& line) {
  std::size_t close = open + 1;
  for (; close < text.size() && text[close] != ')'; ++close) {
    if (text[close] == '(') throw Error("nested comment");
    if (is_bad_byte(static_cast<unsigned char>(text[close]), true)) bad_byte(static_cast<unsigned char>(text[close]));
  }
  if (close == text.size()) throw Error("unclosed comment");
  if (const auto message = message_of(text.substr(open + 1, close - open - 1))) line.message = *message;
  return close + 1;
}

/// Checks the number as written ("-.5", "+1", "1.", not "1.2.3" or "--1")
/// and converts it. `shown` is the word as written, for messages.
double parse_number(const std::string& digits, const std::string& shown) {
  std::size_t first = 0;
  if (!digits.empty() && (digits[0] == '+' || digits[0] == '-')) first = 1;
  std::size_t digit_count = 0, dot_count = 0;
  bool inner_sign = false;
  for (std::size_t i = first; i < digits.size(); ++i) {
    if (digits[i] == '.') ++dot_count;
    else if (std::isdigit(static_cast<unsigned char>(digits[i]))) ++digit_count;
    else inner_sign = true;
  }
  if (digit_count == 0 || dot_count > 1 || inner_sign) throw Error(fmt::format("bad number '{}'", shown));
  // from_chars takes no '+'; the minus sign it reads itself.
  const char* begin = digits.data() + (digits[0] == '+' ? 1 : 0);
  const char* end = digits.data() + digits.size();
  double value = 0;
  const auto [stop, error] = std::from_chars(begin, end, value);
  if (error != std::errc{} || stop != end || !std::isfinite(value)) throw Error(fmt::format("bad number '{}'", shown));
  return value;
}

/// Reads the word whose letter is text[start]; returns the index after it.
std::size_t read_word(std::string_view text, std::size_t start, GcodeLine& line) {
  const char written = text[start];
  const char letter = static_cast<char>(std::toupper(static_cast<unsigned char>(written)));
  if (letter == 'O') throw Error("'O' words (subroutines) are not supported" + std::string(kCanonHint));
  std::size_t i = start + 1;
  while (i < text.size() && is_blank(static_cast<unsigned char>(text[i]))) ++i;
  const std::string_view rest = text.substr(i);
  if (starts_with_nocase(rest, "inf") || starts_with_nocase(rest, "nan"))
    throw Error(fmt::format("bad number '{}{}'", written, rest.substr(0, 3)));
  // The number: digits, '.', signs, with blanks allowed between them as
  // LinuxCNC ignores blanks ("X 1 2" is X12); a blank ends it only when no
  // number character follows.
  std::string digits;
  while (i < text.size()) {
    if (is_number_char(text[i])) {
      digits += text[i++];
      continue;
    }
    std::size_t next = i;
    while (next < text.size() && is_blank(static_cast<unsigned char>(text[next]))) ++next;
    if (next == i || digits.empty() || next == text.size() || !is_number_char(text[next])) break;
    i = next;
  }
  if (digits.empty()) throw Error(fmt::format("letter '{}' without a number", letter));
  if (digits.size() > kMaxNumberLength)
    throw Error(fmt::format("bad number '{}{}...': longer than {} characters", written, digits.substr(0, 16),
                            kMaxNumberLength));
  const double value = parse_number(digits, written + digits);
  if (letter != 'N') line.words.push_back({letter, value});
  return i;
}

[[noreturn]] void unexpected(unsigned char c) {
  if (is_bad_byte(c, false)) bad_byte(c);
  switch (c) {
    case '#': throw Error("unexpected character '#': parameters are not supported" + std::string(kCanonHint));
    case '[': throw Error("unexpected character '[': expressions are not supported" + std::string(kCanonHint));
    case '@':
    case '^':
      throw Error(fmt::format("'{}' is LinuxCNC's polar {} word: polar coordinates are not supported{}",
                              static_cast<char>(c), c == '@' ? "distance" : "angle", kCanonHint));
    case '$':
      throw Error("'$' is LinuxCNC's spindle selection word: one spindle only, no '$'" + std::string(kCanonHint));
    case '/': throw Error("unexpected character '/': block delete must start the line");
    default: throw Error(fmt::format("unexpected character '{}'", static_cast<char>(c)));
  }
}

}  // namespace

GcodeLine lex_gcode_line(std::string_view text) {
  GcodeLine line;
  bool started = false;  // something other than blanks and comments came
  for (std::size_t i = 0; i < text.size();) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (is_blank(c)) {
      ++i;
    } else if (c == '(') {
      i = read_comment(text, i, line);
    } else if (c == ';') {
      // A comment to the end of the line: its bytes are not checked.
      break;
    } else if (c == '%') {
      if (started) throw Error("'%' must be alone on its line");
      line.percent = started = true;
      ++i;
    } else if (line.percent) {
      throw Error("'%' must be alone on its line");
    } else if (c == '/' && !started) {
      line.block_delete = started = true;
      ++i;
    } else if (std::isalpha(c)) {
      i = read_word(text, i, line);
      started = true;
    } else {
      unexpected(c);
    }
  }
  return line;
}

}  // namespace tk::motion
