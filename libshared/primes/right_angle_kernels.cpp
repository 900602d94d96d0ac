/// @file right_angle_kernels.cpp
/// @brief The passes of RightAngleSquarer, written once over a GCC vector
/// type and compiled for AVX-512 (8 doubles) and AVX2 with FMA (4).
///
/// Forward passes are decimation in frequency: a radix-r pass over a block
/// of B points takes x_(j + s*B/r), s < r, to y_t = w^(j*t) * sum_s
/// x_(j + s*B/r) * e^(-2*pi*i*s*t/r), w = e^(-2*pi*i/B), stored at slot t.
/// Each inverse pass undoes its forward pass exactly (times r): conjugate
/// twiddles first, then the inverse butterfly. The inverse passes run in
/// the reverse order, so the whole is the DFT's inverse times N, whatever
/// order the spectrum is in between.
#include "primes/right_angle_kernels.hpp"

#include <cstring>

// The vector helpers below are always inlined into the functions compiled
// for AVX2 or AVX-512, so no vector ever crosses a call.
#pragma GCC diagnostic ignored "-Wpsabi"

namespace tk::primes::right_angle {

namespace {

typedef double v8d __attribute__((vector_size(64)));
typedef long long v8i __attribute__((vector_size(64)));
typedef double v4d __attribute__((vector_size(32)));
typedef long long v4i __attribute__((vector_size(32)));

template <class V>
constexpr std::size_t kLanes = sizeof(V) / sizeof(double);

#define TK_INLINE __attribute__((always_inline)) inline

template <class V>
TK_INLINE V load(const double* p) {
  V v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
template <class V>
TK_INLINE void store(double* p, V v) {
  std::memcpy(p, &v, sizeof v);
}
template <class V>
TK_INLINE V splat(double d) {
  V v;
  for (std::size_t l = 0; l < kLanes<V>; ++l) v[l] = d;
  return v;
}

// (r + i*m) times the twiddle (wr + i*wi), or by its conjugate.
template <class V>
TK_INLINE void times(V& r, V& m, V wr, V wi) {
  const V t = r * wr - m * wi;
  m = r * wi + m * wr;
  r = t;
}
template <class V>
TK_INLINE void times_conjugate(V& r, V& m, V wr, V wi) {
  const V t = r * wr + m * wi;
  m = m * wr - r * wi;
  r = t;
}

template <class V>
TK_INLINE void forward4(double* re, double* im, const double* twr, const double* twi, std::size_t block, std::size_t begin,
              std::size_t end) {
  const std::size_t q = block / 4;
  for (std::size_t base = begin; base < end; base += block)
    for (std::size_t j = 0; j < q; j += kLanes<V>) {
      double *r0 = re + base + j, *i0 = im + base + j;
      const V ar = load<V>(r0), ai = load<V>(i0), br = load<V>(r0 + q), bi = load<V>(i0 + q);
      const V cr = load<V>(r0 + 2 * q), ci = load<V>(i0 + 2 * q), dr = load<V>(r0 + 3 * q), di = load<V>(i0 + 3 * q);
      const V t0r = ar + cr, t0i = ai + ci, t1r = ar - cr, t1i = ai - ci;
      const V t2r = br + dr, t2i = bi + di, t3r = br - dr, t3i = bi - di;
      store(r0, t0r + t2r);
      store(i0, t0i + t2i);
      V y1r = t1r + t3i, y1i = t1i - t3r;  // t1 - i*t3
      V y2r = t0r - t2r, y2i = t0i - t2i;
      V y3r = t1r - t3i, y3i = t1i + t3r;  // t1 + i*t3
      times(y1r, y1i, load<V>(twr + j), load<V>(twi + j));
      times(y2r, y2i, load<V>(twr + q + j), load<V>(twi + q + j));
      times(y3r, y3i, load<V>(twr + 2 * q + j), load<V>(twi + 2 * q + j));
      store(r0 + q, y1r);
      store(i0 + q, y1i);
      store(r0 + 2 * q, y2r);
      store(i0 + 2 * q, y2i);
      store(r0 + 3 * q, y3r);
      store(i0 + 3 * q, y3i);
    }
}

template <class V>
TK_INLINE void inverse4(double* re, double* im, const double* twr, const double* twi, std::size_t block, std::size_t begin,
              std::size_t end) {
  const std::size_t q = block / 4;
  for (std::size_t base = begin; base < end; base += block)
    for (std::size_t j = 0; j < q; j += kLanes<V>) {
      double *r0 = re + base + j, *i0 = im + base + j;
      const V y0r = load<V>(r0), y0i = load<V>(i0);
      V y1r = load<V>(r0 + q), y1i = load<V>(i0 + q);
      V y2r = load<V>(r0 + 2 * q), y2i = load<V>(i0 + 2 * q);
      V y3r = load<V>(r0 + 3 * q), y3i = load<V>(i0 + 3 * q);
      times_conjugate(y1r, y1i, load<V>(twr + j), load<V>(twi + j));
      times_conjugate(y2r, y2i, load<V>(twr + q + j), load<V>(twi + q + j));
      times_conjugate(y3r, y3i, load<V>(twr + 2 * q + j), load<V>(twi + 2 * q + j));
      const V u0r = y0r + y2r, u0i = y0i + y2i, u1r = y0r - y2r, u1i = y0i - y2i;
      const V u2r = y1r + y3r, u2i = y1i + y3i, u3r = y1r - y3r, u3i = y1i - y3i;
      store(r0, u0r + u2r);
      store(i0, u0i + u2i);
      store(r0 + q, u1r - u3i);  // u1 + i*u3
      store(i0 + q, u1i + u3r);
      store(r0 + 2 * q, u0r - u2r);
      store(i0 + 2 * q, u0i - u2i);
      store(r0 + 3 * q, u1r + u3i);  // u1 - i*u3
      store(i0 + 3 * q, u1i - u3r);
    }
}

template <class V>
TK_INLINE void forward2(double* re, double* im, const double* twr, const double* twi, std::size_t block, std::size_t begin,
              std::size_t end) {
  const std::size_t h = block / 2;
  for (std::size_t base = begin; base < end; base += block)
    for (std::size_t j = 0; j < h; j += kLanes<V>) {
      double *r0 = re + base + j, *i0 = im + base + j;
      const V ar = load<V>(r0), ai = load<V>(i0), br = load<V>(r0 + h), bi = load<V>(i0 + h);
      store(r0, ar + br);
      store(i0, ai + bi);
      V dr = ar - br, di = ai - bi;
      times(dr, di, load<V>(twr + j), load<V>(twi + j));
      store(r0 + h, dr);
      store(i0 + h, di);
    }
}

template <class V>
TK_INLINE void inverse2(double* re, double* im, const double* twr, const double* twi, std::size_t block, std::size_t begin,
              std::size_t end) {
  const std::size_t h = block / 2;
  for (std::size_t base = begin; base < end; base += block)
    for (std::size_t j = 0; j < h; j += kLanes<V>) {
      double *r0 = re + base + j, *i0 = im + base + j;
      const V ar = load<V>(r0), ai = load<V>(i0);
      V br = load<V>(r0 + h), bi = load<V>(i0 + h);
      times_conjugate(br, bi, load<V>(twr + j), load<V>(twi + j));
      store(r0, ar + br);
      store(i0, ai + bi);
      store(r0 + h, ar - br);
      store(i0 + h, ai - bi);
    }
}

constexpr double kHalfRoot3 = 0.86602540378443864676;  // sin(2*pi/3)

template <class V>
TK_INLINE void forward3(double* re, double* im, const double* twr, const double* twi, std::size_t block, std::size_t begin,
              std::size_t end) {
  const std::size_t q = block / 3;
  const V half = splat<V>(0.5), h = splat<V>(kHalfRoot3);
  for (std::size_t base = begin; base < end; base += block)
    for (std::size_t j = 0; j < q; j += kLanes<V>) {
      double *r0 = re + base + j, *i0 = im + base + j;
      const V ar = load<V>(r0), ai = load<V>(i0), br = load<V>(r0 + q), bi = load<V>(i0 + q);
      const V cr = load<V>(r0 + 2 * q), ci = load<V>(i0 + 2 * q);
      const V sr = br + cr, si = bi + ci, dr = br - cr, di = bi - ci;
      store(r0, ar + sr);
      store(i0, ai + si);
      const V mr = ar - half * sr, mi = ai - half * si;
      V y1r = mr + h * di, y1i = mi - h * dr;  // m - i*h*d
      V y2r = mr - h * di, y2i = mi + h * dr;
      times(y1r, y1i, load<V>(twr + j), load<V>(twi + j));
      times(y2r, y2i, load<V>(twr + q + j), load<V>(twi + q + j));
      store(r0 + q, y1r);
      store(i0 + q, y1i);
      store(r0 + 2 * q, y2r);
      store(i0 + 2 * q, y2i);
    }
}

template <class V>
TK_INLINE void inverse3(double* re, double* im, const double* twr, const double* twi, std::size_t block, std::size_t begin,
              std::size_t end) {
  const std::size_t q = block / 3;
  const V half = splat<V>(0.5), h = splat<V>(kHalfRoot3);
  for (std::size_t base = begin; base < end; base += block)
    for (std::size_t j = 0; j < q; j += kLanes<V>) {
      double *r0 = re + base + j, *i0 = im + base + j;
      const V y0r = load<V>(r0), y0i = load<V>(i0);
      V y1r = load<V>(r0 + q), y1i = load<V>(i0 + q), y2r = load<V>(r0 + 2 * q), y2i = load<V>(i0 + 2 * q);
      times_conjugate(y1r, y1i, load<V>(twr + j), load<V>(twi + j));
      times_conjugate(y2r, y2i, load<V>(twr + q + j), load<V>(twi + q + j));
      const V sr = y1r + y2r, si = y1i + y2i, dr = y1r - y2r, di = y1i - y2i;
      store(r0, y0r + sr);
      store(i0, y0i + si);
      const V mr = y0r - half * sr, mi = y0i - half * si;
      store(r0 + q, mr - h * di);  // m + i*h*d
      store(i0 + q, mi + h * dr);
      store(r0 + 2 * q, mr + h * di);  // m - i*h*d
      store(i0 + 2 * q, mi - h * dr);
    }
}

template <class V>
TK_INLINE void run_stage(const Arrays& a, const RightAngleSquarer::Stage& stage, bool forward, std::size_t begin,
               std::size_t end) {
  const double *twr = a.twiddle_re + stage.twiddles, *twi = a.twiddle_im + stage.twiddles;
  switch (stage.radix * (forward ? 1 : -1)) {
    case 4: return forward4<V>(a.re, a.im, twr, twi, stage.block, begin, end);
    case -4: return inverse4<V>(a.re, a.im, twr, twi, stage.block, begin, end);
    case 3: return forward3<V>(a.re, a.im, twr, twi, stage.block, begin, end);
    case -3: return inverse3<V>(a.re, a.im, twr, twi, stage.block, begin, end);
    case 2: return forward2<V>(a.re, a.im, twr, twi, stage.block, begin, end);
    default: return inverse2<V>(a.re, a.im, twr, twi, stage.block, begin, end);
  }
}

// The last log2(lanes) radix-2 passes, on the points one vector holds,
// then the pointwise square, then their inverses. A lane's partner at
// distance h is lane ^ h; the upper lane of a pair takes
// partner - itself, then its twiddle e^(-2*pi*i*(lane mod h)/(2h)).
template <class V, class I>
struct LanePasses {
  static constexpr std::size_t kPasses = __builtin_ctz(kLanes<V>);
  I partner[kPasses];
  V sign[kPasses], twr[kPasses], twi[kPasses];

  TK_INLINE LanePasses() {
    std::size_t pass = 0;
    for (std::size_t h = kLanes<V> / 2; h >= 1; h /= 2, ++pass)
      for (std::size_t l = 0; l < kLanes<V>; ++l) {
        partner[pass][l] = static_cast<long long>(l ^ h);
        const bool upper = (l & h) != 0;
        sign[pass][l] = upper ? -1.0 : 1.0;
        const double angle = -3.14159265358979323846 * static_cast<double>(l % h) / static_cast<double>(h);
        twr[pass][l] = upper ? __builtin_cos(angle) : 1.0;
        twi[pass][l] = upper ? __builtin_sin(angle) : 0.0;
      }
  }

  TK_INLINE void square(double* re, double* im) const {
    V r = load<V>(re), m = load<V>(im);
#pragma GCC unroll 4
    for (std::size_t pass = 0; pass < kPasses; ++pass) {
      r = __builtin_shuffle(r, partner[pass]) + sign[pass] * r;
      m = __builtin_shuffle(m, partner[pass]) + sign[pass] * m;
      if (pass + 1 < kPasses) times(r, m, twr[pass], twi[pass]);  // the last pass's twiddles are all 1
    }
    const V t = r * r - m * m;
    m = (r + r) * m;
    r = t;
#pragma GCC unroll 4
    for (std::size_t undone = 0; undone < kPasses; ++undone) {
      const std::size_t pass = kPasses - 1 - undone;
      if (pass + 1 < kPasses) times_conjugate(r, m, twr[pass], twi[pass]);
      r = __builtin_shuffle(r, partner[pass]) + sign[pass] * r;
      m = __builtin_shuffle(m, partner[pass]) + sign[pass] * m;
    }
    store(re, r);
    store(im, m);
  }
};

// The passes forward, the pointwise square, the passes back, on a.re/a.im.
template <class V, class I>
TK_INLINE void passes(const Arrays& a) {
  const std::size_t n = a.half;
  for (std::size_t s = 0; s < a.inner_from; ++s) run_stage<V>(a, a.stages[s], true, 0, n);
  const LanePasses<V, I> lanes;
  for (std::size_t begin = 0; begin < n; begin += a.inner_block) {
    const std::size_t end = begin + a.inner_block;
    for (std::size_t s = a.inner_from; s < a.stage_count; ++s) run_stage<V>(a, a.stages[s], true, begin, end);
    for (std::size_t j = begin; j < end; j += kLanes<V>) lanes.square(a.re + j, a.im + j);
    for (std::size_t s = a.stage_count; s-- > a.inner_from;) run_stage<V>(a, a.stages[s], false, begin, end);
  }
  for (std::size_t s = a.inner_from; s-- > 0;) run_stage<V>(a, a.stages[s], false, 0, n);
}

template <class V, class I>
TK_INLINE void square_with(const Arrays& a, const double* input, double* output) {
  const std::size_t n = a.half;
  // c_j = x_j * theta^j: the upper half of the real sequence is zero.
  for (std::size_t j = 0; j < n; j += kLanes<V>) {
    const V x = load<V>(input + j);
    store(a.re + j, x * load<V>(a.theta_cos + j));
    store(a.im + j, x * load<V>(a.theta_sin + j));
  }
  passes<V, I>(a);
  // times theta^-j, and 2 for FFTW's scale (L where this transform gives N).
  for (std::size_t j = 0; j < n; j += kLanes<V>) {
    const V r = load<V>(a.re + j), m = load<V>(a.im + j);
    const V c = load<V>(a.theta_cos + j), s = load<V>(a.theta_sin + j);
    store(output + j, 2.0 * (r * c + m * s));
    store(output + n + j, 2.0 * (m * c - r * s));
  }
}

}  // namespace

__attribute__((target("avx512f,avx512dq,fma"))) void square_avx512(const Arrays& arrays, const double* input,
                                                                   double* output) {
  square_with<v8d, v8i>(arrays, input, output);
}

__attribute__((target("avx2,fma"))) void square_avx2(const Arrays& arrays, const double* input, double* output) {
  square_with<v4d, v4i>(arrays, input, output);
}

__attribute__((target("avx512f,avx512dq,fma"))) void passes_avx512(const Arrays& arrays) { passes<v8d, v8i>(arrays); }

__attribute__((target("avx2,fma"))) void passes_avx2(const Arrays& arrays) { passes<v4d, v4i>(arrays); }

}  // namespace tk::primes::right_angle
