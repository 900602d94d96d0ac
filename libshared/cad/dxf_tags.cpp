/// @file dxf_tags.cpp
/// @brief Tag splitting for ASCII and binary DXF, and number conversion.
/// Works on the whole file in memory with string_views: no allocation per
/// line, numbers by std::from_chars, and only when asked for.
#include "cad/dxf_tags.hpp"

#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <system_error>

#include "io/error.hpp"

namespace tk::cad::dxf {

namespace {

constexpr std::string_view kUtf8Bom{"\xEF\xBB\xBF"};
constexpr int kMaxGroupCode = 1071;

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

std::string_view trim(std::string_view s) {
  while (!s.empty() && is_blank(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_blank(s.back())) s.remove_suffix(1);
  return s;
}

/// A value as it appears in a message: at most 40 bytes.
std::string shown(std::string_view text) {
  return text.size() <= 40 ? std::string(text) : std::string(text.substr(0, 40)) + "...";
}

/// Group codes are small integers; a hand-written loop beats from_chars here.
bool parse_code(std::string_view s, int& code) {
  const char* p = s.data();
  const char* end = p + s.size();
  bool negative = false;
  if (p < end && (*p == '-' || *p == '+')) negative = *p++ == '-';
  if (p == end || end - p > 9) return false;
  int value = 0;
  for (; p < end; ++p) {
    const unsigned digit = static_cast<unsigned>(*p - '0');
    if (digit > 9) return false;
    value = value * 10 + static_cast<int>(digit);
  }
  if (negative) value = -value;
  if (value < -5 || value > kMaxGroupCode) return false;  // -5..-1 are reserved but legal
  code = value;
  return true;
}

/// For a decimal that from_chars found out of range: true when it is too
/// large (an error), false when it is too small (read as zero).
bool too_large(std::string_view s) {
  std::size_t i = (!s.empty() && s[0] == '-') ? 1 : 0;
  long long before_point = 0, first_nonzero = -1, digits = 0;
  bool point = false;
  for (; i < s.size() && s[i] != 'e' && s[i] != 'E'; ++i) {
    if (s[i] == '.') {
      point = true;
      continue;
    }
    if (first_nonzero < 0 && s[i] != '0') first_nonzero = digits;
    ++digits;
    if (!point) ++before_point;
  }
  long long exponent = 0;
  if (i < s.size()) {
    ++i;
    bool negative = false;
    if (i < s.size() && (s[i] == '-' || s[i] == '+')) negative = s[i++] == '-';
    for (; i < s.size() && exponent < 1000000000; ++i) exponent = exponent * 10 + (s[i] - '0');
    if (negative) exponent = -exponent;
  }
  if (first_nonzero < 0) return false;
  return before_point - 1 - first_nonzero + exponent > 0;
}

/// Little-endian fixed-size values of binary DXF, on any host.
template <class T>
T little_endian(const char* p) {
  using U = std::make_unsigned_t<T>;
  U value = 0;
  for (std::size_t i = 0; i < sizeof(T); ++i)
    value |= static_cast<U>(static_cast<U>(static_cast<unsigned char>(p[i])) << (8 * i));
  return static_cast<T>(value);
}

enum class BinaryType { string, real, int16, int32, int64, boolean, chunk };

/// The value type of a group code in binary DXF (as ezdxf and the DXF
/// reference assign them).
BinaryType binary_type(int code) {
  const auto in = [code](int low, int high) { return code >= low && code <= high; };
  if (in(10, 59) || in(110, 149) || in(210, 239) || in(460, 469) || in(1010, 1059)) return BinaryType::real;
  if (in(60, 79) || in(170, 179) || in(270, 289) || in(370, 389) || in(400, 409) || in(1060, 1070))
    return BinaryType::int16;
  if (in(90, 99) || in(420, 429) || in(440, 459) || code == 1071) return BinaryType::int32;
  if (in(160, 169)) return BinaryType::int64;
  if (in(290, 299)) return BinaryType::boolean;
  if (in(310, 319) || code == 1004) return BinaryType::chunk;
  return BinaryType::string;
}

}  // namespace

TagReader::TagReader(std::string_view contents, const std::string& name) : data_(contents), name_(name) {
  if (data_.starts_with(kBinarySentinel)) {
    binary_ = true;
    pos_ = kBinarySentinel.size();
    // The first tag is (0, "SECTION"): "\0\0SECTION" with two-byte codes, "\0SECTION" with one.
    two_byte_codes_ = !(data_.size() > pos_ + 1 && data_[pos_] == 0 && data_[pos_ + 1] != 0);
    return;
  }
  if (data_.starts_with(kUtf8Bom)) pos_ = kUtf8Bom.size();
  // One vectorised scan now instead of one per line; the line that holds
  // the NUL is reported when it is reached, so bytes after EOF do not count.
  if (const void* nul = std::memchr(data_.data(), 0, data_.size()))
    nul_ = static_cast<std::size_t>(static_cast<const char*>(nul) - data_.data());
}

void TagReader::fail_at(std::size_t where, const std::string& message) const {
  if (binary_) throw Error("byte " + std::to_string(where) + ": " + message, {name_, 0});
  throw Error(message, {name_, where});
}

bool TagReader::next_line(std::string_view& line) {
  if (pos_ >= data_.size()) return false;
  const char* begin = data_.data() + pos_;
  const std::size_t left = data_.size() - pos_;
  const void* newline = std::memchr(begin, '\n', left);
  const std::size_t length = newline ? static_cast<std::size_t>(static_cast<const char*>(newline) - begin) : left;
  pos_ += newline ? length + 1 : length;
  ++line_;
  if (nul_ < pos_) fail_at(line_, "nul byte in a text DXF file");
  line = {begin, length};
  return true;
}

bool TagReader::next_ascii(Tag& tag) {
  std::string_view code_line, value_line;
  for (;;) {
    if (!next_line(code_line)) return false;
    const std::string_view code_text = trim(code_line);
    int code = 0;
    if (!parse_code(code_text, code)) {
      // Blank lines (and a DOS end-of-file mark) after the last tag are no tag.
      if (code_text.empty() || code_text == "\x1a") {
        const std::string_view rest = data_.substr(pos_);
        if (rest.find_first_not_of(" \t\r\n\x1a") == std::string_view::npos) return false;
      }
      fail_at(line_, "bad group code '" + shown(code_text) + "'");
    }
    if (!next_line(value_line))
      fail_at(line_, "group code " + std::to_string(code) + " without a value at the end of the file");
    if (code == 999) continue;
    tag.code = code;
    tag.text = trim(value_line);
    tag.typed = false;
    tag.where = line_;
    return true;
  }
}

bool TagReader::next_binary(Tag& tag) {
  for (;;) {
    if (pos_ >= data_.size()) return false;
    const std::size_t at = pos_;
    unsigned code = 0;
    bool code_read = false;
    const auto need = [&](std::size_t bytes) {
      if (data_.size() - pos_ < bytes)
        fail_at(at, code_read ? "truncated value of group code " + std::to_string(code) : "truncated group code");
    };
    if (two_byte_codes_) {
      need(2);
      code = little_endian<std::uint16_t>(data_.data() + pos_);
      pos_ += 2;
    } else {
      code = static_cast<unsigned char>(data_[pos_++]);
      if (code == 255) {  // R12: a larger code follows in two bytes
        need(2);
        code = little_endian<std::uint16_t>(data_.data() + pos_);
        pos_ += 2;
      }
    }
    code_read = true;
    if (code > kMaxGroupCode) fail_at(at, "bad group code " + std::to_string(code));
    tag.code = static_cast<int>(code);
    tag.where = at;
    tag.text = {};
    tag.typed = true;
    switch (binary_type(tag.code)) {
      case BinaryType::string: {
        const void* nul = std::memchr(data_.data() + pos_, 0, data_.size() - pos_);
        if (!nul) fail_at(at, "unterminated string value of group code " + std::to_string(code));
        const std::size_t length = static_cast<std::size_t>(static_cast<const char*>(nul) - (data_.data() + pos_));
        tag.text = data_.substr(pos_, length);
        tag.typed = false;
        pos_ += length + 1;
        break;
      }
      case BinaryType::real:
        need(8);
        tag.number = std::bit_cast<double>(little_endian<std::uint64_t>(data_.data() + pos_));
        pos_ += 8;
        break;
      case BinaryType::int16:
        need(2);
        tag.number = little_endian<std::int16_t>(data_.data() + pos_);
        pos_ += 2;
        break;
      case BinaryType::int32:
        need(4);
        tag.number = little_endian<std::int32_t>(data_.data() + pos_);
        pos_ += 4;
        break;
      case BinaryType::int64:
        need(8);
        tag.number = static_cast<double>(little_endian<std::int64_t>(data_.data() + pos_));
        pos_ += 8;
        break;
      case BinaryType::boolean:
        need(1);
        tag.number = static_cast<unsigned char>(data_[pos_++]);
        break;
      case BinaryType::chunk: {
        need(1);
        const std::size_t length = static_cast<unsigned char>(data_[pos_++]);
        need(length);
        tag.text = data_.substr(pos_, length);
        tag.typed = false;
        pos_ += length;
        break;
      }
    }
    if (code == 999) continue;
    return true;
  }
}

void TagReader::fail_number(const Tag& tag, const char* what) const {
  std::string text = tag.typed ? (std::isnan(tag.number)   ? "nan"
                                  : std::isinf(tag.number) ? "inf"
                                                           : std::to_string(tag.number))
                               : shown(tag.text);
  fail(tag, std::string(what) + " '" + text + "' for group code " + std::to_string(tag.code));
}

double TagReader::real(const Tag& tag) const {
  if (tag.typed) {
    if (!std::isfinite(tag.number)) fail_number(tag, "bad number");
    return tag.number;
  }
  std::string_view text = tag.text;
  if (text.size() > 1 && text[0] == '+' && text[1] != '-') text.remove_prefix(1);
  double value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (end != text.data() + text.size() || error == std::errc::invalid_argument) fail_number(tag, "bad number");
  if (error == std::errc::result_out_of_range) {
    if (too_large(text)) fail_number(tag, "number out of range");
    return text[0] == '-' ? -0.0 : 0.0;
  }
  if (!std::isfinite(value)) fail_number(tag, "bad number");  // "nan", "inf", "infinity"
  return value;
}

std::int64_t TagReader::integer(const Tag& tag) const {
  if (tag.typed) {
    // Binary integers are exact in the double; a real where an integer
    // belongs is a bad number.
    if (!(std::abs(tag.number) < 9.2e18) || tag.number != std::floor(tag.number)) fail_number(tag, "bad integer");
    return static_cast<std::int64_t>(tag.number);
  }
  std::string_view text = tag.text;
  if (text.size() > 1 && text[0] == '+' && text[1] != '-') text.remove_prefix(1);
  std::int64_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (end != text.data() + text.size() || error == std::errc::invalid_argument) fail_number(tag, "bad integer");
  if (error == std::errc::result_out_of_range) fail_number(tag, "number out of range");
  return value;
}

}  // namespace tk::cad::dxf
