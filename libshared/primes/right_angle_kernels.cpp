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
// The butterflies' lambdas too: left to the inliner's budget, they stop
// being inlined once the file holds more users of them (the split passes),
// and a lambda does not take its caller's target (AVX-512, AVX2).
#define TK_LAMBDA_INLINE __attribute__((always_inline))

template <class V>
TK_INLINE V load(const double* p) {
  V v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
template <class V>
TK_INLINE void store(double* p, const V& v) {
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
TK_INLINE void times(V& r, V& m, const V& wr, const V& wi) {
  const V t = r * wr - m * wi;
  m = r * wi + m * wr;
  r = t;
}
template <class V>
TK_INLINE void times_conjugate(V& r, V& m, const V& wr, const V& wi) {
  const V t = r * wr + m * wi;
  m = m * wr - r * wi;
  r = t;
}

// One complex point per lane, from the split arrays.
template <class V>
struct Point {
  V r, m;
};
template <class V>
TK_INLINE Point<V> get(const double* re, const double* im, std::size_t at) {
  return {load<V>(re + at), load<V>(im + at)};
}
template <class V>
TK_INLINE void put(double* re, double* im, std::size_t at, const Point<V>& p) {
  store(re + at, p.r);
  store(im + at, p.m);
}
template <class V>
TK_INLINE Point<V> operator+(const Point<V>& a, const Point<V>& b) {
  return {a.r + b.r, a.m + b.m};
}
template <class V>
TK_INLINE Point<V> operator-(const Point<V>& a, const Point<V>& b) {
  return {a.r - b.r, a.m - b.m};
}
template <class V>
TK_INLINE Point<V> times_i(const Point<V>& a) {
  return {-a.m, a.r};
}
// times the twiddle of slot t (1 <= t < r) at j, or by its conjugate
template <class V>
TK_INLINE Point<V> twiddled(const Point<V>& a, const double* twr, const double* twi, std::size_t at) {
  Point<V> b = a;
  times(b.r, b.m, load<V>(twr + at), load<V>(twi + at));
  return b;
}
template <class V>
TK_INLINE Point<V> untwiddled(const Point<V>& a, const double* twr, const double* twi, std::size_t at) {
  Point<V> b = a;
  times_conjugate(b.r, b.m, load<V>(twr + at), load<V>(twi + at));
  return b;
}

// Where a forward pass reads its points: re/im, or (the first pass of a
// weighted square) digits times their weights. The weighted point is
// pinned in registers before any butterfly sees it, so no multiply-add
// fuses it: the same roundings as weighting into re/im first.
template <class V>
struct FromArrays {
  const double* re;
  const double* im;
  TK_INLINE Point<V> operator()(std::size_t at) const { return get<V>(re, im, at); }
};
template <class V, class I>
struct FromDigits {
  const std::int64_t* digits;
  const double* weight_re;
  const double* weight_im;
  TK_INLINE Point<V> operator()(std::size_t at) const {
    I whole;
    std::memcpy(&whole, digits + at, sizeof whole);
    const V value = __builtin_convertvector(whole, V);
    V r = value * load<V>(weight_re + at), m = value * load<V>(weight_im + at);
#if !defined(__clang__)  // clang contracts only within one expression, and refuses this 64-byte operand here
    __asm__("" : "+v"(r), "+v"(m));
#endif
    return {r, m};
  }
};

// Which butterflies of each block a call does: columns j in [from, to)
// (all by default; a thread of a split square takes a window of them).
struct Columns {
  std::size_t from = 0;
  std::size_t to = ~std::size_t{0};
};

// Calls butterfly(re, im, j, q) for every group of lanes of every block
// (the columns asked for): the group's points are at j + s*q, s < radix,
// and its twiddles at j + (t - 1)*q.
template <class V, class Butterfly>
TK_INLINE void for_each_butterfly(int radix, std::size_t block, std::size_t begin, std::size_t end, Columns columns,
                                  Butterfly&& butterfly) {
  const std::size_t q = block / static_cast<std::size_t>(radix);
  const std::size_t to = columns.to < q ? columns.to : q;
  for (std::size_t base = begin; base < end; base += block)
    for (std::size_t j = columns.from; j < to; j += kLanes<V>) butterfly(base + j, j, q);
}

template <class V, class Source>
TK_INLINE void forward4_from(const Source& source, double* re, double* im, const double* twr, const double* twi,
                             std::size_t block, std::size_t begin, std::size_t end, Columns columns) {
  for_each_butterfly<V>(
      4, block, begin, end, columns, [&](std::size_t at, std::size_t j, std::size_t q) TK_LAMBDA_INLINE {
        const Point<V> a = source(at), b = source(at + q), c = source(at + 2 * q), d = source(at + 3 * q);
        const Point<V> t0 = a + c, t1 = a - c, t2 = b + d, t3 = times_i(b - d);
        put(re, im, at, t0 + t2);
        put(re, im, at + q, twiddled(t1 - t3, twr, twi, j));
        put(re, im, at + 2 * q, twiddled(t0 - t2, twr, twi, q + j));
        put(re, im, at + 3 * q, twiddled(t1 + t3, twr, twi, 2 * q + j));
      });
}

template <class V>
TK_INLINE void forward4(double* re, double* im, const double* twr, const double* twi, std::size_t block,
                        std::size_t begin, std::size_t end, Columns columns = {}) {
  forward4_from<V>(FromArrays<V>{re, im}, re, im, twr, twi, block, begin, end, columns);
}

template <class V>
TK_INLINE void inverse4(double* re, double* im, const double* twr, const double* twi, std::size_t block,
                        std::size_t begin, std::size_t end, Columns columns = {}) {
  for_each_butterfly<V>(4, block, begin, end, columns,
                        [&](std::size_t at, std::size_t j, std::size_t q) TK_LAMBDA_INLINE {
                          const Point<V> y0 = get<V>(re, im, at), y1 = untwiddled(get<V>(re, im, at + q), twr, twi, j),
                                         y2 = untwiddled(get<V>(re, im, at + 2 * q), twr, twi, q + j),
                                         y3 = untwiddled(get<V>(re, im, at + 3 * q), twr, twi, 2 * q + j);
                          const Point<V> u0 = y0 + y2, u1 = y0 - y2, u2 = y1 + y3, u3 = times_i(y1 - y3);
                          put(re, im, at, u0 + u2);
                          put(re, im, at + q, u1 + u3);
                          put(re, im, at + 2 * q, u0 - u2);
                          put(re, im, at + 3 * q, u1 - u3);
                        });
}

template <class V, class Source>
TK_INLINE void forward2_from(const Source& source, double* re, double* im, const double* twr, const double* twi,
                             std::size_t block, std::size_t begin, std::size_t end, Columns columns) {
  for_each_butterfly<V>(2, block, begin, end, columns,
                        [&](std::size_t at, std::size_t j, std::size_t h) TK_LAMBDA_INLINE {
                          const Point<V> a = source(at), b = source(at + h);
                          put(re, im, at, a + b);
                          put(re, im, at + h, twiddled(a - b, twr, twi, j));
                        });
}

template <class V>
TK_INLINE void forward2(double* re, double* im, const double* twr, const double* twi, std::size_t block,
                        std::size_t begin, std::size_t end, Columns columns = {}) {
  forward2_from<V>(FromArrays<V>{re, im}, re, im, twr, twi, block, begin, end, columns);
}

template <class V>
TK_INLINE void inverse2(double* re, double* im, const double* twr, const double* twi, std::size_t block,
                        std::size_t begin, std::size_t end, Columns columns = {}) {
  for_each_butterfly<V>(2, block, begin, end, columns,
                        [&](std::size_t at, std::size_t j, std::size_t h) TK_LAMBDA_INLINE {
                          const Point<V> a = get<V>(re, im, at), b = untwiddled(get<V>(re, im, at + h), twr, twi, j);
                          put(re, im, at, a + b);
                          put(re, im, at + h, a - b);
                        });
}

constexpr double kHalfRoot3 = 0.86602540378443864676;  // sin(2*pi/3)

// y1, y2 = m -+ i*h*d (forward: e^(-2*pi*i/3) = -1/2 - i*h), or +- for the inverse.
template <class V, class Source>
TK_INLINE void forward3_from(const Source& source, double* re, double* im, const double* twr, const double* twi,
                             std::size_t block, std::size_t begin, std::size_t end, Columns columns) {
  const V half = splat<V>(0.5), h = splat<V>(kHalfRoot3);
  for_each_butterfly<V>(3, block, begin, end, columns,
                        [&](std::size_t at, std::size_t j, std::size_t q) TK_LAMBDA_INLINE {
                          const Point<V> a = source(at), b = source(at + q), c = source(at + 2 * q);
                          const Point<V> sum = b + c, m = {a.r - half * sum.r, a.m - half * sum.m};
                          const Point<V> ihd = times_i(Point<V>{h * (b.r - c.r), h * (b.m - c.m)});
                          put(re, im, at, a + sum);
                          put(re, im, at + q, twiddled(m - ihd, twr, twi, j));
                          put(re, im, at + 2 * q, twiddled(m + ihd, twr, twi, q + j));
                        });
}

template <class V>
TK_INLINE void forward3(double* re, double* im, const double* twr, const double* twi, std::size_t block,
                        std::size_t begin, std::size_t end, Columns columns = {}) {
  forward3_from<V>(FromArrays<V>{re, im}, re, im, twr, twi, block, begin, end, columns);
}

template <class V>
TK_INLINE void inverse3(double* re, double* im, const double* twr, const double* twi, std::size_t block,
                        std::size_t begin, std::size_t end, Columns columns = {}) {
  const V half = splat<V>(0.5), h = splat<V>(kHalfRoot3);
  for_each_butterfly<V>(3, block, begin, end, columns,
                        [&](std::size_t at, std::size_t j, std::size_t q) TK_LAMBDA_INLINE {
                          const Point<V> y0 = get<V>(re, im, at), y1 = untwiddled(get<V>(re, im, at + q), twr, twi, j),
                                         y2 = untwiddled(get<V>(re, im, at + 2 * q), twr, twi, q + j);
                          const Point<V> sum = y1 + y2, m = {y0.r - half * sum.r, y0.m - half * sum.m};
                          const Point<V> ihd = times_i(Point<V>{h * (y1.r - y2.r), h * (y1.m - y2.m)});
                          put(re, im, at, y0 + sum);
                          put(re, im, at + q, m + ihd);
                          put(re, im, at + 2 * q, m - ihd);
                        });
}

template <class V>
TK_INLINE void run_stage(const Arrays& a, const RightAngleSquarer::Stage& stage, bool forward, std::size_t begin,
                         std::size_t end, Columns columns = {}) {
  const double *twr = a.twiddle_re + stage.twiddles, *twi = a.twiddle_im + stage.twiddles;
  switch (stage.radix * (forward ? 1 : -1)) {
    case 4: return forward4<V>(a.re, a.im, twr, twi, stage.block, begin, end, columns);
    case -4: return inverse4<V>(a.re, a.im, twr, twi, stage.block, begin, end, columns);
    case 3: return forward3<V>(a.re, a.im, twr, twi, stage.block, begin, end, columns);
    case -3: return inverse3<V>(a.re, a.im, twr, twi, stage.block, begin, end, columns);
    case 2: return forward2<V>(a.re, a.im, twr, twi, stage.block, begin, end, columns);
    default: return inverse2<V>(a.re, a.im, twr, twi, stage.block, begin, end, columns);
  }
}

// The first forward pass, reading digits times their weights (Arrays::digits).
template <class V, class I>
TK_INLINE void run_first_stage_from_digits(const Arrays& a, std::size_t begin, std::size_t end, Columns columns = {}) {
  const RightAngleSquarer::Stage& stage = a.stages[0];
  const double *twr = a.twiddle_re + stage.twiddles, *twi = a.twiddle_im + stage.twiddles;
  const FromDigits<V, I> source{a.digits, a.weight_re, a.weight_im};
  switch (stage.radix) {
    case 4: return forward4_from<V>(source, a.re, a.im, twr, twi, stage.block, begin, end, columns);
    case 3: return forward3_from<V>(source, a.re, a.im, twr, twi, stage.block, begin, end, columns);
    default: return forward2_from<V>(source, a.re, a.im, twr, twi, stage.block, begin, end, columns);
  }
}

// Lane l of the result is lane partner[l] of v: one permute under GCC;
// clang (the fuzz build) has no shuffle by a mask known only at run time,
// so there lane by lane, which is right and slow.
template <class V, class I>
TK_INLINE V permuted(V v, I partner) {
#if defined(__clang__)
  V r;
  for (std::size_t l = 0; l < kLanes<V>; ++l) r[l] = v[partner[l]];
  return r;
#else
  return __builtin_shuffle(v, partner);
#endif
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

  // The passes forward and back on one vector of points in registers.
  TK_INLINE void forward_in(V& r, V& m) const {
#pragma GCC unroll 4
    for (std::size_t pass = 0; pass < kPasses; ++pass) {
      r = permuted(r, partner[pass]) + sign[pass] * r;
      m = permuted(m, partner[pass]) + sign[pass] * m;
      if (pass + 1 < kPasses) times(r, m, twr[pass], twi[pass]);  // the last pass's twiddles are all 1
    }
  }
  TK_INLINE void inverse_in(V& r, V& m) const {
#pragma GCC unroll 4
    for (std::size_t undone = 0; undone < kPasses; ++undone) {
      const std::size_t pass = kPasses - 1 - undone;
      if (pass + 1 < kPasses) times_conjugate(r, m, twr[pass], twi[pass]);
      r = permuted(r, partner[pass]) + sign[pass] * r;
      m = permuted(m, partner[pass]) + sign[pass] * m;
    }
  }

  TK_INLINE void square(double* re, double* im) const {
    V r = load<V>(re), m = load<V>(im);
    forward_in(r, m);
    const V t = r * r - m * m;
    m = (r + r) * m;
    r = t;
    inverse_in(r, m);
    store(re, r);
    store(im, m);
  }

  // The same lane passes split up, for the forward, pointwise product and
  // inverse the caller sequences itself.
  TK_INLINE void forward(double* re, double* im) const {
    V r = load<V>(re), m = load<V>(im);
    forward_in(r, m);
    store(re, r);
    store(im, m);
  }
  TK_INLINE void inverse(double* re, double* im) const {
    V r = load<V>(re), m = load<V>(im);
    inverse_in(r, m);
    store(re, r);
    store(im, m);
  }

  // forward, times the stored spectrum (sre + i*sim) point by point, inverse
  TK_INLINE void multiply(double* re, double* im, const double* sre, const double* sim) const {
    V r = load<V>(re), m = load<V>(im);
    forward_in(r, m);
    times(r, m, load<V>(sre), load<V>(sim));
    inverse_in(r, m);
    store(re, r);
    store(im, m);
  }
};

// The passes over the whole array (blocks above an L1's worth), forward
// or back.
template <class V>
TK_INLINE void outer_passes(const Arrays& a, bool forward) {
  if (forward)
    for (std::size_t s = 0; s < a.inner_from; ++s) run_stage<V>(a, a.stages[s], true, 0, a.half);
  else
    for (std::size_t s = a.inner_from; s-- > 0;) run_stage<V>(a, a.stages[s], false, 0, a.half);
}

// What the lane passes do between the forward and inverse passes.
enum class Pointwise { square, multiply, forward_only, inverse_only };

// The passes forward (unless inverse_only), the pointwise step, the passes
// back (unless forward_only), on a.re/a.im, the inner passes one L1-sized
// block at a time. (No lambdas here: a lambda does not take its caller's
// target attribute, so its vectors would be built for the baseline.)
template <class V, class I, Pointwise kind>
TK_INLINE void run_passes(const Arrays& a, const LanePasses<V, I>& lanes, const double* sre = nullptr,
                          const double* sim = nullptr) {
  constexpr bool forward = kind != Pointwise::inverse_only, back = kind != Pointwise::forward_only;
  if (forward) outer_passes<V>(a, true);
  for (std::size_t begin = 0; begin < a.half; begin += a.inner_block) {
    const std::size_t end = begin + a.inner_block;
    if (forward)
      for (std::size_t s = a.inner_from; s < a.stage_count; ++s) run_stage<V>(a, a.stages[s], true, begin, end);
    for (std::size_t j = begin; j < end; j += kLanes<V>) {
      if constexpr (kind == Pointwise::square) lanes.square(a.re + j, a.im + j);
      else if constexpr (kind == Pointwise::multiply) lanes.multiply(a.re + j, a.im + j, sre + j, sim + j);
      else if constexpr (kind == Pointwise::forward_only) lanes.forward(a.re + j, a.im + j);
      else lanes.inverse(a.re + j, a.im + j);
    }
    if (back)
      for (std::size_t s = a.stage_count; s-- > a.inner_from;) run_stage<V>(a, a.stages[s], false, begin, end);
  }
  if (back) outer_passes<V>(a, false);
}

// The passes forward, the pointwise square, the passes back, on a.re/a.im.
template <class V, class I>
TK_INLINE void passes(const Arrays& a) {
  const LanePasses<V, I> lanes;
  run_passes<V, I, Pointwise::square>(a, lanes);
}

// The split passes compute the lanes' twiddles once (static): the
// transforms they serve are short, and called several times a bit.
// forward_passes leaves the spectrum in the order inverse_passes takes.
template <class V, class I>
TK_INLINE void forward_passes(const Arrays& a) {
  static const LanePasses<V, I> lanes;
  run_passes<V, I, Pointwise::forward_only>(a, lanes);
}

template <class V, class I>
TK_INLINE void inverse_passes(const Arrays& a) {
  static const LanePasses<V, I> lanes;
  run_passes<V, I, Pointwise::inverse_only>(a, lanes);
}

// passes() with a product by a stored spectrum in place of the square.
template <class V, class I>
TK_INLINE void multiply_passes(const Arrays& a, const double* sre, const double* sim) {
  static const LanePasses<V, I> lanes;
  run_passes<V, I, Pointwise::multiply>(a, lanes, sre, sim);
}

template <class V>
TK_INLINE void pointwise(const Arrays& a, const double* sre, const double* sim) {
  for (std::size_t j = 0; j < a.half; j += kLanes<V>) {
    V r = load<V>(a.re + j), m = load<V>(a.im + j);
    times(r, m, load<V>(sre + j), load<V>(sim + j));
    store(a.re + j, r);
    store(a.im + j, m);
  }
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

#define TK_AVX512 __attribute__((target("avx512f,avx512dq,fma")))
#define TK_AVX2 __attribute__((target("avx2,fma")))

TK_AVX512 void forward_avx512(const Arrays& arrays) { forward_passes<v8d, v8i>(arrays); }
TK_AVX2 void forward_avx2(const Arrays& arrays) { forward_passes<v4d, v4i>(arrays); }
TK_AVX512 void inverse_avx512(const Arrays& arrays) { inverse_passes<v8d, v8i>(arrays); }
TK_AVX2 void inverse_avx2(const Arrays& arrays) { inverse_passes<v4d, v4i>(arrays); }
TK_AVX512 void multiply_avx512(const Arrays& arrays, const double* re, const double* im) {
  multiply_passes<v8d, v8i>(arrays, re, im);
}
TK_AVX2 void multiply_avx2(const Arrays& arrays, const double* re, const double* im) {
  multiply_passes<v4d, v4i>(arrays, re, im);
}
TK_AVX512 void pointwise_avx512(const Arrays& arrays, const double* re, const double* im) {
  pointwise<v8d>(arrays, re, im);
}
TK_AVX2 void pointwise_avx2(const Arrays& arrays, const double* re, const double* im) {
  pointwise<v4d>(arrays, re, im);
}

// ---- One square split over threads (RightAngleSquarer's split passes) ----

namespace {

// The outer passes (blocks larger than the inner block Q) on the columns
// whose index modulo Q is in [from, to): every point such a pass reads or
// writes has its index modulo Q in that window too, so a thread that owns
// the window runs all outer passes with no barrier between them.
template <class V, class I>
TK_INLINE void outer_columns(const Arrays& a, bool forward, std::size_t from, std::size_t to) {
  const std::size_t period = a.inner_block;
  auto one = [&](const RightAngleSquarer::Stage& stage, bool from_digits) __attribute__((always_inline)) {
    const std::size_t q = stage.block / static_cast<std::size_t>(stage.radix);
    for (std::size_t u = 0; u < q; u += period) {
      const Columns columns{u + from, u + to};
      if (from_digits) run_first_stage_from_digits<V, I>(a, 0, a.half, columns);
      else run_stage<V>(a, stage, forward, 0, a.half, columns);
    }
  };
  if (forward)
    for (std::size_t s = 0; s < a.inner_from; ++s) one(a.stages[s], s == 0 && a.digits);
  else
    for (std::size_t s = a.inner_from; s-- > 0;) one(a.stages[s], false);
}

// The inner passes, pointwise square and inverse inner passes of inner
// blocks [first, last): independent of every other block.
template <class V, class I>
TK_INLINE void inner_blocks(const Arrays& a, std::size_t first, std::size_t last) {
  const LanePasses<V, I> lanes;
  for (std::size_t begin = first * a.inner_block; begin < last * a.inner_block; begin += a.inner_block) {
    const std::size_t end = begin + a.inner_block;
    for (std::size_t s = a.inner_from; s < a.stage_count; ++s) {
      if (s == 0 && a.digits) run_first_stage_from_digits<V, I>(a, begin, end);
      else run_stage<V>(a, a.stages[s], true, begin, end);
    }
    for (std::size_t j = begin; j < end; j += kLanes<V>) lanes.square(a.re + j, a.im + j);
    for (std::size_t s = a.stage_count; s-- > a.inner_from;) run_stage<V>(a, a.stages[s], false, begin, end);
  }
}

}  // namespace

__attribute__((target("avx512f,avx512dq,fma"))) void outer_columns_avx512(const Arrays& arrays, bool forward,
                                                                          std::size_t from, std::size_t to) {
  outer_columns<v8d, v8i>(arrays, forward, from, to);
}
__attribute__((target("avx2,fma"))) void outer_columns_avx2(const Arrays& arrays, bool forward, std::size_t from,
                                                            std::size_t to) {
  outer_columns<v4d, v4i>(arrays, forward, from, to);
}
__attribute__((target("avx512f,avx512dq,fma"))) void inner_blocks_avx512(const Arrays& arrays, std::size_t first,
                                                                         std::size_t last) {
  inner_blocks<v8d, v8i>(arrays, first, last);
}
__attribute__((target("avx2,fma"))) void inner_blocks_avx2(const Arrays& arrays, std::size_t first, std::size_t last) {
  inner_blocks<v4d, v4i>(arrays, first, last);
}

}  // namespace tk::primes::right_angle
