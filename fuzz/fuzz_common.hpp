/// @file fuzz_common.hpp
/// @brief Helpers shared by the fuzz targets: oracle switches, a loud abort,
/// an in-memory file with a path, and /dev/null as a FILE*.
#pragma once

#include <sys/mman.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

namespace tk::fuzz {

/// Oracles beyond "no crash" can be switched off by name while a known
/// finding is being fixed: TK_FUZZ_SKIP=max_bits,roundtrip ...
inline bool oracle_enabled(std::string_view name) {
  static const std::string skip = [] {
    const char* env = std::getenv("TK_FUZZ_SKIP");
    return "," + std::string(env ? env : "") + ",";
  }();
  return skip.find("," + std::string(name) + ",") == std::string::npos;
}

/// Reports a broken invariant so libFuzzer saves the input as a crash.
[[noreturn]] inline void invariant_failed(std::string_view oracle, const std::string& message) {
  std::fprintf(stderr, "\n==fuzz== invariant '%.*s' failed: %s\n", static_cast<int>(oracle.size()), oracle.data(),
               message.c_str());
  std::fprintf(stderr, "==fuzz== (TK_FUZZ_SKIP=%.*s disables this check)\n", static_cast<int>(oracle.size()),
               oracle.data());
  std::abort();
}

/// An in-memory file with a path that fopen() accepts, reused across runs.
class MemoryFile {
 public:
  explicit MemoryFile(const char* name) {
    fd_ = memfd_create(name, 0);
    if (fd_ < 0) {
      std::perror("memfd_create");
      std::abort();
    }
    path_ = "/proc/self/fd/" + std::to_string(fd_);
  }
  void assign(std::string_view bytes) {
    if (ftruncate(fd_, 0) != 0) std::abort();
    std::size_t done = 0;
    while (done < bytes.size()) {
      const ssize_t n = pwrite(fd_, bytes.data() + done, bytes.size() - done, static_cast<off_t>(done));
      if (n <= 0) std::abort();
      done += static_cast<std::size_t>(n);
    }
  }
  const std::string& path() const { return path_; }

 private:
  int fd_ = -1;
  std::string path_;
};

/// /dev/null as a FILE*, opened once: targets write output nobody reads.
inline std::FILE* null_output() {
  static std::FILE* out = [] {
    std::FILE* f = std::fopen("/dev/null", "w");
    if (!f) std::abort();
    return f;
  }();
  return out;
}

}  // namespace tk::fuzz
