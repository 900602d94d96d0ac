/// @file fuzz_line_decoders.cpp
/// @brief libFuzzer target: the per-line decoders behind RecordReader, fed
/// directly (no InputFile), so they run at full speed.
///
/// The bytes are split into lines as InputFile does (LF, one trailing CR
/// dropped, blank lines skipped). The first line picks the format as
/// RecordReader::start_format does: '{' means JSON Lines (parse_json_object
/// per line); otherwise candidate_format_probe(4096) chooses a native decoder
/// (plain numbers, NewPGen, ABC/ABCD); a CSV header (no decoder) ends the run,
/// since CSV rows need an InputFile (fuzz_record_reader covers them).
/// Every record goes through candidate_from_record. tk::Error is expected
/// and skipped, as --skip-bad does.
///
/// fuzz_record_reader covers the same code through real files but pays for
/// InputFile's 1 MiB buffer on every input; this target is ~10x faster.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

#include "fuzz_common.hpp"
#include "io/error.hpp"
#include "io/record_reader.hpp"
#include "primes/candidate.hpp"
#include "primes/candidate_input.hpp"

namespace {

constexpr std::size_t kMaxBits = 4096;

bool is_blank(std::string_view line) { return line.find_first_not_of(" \t\r\f\v") == std::string_view::npos; }

void use(const tk::Record& record) {
  if (!record.is_object() && tk::fuzz::oracle_enabled("object"))
    tk::fuzz::invariant_failed("object", "decoder returned a " + std::string(record.type_name()));
  try {
    (void)tk::primes::candidate_from_record(record, kMaxBits);
  } catch (const tk::Error&) {
  }
  (void)record.dump(-1, ' ', false, tk::Record::error_handler_t::replace);
}

void run(std::string_view bytes) {
  const auto probe = tk::primes::candidate_format_probe(kMaxBits);
  std::unique_ptr<tk::io::LineDecoder> decoder;
  bool json = false, started = false;
  tk::Location where{"fuzz", 0};
  std::size_t pos = 0;
  while (pos < bytes.size()) {
    const std::size_t newline = bytes.find('\n', pos);
    const std::size_t end = newline == std::string_view::npos ? bytes.size() : newline;
    std::string_view line = bytes.substr(pos, end - pos);
    pos = end + 1;
    ++where.line;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (line.find('\0') != std::string_view::npos) continue;  // InputFile rejects NUL bytes
    if (is_blank(line)) continue;
    if (!started) {
      started = true;
      const auto start = line.find_first_not_of(" \t");
      if (line[start] == '{') {
        json = true;
      } else {
        decoder = probe(line);
        if (!decoder) return;  // CSV
      }
    }
    tk::Record record;
    try {
      if (json) {
        record = tk::io::parse_json_object(line, where);
      } else if (!decoder->decode(line, where, record)) {
        continue;
      }
    } catch (const tk::Error&) {
      continue;
    }
    use(record);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  // No catch here: an exception other than tk::Error reaches std::terminate
  // while its throw site is still on the stack, so the report shows it.
  run(bytes);
  return 0;
}
