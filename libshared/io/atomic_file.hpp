/// @file atomic_file.hpp
/// @brief Replaces a file so that a crash at any moment leaves the old
/// content or the new, never half of it: write a temporary file, fsync it,
/// rename it over the old one, fsync the directory.
#pragma once

#include <cstdio>
#include <string>
#include <string_view>

namespace tk::io {

/// An output file that appears whole or not at all. The bytes go to a
/// temporary ".NAME.tmp.PID" beside the target; commit() syncs it and
/// renames it over the target. Destroyed without commit() (an error), it
/// removes the temporary, so the target keeps what it held before. A
/// process killed with SIGKILL leaves its temporary behind: opening the same
/// target again removes every such temporary whose process no longer runs.
/// A symbolic link is followed (the file it names is replaced); a target
/// that is not a regular file (/dev/stdout, a FIFO) is written in place.
class AtomicFile {
 public:
  /// Error naming `path` when the temporary cannot be made.
  explicit AtomicFile(std::string path);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::FILE* stream() const { return file_; }
  const std::string& path() const { return path_; }
  /// Flushes, syncs and renames into place; Error naming the path.
  void commit();

 private:
  std::string path_;       ///< as given, for messages
  std::string target_;     ///< the file replaced (a link's destination)
  std::string temporary_;  ///< empty when writing in place
  std::FILE* file_ = nullptr;
};

/// The temporary an AtomicFile of `path` writes in the process `pid`.
std::string temporary_name(const std::string& path, long pid);

/// Removes the temporaries of `path` left by processes that no longer run.
void remove_stale_temporaries(const std::string& path);

/// `bytes` as the whole new content of `path`, through an AtomicFile. Throws Error.
void write_file_atomically(const std::string& path, std::string_view bytes);

/// Writes all of `bytes` to `fd` (a journal appends each line with one such
/// call, so a kill cannot split it), then fsyncs it. Error names `path`.
void write_all_synced(int fd, const std::string& path, std::string_view bytes);

/// The same with a temporary chosen by the caller: it must be in the same
/// directory as `path` and unique to the writer. Throws Error.
void write_file_atomically(const std::string& path, std::string_view bytes, const std::string& temporary);

}  // namespace tk::io
