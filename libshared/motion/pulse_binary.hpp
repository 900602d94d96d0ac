/// @file pulse_binary.hpp
/// @brief gcode-pulse's compact binary pulse stream, for programs whose
/// text output would run to gigabytes. Layout (all little-endian):
///
///   header  8 bytes "GCPULSE2", then steps per mm of X, Y, Z as three
///           IEEE-754 doubles (32 bytes in all)
///   event   the time since the previous event (the first: since 0) in
///           whole nanoseconds as an unsigned LEB128 varint, then one byte
///           (dx + 1) + 3 (dy + 1) + 9 (dz + 1), 0 to 26 (13, no move,
///           never occurs)
///   trailer the bytes 0 and 13 (a zero delta with the move no event has),
///           the number of events as a uint64 and the last event's time in
///           nanoseconds as a uint64 (0 without events): 18 bytes, the
///           stream's last
///
/// Times are rounded to the nanosecond from the start, and differences
/// taken of the rounded values, so the stream accumulates no rounding. A
/// stream without its trailer was cut short (a killed run, a full disk, an
/// error in the G-code); read_pulse_binary() refuses it.
#pragma once

#include <array>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <span>
#include <string>

#include "io/record.hpp"
#include "motion/pulse_run.hpp"

namespace tk::motion {

class PulseBinaryWriter {
 public:
  PulseBinaryWriter(std::FILE* out, const std::array<double, 3>& steps_per_mm);
  void write(std::span<const Pulse> pulses);
  /// Writes what is buffered, without the trailer: the events before an
  /// error stay written, in a stream that says it is incomplete.
  void flush();  ///< throws tk::Error on a write failure
  /// Writes the trailer and flushes: the stream is complete.
  void finish();

 private:
  std::FILE* out_;
  std::uint64_t last_ns_ = 0;
  std::uint64_t events_ = 0;
  std::string buffer_;
};

/// What a complete stream holds.
struct PulseStreamInfo {
  std::array<double, 3> steps_per_mm{};
  std::uint64_t events = 0;
  std::uint64_t last_ns = 0;
  std::array<std::uint64_t, 3> steps{};  ///< steps per axis, both directions
};

/// One event as read back: its time in nanoseconds and its move.
using PulseEventSink = std::function<void(std::uint64_t ns, const std::array<int, 3>& delta)>;

/// Reads a whole stream from `path` ("-": standard input), handing each
/// event to `on_event` when given. Error naming the file and the byte
/// offset when it is not a complete GCPULSE2 stream: another header, a bad
/// move byte, no trailer or a short one (truncated), a trailer that
/// disagrees with the events, bytes after it.
PulseStreamInfo read_pulse_binary(const std::string& path, const PulseEventSink& on_event = {});

/// gcode-pulse --verify-binary's record: file, events, last_t (seconds),
/// pulses_x/y/z as --summary counts them, steps_per_mm_x/y/z.
Record pulse_stream_record(const std::string& path, const PulseStreamInfo& info);

}  // namespace tk::motion
