/// @file atomic_file.cpp
#include "io/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "io/error.hpp"

namespace tk::io {

namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what, int fd = -1) {
  const int error = errno;
  if (fd >= 0) ::close(fd);
  throw Error("cannot " + what + ": " + std::strerror(error), Location{path, 0});
}

}  // namespace

void write_file_atomically(const std::string& path, std::string_view bytes, const std::string& temporary) {
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) fail(temporary, "create");
  for (std::size_t done = 0; done < bytes.size();) {
    const ssize_t wrote = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (wrote < 0 && errno == EINTR) continue;
    if (wrote <= 0) fail(temporary, "write", fd);
    done += static_cast<std::size_t>(wrote);
  }
  if (::fsync(fd) != 0) fail(temporary, "sync", fd);
  if (::close(fd) != 0) fail(temporary, "close");
  if (std::rename(temporary.c_str(), path.c_str()) != 0) fail(path, "rename into place");
  // The rename itself is durable once the directory is synced.
  const std::string directory = std::filesystem::path(path).parent_path().string();
  const int dir = ::open(directory.empty() ? "." : directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir >= 0) {
    ::fsync(dir);
    ::close(dir);
  }
}

}  // namespace tk::io
