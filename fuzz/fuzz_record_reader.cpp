/// @file fuzz_record_reader.cpp
/// @brief libFuzzer target: bytes as one or two input files of a prime tool.
///
/// The input is split at its first 0x1E byte (ASCII record separator) into
/// two files, so switching format between inputs is covered too; without one
/// it is a single file. The files are read with tk::io::RecordReader and the
/// native-format probe candidate_format_probe(4096) (JSON Lines, CSV, plain
/// numbers, NewPGen/ABC), as mrtest does. Every record goes through
/// candidate_from_record and is written back out as JSON Lines and CSV
/// (to /dev/null). tk::Error is caught and reading continues, as --skip-bad
/// does.
///
/// Oracles (switch off by name with TK_FUZZ_SKIP=a,b while a finding is open):
///   progress   after an error the reader moves on: no more errors and
///              records than the input has lines
///   object     every record is a JSON object
#include <sys/mman.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "fuzz_common.hpp"
#include "io/error.hpp"
#include "io/record_reader.hpp"
#include "io/record_writer.hpp"
#include "primes/candidate.hpp"
#include "primes/candidate_input.hpp"

namespace {

using tk::fuzz::MemoryFile;
using tk::fuzz::null_output;

constexpr std::size_t kMaxBits = 4096;

std::size_t lines_in(std::string_view bytes) {
  std::size_t lines = 0;
  for (char ch : bytes) lines += ch == '\n';
  return lines + 1;  // a last line without a newline
}

void run(std::string_view bytes) {
  static MemoryFile first("fuzz-input-1"), second("fuzz-input-2");
  std::vector<std::string> paths;
  std::size_t max_lines = 0;
  if (const auto split = bytes.find('\x1e'); split != std::string_view::npos) {
    first.assign(bytes.substr(0, split));
    second.assign(bytes.substr(split + 1));
    paths = {first.path(), second.path()};
    max_lines = lines_in(bytes.substr(0, split)) + lines_in(bytes.substr(split + 1));
  } else {
    first.assign(bytes);
    paths = {first.path()};
    max_lines = lines_in(bytes);
  }

  tk::io::RecordReader reader(paths, tk::primes::candidate_format_probe(kMaxBits));
  tk::io::RecordWriter json_out(tk::io::OutputFormat::json_lines, null_output());
  tk::io::RecordWriter csv_out(tk::io::OutputFormat::csv, null_output());
  csv_out.declare_fields({"verdict", "test"});

  std::size_t errors = 0, records = 0;
  for (;;) {
    tk::Record record;
    try {
      if (!reader.next(record)) break;
    } catch (const tk::Error&) {
      (void)reader.where();
      if (++errors + records > max_lines) {
        if (tk::fuzz::oracle_enabled("progress"))
          tk::fuzz::invariant_failed("progress", std::to_string(errors) + " errors and " + std::to_string(records) +
                                                     " records from " + std::to_string(max_lines) +
                                                     " lines: the reader does not move on after an error");
        break;
      }
      continue;
    }
    ++records;
    (void)reader.where();
    (void)reader.fraction_done();
    if (errors + records > max_lines) {
      if (tk::fuzz::oracle_enabled("progress"))
        tk::fuzz::invariant_failed("progress", std::to_string(records) + " records and " + std::to_string(errors) +
                                                   " errors from " + std::to_string(max_lines) + " lines");
      break;
    }
    if (!record.is_object()) {
      if (tk::fuzz::oracle_enabled("object"))
        tk::fuzz::invariant_failed("object", "reader returned a " + std::string(record.type_name()));
      continue;
    }
    try {
      (void)tk::primes::candidate_from_record(record, kMaxBits);
    } catch (const tk::Error&) {
    }
    try {
      json_out.write(record);
    } catch (const tk::Error&) {
    }
    try {
      csv_out.write(record);
    } catch (const tk::Error&) {
    }
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
