/// @file fuzz_proof_journal.cpp
/// @brief libFuzzer target: bytes as a riesel --state journal.tsv, read with
/// tk::primes::read_journal, and the lresults.txt completion of its entries.
///
/// Each line ends in the FNV-1a checksum of what comes before its last tab,
/// which a random mutation almost always breaks, so every input is read
/// twice: as it is, and with each line's last field replaced by the correct
/// checksum, so the key, output, offset and lresults fields are reached.
///
/// Parse errors are no exceptions here: read_journal reports them as
/// refused lines. Any exception, crash, sanitizer report or hang is a bug.
///
/// Oracles (switch off by name with TK_FUZZ_SKIP=a,b while a finding is open):
///   canonical   an entry read is byte for byte the line journal_line writes
///               for it (nothing else passes)
///   verdict     an entry's output record is a JSON object whose verdict is
///               prime, composite or probable-prime
///   lines       entries and refused lines add up to the whole lines, and
///               whole_bytes ends at a newline
///   completion  log_completion of any bytes gives nothing or exactly the
///               rest of the entry's lresults.txt lines
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include <fmt/format.h>

#include "fuzz_common.hpp"
#include "io/checksum.hpp"
#include "io/record.hpp"
#include "primes/proof_journal_format.hpp"

namespace {

using tk::primes::JournalEntry;

/// Each line's text after its last tab replaced by the checksum of what is before it.
std::string with_checksums(std::string_view bytes) {
  std::string out;
  for (std::size_t start = 0; start < bytes.size();) {
    std::size_t end = bytes.find('\n', start);
    const bool whole = end != std::string_view::npos;
    if (!whole) end = bytes.size();
    const std::string_view line = bytes.substr(start, end - start);
    const std::size_t tab = line.rfind('\t');
    if (tab == std::string_view::npos) out += line;
    else out += fmt::format("{}\t{:016x}", line.substr(0, tab), tk::io::fnv1a(line.substr(0, tab)));
    if (whole) out += '\n';
    start = end + 1;
  }
  return out;
}

void check_completion(std::string_view written, const JournalEntry& entry) {
  const std::string all = tk::primes::log_text(entry);
  const auto rest = tk::primes::log_completion(written, entry);
  if (rest && std::string(written) + *rest != all)
    tk::fuzz::invariant_failed("completion", "the completion does not end the entry's lines");
}

void read(std::string_view bytes) {
  const tk::primes::JournalText journal = tk::primes::read_journal(bytes);
  if (tk::fuzz::oracle_enabled("lines")) {
    std::size_t whole_lines = 0;
    for (char c : bytes.substr(0, journal.whole_bytes)) whole_lines += c == '\n';
    if (journal.entries.size() + journal.refused.size() != whole_lines ||
        (journal.whole_bytes && bytes[journal.whole_bytes - 1] != '\n') ||
        bytes.find('\n', journal.whole_bytes) != std::string_view::npos)
      tk::fuzz::invariant_failed("lines", "entries and refused lines are not the whole lines");
  }
  std::size_t start = 0;
  for (const JournalEntry& entry : journal.entries) {
    const std::string line = tk::primes::journal_line(entry);
    if (tk::fuzz::oracle_enabled("canonical") && bytes.find(line + "\n") == std::string_view::npos)
      tk::fuzz::invariant_failed("canonical", "read an entry that journal_line does not write as the input has it");
    if (tk::fuzz::oracle_enabled("verdict")) {
      const tk::Record output = tk::Record::parse(entry.output, nullptr, false);
      const auto verdict = output.is_object() ? output.find("verdict") : output.end();
      if (verdict == output.end() || !verdict->is_string() ||
          (*verdict != "prime" && *verdict != "composite" && *verdict != "probable-prime"))
        tk::fuzz::invariant_failed("verdict", "an entry without a verdict riesel computes: " + entry.output);
    }
    if (tk::fuzz::oracle_enabled("completion")) {
      const std::string all = tk::primes::log_text(entry);
      check_completion(std::string_view(all).substr(0, all.size() / 2), entry);
      check_completion(bytes.substr(start, 64), entry);
      start = (start + 1) % (bytes.size() + 1);
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  read(bytes);
  read(with_checksums(bytes));
  return 0;
}
