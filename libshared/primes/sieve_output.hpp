/// @file sieve_output.hpp
/// @brief Survivors of a generalized sieve in the formats other prime
/// tools read, the factors file, and the merge of shard outputs.
///
/// - JSON Lines / CSV records: k, n, form (+ length for chains, x when k = h0 + c*x).
/// - NewPGen, ABC, ABCD: headers as candidate_formats.hpp writes them,
///   then one line per k ("k n", "k" or "k n", differences of k).
/// - Factors: "p | k*2^e+c", one line per removal.
/// - A --shard K/N run (N > 1) ends its output, in any format, with the
///   trailer "// sieve shard K/N of <candidates identity>: S candidates,
///   complete", written last, so that a merge can tell a finished shard
///   from one cut short. One run and a merge write none.
#pragma once

#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "primes/generalized_sieve.hpp"

namespace tk::primes {

enum class SieveOutputFormat { json_lines, csv, newpgen, abc, abcd };

/// The last line of a shard's output.
struct ShardTrailer {
  unsigned index = 0;  ///< 0-based K - 1
  unsigned count = 1;
  std::uint64_t candidates = 0;  ///< lines of candidates before it (the ABCD header is one)
  std::string run;               ///< SieveSpec::candidates_identity()
};

std::string format_shard_trailer(const ShardTrailer& trailer);
/// The trailer `line` holds; nothing when it is not one (or is cut short).
std::optional<ShardTrailer> parse_shard_trailer(std::string_view line);
/// True for a line that claims to be a trailer, whole or not.
bool looks_like_shard_trailer(std::string_view line);

/// Writes every survivor; `depth` is the sieve bound the text formats
/// record. With shard_count > 1 the output ends with the shard trailer.
void write_survivors(const GeneralizedSieve& sieve, SieveOutputFormat format, std::uint64_t depth, std::FILE* out,
                     unsigned shard_index = 0, unsigned shard_count = 1);

/// fwrite, Error("cannot write the output") when it fails.
void write_output_bytes(std::FILE* out, std::string_view bytes);

/// "p | k*2^e+c" for a factors file (no newline).
std::string factor_line(const SieveSpec& spec, const SieveFactor& factor);

/// Intersects the outputs of all N shards of one run (any one format): the
/// result equals the output of a single run, byte for byte. Every file
/// must be a finished shard output (see ShardTrailer) of the same
/// candidates, each shard exactly once; headers must agree except for the
/// recorded depth, of which the smallest is kept. (sieve_merge.cpp)
void merge_sieve_outputs(const std::vector<std::string>& files, std::FILE* out);

}  // namespace tk::primes
