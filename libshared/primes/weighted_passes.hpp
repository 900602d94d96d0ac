/// @file weighted_passes.hpp
/// @brief WeightedSquaring's passes over the digits: balancing (carrying),
/// the multiplication by k that reduces the square, and the weighting into
/// the next transform's input. Free functions compiled for AVX-512 and
/// AVX2/BMI2 where the CPU has them (chosen at run time), else portable.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace tk::primes {

class ProofThreads;

/// Balances digit[0..count) (digit j has bits[j] bits): each digit's excess
/// over [-2^(s-1), 2^(s-1)) moves up until no digit carries more than
/// `enough` into the next (so |digit| <= 2^(s-1) + enough after), or fully
/// in one pass on the scalar path. The value is unchanged; returns the carry
/// out of the last digit. `wide`: AVX-512 lanes where the CPU has them.
std::int64_t balance_digits(std::int64_t* digit, const std::uint8_t* bits, std::size_t count, std::int64_t enough,
                            bool wide);

/// k = high * 2^bits + low, bits >= every digit's size, so each half times
/// a digit fits 64 bits.
struct SplitK {
  std::int64_t low = 0;
  std::int64_t high = 0;
  unsigned bits = 0;
};

/// In place, for j < m: d[j] := k*d[j] + sign*d[j+m], with k*d[j]'s high
/// half moved into d[j+1] (times 2^(bits - s_j), exact): so
/// d[j] = low*d[j] + sign*d[j+m] + high*d[j-1]*2^(bits - s_(j-1)), on the
/// old values. sign is +1 with add_upper, else -1. d[m..2m) are read only.
void multiply_low_by_k(std::int64_t* d, const std::uint8_t* bits, std::size_t m, const SplitK& k, bool add_upper,
                       bool wide);

/// AVX-512 only: out[j] for j < m = multiply_low_by_k's d[j] (d is only
/// read), plus `add_at_zero` at digit 0, then balance_digits' first lane
/// pass on out[0..m), in one sweep. Returns the largest carry moved;
/// `carry_out` gets the carry out of digit m - 1. Further passes, where
/// the largest carry calls for them, are the caller's.
std::int64_t multiply_and_carry(const std::int64_t* d, std::int64_t* out, const std::uint8_t* bits, std::size_t m,
                                const SplitK& k, bool add_upper, std::int64_t add_at_zero, std::int64_t& carry_out);

/// Adds `carry` to digit 0 and carries it on until it is absorbed or
/// reaches `end`; returns what is left (0 but for a freak value).
std::int64_t absorb_at_bottom(std::int64_t* digit, const std::uint8_t* bits, std::size_t end, std::int64_t carry);

/// Where the next transform's input goes: the integer digits, and each
/// digit times re_weight[j] into re[j] and, for the right-angle transform
/// (im not null), times im_weight[j] into im[j].
struct FoldTarget {
  std::int64_t* digits;
  double* re;
  const double* re_weight;
  double* im = nullptr;
  const double* im_weight = nullptr;
  bool wide = true;  ///< AVX-512 where the CPU has it
};

/// target.digits[j] = low[j] for j < low_digits; the digits from there up
/// the balanced digits of `top` (the last takes what is left); all of them
/// weighted into the input.
void write_input(const std::int64_t* low, const FoldTarget& target, const std::uint8_t* bits, std::size_t low_digits,
                 std::size_t digits, std::int64_t top);

// ---- One square split over threads ----

/// multiply_low_by_k's values for j in [from, to), written to out[j]
/// (d is only read, so parts of the digits can run at once).
void multiply_low_by_k_into(const std::int64_t* d, std::int64_t* out, const std::uint8_t* bits, std::size_t m,
                            std::size_t from, std::size_t to, const SplitK& k, bool add_upper, bool wide);

/// write_input's digits from `low_digits` up (the balanced digits of
/// `top`), without the weighting.
void write_top_digits(std::int64_t* digit, const std::uint8_t* bits, std::size_t low_digits, std::size_t digits,
                      std::int64_t top);

/// write_input's weighting of the digits (zero from `digits` on) for the
/// points j < half whose index modulo `period` is in [from, to).
void weigh_columns(const FoldTarget& target, std::size_t digits, std::size_t half, std::size_t period, std::size_t from,
                   std::size_t to);

/// What the parts of a split balance_digits hand each other.
struct CarryExchange {
  explicit CarryExchange(unsigned parts = 1)
      : up{std::vector<std::int64_t>(parts), std::vector<std::int64_t>(parts)},
        largest{std::vector<std::int64_t>(parts), std::vector<std::int64_t>(parts)} {}
  std::vector<std::int64_t> up[2];       ///< each part's carry out, by pass parity
  std::vector<std::int64_t> largest[2];  ///< each part's largest carry moved
  std::int64_t chain_carry[4] = {};
};

/// balance_digits(digit, bits, count, enough, wide), digit for digit,
/// called by every part of threads.run() at once: the classic parallel
/// carry. Each part carries its range of digits; after a barrier the carry
/// out of each range is added to the next range's first digit; passes go on
/// until no carry exceeds `enough` (AVX-512 lanes), or the scalar chains
/// run on the parts and part 0 absorbs each chain's carry into the next.
/// Part 0 gets the carry out of the last digit.
std::int64_t balance_digits_split(std::int64_t* digit, const std::uint8_t* bits, std::size_t count, std::int64_t enough,
                                  bool wide, ProofThreads& threads, unsigned part, CarryExchange& exchange);

}  // namespace tk::primes
