/// @file file_lock.cpp
#include "io/file_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "io/error.hpp"

namespace tk::io {

FileLock::FileLock(const std::string& path, const std::string& owner, const std::string& what) {
  fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) throw Error(std::string("cannot open the lock: ") + std::strerror(errno), Location{path, 0});
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int error = errno;
    ::close(fd_);
    fd_ = -1;
    if (error == EWOULDBLOCK) throw Error("another run holds " + what + "'s lock (" + path + ")", Location{owner, 0});
    throw Error(std::string("cannot lock: ") + std::strerror(error), Location{path, 0});
  }
}

FileLock::~FileLock() {
  if (fd_ >= 0) ::close(fd_);
}

}  // namespace tk::io
