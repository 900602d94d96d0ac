/// @file stop_signal.cpp
#include "io/stop_signal.hpp"

#include <atomic>

namespace tk::io {

namespace {
std::atomic<int> g_noticed{0};
static_assert(std::atomic<int>::is_always_lock_free, "the handler needs a lock-free store");
}  // namespace

void notice_stop_signal(int signal) noexcept { g_noticed.store(signal); }

int noticed_stop_signal() noexcept { return g_noticed.load(); }

}  // namespace tk::io
