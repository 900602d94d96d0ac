/// @file brute_force_prime.hpp
/// @brief Trial division to the square root: the oracle the 64-bit prime
/// tests are checked against.
#pragma once

#include <cstdint>

namespace tk::test {

inline bool brute_force_prime(std::uint64_t n) {
  if (n < 2) return false;
  for (std::uint64_t d = 2; d * d <= n; ++d)
    if (n % d == 0) return false;
  return true;
}

}  // namespace tk::test
