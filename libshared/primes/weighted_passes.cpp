/// @file weighted_passes.cpp
#include "primes/weighted_passes.hpp"

#include <algorithm>

#include "primes/cpu_features.hpp"
#include "primes/proof_threads.hpp"
#include "primes/weighted_carry_lanes.hpp"

namespace tk::primes {

namespace {

#define TK_WIDE __attribute__((target("avx512f,avx512dq,avx512vl,avx2,bmi,bmi2")))
#define TK_INLINE __attribute__((always_inline)) inline

// Balanced digits: digit in [-2^(s-1), 2^(s-1)), the rest carried up.
// Half of 2^s is added before the carry, so the chain is an add and a shift.
struct Balancer {
  std::int64_t* __restrict digit;
  const std::uint8_t* __restrict bits;

  TK_INLINE std::int64_t step(std::size_t j, std::int64_t carry) const {
    const unsigned s = bits[j];
    const std::int64_t total = digit[j] + (std::int64_t{1} << (s - 1));
    const std::int64_t up = (total + carry) >> s;
    digit[j] =
        total + carry - static_cast<std::int64_t>(static_cast<std::uint64_t>(up) << s) - (std::int64_t{1} << (s - 1));
    return up;
  }
  // Adds `carry` at digit `from` and carries it on until it is absorbed or
  // reaches `end` (then returned): two or three digits for a carry that
  // came from another chain.
  TK_INLINE std::int64_t absorb(std::size_t from, std::size_t end, std::int64_t carry) const {
    for (std::size_t j = from; carry != 0 && j < end; ++j) carry = step(j, carry);
    return carry;
  }
};

// The digits carry in kChains independent chains over as many stretches,
// interleaved (one chain is bound by its add-and-shift latency); each
// chain's last carry is then absorbed at the start of the next stretch.
// The value is the serial pass's; the digits are as balanced.
constexpr std::size_t kChains = 4;

TK_INLINE std::int64_t balance_chains(std::int64_t* __restrict digit, const std::uint8_t* __restrict bits,
                                      std::size_t count) {
  const Balancer balancer{digit, bits};
  const std::size_t stretch = count / kChains;
  std::int64_t carry[kChains] = {};
  for (std::size_t i = 0; i < stretch; ++i)
    for (std::size_t c = 0; c < kChains; ++c) carry[c] = balancer.step(c * stretch + i, carry[c]);
  for (std::size_t j = kChains * stretch; j < count; ++j) carry[kChains - 1] = balancer.step(j, carry[kChains - 1]);
  for (std::size_t c = 1; c < kChains; ++c) {
    const std::size_t end = c + 1 < kChains ? (c + 1) * stretch : count;
    carry[c] += balancer.absorb(c * stretch, end, carry[c - 1]);
  }
  return carry[kChains - 1];
}

// One lane pass (balance_lanes below) over the whole vectors of digits
// [begin, end), by CarryLanes, the step the fused passes also take: the
// first vector takes no carry in (the caller adds it); `last_up` gets the
// carry out of digit end - 1. Returns the largest carry moved.
TK_INLINE std::int64_t lanes_pass(std::int64_t* __restrict digit, const std::uint8_t* __restrict bits,
                                  std::size_t begin, std::size_t end, std::int64_t& last_up) {
  carry_lanes::CarryLanes carry;
  for (std::size_t j = begin; j < end; j += 8)
    carry_lanes::store(digit + j, carry.carried(carry_lanes::load(digit + j), bits + j));
  last_up = end > begin ? carry.last_up() : 0;
  return carry.most();
}

// The same pass on the digits past the whole vectors, one at a time;
// `carry` comes in and goes out. Returns the largest carry moved.
TK_INLINE std::int64_t tail_pass(std::int64_t* __restrict digit, const std::uint8_t* __restrict bits, std::size_t begin,
                                 std::size_t end, std::int64_t& carry) {
  std::int64_t tail_largest = 0;
  for (std::size_t j = begin; j < end; ++j) {
    const unsigned s = bits[j];
    const std::int64_t total = digit[j] + (std::int64_t{1} << (s - 1));
    const std::int64_t up = total >> s;
    digit[j] =
        total - static_cast<std::int64_t>(static_cast<std::uint64_t>(up) << s) - (std::int64_t{1} << (s - 1)) + carry;
    tail_largest = std::max(tail_largest, up < 0 ? -up : up);
    carry = up;
  }
  return tail_largest;
}

// The digits balanced in lanes, eight at a time, by passes that each move
// every digit's excess over [-2^(s-1), 2^(s-1)) one digit up at once (the
// carry a digit takes in is what its neighbour gave off before this
// pass). Each pass divides the excess by about 2^s; passes run until no
// carry exceeds `enough` (2^51 to 1 in three passes at s = 20), while the
// scalar chain is bound by its add-and-shift latency. The value is the
// same; returns the carry out of the last digit.
TK_WIDE std::int64_t balance_lanes(std::int64_t* __restrict digit, const std::uint8_t* __restrict bits,
                                   std::size_t count, std::int64_t enough) {
  const std::size_t whole = count / 8 * 8;
  std::int64_t carried_out = 0;
  for (int pass = 0; pass < 64; ++pass) {
    std::int64_t carry = 0;
    const std::int64_t largest = lanes_pass(digit, bits, 0, whole, carry);
    const std::int64_t tail_largest = tail_pass(digit, bits, whole, count, carry);
    carried_out += carry;
    if (std::max(largest, tail_largest) <= enough) break;
  }
  return carried_out;
}

TK_INLINE std::int64_t scaled_high(const SplitK& k, std::int64_t previous, unsigned previous_bits) {
  return static_cast<std::int64_t>(static_cast<std::uint64_t>(k.high * previous) << (k.bits - previous_bits));
}

// The scalar multiplication by k, on the old values kept as it goes.
TK_INLINE void multiply_body(std::int64_t* __restrict d, const std::uint8_t* __restrict bits, std::size_t from,
                             std::size_t m, const SplitK& k, bool add_upper, std::int64_t previous) {
  for (std::size_t j = from; j < m; ++j) {
    const std::int64_t old = d[j], upper = d[j + m];
    const std::int64_t high = j > 0 ? scaled_high(k, previous, bits[j - 1]) : 0;
    d[j] = k.low * old + (add_upper ? upper : -upper) + high;
    previous = old;
  }
}

// In place: a vector's old digits are read before it is written.
TK_WIDE void multiply_lanes(std::int64_t* __restrict d, const std::uint8_t* __restrict bits, std::size_t m,
                            const SplitK& k, bool add_upper) {
  const std::size_t whole = m / 8 * 8;
  const std::int64_t tail_previous = whole > 0 ? d[whole - 1] : 0;
  carry_lanes::ProductLanes products(k);
  for (std::size_t j = 0; j < whole; j += 8) carry_lanes::store(d + j, products.next(d, bits, j, m, add_upper));
  multiply_body(d, bits, whole, m, k, add_upper, tail_previous);
}

// multiply_lanes into `out`, each vector of products carried by the lane
// pass before it is stored (tail_pass's serial form for the digits past
// the whole vectors): multiply_low_by_k, then the first pass of
// balance_lanes, in one sweep.
TK_WIDE std::int64_t multiply_carry_lanes(const std::int64_t* __restrict d, std::int64_t* __restrict out,
                                          const std::uint8_t* __restrict bits, std::size_t m, const SplitK& k,
                                          bool add_upper, std::int64_t add_at_zero, std::int64_t& carry_out) {
  const std::size_t whole = m / 8 * 8;
  carry_lanes::ProductLanes products(k);
  carry_lanes::CarryLanes carry;
  carry_lanes::Lanes at_zero{};
  at_zero[0] = add_at_zero;
  for (std::size_t j = 0; j < whole; j += 8) {
    const carry_lanes::Lanes product = products.next(d, bits, j, m, add_upper);
    carry_lanes::store(out + j, carry.carried(j == 0 ? product + at_zero : product, bits + j));
  }
  std::int64_t up = whole > 0 ? carry.last_up() : 0;
  std::int64_t largest = whole > 0 ? carry.most() : 0;
  for (std::size_t j = whole; j < m; ++j) {
    std::int64_t product = k.low * d[j] + (add_upper ? d[j + m] : -d[j + m]);
    product += j > 0 ? scaled_high(k, d[j - 1], bits[j - 1]) : add_at_zero;
    out[j] = product;
    largest = std::max(largest, tail_pass(out, bits, j, j + 1, up));
  }
  carry_out = up;
  return largest;
}

// The top digits hold only what carries in (`up`); the last takes what is
// left, unbalanced.
TK_INLINE void balance_top(std::int64_t* __restrict digit, const std::uint8_t* __restrict bits, std::size_t low_digits,
                           std::size_t digits, std::int64_t up) {
  const Balancer balancer{digit, bits};
  for (std::size_t j = low_digits; j + 1 < digits; ++j) {
    digit[j] = 0;
    up = balancer.step(j, up);
  }
  digit[digits - 1] = up;
}

// Copies the low digits and weighs every digit (vectorised where the CPU
// converts int64 lanes).
TK_INLINE void write_body(const std::int64_t* __restrict low, const FoldTarget& target,
                          const std::uint8_t* __restrict bits, std::size_t low_digits, std::size_t digits,
                          std::int64_t top) {
  std::int64_t* __restrict digit = target.digits;
  balance_top(digit, bits, low_digits, digits, top);
  double* __restrict re = target.re;
  const double* __restrict re_weight = target.re_weight;
  if (target.im) {
    double* __restrict im = target.im;
    const double* __restrict im_weight = target.im_weight;
    for (std::size_t j = 0; j < low_digits; ++j) {
      const std::int64_t value = low[j];
      digit[j] = value;
      re[j] = static_cast<double>(value) * re_weight[j];
      im[j] = static_cast<double>(value) * im_weight[j];
    }
    for (std::size_t j = low_digits; j < digits; ++j) {
      re[j] = static_cast<double>(digit[j]) * re_weight[j];
      im[j] = static_cast<double>(digit[j]) * im_weight[j];
    }
    return;
  }
  for (std::size_t j = 0; j < low_digits; ++j) {
    const std::int64_t value = low[j];
    digit[j] = value;
    re[j] = static_cast<double>(value) * re_weight[j];
  }
  for (std::size_t j = low_digits; j < digits; ++j) re[j] = static_cast<double>(digit[j]) * re_weight[j];
}

#define TK_WRITE_ARGS                                                                                  \
  const std::int64_t *low, const FoldTarget &target, const std::uint8_t *bits, std::size_t low_digits, \
      std::size_t digits, std::int64_t top
TK_WIDE void write_avx512(TK_WRITE_ARGS) { write_body(low, target, bits, low_digits, digits, top); }
__attribute__((target("avx2,bmi,bmi2"))) void write_fast(TK_WRITE_ARGS) {
  write_body(low, target, bits, low_digits, digits, top);
}
void write_portable(TK_WRITE_ARGS) { write_body(low, target, bits, low_digits, digits, top); }
#undef TK_WRITE_ARGS

__attribute__((target("avx2,bmi,bmi2"))) std::int64_t chains_fast(std::int64_t* digit, const std::uint8_t* bits,
                                                                  std::size_t count) {
  return balance_chains(digit, bits, count);
}
std::int64_t chains_portable(std::int64_t* digit, const std::uint8_t* bits, std::size_t count) {
  return balance_chains(digit, bits, count);
}

}  // namespace

std::int64_t balance_digits(std::int64_t* digit, const std::uint8_t* bits, std::size_t count, std::int64_t enough,
                            bool wide) {
  if (wide && cpu::has_avx512()) return balance_lanes(digit, bits, count, std::max<std::int64_t>(enough, 1));
  return cpu::has_avx2() ? chains_fast(digit, bits, count) : chains_portable(digit, bits, count);
}

void multiply_low_by_k(std::int64_t* d, const std::uint8_t* bits, std::size_t m, const SplitK& k, bool add_upper,
                       bool wide) {
  if (wide && cpu::has_avx512()) multiply_lanes(d, bits, m, k, add_upper);
  else multiply_body(d, bits, 0, m, k, add_upper, 0);
}

std::int64_t multiply_and_carry(const std::int64_t* d, std::int64_t* out, const std::uint8_t* bits, std::size_t m,
                                const SplitK& k, bool add_upper, std::int64_t add_at_zero, std::int64_t& carry_out) {
  return multiply_carry_lanes(d, out, bits, m, k, add_upper, add_at_zero, carry_out);
}

std::int64_t absorb_at_bottom(std::int64_t* digit, const std::uint8_t* bits, std::size_t end, std::int64_t carry) {
  return Balancer{digit, bits}.absorb(0, end, carry);
}

void write_input(const std::int64_t* low, const FoldTarget& target, const std::uint8_t* bits, std::size_t low_digits,
                 std::size_t digits, std::int64_t top) {
  if (cpu::has_avx512() && target.wide) write_avx512(low, target, bits, low_digits, digits, top);
  else if (cpu::has_avx2()) write_fast(low, target, bits, low_digits, digits, top);
  else write_portable(low, target, bits, low_digits, digits, top);
}

// ---- One square split over threads ----

namespace {

TK_INLINE void multiply_into_body(const std::int64_t* __restrict d, std::int64_t* __restrict out,
                                  const std::uint8_t* __restrict bits, std::size_t m, std::size_t from, std::size_t to,
                                  const SplitK& k, bool add_upper) {
  if (from == 0 && to > 0) {
    out[0] = k.low * d[0] + (add_upper ? d[m] : -d[m]);
    from = 1;
  }
  if (add_upper)
    for (std::size_t j = from; j < to; ++j) out[j] = k.low * d[j] + d[j + m] + scaled_high(k, d[j - 1], bits[j - 1]);
  else
    for (std::size_t j = from; j < to; ++j) out[j] = k.low * d[j] - d[j + m] + scaled_high(k, d[j - 1], bits[j - 1]);
}

TK_INLINE void weigh_columns_body(const FoldTarget& target, std::size_t digits, std::size_t half, std::size_t period,
                                  std::size_t from, std::size_t to) {
  const std::int64_t* __restrict digit = target.digits;
  double* __restrict re = target.re;
  double* __restrict im = target.im;
  const double* __restrict re_weight = target.re_weight;
  const double* __restrict im_weight = target.im_weight;
  for (std::size_t base = 0; base < half; base += period) {
    const std::size_t end = std::min(base + to, digits);
    std::size_t j = base + from;
    for (; j < end; ++j) {
      re[j] = static_cast<double>(digit[j]) * re_weight[j];
      im[j] = static_cast<double>(digit[j]) * im_weight[j];
    }
    for (; j < base + to; ++j) re[j] = im[j] = 0.0;
  }
}

#define TK_MULTIPLY_ARGS                                                                                               \
  const std::int64_t *d, std::int64_t *out, const std::uint8_t *bits, std::size_t m, std::size_t from, std::size_t to, \
      const SplitK &k, bool add_upper
TK_WIDE void multiply_into_avx512(TK_MULTIPLY_ARGS) { multiply_into_body(d, out, bits, m, from, to, k, add_upper); }
void multiply_into_portable(TK_MULTIPLY_ARGS) { multiply_into_body(d, out, bits, m, from, to, k, add_upper); }
#undef TK_MULTIPLY_ARGS

#define TK_WEIGH_ARGS \
  const FoldTarget &target, std::size_t digits, std::size_t half, std::size_t period, std::size_t from, std::size_t to
TK_WIDE void weigh_avx512(TK_WEIGH_ARGS) { weigh_columns_body(target, digits, half, period, from, to); }
__attribute__((target("avx2,bmi,bmi2"))) void weigh_fast(TK_WEIGH_ARGS) {
  weigh_columns_body(target, digits, half, period, from, to);
}
#undef TK_WEIGH_ARGS

}  // namespace

void multiply_low_by_k_into(const std::int64_t* d, std::int64_t* out, const std::uint8_t* bits, std::size_t m,
                            std::size_t from, std::size_t to, const SplitK& k, bool add_upper, bool wide) {
  if (wide && cpu::has_avx512()) multiply_into_avx512(d, out, bits, m, from, to, k, add_upper);
  else multiply_into_portable(d, out, bits, m, from, to, k, add_upper);
}

void write_top_digits(std::int64_t* digit, const std::uint8_t* bits, std::size_t low_digits, std::size_t digits,
                      std::int64_t top) {
  balance_top(digit, bits, low_digits, digits, top);
}

// Only the right-angle transform is split, and it needs AVX2.
void weigh_columns(const FoldTarget& target, std::size_t digits, std::size_t half, std::size_t period, std::size_t from,
                   std::size_t to) {
  if (cpu::has_avx512() && target.wide) weigh_avx512(target, digits, half, period, from, to);
  else weigh_fast(target, digits, half, period, from, to);
}

namespace {

// The lanes' passes split: part p carries whole vectors [share(p), share(p + 1)),
// the last part also the digits past them.
TK_WIDE std::int64_t lanes_split(std::int64_t* digit, const std::uint8_t* bits, std::size_t count, std::int64_t enough,
                                 ProofThreads& threads, unsigned part, CarryExchange& exchange) {
  const unsigned parts = threads.count();
  const std::size_t vectors = count / 8, begin = share(vectors, part, parts) * 8;
  const std::size_t end = share(vectors, part + 1, parts) * 8;
  std::int64_t carried_out = 0;
  for (int pass = 0; pass < 64; ++pass) {
    std::int64_t up = 0;
    std::int64_t largest = lanes_pass(digit, bits, begin, end, up);
    if (part + 1 == parts) {
      largest = std::max(largest, tail_pass(digit, bits, vectors * 8, count, up));
      carried_out += up;
    }
    exchange.up[pass % 2][part] = up;
    exchange.largest[pass % 2][part] = largest;
    threads.barrier();
    // The carry the first digit missed: out of the range before, before this pass.
    if (part > 0) digit[begin] += exchange.up[pass % 2][part - 1];
    std::int64_t most = 0;
    for (unsigned other = 0; other < parts; ++other) most = std::max(most, exchange.largest[pass % 2][other]);
    if (most <= enough) break;
  }
  if (part + 1 == parts) exchange.chain_carry[0] = carried_out;
  threads.barrier();
  return exchange.chain_carry[0];
}

__attribute__((target("avx2,bmi,bmi2"))) void chain_fast(std::int64_t* digit, const std::uint8_t* bits,
                                                         std::size_t from, std::size_t to, std::int64_t& carry) {
  const Balancer balancer{digit, bits};
  for (std::size_t j = from; j < to; ++j) carry = balancer.step(j, carry);
}

// balance_chains's chains shared out (chain c to part c * parts / kChains),
// each the same as there; part 0 then absorbs them in order.
std::int64_t chains_split(std::int64_t* digit, const std::uint8_t* bits, std::size_t count, ProofThreads& threads,
                          unsigned part, CarryExchange& exchange) {
  const unsigned parts = threads.count();
  const std::size_t stretch = count / kChains;
  for (std::size_t c = 0; c < kChains; ++c) {
    if (c * parts / kChains != part) continue;
    exchange.chain_carry[c] = 0;
    chain_fast(digit, bits, c * stretch, c + 1 < kChains ? (c + 1) * stretch : count, exchange.chain_carry[c]);
  }
  threads.barrier();
  if (part != 0) return 0;
  const Balancer balancer{digit, bits};
  std::int64_t* carry = exchange.chain_carry;
  for (std::size_t c = 1; c < kChains; ++c) {
    const std::size_t end = c + 1 < kChains ? (c + 1) * stretch : count;
    carry[c] += balancer.absorb(c * stretch, end, carry[c - 1]);
  }
  return carry[kChains - 1];
}

}  // namespace

std::int64_t balance_digits_split(std::int64_t* digit, const std::uint8_t* bits, std::size_t count, std::int64_t enough,
                                  bool wide, ProofThreads& threads, unsigned part, CarryExchange& exchange) {
  if (count / 8 < threads.count()) {  // too few digits for a range each: part 0 carries them all
    const std::int64_t carry = part == 0 ? balance_digits(digit, bits, count, enough, wide) : 0;
    threads.barrier();
    return carry;
  }
  if (wide && cpu::has_avx512())
    return lanes_split(digit, bits, count, std::max<std::int64_t>(enough, 1), threads, part, exchange);
  return chains_split(digit, bits, count, threads, part, exchange);
}

}  // namespace tk::primes
