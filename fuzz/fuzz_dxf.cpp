/// @file fuzz_dxf.cpp
/// @brief libFuzzer target: the bytes as one DXF file (ASCII or, after the
/// "AutoCAD Binary DXF" sentinel, binary) through tk::cad::read_dxf, with
/// DxfReadOptions{chord_tolerance 0.01, max_segments 20000}. Seeds in
/// fuzz/seeds/fuzz_dxf/, dictionary fuzz/dicts/dxf.dict, run with
/// -max_len=4096.
///
/// tk::Error is the expected rejection; any other exception, crash,
/// sanitizer report, hang or huge allocation is a bug.
///
/// Oracles (switch off by name with TK_FUZZ_SKIP=a,b while a finding is open):
///   finite    every segment's ends and bulge are finite
///   bounded   no more segments than max_segments
///   layer     every segment's layer indexes Drawing::layers, and the
///             layers are distinct
///   order     entity indices never decrease along the segments
///   line      source_line is 0 in binary DXF, else within the input's lines
///   counts    at least as many entities read as entities with segments
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <set>
#include <string>
#include <string_view>

#include "cad/dxf_reader.hpp"
#include "fuzz_common.hpp"
#include "io/error.hpp"

namespace {

using namespace tk::cad;

void check(const Drawing& d, std::string_view bytes, const DxfReadOptions& options) {
  using tk::fuzz::invariant_failed;
  using tk::fuzz::oracle_enabled;
  if (oracle_enabled("bounded") && d.segments.size() > options.max_segments)
    invariant_failed("bounded", std::to_string(d.segments.size()) + " segments");
  if (oracle_enabled("layer") && std::set<std::string>(d.layers.begin(), d.layers.end()).size() != d.layers.size())
    invariant_failed("layer", "a layer listed twice");
  const std::size_t lines = static_cast<std::size_t>(std::count(bytes.begin(), bytes.end(), '\n')) + 1;
  std::size_t entities_with_segments = 0;
  for (std::size_t i = 0; i < d.segments.size(); ++i) {
    const Segment& s = d.segments[i];
    if (oracle_enabled("finite") && !(std::isfinite(s.start.x) && std::isfinite(s.start.y) && std::isfinite(s.end.x) &&
                                      std::isfinite(s.end.y) && std::isfinite(s.bulge)))
      invariant_failed("finite", "segment " + std::to_string(i) + " of entity " + std::to_string(s.entity));
    if (oracle_enabled("layer") && s.layer >= d.layers.size())
      invariant_failed("layer", "layer " + std::to_string(s.layer) + " of " + std::to_string(d.layers.size()));
    if (i == 0 || s.entity != d.segments[i - 1].entity) ++entities_with_segments;
    if (oracle_enabled("order") && i > 0 && s.entity < d.segments[i - 1].entity)
      invariant_failed("order",
                       "entity " + std::to_string(s.entity) + " after " + std::to_string(d.segments[i - 1].entity));
    if (oracle_enabled("line") && (d.binary ? s.source_line != 0 : s.source_line == 0 || s.source_line > lines))
      invariant_failed("line", "source line " + std::to_string(s.source_line) + " of " + std::to_string(lines));
  }
  std::size_t read = 0;
  for (const auto& [type, count] : d.entities_read) read += count;
  if (oracle_enabled("counts") && read < entities_with_segments)
    invariant_failed("counts", std::to_string(read) + " entities read, " + std::to_string(entities_with_segments) +
                                   " with segments");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  DxfReadOptions options;
  options.chord_tolerance = 0.01;
  options.max_segments = 20000;  // keeps curves with tiny tolerances quick
  try {
    check(read_dxf(bytes, "fuzz.dxf", options), bytes, options);
  } catch (const tk::Error&) {
    // the expected rejection; anything else reaches std::terminate
  }
  return 0;
}
