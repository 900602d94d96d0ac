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
/// "\r\n"; a NUL byte or a line longer than the limit is an Error at that
/// line, so binary garbage never reaches a parser.
class InputFile {
 public:
  static constexpr std::size_t kMaxLineBytes = 64u << 20;

  explicit InputFile(const std::string& path);
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
  [[noreturn]] void skip_long_line();

  std::FILE* file_ = nullptr;
  bool owns_ = false;
  std::string name_;
  std::size_t line_number_ = 0;
  std::vector<char> buffer_;
  std::size_t begin_ = 0, end_ = 0;
  bool eof_ = false;
  std::uint64_t consumed_ = 0, size_ = 0;
};

}  // namespace tk::io
