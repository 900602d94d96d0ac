/// @file atomic_file.cpp
#include "io/atomic_file.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <system_error>

#include "io/error.hpp"

namespace tk::io {

namespace {

namespace fs = std::filesystem;

// The rename itself is durable once the directory is synced.
void sync_directory_of(const std::string& path) {
  const std::string directory = fs::path(path).parent_path().string();
  const int dir = ::open(directory.empty() ? "." : directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir >= 0) {
    ::fsync(dir);
    ::close(dir);
  }
}

// ".NAME.tmp." (built by appending: GCC 12 warns falsely on "." + string).
std::string temporary_prefix(const fs::path& target) {
  std::string prefix = ".";
  prefix += target.filename().string();
  prefix += ".tmp.";
  return prefix;
}

bool only_digits(std::string_view text) {
  if (text.empty()) return false;
  for (char c : text)
    if (c < '0' || c > '9') return false;
  return true;
}

}  // namespace

std::string temporary_name(const std::string& path, long pid) {
  const fs::path target(path);
  return (target.parent_path() / (temporary_prefix(target) + std::to_string(pid))).string();
}

void remove_stale_temporaries(const std::string& path) {
  const fs::path target(path);
  const std::string prefix = temporary_prefix(target);
  const fs::path directory = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  std::error_code ignored;  // a directory we cannot list has nothing of ours to tidy
  for (const fs::directory_entry& entry : fs::directory_iterator(directory, ignored)) {
    const std::string name = entry.path().filename().string();
    if (name.compare(0, prefix.size(), prefix) != 0 || !only_digits(name.substr(prefix.size())) ||
        name.size() - prefix.size() > 9)
      continue;
    const long pid = std::stol(name.substr(prefix.size()));
    // One with our own pid was left by a dead process whose pid we now have.
    if (pid == ::getpid() || (::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH))
      fs::remove(entry.path(), ignored);
  }
}

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)), target_(path_) {
  std::error_code error;
  if (fs::is_symlink(fs::symlink_status(target_, error))) target_ = fs::weakly_canonical(target_, error).string();
  struct stat existing {};
  const bool exists = ::stat(target_.c_str(), &existing) == 0;
  if (exists && !S_ISREG(existing.st_mode)) {  // a device or a pipe: nothing to rename
    file_ = std::fopen(target_.c_str(), "w");
    if (!file_) throw errno_error(path_, "write", errno);
    return;
  }
  remove_stale_temporaries(target_);
  temporary_ = temporary_name(target_, ::getpid());
  const int fd = ::open(temporary_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) throw errno_error(path_, "write", errno);
  if (exists) ::fchmod(fd, existing.st_mode & 07777);  // the replacement keeps the file's permissions
  file_ = ::fdopen(fd, "w");
  if (!file_) {
    const int saved = errno;
    ::close(fd);
    ::unlink(temporary_.c_str());
    throw errno_error(path_, "write", saved);
  }
}

AtomicFile::~AtomicFile() {
  if (!file_) return;
  std::fclose(file_);
  if (!temporary_.empty()) ::unlink(temporary_.c_str());
}

void AtomicFile::commit() {
  std::FILE* file = file_;
  file_ = nullptr;
  const bool written =
      std::fflush(file) == 0 && !std::ferror(file) && (temporary_.empty() || ::fsync(fileno(file)) == 0);
  const int error = errno;
  const bool closed = std::fclose(file) == 0;
  if (!written || !closed) {
    if (!temporary_.empty()) ::unlink(temporary_.c_str());
    throw errno_error(path_, "write", written ? errno : error);
  }
  if (temporary_.empty()) return;
  if (std::rename(temporary_.c_str(), target_.c_str()) != 0) {
    const int saved = errno;
    ::unlink(temporary_.c_str());
    throw errno_error(path_, "rename into place", saved);
  }
  sync_directory_of(target_);
}

void write_all_synced(int fd, const std::string& path, std::string_view bytes) {
  for (std::size_t done = 0; done < bytes.size();) {
    const ssize_t wrote = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (wrote < 0 && errno == EINTR) continue;
    if (wrote <= 0) throw errno_error(path, "write", errno);
    done += static_cast<std::size_t>(wrote);
  }
  if (::fsync(fd) != 0) throw errno_error(path, "sync", errno);
}

void write_file_atomically(const std::string& path, std::string_view bytes) {
  AtomicFile file(path);
  if (!bytes.empty() && std::fwrite(bytes.data(), 1, bytes.size(), file.stream()) != bytes.size())
    throw errno_error(path, "write", errno);
  file.commit();
}

void write_file_atomically(const std::string& path, std::string_view bytes, const std::string& temporary) {
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw errno_error(temporary, "create", errno);
  try {
    write_all_synced(fd, temporary, bytes);
  } catch (const Error&) {
    ::close(fd);
    throw;
  }
  if (::close(fd) != 0) throw errno_error(temporary, "close", errno);
  if (std::rename(temporary.c_str(), path.c_str()) != 0) throw errno_error(path, "rename into place", errno);
  sync_directory_of(path);
}

}  // namespace tk::io
