/// @file pulse_binary.cpp
#include "motion/pulse_binary.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <vector>

#include <fmt/format.h>

#include "io/error.hpp"

namespace tk::motion {

namespace {

constexpr char kMagic[9] = "GCPULSE2";
constexpr unsigned char kEndMove = 13;  // the move byte no event has: it starts the trailer

void put_u64(std::string& out, std::uint64_t value) {
  for (int byte = 0; byte < 8; ++byte) out.push_back(static_cast<char>(value >> (8 * byte) & 0xFF));
}

/// The stream's bytes one at a time, with the offset for messages.
class ByteSource {
 public:
  explicit ByteSource(const std::string& path) : path_(path), buffer_(1 << 16) {
    const bool standard_input = path == "-";
    file_ = standard_input ? stdin : std::fopen(path.c_str(), "rb");
    if (!file_) throw Error(std::string("cannot open: ") + std::strerror(errno), Location{name(), 0});
    owns_ = !standard_input;
  }
  ~ByteSource() {
    if (owns_) std::fclose(file_);
  }
  ByteSource(const ByteSource&) = delete;
  ByteSource& operator=(const ByteSource&) = delete;

  /// The next byte, or -1 at the end.
  int next() {
    if (at_ == end_ && !fill()) return -1;
    ++offset_;
    return buffer_[at_++];
  }
  /// The next byte; Error "truncated" at the end, saying what was expected.
  unsigned char need(const char* what) {
    const int byte = next();
    if (byte < 0) fail(fmt::format("the stream ends inside {}: truncated", what));
    return static_cast<unsigned char>(byte);
  }
  std::uint64_t need_u64(const char* what) {
    std::uint64_t value = 0;
    for (int byte = 0; byte < 8; ++byte) value |= std::uint64_t{need(what)} << (8 * byte);
    return value;
  }
  [[noreturn]] void fail(const std::string& message) const {
    throw Error(fmt::format("byte {}: {}", offset_, message), Location{name(), 0});
  }

 private:
  std::string name() const { return path_ == "-" ? "<stdin>" : path_; }
  bool fill() {
    at_ = 0;
    end_ = std::fread(buffer_.data(), 1, buffer_.size(), file_);
    if (end_ == 0 && std::ferror(file_)) fail(std::string("read error: ") + std::strerror(errno));
    return end_ > 0;
  }

  std::string path_;
  std::FILE* file_ = nullptr;
  bool owns_ = false;
  std::vector<unsigned char> buffer_;
  std::size_t at_ = 0, end_ = 0;
  std::uint64_t offset_ = 0;
};

}  // namespace

PulseBinaryWriter::PulseBinaryWriter(std::FILE* out, const std::array<double, 3>& steps_per_mm) : out_(out) {
  buffer_.append(kMagic, 8);
  for (double value : steps_per_mm) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &value, sizeof bits);
    put_u64(buffer_, bits);
  }
}

void PulseBinaryWriter::write(std::span<const Pulse> pulses) {
  for (const Pulse& pulse : pulses) {
    const auto ns = static_cast<std::uint64_t>(std::llround(pulse.t * 1e9));
    std::uint64_t delta = ns >= last_ns_ ? ns - last_ns_ : 0;
    last_ns_ = std::max(last_ns_, ns);
    do {
      const auto low = static_cast<unsigned char>(delta & 0x7F);
      delta >>= 7;
      buffer_.push_back(static_cast<char>(delta ? low | 0x80 : low));
    } while (delta);
    buffer_.push_back(static_cast<char>((pulse.delta[0] + 1) + 3 * (pulse.delta[1] + 1) + 9 * (pulse.delta[2] + 1)));
  }
  events_ += pulses.size();
  if (buffer_.size() >= (1u << 16)) flush();
}

void PulseBinaryWriter::flush() {
  if (!buffer_.empty() && std::fwrite(buffer_.data(), 1, buffer_.size(), out_) != buffer_.size())
    throw Error(std::string("write error: ") + std::strerror(errno));
  buffer_.clear();
  if (std::fflush(out_) != 0) throw Error(std::string("write error: ") + std::strerror(errno));
}

void PulseBinaryWriter::finish() {
  buffer_.push_back(0);
  buffer_.push_back(static_cast<char>(kEndMove));
  put_u64(buffer_, events_);
  put_u64(buffer_, last_ns_);
  flush();
}

PulseStreamInfo read_pulse_binary(const std::string& path, const PulseEventSink& on_event) {
  ByteSource in(path);
  PulseStreamInfo info;
  for (char expected : std::string_view(kMagic, 8))
    if (in.need("the header") != static_cast<unsigned char>(expected)) in.fail("not a GCPULSE2 stream");
  for (double& value : info.steps_per_mm) {
    const std::uint64_t bits = in.need_u64("the header");
    std::memcpy(&value, &bits, sizeof value);
  }
  std::uint64_t ns = 0;
  for (;;) {
    int byte = in.next();
    if (byte < 0) in.fail(fmt::format("no trailer after {} events: truncated", info.events));
    std::uint64_t delta = 0;
    for (int shift = 0;; shift += 7) {
      if (shift > 63) in.fail("a time delta longer than 64 bits");
      delta |= std::uint64_t(byte & 0x7F) << shift;
      if (!(byte & 0x80)) break;
      byte = in.need("an event");
    }
    const unsigned char move = in.need("an event");
    if (move == kEndMove && delta == 0) break;
    if (move > 26 || move == kEndMove) in.fail(fmt::format("bad move byte {}", move));
    ns += delta;
    ++info.events;
    const std::array<int, 3> step{move % 3 - 1, move / 3 % 3 - 1, move / 9 - 1};
    for (int axis = 0; axis < 3; ++axis) info.steps[axis] += step[axis] != 0;
    if (on_event) on_event(ns, step);
  }
  const std::uint64_t events = in.need_u64("the trailer"), last_ns = in.need_u64("the trailer");
  if (events != info.events || last_ns != ns)
    in.fail(fmt::format("the trailer says {} events ending at {} ns; the stream has {} ending at {} ns", events,
                        last_ns, info.events, ns));
  if (in.next() >= 0) in.fail("bytes after the trailer");
  info.last_ns = ns;
  return info;
}

Record pulse_stream_record(const std::string& path, const PulseStreamInfo& info) {
  Record record;
  record["file"] = path;
  record["events"] = info.events;
  record["last_t"] = static_cast<double>(info.last_ns) / 1e9;
  static const char* const kAxes[3] = {"x", "y", "z"};
  for (int axis = 0; axis < 3; ++axis) record[std::string("pulses_") + kAxes[axis]] = info.steps[axis];
  for (int axis = 0; axis < 3; ++axis) record[std::string("steps_per_mm_") + kAxes[axis]] = info.steps_per_mm[axis];
  return record;
}

}  // namespace tk::motion
