/// @file weighted_squaring_split.cpp
/// @brief WeightedSquaring's squaring split over threads (ProofThreads),
/// digit for digit the one-thread squaring's. Points split by their index
/// modulo the transform's inner block Q (RightAngleSquarer::split_period):
/// a thread weighs its points into the input and runs the outer forward
/// passes on them with no barrier; after a barrier the inner blocks are
/// shared out; after another the thread runs the outer inverse passes on
/// its points and rounds them, its sums mod 2^61-1 added up afterwards. The
/// two halves of the coefficients carry at once on two threads; the
/// multiplication by k is split in ranges into a second array (so no
/// thread reads a digit another has overwritten), and its carry by the
/// parallel carry (balance_digits_split); the fold and the top digits stay
/// on one thread.
#include <algorithm>
#include <chrono>
#include <cstdlib>

#include "primes/proof_threads.hpp"
#include "primes/right_angle_transform.hpp"
#include "primes/weighted_passes.hpp"
#include "primes/weighted_squaring.hpp"
#include "primes/weighted_squaring_detail.hpp"

namespace tk::primes {

using namespace weighted_detail;

namespace {

// Below this transform length a second thread did not pay (bench_riesel's
// split table, riesel(1)).
constexpr std::size_t kSplitFromLength = 16384;

// Paced splits: a trial of this many squarings each way, then this many
// squarings the faster way (the trials cost a few percent at worst).
constexpr std::int64_t kTrialSquares = 32, kStretchSquares = 2048, kLongestStretch = 65536;

}  // namespace

std::size_t WeightedSquaring::split_from_length() {
  static const std::size_t from = [] {
    const char* set = std::getenv("TOOLKIT_PROOF_THREADS_FROM");
    return set && *set ? static_cast<std::size_t>(std::strtoull(set, nullptr, 10)) : kSplitFromLength;
  }();
  return from;
}

unsigned WeightedSquaring::threads() const { return threads_ ? threads_->count() : 1; }

bool WeightedSquaring::use_threads(unsigned count, bool paced) {
  weigh_pending();
  paced_ = paced;
  split_active_ = true;
  pace_left_ = 0;
  pace_phase_ = 2;  // the first squaring starts a split trial
  stretch_ = kStretchSquares;
  if (count <= 1 || !right_angle_) {
    threads_.reset();
    return false;
  }
  if (!threads_ || threads_->count() != count) threads_ = std::make_unique<ProofThreads>(count);
  product_.assign(digit_.size(), 0);
  rounded_parts_.assign(count, RoundedCoefficients{});
  carry_exchange_ = CarryExchange(count);
  return true;
}

// Trial on `split`, trial on one thread, stretch the faster way, again;
// each lost trial doubles the stretch (the trials cost most where the
// split loses, on a busy machine), each won one resets it.
void WeightedSquaring::pace() {
  if (!paced_ || pace_left_-- > 0) return;
  const double now = std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
  pace_phase_ = (pace_phase_ + 1) % 3;
  if (pace_phase_ == 0) {  // a split trial
    split_active_ = true;
    pace_left_ = kTrialSquares;
  } else if (pace_phase_ == 1) {  // a one-thread trial
    split_seconds_ = now - pace_mark_;
    split_active_ = false;
    pace_left_ = kTrialSquares;
  } else {  // a gain worth a second core, or one thread for longer
    split_active_ = split_seconds_ < 0.95 * (now - pace_mark_);
    stretch_ = split_active_ ? kStretchSquares : std::min(2 * stretch_, kLongestStretch);
    pace_left_ = stretch_;
  }
  --pace_left_;
  pace_mark_ = now;
}

void WeightedSquaring::weigh_pending() {
  if (!weights_pending_) return;
  const FoldTarget target{
      digit_.data(), right_angle_->real(), re_weight_.data(), right_angle_->imaginary(), im_weight_.data(), wide_};
  weigh_columns(target, digits_, length_ / 2, length_ / 2, 0, length_ / 2);
  weights_pending_ = false;
}

// One parallel step a square: the threads meet at barriers only where a
// stage needs what others wrote, and the workers never wait between two
// steps for longer than the caller's few checks.
bool WeightedSquaring::square_and_reduce_split(unsigned long minus) {
  ProofThreads& threads = *threads_;
  RightAngleSquarer& transform = *right_angle_;
  const unsigned parts = threads.count();
  const std::size_t half = length_ / 2, m = low_digits_, period = transform.split_period();
  const std::size_t lanes = static_cast<std::size_t>(transform.lanes()), blocks = transform.inner_blocks();
  std::int64_t* z = coefficient_.data();
  std::int64_t* product = product_.data();
  const std::uint8_t* bits = bits_.data();
  const std::int64_t c = form_.c;
  const RightAngleWeights weights{round_a_.data(), round_b_.data(), round_c_.data(), round_d_.data()};
  const FoldTarget target{digit_.data(),         transform.real(),  re_weight_.data(),
                          transform.imaginary(), im_weight_.data(), wide_};
  const SplitK split{k_low_, k_high_, static_cast<unsigned>(max_digit_bits_)};
  const bool weigh = weights_pending_;
  const unsigned high_part = std::min(1u, parts - 1);  // carries the upper half while part 0 carries the lower
  RoundedCoefficients rounded;
  bool checked = false;
  std::int64_t low_carry = 0, high_carry = 0, carry = 0;
  threads.run([&](unsigned part) {
    const std::size_t from = share(period / lanes, part, parts) * lanes;
    const std::size_t to = share(period / lanes, part + 1, parts) * lanes;
    if (weigh) weigh_columns(target, digits_, half, period, from, to);
    transform.outer_passes(true, from, to);
    threads.barrier();
    transform.inner_passes(share(blocks, part, parts), share(blocks, part + 1, parts));
    threads.barrier();
    transform.outer_passes(false, from, to);
    rounded_parts_[part] = round_right_angle_columns(transform.real(), transform.imaginary(), weights, rotation_.data(),
                                                     z, half, m, period, from, to, wide_);
    threads.barrier();
    // The two halves carry at once, each by the one-thread pass (their
    // digits are scratch until the checks pass).
    if (part == 0) {
      rounded = rounded_parts_[0];
      for (unsigned other = 1; other < parts; ++other) rounded = combine(rounded, rounded_parts_[other]);
      checked = rounding_checks_out(rounded);
      if (checked) low_carry = balance_digits(z, bits, m, carry_enough(), wide_);
    }
    if (part == high_part) high_carry = balance_digits(z + m, bits + m, coefficients_ - m, carry_enough(), wide_);
    threads.barrier();
    if (!checked || high_carry != 0) return;
    // By ranges into the second array: no part reads a digit another wrote.
    multiply_low_by_k_into(z, product, bits, m, share(m / 8, part, parts) * 8,
                           part + 1 == parts ? m : share(m / 8, part + 1, parts) * 8, split, c < 0, wide_);
    threads.barrier();                           // the carries' ranges are not the multiplication's
    if (part == 0) product[0] -= c * low_carry;  // digit 0 is part 0's in the carries
    const std::int64_t out =
        balance_digits_split(product, bits, m, kProductCarryEnough, wide_, threads, part, carry_exchange_);
    if (part == 0) carry = out;
  });
  weights_pending_ = false;
  if (!checked || high_carry != 0) return false;
  return fold_product(carry, rounded, low_carry, minus);  // weighted at the next square's start, by every thread
}

}  // namespace tk::primes
