/// @file progress.cpp
#include "cli/progress.hpp"

#include <fmt/format.h>

#include <unistd.h>

#include <cstdio>

namespace tk::cli {

Progress::Progress(std::string tool, bool enabled)
    : tool_(std::move(tool)), enabled_(enabled), start_(std::chrono::steady_clock::now()), last_(start_) {}

Progress::~Progress() { finish(); }

void Progress::update(std::uint64_t done, double fraction, std::string_view detail) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  // A terminal gets one line redrawn in place; a log file a line every 2 s.
  const bool terminal = isatty(2) != 0;
  if (now - last_ < std::chrono::milliseconds(terminal ? 200 : 2000)) return;
  last_ = now;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  std::string text = detail.empty()
                         ? fmt::format("{}: {} done, {:.1f}/s", tool_, done, elapsed > 0 ? done / elapsed : 0.0)
                         : fmt::format("{}: {}", tool_, detail);
  if (fraction > 0.0 && fraction <= 1.0)
    text += fmt::format(", {:.1f}%, eta {:.0f} s", 100.0 * fraction, elapsed * (1.0 - fraction) / fraction);
  if (terminal) {
    std::fprintf(stderr, "\r%s\x1b[K", text.c_str());
    drawn_ = true;
  } else {
    std::fprintf(stderr, "%s\n", text.c_str());
  }
  std::fflush(stderr);
}

void Progress::finish() {
  if (drawn_) std::fprintf(stderr, "\r\x1b[K");
  drawn_ = false;
}

}  // namespace tk::cli
