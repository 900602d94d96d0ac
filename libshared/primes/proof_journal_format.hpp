/// @file proof_journal_format.hpp
/// @brief The text of a --state directory's journal lines and checkpoints,
/// written and read back without touching files (so they can be fuzzed).
///
/// Everything read back is checked field by field and refused with an
/// Error naming what is wrong: a damaged line or checkpoint must never give
/// a verdict that was not computed.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "primes/riesel_proof.hpp"

namespace tk::primes {

/// One finished record: its key ("start=NAME " and the input record), the
/// output record (compact JSON), and its lresults.txt lines with the size
/// lresults.txt had before them, so a run killed between the journal and
/// lresults.txt can finish the latter.
struct JournalEntry {
  std::string key;
  std::string output;
  std::uint64_t log_offset = 0;
  std::vector<std::string> log_lines;
};

/// The line (without its newline): key, output, log offset, log lines as a
/// JSON array, and the FNV-1a checksum of all before it, separated by tabs.
std::string journal_line(const JournalEntry& entry);
/// Throws Error saying why the line is refused (damaged, an older riesel's).
JournalEntry parse_journal_line(std::string_view line);

/// A journal file's text: the entries of its whole lines in order, the
/// lines refused (with their 1-based numbers and why), and the length of
/// its whole lines (a last line without a newline is torn by a kill).
struct JournalText {
  struct Refused {
    std::uint64_t line = 0;
    std::string text, why;
  };
  std::vector<JournalEntry> entries;
  std::vector<Refused> refused;
  std::size_t whole_bytes = 0;
};
JournalText read_journal(std::string_view text);

/// The lresults.txt lines of `entry` as they are appended (each with '\n').
std::string log_text(const JournalEntry& entry);
/// What lresults.txt lacks when `written` (its bytes from entry.log_offset
/// on) is the start of the entry's lines: the rest of them; nothing when
/// they are all there or the file does not continue that way.
std::optional<std::string> log_completion(std::string_view written, const JournalEntry& entry);

/// A checkpoint: "riesel-checkpoint 1", the member (with its start), the
/// iteration, the residue in hex and the checksum, one per line.
std::string checkpoint_text(const std::string& member, const ProofState& state);
/// Throws Error saying why the text is not a checkpoint of `member`. The
/// proof itself checks that iteration and residue fit the number.
ProofState parse_checkpoint(std::string_view text, const std::string& member);

}  // namespace tk::primes
