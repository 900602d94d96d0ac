/// @file inference_timing.hpp
/// @brief Timing Mamdani inferences the way the line-follower paper did
/// (2 x 1024: both motors for 1024 sensor triples) and over many more for a
/// stable figure. An inference is one output's value for one input vector.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "fuzzy/mamdani.hpp"

namespace tk::fuzzy {

/// 1024 sensor triples for an ADC of `adc_bits`, the same on every run: a
/// deterministic spread over the whole scale, so every rule and every pair
/// of partly true terms occurs (a car on a track sees fewer of them).
std::vector<std::array<double, 3>> protocol_triples(int adc_bits);

struct InferenceTiming {
  double ns_per_inference = 0;   ///< median over rounds of many protocol blocks
  double ms_per_2x1024 = 0;      ///< the paper's protocol: one block, median over rounds
  std::uint64_t inferences = 0;  ///< how many were timed in all
};

/// Times `controller` (3 inputs) on `triples` for about `seconds` of CPU.
/// inferences per evaluation = the controller's output count.
InferenceTiming time_inferences(Mamdani& controller, std::span<const std::array<double, 3>> triples, double seconds);

}  // namespace tk::fuzzy
