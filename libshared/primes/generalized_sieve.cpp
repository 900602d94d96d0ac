/// @file generalized_sieve.cpp
#include "primes/generalized_sieve.hpp"

#include <primesieve.hpp>

#include <algorithm>
#include <atomic>
#include <bit>

#include "concurrency/ordered_pool.hpp"
#include "io/error.hpp"

namespace tk::primes {

namespace {

/// Workers read the bitmap while the calling thread clears bits in it.
inline bool bit_is_set(std::uint64_t* words, std::uint64_t offset) {
  return (std::atomic_ref<std::uint64_t>(words[offset >> 6]).load(std::memory_order_relaxed) >> (offset & 63)) & 1;
}

}  // namespace

GeneralizedSieve::GeneralizedSieve(const SieveSpec& spec)
    : spec_(spec),
      roots_(spec),
      members_(spec.members()),
      count_(spec.count()),
      small_bound_(std::min(spec.p_max, kSmallPrimeBound)),
      block_count_(spec.p_max > small_bound_ ? (spec.p_max - small_bound_ + kBlockWidth - 1) / kBlockWidth : 0),
      small_exponents_(spec.n < 64),
      bits_((count_ + 63) / 64),
      survivors_(count_) {}

std::uint64_t GeneralizedSieve::settled_count() const {
  return small_done_ ? count_ : std::min(count_, next_segment_ * kSegmentBits);
}

std::uint64_t GeneralizedSieve::block_high(std::uint64_t block) const {
  return std::min(spec_.p_max, block_low(block) + kBlockWidth - 1);
}

std::uint64_t GeneralizedSieve::sieved_to() const {
  if (!small_done_) return 0;
  return next_block_ == 0 ? small_bound_ : block_high(next_block_ - 1);
}

void GeneralizedSieve::restore(SieveBitmap bitmap, std::uint64_t next_segment, std::uint64_t next_block) {
  const std::uint64_t segments = segment_count();
  if (next_block > block_count_ || next_segment > segments || (next_segment < segments && next_block > 0) ||
      bitmap.size() != bits_.size())
    throw Error(
        "checkpoint does not fit this run (its segment or block of primes or its candidate count is out of range)");
  bits_ = std::move(bitmap);
  next_segment_ = next_segment;
  next_block_ = next_block;
  small_done_ = next_segment == segments;
  survivors_ = count_survivors() + (count_ - settled_count());
}

std::uint64_t GeneralizedSieve::count_survivors() const {
  std::uint64_t total = 0;
  for_each_survivor([&](std::uint64_t) { ++total; });
  return total;
}

bool GeneralizedSieve::candidate_is(std::uint64_t offset, std::uint32_t member, std::uint64_t p) const {
  const std::uint64_t e = spec_.n + members_[member].exponent_offset;
  if (e >= 64) return false;
  const std::uint64_t k = spec_.k_at(spec_.x_min + offset);
  const int c = members_[member].c;
  const std::uint64_t without_c = c < 0 ? p + 1 : p - 1;  // k*2^e
  return (without_c >> e) == k && (without_c & ((std::uint64_t(1) << e) - 1)) == 0;
}

GeneralizedSieve::SegmentResult GeneralizedSieve::sieve_segment(std::uint64_t segment,
                                                                const std::vector<std::uint32_t>& primes,
                                                                const std::vector<std::uint64_t>& roots, bool record) {
  SegmentResult result;
  std::vector<SieveFactor>& factors = result.factors;
  const std::uint64_t start = segment * kSegmentBits;
  const std::uint64_t length = std::min(kSegmentBits, count_ - start);
  std::uint64_t* words = bits_.data() + start / 64;  // this segment's words belong to this job alone
  const std::size_t word_count = static_cast<std::size_t>((length + 63) / 64);
  std::fill(words, words + word_count, ~std::uint64_t(0));
  if (length % 64) words[word_count - 1] = (std::uint64_t(1) << (length % 64)) - 1;
  const std::size_t width = members_.size();
  for (std::size_t i = 0; i < primes.size(); ++i) {
    const std::uint64_t p = primes[i];
    const std::uint64_t start_mod = start % p;
    for (std::size_t m = 0; m < width; ++m) {
      const std::uint64_t root = roots[i * width + m];
      if (root == SieveRootFinder::kNoRoot) continue;
      std::uint64_t o = root >= start_mod ? root - start_mod : root + p - start_mod;
      for (; o < length; o += p) {
        const std::uint64_t mask = std::uint64_t(1) << (o & 63);
        if (!(words[o >> 6] & mask)) continue;
        if (small_exponents_ && candidate_is(start + o, static_cast<std::uint32_t>(m), p)) continue;
        words[o >> 6] &= ~mask;
        if (record) factors.push_back({start + o, p, static_cast<std::uint32_t>(m)});
      }
    }
  }
  for (std::size_t w = 0; w < word_count; ++w) result.survivors += static_cast<std::uint64_t>(std::popcount(words[w]));
  return result;
}

void GeneralizedSieve::sieve_small_primes(const SieveControl& control) {
  if (small_done_) return;
  std::vector<std::uint64_t> wide_primes;
  primesieve::generate_primes(3, small_bound_, &wide_primes);
  std::vector<std::uint64_t> roots(wide_primes.size() * members_.size());
  roots_.find(wide_primes.data(), wide_primes.size(), roots.data());
  const std::vector<std::uint32_t> primes(wide_primes.begin(), wide_primes.end());  // below 2^20: halves the cache use

  const bool record = static_cast<bool>(control.on_factor);
  const std::uint64_t segments = segment_count();
  // Segments are settled in order, so the settled ones are always a prefix
  // that a checkpoint can hold.
  OrderedPool<std::uint64_t, SegmentResult> pool(
      control.threads, [&](std::uint64_t& segment) { return sieve_segment(segment, primes, roots, record); },
      [&](SegmentResult& result) {
        for (const SieveFactor& factor : result.factors) control.on_factor(factor);
        const std::uint64_t length = std::min(kSegmentBits, count_ - next_segment_ * kSegmentBits);
        survivors_ -= length - result.survivors;
        ++next_segment_;
        if (control.after_segment) control.after_segment(next_segment_, segments);
      },
      2 * static_cast<std::size_t>(control.threads));
  for (std::uint64_t job = next_segment_; job < segments; ++job) {
    if (control.should_stop && control.should_stop()) break;
    pool.submit(job);
  }
  pool.finish();
  small_done_ = next_segment_ == segments;
}

std::optional<std::vector<SieveFactor>> GeneralizedSieve::sieve_block(std::uint64_t block,
                                                                      const std::function<bool()>& stop) {
  if (stop && stop()) return std::nullopt;  // queued before the stop: not worth starting
  thread_local std::vector<std::uint64_t> primes, roots;
  primes.clear();
  primesieve::generate_primes(block_low(block), block_high(block), &primes);
  const std::size_t width = members_.size();
  roots.resize(primes.size() * width);
  roots_.find(primes.data(), primes.size(), roots.data());
  std::vector<SieveFactor> factors;
  std::uint64_t* words = bits_.data();
  // With a huge bitmap one block is minutes of work: look for a stop every
  // 2^20 or so steps through the bitmap (at most a few tenths of a second of
  // cache misses on a bitmap of gigabytes).
  constexpr std::uint64_t kStepsBetweenChecks = std::uint64_t(1) << 20;
  std::uint64_t steps = 0;
  for (std::size_t i = 0; i < primes.size(); ++i) {
    const std::uint64_t p = primes[i];
    steps += width * (count_ / p + 1);
    if (steps >= kStepsBetweenChecks) {
      steps = 0;
      if (stop && stop()) return std::nullopt;
    }
    for (std::size_t m = 0; m < width; ++m) {
      const std::uint64_t root = roots[i * width + m];
      if (root == SieveRootFinder::kNoRoot) continue;
      for (std::uint64_t o = root; o < count_; o += p) {
        if (!bit_is_set(words, o)) continue;
        if (small_exponents_ && candidate_is(o, static_cast<std::uint32_t>(m), p)) continue;
        factors.push_back({o, p, static_cast<std::uint32_t>(m)});
      }
    }
  }
  return factors;
}

bool GeneralizedSieve::sieve_large_primes(const SieveControl& control) {
  if (!small_done_) sieve_small_primes(control);
  if (!small_done_) return false;
  struct BlockResult {
    std::uint64_t block;
    std::optional<std::vector<SieveFactor>> factors;  ///< none: cut short by a stop
  };
  std::uint64_t* words = bits_.data();
  bool cut_short = false;  // a block was dropped: no later block may count as done
  OrderedPool<std::uint64_t, BlockResult> pool(
      control.threads,
      [&](std::uint64_t& block) {
        return BlockResult{block, sieve_block(block, control.should_stop)};
      },
      [&](BlockResult& result) {
        if (cut_short || !result.factors) {
          cut_short = true;
          return;
        }
        for (const SieveFactor& factor : *result.factors) {
          std::atomic_ref<std::uint64_t> word(words[factor.offset >> 6]);
          const std::uint64_t mask = std::uint64_t(1) << (factor.offset & 63);
          const std::uint64_t value = word.load(std::memory_order_relaxed);
          if (!(value & mask)) continue;  // an earlier prime removed it already
          word.store(value & ~mask, std::memory_order_relaxed);
          --survivors_;
          if (control.on_factor) control.on_factor(factor);
        }
        next_block_ = result.block + 1;
        if (control.after_block) control.after_block();
      });
  bool stopped = false;
  for (std::uint64_t block = next_block_; block < block_count_; ++block) {
    if (block % control.shard_count != control.shard_index) continue;
    if (control.should_stop && control.should_stop()) {
      stopped = true;
      break;
    }
    pool.submit(block);
  }
  pool.finish();
  stopped = stopped || cut_short;
  if (!stopped) next_block_ = block_count_;
  return !stopped;
}

}  // namespace tk::primes
