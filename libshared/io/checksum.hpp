/// @file checksum.hpp
/// @brief FNV-1a 64, the checksum of the state files (sieve checkpoints,
/// riesel's journal and checkpoints). Changing any one byte always changes
/// it: each step is a bijection of the running hash.
#pragma once

#include <cstdint>
#include <string_view>

namespace tk::io {

inline std::uint64_t fnv1a(std::string_view bytes) {
  std::uint64_t hash = 0xcbf29ce484222325ull;
  for (unsigned char byte : bytes) hash = (hash ^ byte) * 0x100000001b3ull;
  return hash;
}

}  // namespace tk::io
