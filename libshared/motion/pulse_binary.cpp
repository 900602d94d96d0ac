/// @file pulse_binary.cpp
#include "motion/pulse_binary.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>

#include "io/error.hpp"

namespace tk::motion {

PulseBinaryWriter::PulseBinaryWriter(std::FILE* out, const std::array<double, 3>& steps_per_mm) : out_(out) {
  buffer_.append("GCPULSE1", 8);
  for (double value : steps_per_mm) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &value, sizeof bits);
    for (int byte = 0; byte < 8; ++byte) buffer_.push_back(static_cast<char>(bits >> (8 * byte) & 0xFF));
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
  if (buffer_.size() >= (1u << 16)) flush();
}

void PulseBinaryWriter::flush() {
  if (!buffer_.empty() && std::fwrite(buffer_.data(), 1, buffer_.size(), out_) != buffer_.size())
    throw Error(std::string("write error: ") + std::strerror(errno));
  buffer_.clear();
  if (std::fflush(out_) != 0) throw Error(std::string("write error: ") + std::strerror(errno));
}

}  // namespace tk::motion
