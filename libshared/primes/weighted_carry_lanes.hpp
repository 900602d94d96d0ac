/// @file weighted_carry_lanes.hpp
/// @brief One lane pass of balance_digits (weighted_passes.hpp) on eight
/// digits, for the AVX-512 passes that compute the digits themselves (the
/// rounding, the multiplication by k) and carry them in the same sweep
/// rather than in a pass of their own. Include only from files built with
/// AVX-512 intrinsics; the caller's target must include avx512f.
#pragma once

// GCC 12 warns inside its own AVX-512 intrinsics (their _mm512_undefined).
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wpsabi"
#include <immintrin.h>

#include <cstdint>

namespace tk::primes {

/// Each digit's excess over [-2^(s-1), 2^(s-1)) moves one digit up, the
/// carry a digit takes in being what its neighbour gave off before this
/// pass: the same values as balance_digits' lanes pass. `before` holds the
/// previous vector's carries (its lane 7 is the carry into this vector's
/// lane 0), `largest` each lane's largest carry so far.
struct CarryLanes {
  __m512i before, largest;

  __attribute__((always_inline, target("avx512f"))) inline CarryLanes()
      : before(_mm512_setzero_si512()), largest(_mm512_setzero_si512()) {}

  /// The eight digits `value` at bits[0..8) after the pass; `up` gets their carries out.
  __attribute__((always_inline, target("avx512f"))) inline __m512i step(__m512i value, const std::uint8_t* bits,
                                                                        __m512i& up) {
    const __m512i one = _mm512_set1_epi64(1);
    const __m512i size = _mm512_cvtepu8_epi64(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(bits)));
    const __m512i half = _mm512_sllv_epi64(one, _mm512_sub_epi64(size, one));
    const __m512i total = _mm512_add_epi64(value, half);
    up = _mm512_srav_epi64(total, size);
    const __m512i kept = _mm512_sub_epi64(_mm512_sub_epi64(total, _mm512_sllv_epi64(up, size)), half);
    largest = _mm512_max_epi64(largest, _mm512_abs_epi64(up));
    return kept;
  }
  /// The carries into the eight digits whose carries out are `up`.
  __attribute__((always_inline, target("avx512f"))) inline __m512i carries_in(__m512i up) const {
    return _mm512_alignr_epi64(up, before, 7);
  }
  /// step() with the carries in added; `before` moves on.
  __attribute__((always_inline, target("avx512f"))) inline __m512i carried(__m512i value, const std::uint8_t* bits) {
    __m512i up;
    const __m512i kept = step(value, bits, up);
    const __m512i digits = _mm512_add_epi64(kept, carries_in(up));
    before = up;
    return digits;
  }
  /// The carry out of the last vector's lane 7.
  __attribute__((always_inline, target("avx512f"))) inline std::int64_t last_up() const {
    return _mm512_mask_reduce_max_epi64(0x80, before);
  }
  __attribute__((always_inline, target("avx512f"))) inline std::int64_t most() const {
    return _mm512_reduce_max_epi64(largest);
  }
};

}  // namespace tk::primes
