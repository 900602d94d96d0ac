/// @file sieve_run.cpp
#include "primes/sieve_run.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>

#include "cli/progress.hpp"
#include "io/error.hpp"
#include "io/file_lock.hpp"
#include "primes/sieve_checkpoint.hpp"
#include "primes/sieve_output.hpp"

namespace tk::primes {

namespace {

using Clock = std::chrono::steady_clock;

/// Roughly pi(x), for the progress fraction.
double prime_count_estimate(std::uint64_t x) {
  const double value = static_cast<double>(std::max<std::uint64_t>(x, 3));
  return value / std::log(value);
}

/// The factors file, truncated to where the checkpoint left it on resume.
class FactorsFile {
 public:
  FactorsFile(const std::string& path, std::uint64_t keep_bytes, bool resume) : path_(path) {
    if (path.empty()) return;
    file_ = std::fopen(path.c_str(), resume ? "r+" : "w");
    if (!file_ && resume && errno == ENOENT) file_ = std::fopen(path.c_str(), "w");
    if (!file_) throw Error(fmt::format("cannot open the factors file: {}", std::strerror(errno)), Location{path, 0});
    if (resume) {
      std::fseek(file_, 0, SEEK_END);
      const long size = std::ftell(file_);
      if (size < 0 || static_cast<std::uint64_t>(size) < keep_bytes)
        throw Error(
            fmt::format("the factors file is shorter ({} bytes) than the checkpoint recorded ({})", size, keep_bytes),
            Location{path, 0});
      if (::ftruncate(fileno(file_), static_cast<off_t>(keep_bytes)) != 0 || std::fseek(file_, 0, SEEK_END) != 0)
        throw Error(fmt::format("cannot truncate the factors file: {}", std::strerror(errno)), Location{path, 0});
    }
  }
  ~FactorsFile() {
    if (file_) std::fclose(file_);
  }
  explicit operator bool() const { return file_ != nullptr; }
  void write(const std::string& line) {
    if (std::fputs(line.c_str(), file_) < 0 || std::fputc('\n', file_) < 0) fail("write");
  }
  /// Flushes and syncs; the byte count a checkpoint may record.
  std::uint64_t sync() {
    if (!file_) return 0;
    if (std::fflush(file_) != 0 || ::fsync(fileno(file_)) != 0) fail("write");
    return static_cast<std::uint64_t>(std::ftell(file_));
  }

 private:
  [[noreturn]] void fail(const char* what) {
    throw Error(fmt::format("cannot {} the factors file: {}", what, std::strerror(errno)), Location{path_, 0});
  }
  std::string path_;
  std::FILE* file_ = nullptr;
};

}  // namespace

SieveRunOutcome run_sieve(GeneralizedSieve& sieve, const SieveRunOptions& options,
                          const std::function<void(const std::string&)>& warn) {
  const SieveSpec& spec = sieve.spec();
  const std::string identity = checkpoint_identity(spec, options.shard_index, options.shard_count);
  if (options.resume && options.checkpoint_path.empty()) throw UsageError("--resume needs --checkpoint FILE");
  std::unique_ptr<io::FileLock> lock;
  if (!options.checkpoint_path.empty()) {  // find out now, not after hours of sieving
    const std::string directory = std::filesystem::path(options.checkpoint_path).parent_path().string();
    if (::access(directory.empty() ? "." : directory.c_str(), W_OK) != 0)
      throw Error(fmt::format("cannot write a checkpoint there: {}", std::strerror(errno)),
                  Location{options.checkpoint_path, 0});
    // Two runs on one checkpoint would overwrite each other's state.
    lock =
        std::make_unique<io::FileLock>(options.checkpoint_path + ".lock", options.checkpoint_path, "this checkpoint");
    std::error_code ignored;  // a temporary left by a killed run is only ever half a checkpoint
    std::filesystem::remove(checkpoint_temporary(options.checkpoint_path), ignored);
  }
  std::uint64_t factors_bytes = 0;
  bool resumed = false;
  if (options.resume) {
    if (auto checkpoint = load_checkpoint(options.checkpoint_path, identity, spec.count())) {
      try {
        sieve.restore(std::move(checkpoint->bitmap), checkpoint->next_segment, checkpoint->next_block);
      } catch (const Error& e) {
        throw Error(e.what(), Location{options.checkpoint_path, 0});
      }
      factors_bytes = checkpoint->factors_bytes;
      resumed = true;
    } else {
      warn("no checkpoint at " + options.checkpoint_path + ": starting from the beginning");
    }
  }
  FactorsFile factors(options.factors_path, factors_bytes, resumed);

  auto save = [&] {
    if (!options.checkpoint_path.empty()) save_checkpoint(options.checkpoint_path, sieve, identity, factors.sync());
  };
  SieveControl control;
  control.threads = options.threads;
  control.shard_index = options.shard_index;
  control.shard_count = options.shard_count;
  if (factors) control.on_factor = [&](const SieveFactor& factor) { factors.write(factor_line(spec, factor)); };

  SieveRunOutcome outcome;
  // Workers ask should_stop in the middle of a block, while the calling thread sets this.
  std::atomic<bool> rate_stopped{false};
  cli::Progress progress(options.tool_name, options.progress);
  const auto started = Clock::now();
  auto last_save = started, window_start = started, shown_start = started;
  std::uint64_t window_survivors = sieve.survivors(), shown_survivors = sieve.survivors();
  double shown_rate = 0;
  const double done_at_start = prime_count_estimate(sieve.sieved_to()) / prime_count_estimate(spec.p_max);
  const double total = prime_count_estimate(spec.p_max);
  control.should_stop = [&] {
    return rate_stopped.load() || (options.stop_signal && options.stop_signal->load() != 0);
  };
  auto save_when_due = [&](Clock::time_point now) {
    if (!options.checkpoint_path.empty() &&
        std::chrono::duration<double>(now - last_save).count() >= options.checkpoint_seconds) {
      save();
      last_save = now;
    }
  };
  control.after_block = [&] {
    const auto now = Clock::now();
    const double window = std::chrono::duration<double>(now - window_start).count();
    const double rate = window > 0 ? static_cast<double>(window_survivors - sieve.survivors()) / window : 0.0;
    if (options.min_rate > 0 && window >= options.rate_window_seconds) {
      if (rate < options.min_rate) rate_stopped = true;
      window_start = now;
      window_survivors = sieve.survivors();
    }
    save_when_due(now);
    if (options.progress) {
      // The rate shown is over the last ten seconds or so, not since the start.
      const double shown = std::chrono::duration<double>(now - shown_start).count();
      if (shown >= 10 || shown_rate == 0) {
        shown_rate = shown > 0 ? static_cast<double>(shown_survivors - sieve.survivors()) / shown : 0.0;
        if (shown >= 10) {
          shown_start = now;
          shown_survivors = sieve.survivors();
        }
      }
      const double done = prime_count_estimate(sieve.sieved_to()) / total;
      // Progress counts from where this process started (a resume), so the ETA is this run's.
      const double fraction = done_at_start < 1 ? (done - done_at_start) / (1 - done_at_start) : 1.0;
      progress.update(
          sieve.survivors(), fraction,
          fmt::format("p = {}, {} left, {:.0f} removed/s", sieve.sieved_to(), sieve.survivors(), shown_rate));
    }
  };
  control.after_segment = [&](std::uint64_t done, std::uint64_t segments) {
    save_when_due(Clock::now());
    if (options.progress)
      progress.update(done, static_cast<double>(done) / static_cast<double>(segments),
                      fmt::format("primes up to {}: segment {} of {}", sieve.small_prime_bound(), done, segments));
  };
  if (!sieve.small_primes_done()) sieve.sieve_small_primes(control);
  outcome.finished = sieve.sieve_large_primes(control);
  outcome.rate_stopped = rate_stopped.load();
  progress.finish();
  save();
  outcome.depth = outcome.finished ? spec.p_max : sieve.sieved_to();
  return outcome;
}

}  // namespace tk::primes
