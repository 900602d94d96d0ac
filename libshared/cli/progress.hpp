/// @file progress.hpp
/// @brief A progress line on stderr: count, rate, and percent and ETA when
/// the input size is known. Redrawn at most five times a second.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>
#include <string_view>

namespace tk::cli {

class Progress {
 public:
  Progress(std::string tool, bool enabled);
  ~Progress();
  /// `done` items so far; `fraction` of the work done, negative if unknown.
  /// A non-empty `detail` replaces the "N done, R/s" part.
  void update(std::uint64_t done, double fraction = -1.0, std::string_view detail = {});
  /// Clears the line.
  void finish();

 private:
  std::string tool_;
  bool enabled_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point start_, last_;
};

}  // namespace tk::cli
