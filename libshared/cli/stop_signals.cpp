/// @file stop_signals.cpp
#include "cli/stop_signals.hpp"

#include <csignal>
#include <cstdio>
#include <cstdlib>

#include "io/stop_signal.hpp"

namespace tk::cli {

namespace {

std::atomic<int> g_signal{0};
std::atomic<bool> g_cancel{false};
static_assert(std::atomic<int>::is_always_lock_free && std::atomic<bool>::is_always_lock_free,
              "the handler needs lock-free stores");

extern "C" void on_stop_signal(int signal) {
  g_signal.store(signal);
  g_cancel.store(true);
  io::notice_stop_signal(signal);  // a blocked read gives up too
}

}  // namespace

StopSignals::StopSignals() {
  struct sigaction action {};
  action.sa_handler = on_stop_signal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

int StopSignals::caught() const noexcept { return g_signal.load(); }

const std::atomic<int>* StopSignals::signal() const noexcept { return &g_signal; }

const std::atomic<bool>* StopSignals::cancel() const noexcept { return &g_cancel; }

void StopSignals::die(std::string_view tool, std::string_view details) const {
  const int signal = caught();
  std::fflush(stdout);
  std::fprintf(stderr, "%.*s: stopped by signal %d%.*s\n", static_cast<int>(tool.size()), tool.data(), signal,
               static_cast<int>(details.size()), details.data());
  std::signal(signal, SIG_DFL);
  std::raise(signal);
  std::abort();  // not reached: the default action of SIGINT and SIGTERM ends the process
}

}  // namespace tk::cli
