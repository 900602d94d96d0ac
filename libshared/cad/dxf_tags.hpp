/// @file dxf_tags.hpp
/// @brief The lowest layer of the DXF reader (internal to dxf_*.cpp): splits
/// an ASCII or binary DXF held in memory into (group code, value) tags,
/// converts values to numbers on request, and words errors with the line
/// (ASCII) or byte offset (binary) at fault.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace tk::cad::dxf {

/// The first 22 bytes of a binary DXF file.
inline constexpr std::string_view kBinarySentinel{"AutoCAD Binary DXF\r\n\x1a\0", 22};

struct Tag {
  int code = 0;
  std::string_view text;  ///< ASCII: the value line, trimmed; binary: a string or binary chunk
  double number = 0;      ///< binary DXF: a numeric value (the group code gives its type)
  bool typed = false;     ///< `number` holds the value
  std::size_t where = 0;  ///< ASCII: line of the value; binary: byte offset of the group code
};

/// The tags of one file, in order. Group code 999 (comments) never shows.
/// The contents must outlive the reader and every Tag it gives out.
class TagReader {
 public:
  TagReader(std::string_view contents, const std::string& name);

  bool binary() const { return binary_; }
  const std::string& name() const { return name_; }

  /// The next tag; false at the end of the data (trailing blank lines of an
  /// ASCII file are no tag). Throws on a malformed group code, a code
  /// without a value, a NUL byte in ASCII DXF or a truncated binary value.
  bool next(Tag& tag) { return binary_ ? next_binary(tag) : next_ascii(tag); }

  /// Where the entity whose group code 0 is `tag` starts, as an argument for
  /// fail_at(): the line of the code (ASCII) or its byte offset (binary).
  std::size_t start_of(const Tag& tag) const { return binary_ ? tag.where : tag.where - 1; }
  /// Segment::source_line for that entity: 0 in binary DXF.
  std::size_t source_line(std::size_t start) const { return binary_ ? 0 : start; }

  /// The value as a finite double or an integer; throws naming the value's
  /// line ("bad number 'x' for group code 10", "number out of range ...").
  double real(const Tag& tag) const;
  std::int64_t integer(const Tag& tag) const;

  /// Throws tk::Error at the tag's value line or byte offset.
  [[noreturn]] void fail(const Tag& tag, const std::string& message) const { fail_at(tag.where, message); }
  /// Throws at a line (ASCII) or byte offset (binary): "name:LINE: message"
  /// or "name: byte OFFSET: message".
  [[noreturn]] void fail_at(std::size_t where, const std::string& message) const;

 private:
  bool next_ascii(Tag& tag);
  bool next_binary(Tag& tag);
  /// One line of ASCII DXF without its "\n" or "\r\n"; false at the end.
  bool next_line(std::string_view& line);
  [[noreturn]] void fail_number(const Tag& tag, const char* what) const;

  std::string_view data_;
  std::string name_;
  bool binary_ = false;
  bool two_byte_codes_ = true;                ///< binary DXF R13 and later; R12 used one byte
  std::size_t pos_ = 0;                       ///< next byte to read
  std::size_t line_ = 0;                      ///< ASCII: lines read so far
  std::size_t nul_ = std::string_view::npos;  ///< ASCII: first NUL byte
};

}  // namespace tk::cad::dxf
