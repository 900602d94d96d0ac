/// @file input_file.cpp
#include "io/input_file.hpp"

#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "io/stop_signal.hpp"

namespace tk::io {

InputFile::InputFile(const std::string& path, std::size_t max_line_bytes)
    : max_line_bytes_(max_line_bytes), buffer_(1u << 16) {
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
  // read(2), not fread: it returns what a pipe holds instead of waiting for
  // the whole buffer, and the poll's timeout lets a caught SIGINT/SIGTERM
  // end a read that no data would end.
  const int fd = fileno(file_);
  for (;;) {
    if (const int signal = noticed_stop_signal())
      throw Error("stopped by signal " + std::to_string(signal), {name_, line_number_});
    pollfd ready{fd, POLLIN, 0};
    const int polled = ::poll(&ready, 1, 250);
    if (polled == 0 || (polled < 0 && errno == EINTR)) continue;  // look at the signal again
    const ssize_t got = ::read(fd, buffer_.data() + end_, buffer_.size() - end_);
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) {
      eof_ = true;  // also after a read error: the next call ends this input
      if (got < 0) throw Error(std::string("read error: ") + std::strerror(errno), {name_, 0});
      return false;
    }
    end_ += static_cast<std::size_t>(got);
    return true;
  }
}

std::string InputFile::limit_text() const {
  return max_line_bytes_ % (1u << 20) == 0 ? std::to_string(max_line_bytes_ >> 20) + " MiB"
                                           : std::to_string(max_line_bytes_) + " bytes";
}

// Reports the line being read without waiting for its end: the rest is
// dropped by the next call (for --skip-bad), not here, so that an endless
// line is reported at once.
void InputFile::fail_line(const std::string& message) {
  ++line_number_;
  skipping_ = true;
  throw Error(message, where());
}

// Drops the rest of a refused line, reading at most another limit's worth.
// Throws, with the input given up, when the line does not end there.
void InputFile::skip_bad_line() {
  skipping_ = false;
  std::uint64_t dropped = 0;
  const std::uint64_t limit = (end_ - begin_) + max_line_bytes_;
  for (;;) {
    const void* newline = std::memchr(buffer_.data() + begin_, '\n', end_ - begin_);
    if (newline) {
      const std::size_t stop = static_cast<std::size_t>(static_cast<const char*>(newline) - buffer_.data()) + 1;
      consumed_ += stop - begin_;
      begin_ = stop;
      return;
    }
    dropped += end_ - begin_;
    consumed_ += end_ - begin_;
    begin_ = end_ = 0;
    if (dropped > limit) break;
    if (!fill()) return;
  }
  abandoned_ = true;
  throw Error("no end of line within " + limit_text() + " after this line: the rest of the input is skipped", where());
}

bool InputFile::next(std::string_view& line) {
  if (abandoned_) return false;
  if (skipping_) skip_bad_line();
  std::size_t searched = 0;  // bytes after begin_ known to hold no newline and no NUL
  for (;;) {
    const char* base = buffer_.data() + begin_;
    const std::size_t available = end_ - begin_;
    const void* newline = std::memchr(base + searched, '\n', available - searched);
    const std::size_t length = newline ? static_cast<std::size_t>(static_cast<const char*>(newline) - base) : available;
    if (std::memchr(base + searched, '\0', length - searched)) fail_line("binary data (NUL byte) in text input");
    if (length > max_line_bytes_) fail_line("line longer than " + limit_text());
    if (!newline) {
      searched = available;
      if (fill()) continue;  // fill() keeps offsets relative to begin_ valid
      if (end_ == begin_) return false;
      base = buffer_.data() + begin_;  // the last line, without a newline
    }
    const std::size_t advance = newline ? length + 1 : length;
    std::size_t kept = length;
    if (kept > 0 && base[kept - 1] == '\r') --kept;
    ++line_number_;
    consumed_ += advance;
    begin_ += advance;
    line = std::string_view(base, kept);
    if (line_number_ == 1 && line.starts_with("\xEF\xBB\xBF")) line.remove_prefix(3);
    return true;
  }
}

}  // namespace tk::io
