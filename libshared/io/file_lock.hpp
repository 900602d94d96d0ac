/// @file file_lock.hpp
/// @brief An exclusive advisory lock (flock) on a lock file, held for the
/// life of the object, so that two runs never work on the same state. The
/// kernel drops the lock when its holder dies, even by kill -9, so a stale
/// lock file never blocks the next run. The file itself stays: removing it
/// would let a waiting run lock an unlinked file while a third locks a new one.
#pragma once

#include <string>

namespace tk::io {

class FileLock {
 public:
  /// Creates `path` if needed and locks it; Error naming `owner` (the file
  /// or directory the lock guards) when another process holds it.
  FileLock(const std::string& path, const std::string& owner, const std::string& what);
  ~FileLock();
  FileLock(const FileLock&) = delete;
  FileLock& operator=(const FileLock&) = delete;

 private:
  int fd_ = -1;
};

}  // namespace tk::io
