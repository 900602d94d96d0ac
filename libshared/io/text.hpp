/// @file text.hpp
/// @brief Small text helpers shared by the line readers.
#pragma once

#include <string_view>

namespace tk::io {

/// `text` without leading and trailing spaces, tabs and carriage returns
/// (CRLF files from elsewhere).
inline std::string_view trim(std::string_view text) {
  constexpr std::string_view blank = " \t\r";
  const auto first = text.find_first_not_of(blank);
  if (first == std::string_view::npos) return {};
  return text.substr(first, text.find_last_not_of(blank) - first + 1);
}

}  // namespace tk::io
