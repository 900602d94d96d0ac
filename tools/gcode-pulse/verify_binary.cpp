/// @file verify_binary.cpp
/// @brief gcode-pulse --verify-binary: a --binary stream checked and described.
#include "io/error.hpp"
#include "io/record_writer.hpp"
#include "modes.hpp"
#include "motion/pulse_binary.hpp"

namespace gcode_pulse {

void verify_binary(const std::string& path, tk::cli::ToolApp& tool) {
  if (!tool.common().inputs.empty()) throw tk::UsageError("--verify-binary reads no G-code");
  tk::io::RecordWriter writer(tool.output_format());
  writer.write(tk::motion::pulse_stream_record(path, tk::motion::read_pulse_binary(path)));
  writer.flush();
}

}  // namespace gcode_pulse
