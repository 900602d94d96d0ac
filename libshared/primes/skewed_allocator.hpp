/// @file skewed_allocator.hpp
/// @brief An allocator for the long arrays a squaring walks side by side:
/// each allocation starts at its own offset modulo 4 KB (64-byte aligned).
///
/// Why: arrays of a power-of-two size come back from malloc at the same
/// offset modulo 4 KB, so the lines a pass reads at one index from a
/// dozen of them fall in the same set of the 12-way L1 cache and evict
/// each other. Measured at n = 171960: about 8 % per squaring for the
/// transform's own arrays (right_angle_transform.cpp), more with these.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <new>
#include <vector>

namespace tk::primes {

template <class T>
struct SkewedAllocator {
  using value_type = T;

  SkewedAllocator() = default;
  template <class U>
  explicit SkewedAllocator(const SkewedAllocator<U>&) {}

  /// 64 to 3,904 bytes past a 4 KB boundary, in steps of 256 bytes
  /// (four sets), turn by turn; the skew is kept just before the array.
  static T* allocate(std::size_t count) {
    static std::atomic<unsigned> turn{0};
    const std::size_t skew = 64 + 256 * (turn.fetch_add(1, std::memory_order_relaxed) % 16);
    if (count > (SIZE_MAX - skew - 4096) / sizeof(T)) throw std::bad_alloc();
    const std::size_t bytes = (count * sizeof(T) + skew + 4095) / 4096 * 4096;
    auto* base = static_cast<unsigned char*>(std::aligned_alloc(4096, bytes));
    if (!base) throw std::bad_alloc();
    std::memcpy(base + skew - sizeof skew, &skew, sizeof skew);
    return reinterpret_cast<T*>(base + skew);
  }
  static void deallocate(T* array, std::size_t) {
    auto* at = reinterpret_cast<unsigned char*>(array);
    std::size_t skew = 0;
    std::memcpy(&skew, at - sizeof skew, sizeof skew);
    std::free(at - skew);
  }

  template <class U>
  bool operator==(const SkewedAllocator<U>&) const {
    return true;
  }
};

template <class T>
using SkewedVector = std::vector<T, SkewedAllocator<T>>;

}  // namespace tk::primes
