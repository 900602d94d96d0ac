/// @file fuzz_header_detection.cpp
/// @brief libFuzzer target: whether an input's first line is a CSV header.
///
/// The bytes are one input file, read four ways as the tools read them:
/// a number column (subtune: field "size"), designations (threadcalc:
/// "designation"), candidates (mrtest, riesel: "number", "expr" or "k" and
/// "n") and plain records whose header must name "t" and "load" (fuzzyfeed).
/// tk::Error is caught and reading continues, as --skip-bad does.
///
/// Oracles (switch off by name with TK_FUZZ_SKIP=a,b while a finding is open):
///   header    unless the first non-blank line is a JSON object, every record
///             holds the fields its tool needs: a first line that does not
///             name them is data (an error or a record), never a header
///   progress  no more errors and records than the input has lines
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "fuzz_common.hpp"
#include "io/csv.hpp"
#include "io/error.hpp"
#include "io/number_column.hpp"
#include "io/record_reader.hpp"
#include "primes/candidate_input.hpp"
#include "threads/designation_input.hpp"

namespace {

using tk::fuzz::MemoryFile;

std::size_t lines_in(std::string_view bytes) {
  std::size_t lines = 1;
  for (char ch : bytes) lines += ch == '\n';
  return lines;
}

// The first line that is not blank once a byte-order mark is dropped, as
// RecordReader sees it.
std::string_view first_line(std::string_view bytes) {
  if (bytes.starts_with("\xEF\xBB\xBF")) bytes.remove_prefix(3);
  while (!bytes.empty()) {
    const std::size_t end = std::min(bytes.find('\n'), bytes.size());
    const std::string_view line = bytes.substr(0, end);
    if (line.find_first_not_of(" \t\r\f\v") != std::string_view::npos) return line;
    bytes.remove_prefix(std::min(end + 1, bytes.size()));
  }
  return {};
}

void read_as(const std::string& path, tk::io::NativeFormatProbe probe, const tk::io::ColumnSets& needs, bool json_first,
             std::size_t max_lines) {
  tk::io::RecordReader reader({path}, std::move(probe));
  reader.expect_columns(needs);
  std::size_t errors = 0, records = 0;
  for (;;) {
    tk::Record record;
    bool produced = false;
    try {
      if (!reader.next(record)) break;
      produced = true;
    } catch (const tk::Error&) {
      ++errors;
    }
    if (produced) {
      ++records;
      std::vector<std::string> names;
      for (const auto& item : record.items()) names.push_back(item.key());
      if (!json_first && !tk::io::names_columns(names, needs) && tk::fuzz::oracle_enabled("header"))
        tk::fuzz::invariant_failed("header", "a record without " + tk::io::describe_columns(needs) + ": " +
                                                 record.dump(-1, ' ', false, tk::Record::error_handler_t::replace));
    }
    if (errors + records > max_lines) {
      if (tk::fuzz::oracle_enabled("progress"))
        tk::fuzz::invariant_failed("progress", std::to_string(errors) + " errors and " + std::to_string(records) +
                                                   " records from " + std::to_string(max_lines) + " lines");
      break;
    }
  }
}

void run(std::string_view bytes) {
  static MemoryFile file("fuzz-header");
  file.assign(bytes);
  const std::size_t max_lines = lines_in(bytes);
  const std::string_view first = first_line(bytes);
  const std::size_t start = first.find_first_not_of(" \t\r\f\v");
  const bool json_first = start != std::string_view::npos && first[start] == '{';
  read_as(file.path(), tk::io::number_column_probe("size"), {{"size"}}, json_first, max_lines);
  read_as(file.path(), tk::threads::designation_lines_probe("designation"), {{"designation"}}, json_first, max_lines);
  read_as(file.path(), tk::primes::candidate_format_probe(4096), tk::primes::candidate_columns(), json_first,
          max_lines);
  read_as(file.path(), {}, {{"t", "load"}}, json_first, max_lines);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  run(std::string_view(reinterpret_cast<const char*>(data), size));
  return 0;
}
