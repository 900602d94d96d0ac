/// @file stop_signal.hpp
/// @brief The SIGINT/SIGTERM that a checkpointing tool has caught, known to
/// the library's readers, so that a read blocked on a pipe or an endless line
/// gives up within a fraction of a second instead of when the data ends.
#pragma once

namespace tk::io {

/// Called from the tool's signal handler (async-signal-safe).
void notice_stop_signal(int signal) noexcept;

/// The signal noticed, or 0.
int noticed_stop_signal() noexcept;

}  // namespace tk::io
