/// @file stop_signals.hpp
/// @brief SIGINT and SIGTERM in a tool that checkpoints (sieve, riesel):
/// caught, seen by the library's long loops and blocked reads, and at the end
/// the process dies of the signal after one line on stderr, so that a shell or
/// cron sees 130 or 143.
#pragma once

#include <atomic>
#include <string_view>

namespace tk::cli {

class StopSignals {
 public:
  /// Installs the handler of SIGINT and SIGTERM (for the whole process).
  StopSignals();

  /// The signal caught, or 0.
  int caught() const noexcept;
  /// Nonzero once a signal is caught: what a sieve run polls.
  const std::atomic<int>* signal() const noexcept;
  /// Set once a signal is caught: what a proof polls to stop at its next report.
  const std::atomic<bool>* cancel() const noexcept;

  /// "TOOL: stopped by signal N" and `details` on stderr (standard output
  /// flushed first), then the caught signal again at its default action.
  [[noreturn]] void die(std::string_view tool, std::string_view details) const;
};

}  // namespace tk::cli
