/// @file pulse_binary.hpp
/// @brief gcode-pulse's compact binary pulse stream, for programs whose
/// text output would run to gigabytes. Layout (all little-endian):
///
///   header  8 bytes "GCPULSE1", then steps per mm of X, Y, Z as three
///           IEEE-754 doubles (32 bytes in all)
///   event   the time since the previous event (the first: since 0) in
///           whole nanoseconds as an unsigned LEB128 varint, then one byte
///           (dx + 1) + 3 (dy + 1) + 9 (dz + 1), 0 to 26 (13, no move,
///           never occurs)
///
/// Times are rounded to the nanosecond from the start, and differences
/// taken of the rounded values, so the stream accumulates no rounding.
#pragma once

#include <array>
#include <cstdint>
#include <cstdio>
#include <span>
#include <string>

#include "motion/pulse_run.hpp"

namespace tk::motion {

class PulseBinaryWriter {
 public:
  PulseBinaryWriter(std::FILE* out, const std::array<double, 3>& steps_per_mm);
  void write(std::span<const Pulse> pulses);
  void flush();  ///< throws tk::Error on a write failure

 private:
  void put(const unsigned char* bytes, std::size_t count);

  std::FILE* out_;
  std::uint64_t last_ns_ = 0;
  std::string buffer_;
};

}  // namespace tk::motion
