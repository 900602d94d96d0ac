/// @file input_file.cpp
#include "io/input_file.hpp"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>

namespace tk::io {

InputFile::InputFile(const std::string& path) : buffer_(1u << 16) {
  if (path == "-" || path.empty()) {
    file_ = stdin;
    name_ = "<stdin>";
  } else {
    file_ = std::fopen(path.c_str(), "rb");
    name_ = path;
    if (!file_) throw Error(std::string("cannot open: ") + std::strerror(errno), {path, 0});
    owns_ = true;
    struct stat st {};
    if (fstat(fileno(file_), &st) == 0) {
      if (S_ISDIR(st.st_mode)) {
        std::fclose(file_);
        file_ = nullptr;
        throw Error("is a directory", {path, 0});
      }
      if (S_ISREG(st.st_mode)) size_ = static_cast<std::uint64_t>(st.st_size);
    }
  }
}

InputFile::~InputFile() {
  if (owns_ && file_) std::fclose(file_);
}

bool InputFile::fill() {
  if (eof_) return false;
  if (begin_ > 0) {
    std::memmove(buffer_.data(), buffer_.data() + begin_, end_ - begin_);
    end_ -= begin_;
    begin_ = 0;
  }
  if (end_ == buffer_.size()) buffer_.resize(buffer_.size() * 2);
  std::size_t got = std::fread(buffer_.data() + end_, 1, buffer_.size() - end_, file_);
  if (got == 0) {
    eof_ = true;  // also after a read error: the next call ends this input
    if (std::ferror(file_))
      throw Error(std::string("read error: ") + std::strerror(errno), {name_, 0});
    return false;
  }
  end_ += got;
  return true;
}

// Drops the rest of an over-long line, then reports it, so that the next
// call (with --skip-bad) starts on the following line.
void InputFile::skip_long_line() {
  const std::size_t line = ++line_number_;
  for (;;) {
    const void* newline = std::memchr(buffer_.data() + begin_, '\n', end_ - begin_);
    if (newline) {
      const std::size_t stop = static_cast<std::size_t>(static_cast<const char*>(newline) - buffer_.data()) + 1;
      consumed_ += stop - begin_;
      begin_ = stop;
      break;
    }
    consumed_ += end_ - begin_;
    begin_ = end_ = 0;
    if (!fill()) break;
  }
  throw Error("line longer than 64 MiB", {name_, line});
}

bool InputFile::next(std::string_view& line) {
  std::size_t searched = 0;  // bytes after begin_ already known to hold no newline
  for (;;) {
    const char* base = buffer_.data() + begin_;
    const std::size_t available = end_ - begin_;
    const void* newline = std::memchr(base + searched, '\n', available - searched);
    std::size_t length = 0, advance = 0;
    if (newline) {
      length = static_cast<std::size_t>(static_cast<const char*>(newline) - base);
      advance = length + 1;
    } else {
      searched = available;
      if (available > kMaxLineBytes) skip_long_line();  // throws
      if (fill()) continue;  // fill() keeps offsets relative to begin_ valid
      if (end_ == begin_) return false;
      length = advance = end_ - begin_;  // last line without a newline
      base = buffer_.data() + begin_;
    }
    if (length > kMaxLineBytes) skip_long_line();
    ++line_number_;
    consumed_ += advance;
    begin_ += advance;
    if (length > 0 && base[length - 1] == '\r') --length;
    if (std::memchr(base, '\0', length)) throw Error("binary data (NUL byte) in text input", where());
    line = std::string_view(base, length);
    return true;
  }
}

}  // namespace tk::io
