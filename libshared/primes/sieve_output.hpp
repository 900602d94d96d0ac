/// @file sieve_output.hpp
/// @brief Survivors of a generalized sieve in the formats other prime
/// tools read, the factors file, and the merge of shard outputs.
///
/// - JSON Lines / CSV records: k, n, form (+ length for chains, x when k = h0 + c*x).
/// - NewPGen: "depth:letter:chain:2:mask" then "k n" lines (T/3 twin, M/2
///   riesel, P/1 proth, S/10 Sophie Germain, C/5 second-kind pair, and
///   1/1066 and 2/1045 with the chain length for longer chains).
/// - ABC: "ABC expr // Sieved to depth"; '&' joins a form's members.
/// - ABCD: "ABCD expr [k0] // Sieved to depth", then differences of k.
/// - Factors: "p | k*2^e+c", one line per removal.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "primes/generalized_sieve.hpp"

namespace tk::primes {

enum class SieveOutputFormat { json_lines, csv, newpgen, abc, abcd };

/// Writes every survivor; `depth` is the sieve bound the text formats record.
void write_survivors(const GeneralizedSieve& sieve, SieveOutputFormat format, std::uint64_t depth, std::FILE* out);

/// "p | k*2^e+c" for a factors file (no newline).
std::string factor_line(const SieveSpec& spec, const SieveFactor& factor);

/// Intersects outputs of shards of one run (any one format): the result
/// equals the output of a single run, byte for byte. Headers must agree
/// except for the recorded depth, of which the smallest is kept.
void merge_sieve_outputs(const std::vector<std::string>& files, std::FILE* out);

}  // namespace tk::primes
