/// @file fuzz_common.hpp
/// @brief Helpers shared by the fuzz targets: oracle switches and a loud abort.
#pragma once

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

}  // namespace tk::fuzz
