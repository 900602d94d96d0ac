/// @file project_paths.hpp
/// @brief Where the unit tests find the project's files and the shared
/// corpus (ctest sets TOOLKIT_ROOT; run by hand, the source tree is used).
#pragma once

#include <cstdlib>
#include <filesystem>
#include <string>

namespace tk::test {

inline std::filesystem::path project_root() {
  const char* root = std::getenv("TOOLKIT_ROOT");
  return root ? std::filesystem::path(root)
              : std::filesystem::path(__FILE__).parent_path().parent_path().parent_path();
}

/// $TOOLKIT_ROOT/../shared/corpus/<kind>: absent in a user's clone.
inline std::filesystem::path corpus_folder(const std::string& kind) {
  return project_root() / ".." / "shared" / "corpus" / kind;
}

}  // namespace tk::test
