/// @file generalized_sieve.hpp
/// @brief The generalized sieve of "Prime Hunting" (Farkas et al., after
/// Jarai): removes every x whose candidate k*2^e+c, for any member of the
/// form, has a prime factor up to the bound.
///
/// One bit per x marks the survivors. Primes up to kSmallPrimeBound sieve
/// it segment by segment (256 KiB at a time, so it stays in cache); larger
/// primes come in fixed blocks of the prime range, which worker threads
/// sieve against the bitmap while the calling thread applies the removals
/// in block order. That order makes the survivors, the factor list and the
/// checkpoints the same whatever the thread count, and lets --shard K/N
/// take every N-th block.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "primes/sieve_roots.hpp"
#include "primes/sieve_spec.hpp"

namespace tk::primes {

/// p divides member `member` of the candidate at x = x_min + offset.
struct SieveFactor {
  std::uint64_t offset;
  std::uint64_t p;
  std::uint32_t member;
};

/// Leaves new words uninitialised: each segment fills its own words when it is
/// sieved, so a huge bitmap is not written (and faulted in) all at once
/// before the first check for a stop.
template <class T>
struct UninitialisedAllocator : std::allocator<T> {
  template <class U>
  struct rebind {
    using other = UninitialisedAllocator<U>;
  };
  template <class U>
  void construct(U* at) noexcept {
    ::new (static_cast<void*>(at)) U;
  }
  template <class U, class... Args>
  void construct(U* at, Args&&... args) {
    ::new (static_cast<void*>(at)) U(std::forward<Args>(args)...);
  }
};

/// One bit per x; bits of segments not yet sieved are undefined.
using SieveBitmap = std::vector<std::uint64_t, UninitialisedAllocator<std::uint64_t>>;

struct SieveControl {
  unsigned threads = 1;
  unsigned shard_index = 0;  ///< 0-based
  unsigned shard_count = 1;
  /// Called on the calling thread, in a fixed order, for every removal.
  std::function<void(const SieveFactor&)> on_factor;
  /// Checked before each segment or block is started, and often while a
  /// block of large primes is sieved (on the worker threads too, so it must
  /// be safe to call from any thread); true stops the run cleanly (a block
  /// cut short is dropped and sieved again on resume).
  std::function<bool()> should_stop;
  /// Called on the calling thread after each block's removals are applied.
  std::function<void()> after_block;
  /// Called on the calling thread as small-prime segments finish (done, total).
  std::function<void(std::uint64_t, std::uint64_t)> after_segment;
};

class GeneralizedSieve {
 public:
  static constexpr std::uint64_t kSmallPrimeBound = std::uint64_t(1) << 20;
  static constexpr std::uint64_t kBlockWidth = std::uint64_t(1) << 22;  ///< primes per block span this much
  static constexpr std::uint64_t kSegmentBits = std::uint64_t(1) << 21;

  explicit GeneralizedSieve(const SieveSpec& spec);

  const SieveSpec& spec() const { return spec_; }
  std::uint64_t survivors() const { return survivors_; }
  std::uint64_t small_prime_bound() const { return small_bound_; }
  std::uint64_t block_count() const { return block_count_; }
  std::uint64_t next_block() const { return next_block_; }
  bool small_primes_done() const { return small_done_; }
  /// Segments of x (kSegmentBits each, in order) that the small primes have sieved.
  std::uint64_t next_segment() const { return next_segment_; }
  /// Candidates x_min .. x_min + settled_count() - 1 have their bits defined
  /// (all of them once the small primes are done).
  std::uint64_t settled_count() const;
  bool finished() const { return small_done_ && next_block_ >= block_count_; }
  /// The largest prime whose removals are all applied (for this shard).
  std::uint64_t sieved_to() const;
  std::uint64_t block_low(std::uint64_t block) const { return small_bound_ + 1 + block * kBlockWidth; }
  std::uint64_t block_high(std::uint64_t block) const;

  const SieveBitmap& bitmap() const { return bits_; }
  /// State from a checkpoint: the bitmap after the small primes of the
  /// segments before next_segment and the blocks before next_block (none
  /// unless every segment is done); bits past the settled ones are ignored.
  void restore(SieveBitmap bitmap, std::uint64_t next_segment, std::uint64_t next_block);

  /// Sieves with the small primes, from next_segment() on; should_stop may
  /// end it early, leaving small_primes_done() false.
  void sieve_small_primes(const SieveControl& control);
  /// Sieves the remaining blocks of this shard; false when should_stop ended it early.
  bool sieve_large_primes(const SieveControl& control);

  /// Calls f(offset) for every surviving settled x = x_min + offset, in increasing order.
  template <class F>
  void for_each_survivor(F&& f) const {
    const std::size_t settled_words = static_cast<std::size_t>((settled_count() + 63) / 64);
    for (std::size_t w = 0; w < settled_words; ++w)
      for (std::uint64_t word = bits_[w]; word; word &= word - 1)
        f(static_cast<std::uint64_t>(w) * 64 + static_cast<std::uint64_t>(__builtin_ctzll(word)));
  }

 private:
  /// True when the candidate itself is p (only possible for small n): p is not its proper factor.
  bool candidate_is(std::uint64_t offset, std::uint32_t member, std::uint64_t p) const;
  struct SegmentResult {
    std::vector<SieveFactor> factors;
    std::uint64_t survivors = 0;
  };
  SegmentResult sieve_segment(std::uint64_t segment, const std::vector<std::uint32_t>& primes,
                              const std::vector<std::uint64_t>& roots, bool record);
  /// The block's removals; nothing when `stop` said so before it was done.
  std::optional<std::vector<SieveFactor>> sieve_block(std::uint64_t block, const std::function<bool()>& stop);
  std::uint64_t count_survivors() const;
  std::uint64_t segment_count() const { return (count_ + kSegmentBits - 1) / kSegmentBits; }

  SieveSpec spec_;
  SieveRootFinder roots_;
  std::vector<SieveMember> members_;
  std::uint64_t count_;
  std::uint64_t small_bound_;
  std::uint64_t block_count_;
  bool small_exponents_;  ///< some member's exponent is below 64
  SieveBitmap bits_;
  std::uint64_t survivors_;
  std::uint64_t next_segment_ = 0;
  std::uint64_t next_block_ = 0;
  bool small_done_ = false;
};

}  // namespace tk::primes
