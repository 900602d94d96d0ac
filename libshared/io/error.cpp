/// @file error.cpp
#include "io/error.hpp"

#include <fmt/format.h>

namespace tk {

std::string Error::located_message() const {
  if (where_.file.empty()) return what();
  if (where_.line == 0) return fmt::format("{}: {}", where_.file, what());
  return fmt::format("{}:{}: {}", where_.file, where_.line, what());
}

}  // namespace tk
