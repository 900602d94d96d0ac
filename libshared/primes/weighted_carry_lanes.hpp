/// @file weighted_carry_lanes.hpp
/// @brief One lane pass of balance_digits (weighted_passes.hpp) on eight
/// digits, for the AVX-512 passes that compute the digits themselves (the
/// rounding, the multiplication by k) and carry them in the same sweep
/// rather than in a pass of their own; and those products of k.
///
/// Written over GCC vector types, with no target of their own: the
/// functions that use them are always inlined into one compiled for
/// AVX-512 (so no vector crosses a call, which clang refuses between
/// functions of different targets).
#pragma once

#include <cstdint>
#include <cstring>

#include "primes/weighted_passes.hpp"

#pragma GCC diagnostic ignored "-Wpsabi"

namespace tk::primes::carry_lanes {

typedef std::int64_t Lanes __attribute__((vector_size(64)));

#define TK_LANES_INLINE __attribute__((always_inline)) inline

TK_LANES_INLINE Lanes load(const std::int64_t* p) {
  Lanes v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
TK_LANES_INLINE void store(std::int64_t* p, const Lanes& v) { std::memcpy(p, &v, sizeof v); }
/// bits[0..8) widened, as a broadcast word shifted per lane (GCC 12 makes
/// __builtin_convertvector from eight bytes a chain of inserts).
TK_LANES_INLINE Lanes sizes_at(const std::uint8_t* bits) {
  std::int64_t word;
  std::memcpy(&word, bits, sizeof word);
  const Lanes byte_shift = {0, 8, 16, 24, 32, 40, 48, 56};
  return ((Lanes{} + word) >> byte_shift) & 255;
}
/// Lane i of the result is lane i - 1 of `now`, lane 0 lane 7 of `before`.
TK_LANES_INLINE Lanes shifted_in(const Lanes& before, const Lanes& now) {
  return __builtin_shufflevector(before, now, 7, 8, 9, 10, 11, 12, 13, 14);
}
TK_LANES_INLINE Lanes broadcast(std::int64_t v) { return Lanes{} + v; }

/// Each digit's excess over [-2^(s-1), 2^(s-1)) moves one digit up, the
/// carry a digit takes in being what its neighbour gave off before this
/// pass: the same values as balance_digits' lanes pass. `before` holds the
/// previous vector's carries (its lane 7 is the carry into this vector's
/// lane 0), `largest` each lane's largest carry so far. A size of 0 (the
/// zeros past the last coefficient) passes the digit up whole.
struct CarryLanes {
  Lanes before{}, largest{};

  /// The eight digits `value` at bits[0..8) kept (without the carries in); `up` gets their carries out.
  TK_LANES_INLINE Lanes step(const Lanes& value, const std::uint8_t* bits, Lanes& up) {
    const Lanes size = sizes_at(bits);
    const Lanes half = (broadcast(1) << size) >> 1;
    const Lanes total = value + half;
    up = total >> size;
    const Lanes magnitude = up < 0 ? -up : up;
    largest = magnitude > largest ? magnitude : largest;
    return total - (up << size) - half;
  }
  /// The carries into the eight digits whose carries out are `up`.
  TK_LANES_INLINE Lanes carries_in(const Lanes& up) const { return shifted_in(before, up); }
  /// step() with the carries in added; `before` moves on.
  TK_LANES_INLINE Lanes carried(const Lanes& value, const std::uint8_t* bits) {
    Lanes up;
    const Lanes kept = step(value, bits, up);
    const Lanes digits = kept + carries_in(up);
    before = up;
    return digits;
  }
  TK_LANES_INLINE std::int64_t last_up() const { return before[7]; }  ///< out of the last vector's lane 7
  TK_LANES_INLINE std::int64_t most() const { return largest_of(largest); }
  static TK_LANES_INLINE std::int64_t largest_of(const Lanes& v) {
    std::int64_t most = v[0];
    for (int lane = 1; lane < 8; ++lane) most = v[lane] > most ? v[lane] : most;
    return most;
  }
};

/// multiply_low_by_k's values eight digits at a time, in order: the
/// previous digits are the lanes before (the last of the vector before, kept).
struct ProductLanes {
  Lanes low, high, split, before{}, sizes_before;
  TK_LANES_INLINE explicit ProductLanes(const SplitK& k)
      : low(broadcast(k.low)), high(broadcast(k.high)), split(broadcast(k.bits)), sizes_before(split) {}
  TK_LANES_INLINE Lanes next(const std::int64_t* d, const std::uint8_t* bits, std::size_t j, std::size_t m,
                             bool add_upper) {
    const Lanes old = load(d + j), upper = load(d + j + m), size = sizes_at(bits + j);
    const Lanes moved = (high * shifted_in(before, old)) << (split - shifted_in(sizes_before, size));
    before = old;
    sizes_before = size;
    const Lanes product = low * old + moved;
    return add_upper ? product + upper : product - upper;
  }
};

#undef TK_LANES_INLINE

}  // namespace tk::primes::carry_lanes
