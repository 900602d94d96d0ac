/// @file input_file.hpp
/// @brief Buffered line reader over a file or stdin that tracks line numbers.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include "io/error.hpp"

namespace tk::io {

/// Reads one input ("-" is stdin) line by line. Lines lose their "\n" or
/// "\r\n", and the first line a UTF-8 byte-order mark. A NUL byte or a line
/// longer than the limit is an Error at that line, raised as soon as the
/// bytes arrive (an endless line such as /dev/zero's fails at once), so
/// binary garbage never reaches a parser. The next call skips the rest of
/// the bad line, but at most another limit's worth: an input whose line
/// never ends is then given up with a second Error.
class InputFile {
 public:
  static constexpr std::size_t kMaxLineBytes = 64u << 20;

  /// `max_line_bytes` other than the default is for tests.
  explicit InputFile(const std::string& path, std::size_t max_line_bytes = kMaxLineBytes);
  ~InputFile();
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;

  /// Next line into `line`; false at end of input. The view stays valid
  /// until the next call.
  bool next(std::string_view& line);

  /// Location of the line last returned.
  Location where() const { return {name_, line_number_}; }
  std::size_t line_number() const { return line_number_; }

  /// Bytes consumed and total size (0 when unknown, as for a pipe).
  std::uint64_t bytes_read() const { return consumed_; }
  std::uint64_t size() const { return size_; }

 private:
  bool fill();
  [[noreturn]] void fail_line(const std::string& message);
  std::string limit_text() const;
  void skip_bad_line();

  std::FILE* file_ = nullptr;
  bool owns_ = false;
  std::string name_;
  std::size_t max_line_bytes_;
  std::size_t line_number_ = 0;
  std::vector<char> buffer_;
  std::size_t begin_ = 0, end_ = 0;
  bool eof_ = false;
  bool skipping_ = false;   // the last line was refused: drop its rest first
  bool abandoned_ = false;  // a refused line never ended: the input is over
  std::uint64_t consumed_ = 0, size_ = 0;
};

}  // namespace tk::io
