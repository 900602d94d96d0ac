/// @file proof_journal.hpp
/// @brief The --state directory of a proof run, so cron can start it again
/// and again: a lock (two runs never work on one directory), a journal of
/// finished records (a re-run replays them instead of proving again), an
/// LLR-style results log, and checkpoints of unfinished proofs.
///
/// Every file is written so that a kill at any moment leaves it usable:
/// a finished record goes to the journal first (its line holds the record's
/// lresults.txt lines too), then to lresults.txt, each appended and synced;
/// a run killed between the two completes lresults.txt from the journal
/// when it starts again, so each record is logged once. A torn last
/// journal line is cut off; a journal line that fails its checksum or its
/// field checks (proof_journal_format.hpp) is moved to journal.rejected and
/// its record proved again. Checkpoints go to a temporary file that is
/// synced and renamed, and carry a checksum; a damaged checkpoint is
/// ignored (that proof restarts), never trusted.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "io/record.hpp"
#include "primes/proof_journal_format.hpp"
#include "primes/riesel_proof.hpp"

namespace tk::io {
class FileLock;
}

namespace tk::primes {

class ProofJournal {
 public:
  using Warn = std::function<void(const std::string&)>;

  /// Creates `directory` if needed and takes its lock; Error if another run
  /// holds it. Refused journal lines are reported to `warn`.
  explicit ProofJournal(std::string directory, const Warn& warn = {});
  ~ProofJournal();
  ProofJournal(const ProofJournal&) = delete;
  ProofJournal& operator=(const ProofJournal&) = delete;

  /// The output line of a finished record with this key, if any.
  std::optional<std::string> finished(const std::string& key) const;
  /// Appends a finished record (key, output line, its lresults.txt lines)
  /// to the journal, then its lines to lresults.txt, syncing each.
  void record_finished(const std::string& key, const std::string& output_line,
                       const std::vector<std::string>& log_lines);

  /// The saved state of a proof of `member`; nothing when there is none,
  /// or when the file is damaged or not this member's (then `warn` hears
  /// "FILE: checkpoint <why>", and the proof starts over: a bad checkpoint
  /// never gives a verdict).
  std::optional<ProofState> load_checkpoint(const std::string& member, const Warn& warn = {}) const;
  void save_checkpoint(const std::string& member, const ProofState& state) const;
  void remove_checkpoint(const std::string& member) const;

  std::string checkpoint_path(const std::string& member) const;
  const std::string& directory() const { return directory_; }

 private:
  void load_journal(const Warn& warn);
  void complete_log(const std::optional<JournalEntry>& last);
  std::string directory_;
  std::unique_ptr<io::FileLock> lock_;  // held for the journal's life
  int journal_fd_ = -1;
  int log_fd_ = -1;
  std::unordered_map<std::string, std::string> finished_;
};

}  // namespace tk::primes
