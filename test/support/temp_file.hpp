/// @file temp_file.hpp
/// @brief A temporary file with given content for unit tests, removed at
/// scope exit.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace tk::test {

class TempFile {
 public:
  explicit TempFile(const std::string& content, const std::string& suffix = "") {
    static int counter = 0;
    path_ = (std::filesystem::temp_directory_path() /
             ("tk_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter++) + suffix))
                .string();
    std::ofstream(path_, std::ios::binary) << content;
  }
  ~TempFile() { std::filesystem::remove(path_); }
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

}  // namespace tk::test
