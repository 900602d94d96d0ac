/// @file error.cpp
#include "io/error.hpp"

#include <fmt/format.h>

#include <cstring>

namespace tk {

std::string Error::located_message() const {
  if (where_.file.empty()) return what();
  if (where_.line == 0) return fmt::format("{}: {}", where_.file, what());
  return fmt::format("{}:{}: {}", where_.file, where_.line, what());
}

Error errno_error(const std::string& path, const std::string& what, int error) {
  return Error(fmt::format("cannot {}: {}", what, std::strerror(error)), Location{path, 0});
}

}  // namespace tk
