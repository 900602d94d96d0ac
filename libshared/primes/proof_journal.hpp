/// @file proof_journal.hpp
/// @brief The --state directory of a proof run, so cron can start it again
/// and again: a lock (two runs never work on one directory), a journal of
/// finished records (a re-run replays them instead of proving again), an
/// LLR-style results log, and checkpoints of unfinished proofs.
///
/// Every file is written so that a kill at any moment leaves it usable:
/// journal and log lines are appended and synced one by one (a torn last
/// line is ignored on reading), checkpoints go to a temporary file that is
/// synced and renamed, and carry a checksum; a damaged checkpoint is
/// ignored (that proof restarts), never trusted.
#pragma once

#include <cstdio>
#include <functional>
#include <optional>
#include <string>
#include <unordered_map>

#include "io/record.hpp"
#include "primes/riesel_proof.hpp"

namespace tk::primes {

class ProofJournal {
 public:
  /// Creates `directory` if needed and takes its lock; Error if another run holds it.
  explicit ProofJournal(std::string directory);
  ~ProofJournal();
  ProofJournal(const ProofJournal&) = delete;
  ProofJournal& operator=(const ProofJournal&) = delete;

  /// The output line of a finished record with this key, if any.
  std::optional<std::string> finished(const std::string& key) const;
  /// Appends a finished record (key and output line) and syncs.
  void record_finished(const std::string& key, const std::string& output_line);
  /// Appends a line to lresults.txt and syncs.
  void log_result(const std::string& line);

  /// The saved state of a proof of `member`; nothing when there is none,
  /// or when the file is damaged or not this member's (then `warn` hears
  /// "FILE: checkpoint <why>", and the proof starts over: a bad checkpoint
  /// never gives a verdict).
  std::optional<ProofState> load_checkpoint(const std::string& member,
                                            const std::function<void(const std::string&)>& warn = {}) const;
  void save_checkpoint(const std::string& member, const ProofState& state) const;
  void remove_checkpoint(const std::string& member) const;

  const std::string& directory() const { return directory_; }

 private:
  std::string checkpoint_path(const std::string& member) const;
  std::string directory_;
  int lock_fd_ = -1;
  std::FILE* journal_ = nullptr;
  std::FILE* log_ = nullptr;
  std::unordered_map<std::string, std::string> finished_;
};

}  // namespace tk::primes
