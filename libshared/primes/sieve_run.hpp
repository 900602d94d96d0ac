/// @file sieve_run.hpp
/// @brief One generalized-sieve run as a cron job needs it: resume from a
/// checkpoint, save one every few minutes and when asked to stop, keep the
/// factors file in step with the checkpoint, stop early when removals get
/// too rare, and report progress.
#pragma once

#include <atomic>
#include <cstdint>
#include <string>

#include "primes/generalized_sieve.hpp"

namespace tk::primes {

struct SieveRunOptions {
  std::string tool_name;  ///< the caller's name, which progress lines start with
  unsigned threads = 1;
  unsigned shard_index = 0, shard_count = 1;
  std::string factors_path;     ///< empty: no factors file
  std::string checkpoint_path;  ///< empty: no checkpoint
  double checkpoint_seconds = 300;
  bool resume = false;
  double min_rate = 0;  ///< removals per second; 0: sieve to p_max
  double rate_window_seconds = 60;
  bool progress = false;
  const std::atomic<int>* stop_signal = nullptr;  ///< nonzero: save and stop
};

struct SieveRunOutcome {
  bool finished = false;  ///< every prime up to p_max (of this shard) applied
  bool rate_stopped = false;
  std::uint64_t depth = 0;  ///< the bound to record in output headers
};

/// Runs `sieve` to the end or until stopped; warnings (such as a missing
/// checkpoint on resume) go through `warn`.
SieveRunOutcome run_sieve(GeneralizedSieve& sieve, const SieveRunOptions& options,
                          const std::function<void(const std::string&)>& warn);

}  // namespace tk::primes
