/// @file sieve_roots.cpp
#include "primes/sieve_roots.hpp"

#include <fmt/format.h>

#include <immintrin.h>

#include <algorithm>
#include <cstdlib>
#include <string_view>

#include "io/error.hpp"
#include "primes/montgomery64.hpp"

namespace tk::primes {

namespace {

using u32 = std::uint32_t;

/// REDC for R = 2^32 and an odd p < 2^32: a*b/2^32 mod p. t - m*p has zero
/// low half, so the high halves' difference is the result, less p on a borrow.
inline u32 mul32(u32 a, u32 b, u32 p, u32 p_inverse) {
  const u64 t = static_cast<u64>(a) * b;
  const u32 m = static_cast<u32>(t) * p_inverse;
  const u32 t_high = static_cast<u32>(t >> 32);
  const u32 mp_high = static_cast<u32>((static_cast<u64>(m) * p) >> 32);
  const u32 r = t_high - mp_high;
  return t_high < mp_high ? r + p : r;
}

inline u32 half32(u32 a, u32 p) { return (a & 1) ? static_cast<u32>((static_cast<u64>(a) + p) >> 1) : a >> 1; }

inline u32 inverse32(u32 p) {  // p^-1 mod 2^32 by Newton's iteration
  u32 inverse = p;
  for (int i = 0; i < 4; ++i) inverse *= 2 - p * inverse;
  return inverse;
}

constexpr std::size_t kLanes = 16;

/// (1/2)^n in Montgomery form for kLanes primes below 2^32 at once. The
/// scalar version is the reference; the vector ones keep one prime per
/// 64-bit lane (pmuludq multiplies the low 32 bits) and several vectors in
/// flight so the multiplier's latency is hidden. Chosen once at start-up
/// by what the processor supports.
void half_power_scalar(u32* x, const u32* p, const u32* p_inverse, std::uint64_t n, int top_bit) {
  for (int bit = top_bit; bit >= 0; --bit) {
    for (std::size_t l = 0; l < kLanes; ++l) x[l] = mul32(x[l], x[l], p[l], p_inverse[l]);
    if ((n >> bit) & 1)
      for (std::size_t l = 0; l < kLanes; ++l) x[l] = half32(x[l], p[l]);
  }
}

__attribute__((target("avx2"))) void half_power_avx2(u32* x, const u32* p, const u32* p_inverse, std::uint64_t n,
                                                     int top_bit) {
  constexpr std::size_t kVectors = kLanes / 4;
  __m256i vx[kVectors], vp[kVectors], vq[kVectors], vh[kVectors];
  const __m256i one = _mm256_set1_epi64x(1);
  for (std::size_t v = 0; v < kVectors; ++v) {
    const u32* lane = p + 4 * v;
    vp[v] = _mm256_set_epi64x(lane[3], lane[2], lane[1], lane[0]);
    vq[v] = _mm256_set_epi64x(p_inverse[4 * v + 3], p_inverse[4 * v + 2], p_inverse[4 * v + 1], p_inverse[4 * v]);
    vx[v] = _mm256_set_epi64x(x[4 * v + 3], x[4 * v + 2], x[4 * v + 1], x[4 * v]);
    vh[v] = _mm256_add_epi64(_mm256_srli_epi64(vp[v], 1), one);
  }
  for (int bit = top_bit; bit >= 0; --bit) {
    for (std::size_t v = 0; v < kVectors; ++v) {
      const __m256i t = _mm256_mul_epu32(vx[v], vx[v]);
      const __m256i m = _mm256_mul_epu32(t, vq[v]);
      const __m256i mp_high = _mm256_srli_epi64(_mm256_mul_epu32(m, vp[v]), 32);
      const __m256i t_high = _mm256_srli_epi64(t, 32);
      const __m256i borrow = _mm256_cmpgt_epi64(mp_high, t_high);
      vx[v] = _mm256_add_epi64(_mm256_sub_epi64(t_high, mp_high), _mm256_and_si256(borrow, vp[v]));
    }
    if ((n >> bit) & 1) {
      for (std::size_t v = 0; v < kVectors; ++v) {
        const __m256i odd = _mm256_sub_epi64(_mm256_setzero_si256(), _mm256_and_si256(vx[v], one));
        vx[v] = _mm256_add_epi64(_mm256_srli_epi64(vx[v], 1), _mm256_and_si256(odd, vh[v]));
      }
    }
  }
  for (std::size_t v = 0; v < kVectors; ++v) {
    alignas(32) std::uint64_t out[4];
    _mm256_store_si256(reinterpret_cast<__m256i*>(out), vx[v]);
    for (std::size_t l = 0; l < 4; ++l) x[4 * v + l] = static_cast<u32>(out[l]);
  }
}

// GCC 12's AVX-512 headers trip -Wuninitialized on their own masked builtins (GCC bug 105593).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wuninitialized"
#if !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
__attribute__((target("avx512f"))) void half_power_avx512(u32* x, const u32* p, const u32* p_inverse, std::uint64_t n,
                                                          int top_bit) {
  constexpr std::size_t kVectors = kLanes / 8;
  __m512i vx[kVectors], vp[kVectors], vq[kVectors], vh[kVectors];
  const __m512i one = _mm512_set1_epi64(1);
  for (std::size_t v = 0; v < kVectors; ++v) {
    vp[v] = _mm512_cvtepu32_epi64(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(p + 8 * v)));
    vq[v] = _mm512_cvtepu32_epi64(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(p_inverse + 8 * v)));
    vx[v] = _mm512_cvtepu32_epi64(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(x + 8 * v)));
    vh[v] = _mm512_add_epi64(_mm512_srli_epi64(vp[v], 1), one);
  }
  for (int bit = top_bit; bit >= 0; --bit) {
    for (std::size_t v = 0; v < kVectors; ++v) {
      const __m512i t = _mm512_mul_epu32(vx[v], vx[v]);
      const __m512i m = _mm512_mul_epu32(t, vq[v]);
      const __m512i mp_high = _mm512_srli_epi64(_mm512_mul_epu32(m, vp[v]), 32);
      const __m512i t_high = _mm512_srli_epi64(t, 32);
      const __mmask8 borrow = _mm512_cmpgt_epu64_mask(mp_high, t_high);
      vx[v] =
          _mm512_mask_add_epi64(_mm512_sub_epi64(t_high, mp_high), borrow, _mm512_sub_epi64(t_high, mp_high), vp[v]);
    }
    if ((n >> bit) & 1) {
      for (std::size_t v = 0; v < kVectors; ++v) {
        const __mmask8 odd = _mm512_test_epi64_mask(vx[v], one);
        vx[v] = _mm512_mask_add_epi64(_mm512_srli_epi64(vx[v], 1), odd, _mm512_srli_epi64(vx[v], 1), vh[v]);
      }
    }
  }
  for (std::size_t v = 0; v < kVectors; ++v)
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(x + 8 * v), _mm512_cvtepi64_epi32(vx[v]));
}

#pragma GCC diagnostic pop

using HalfPower = void (*)(u32*, const u32*, const u32*, std::uint64_t, int);

/// The widest kernel the processor runs; TOOLKIT_SIEVE_KERNEL=scalar or
/// avx2 asks for a narrower one (tests compare them).
HalfPower pick_half_power() {
  __builtin_cpu_init();
  const char* wanted = std::getenv("TOOLKIT_SIEVE_KERNEL");
  const std::string_view name = wanted ? wanted : "";
  if (name != "scalar" && name != "avx2" && __builtin_cpu_supports("avx512f")) return half_power_avx512;
  if (name != "scalar" && __builtin_cpu_supports("avx2")) return half_power_avx2;
  return half_power_scalar;
}

const HalfPower half_power_lanes = pick_half_power();

}  // namespace

SieveRootFinder::SieveRootFinder(const SieveSpec& spec)
    : n_(spec.n), members_(spec.members()), k_first_(spec.k_at(spec.x_min)), step_(spec.parametrised ? spec.c : 1) {
  for (const SieveMember& member : members_) max_offset_ = std::max(max_offset_, member.exponent_offset);
}

void SieveRootFinder::find(const std::uint64_t* primes, std::size_t count, std::uint64_t* roots) const {
  std::size_t small = 0;
  while (small < count && primes[small] < (std::uint64_t(1) << 32)) ++small;
  find_small(primes, small, roots);
  for (std::size_t i = small; i < count; ++i) find_large(primes[i], roots + i * members_.size());
}

void SieveRootFinder::store(std::uint64_t p, std::uint64_t t, std::uint64_t inverse_step, std::uint64_t* roots) const {
  const std::uint64_t k_first = k_first_ % p;
  const std::size_t count = members_.size();
  // Members come ordered by exponent offset; t halves from one offset to the next.
  unsigned offset = 0;
  for (std::size_t m = 0; m < count; ++m) {
    for (; offset < members_[m].exponent_offset; ++offset) t = (t & 1) ? (t >> 1) + (p >> 1) + 1 : t >> 1;
    const std::uint64_t k_root = members_[m].c < 0 ? t : p - t;  // k*2^e = -c (mod p)
    const std::uint64_t diff = k_root >= k_first ? k_root - k_first : k_root + p - k_first;
    roots[m] = inverse_step == 1 ? diff : static_cast<std::uint64_t>(static_cast<u128>(diff) * inverse_step % p);
  }
}

void SieveRootFinder::handle_prime_dividing_step(std::uint64_t p, std::uint64_t* roots) const {
  // Every x gives the same residue k_first*2^e + c (mod p).
  Montgomery64 mont(p);
  const std::uint64_t half_form = mont.to_form((p + 1) / 2);
  for (std::size_t m = 0; m < members_.size(); ++m) {
    const std::uint64_t e = n_ + members_[m].exponent_offset;
    const std::uint64_t t = mont.from_form(mont.pow(half_form, e));  // 2^-e
    const std::uint64_t k_root = members_[m].c < 0 ? t : p - t;
    if (k_first_ % p == k_root)
      throw Error(
          fmt::format("every candidate is divisible by {}, which divides c: choose h0 so that "
                      "h0*2^{}{} is not divisible by it",
                      p, e, members_[m].c < 0 ? "-1" : "+1"));
    roots[m] = kNoRoot;
  }
}

void SieveRootFinder::find_small(const std::uint64_t* primes, std::size_t count, std::uint64_t* roots) const {
  const int top_bit = 63 - __builtin_clzll(n_);
  const std::size_t width = members_.size();
  for (std::size_t base = 0; base < count; base += kLanes) {
    const std::size_t lanes = std::min(kLanes, count - base);
    alignas(64) u32 p[kLanes], p_inverse[kLanes], x[kLanes];
    for (std::size_t l = 0; l < kLanes; ++l) {
      p[l] = static_cast<u32>(primes[base + std::min(l, lanes - 1)]);
      p_inverse[l] = inverse32(p[l]);
      x[l] = static_cast<u32>(0u - p[l]) % p[l];  // 2^32 mod p: 1 in Montgomery form
    }
    half_power_lanes(x, p, p_inverse, n_, top_bit);
    for (std::size_t l = 0; l < lanes; ++l) {
      const u32 t = mul32(x[l], 1, p[l], p_inverse[l]);  // out of Montgomery form
      std::uint64_t* out = roots + (base + l) * width;
      if (step_ == 1) {
        store(p[l], t, 1, out);
        continue;
      }
      const u32 step = static_cast<u32>(step_ % p[l]);
      if (step == 0) {
        handle_prime_dividing_step(p[l], out);
        continue;
      }
      // step^-1 = step^(p-2) (Fermat), in Montgomery form, then out of it.
      const u32 step_form = static_cast<u32>((static_cast<std::uint64_t>(step) << 32) % p[l]);
      u32 inverse = static_cast<u32>(0u - p[l]) % p[l];
      for (int bit = 31; bit >= 0; --bit) {
        inverse = mul32(inverse, inverse, p[l], p_inverse[l]);
        if (((p[l] - 2) >> bit) & 1) inverse = mul32(inverse, step_form, p[l], p_inverse[l]);
      }
      store(p[l], t, mul32(inverse, 1, p[l], p_inverse[l]), out);
    }
  }
}

void SieveRootFinder::find_large(std::uint64_t p, std::uint64_t* roots) const {
  Montgomery64 mont(p);
  std::uint64_t x = mont.one();
  for (int bit = 63 - __builtin_clzll(n_); bit >= 0; --bit) {
    x = mont.mul(x, x);
    if ((n_ >> bit) & 1) x = mont.half(x);
  }
  const std::uint64_t t = mont.from_form(x);
  if (step_ == 1) return store(p, t, 1, roots);
  const std::uint64_t step = step_ % p;
  if (step == 0) return handle_prime_dividing_step(p, roots);
  store(p, t, mont.from_form(mont.pow(mont.to_form(step), p - 2)), roots);
}

}  // namespace tk::primes
