/// @file sieve_checkpoint.hpp
/// @brief Saving and resuming a generalized sieve. The file is written to a
/// temporary name, synced and renamed over the old one, so a crash at any
/// moment leaves either the previous or the new checkpoint, never half of
/// one. It holds the run's parameters (checked on resume), the shard, the
/// next block of primes, the factors file's length at that point and the
/// survivors as varint gaps, closed by a checksum.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "primes/generalized_sieve.hpp"

namespace tk::primes {

struct SieveCheckpoint {
  std::string identity;  ///< SieveSpec::identity() plus the shard
  std::uint64_t next_block = 0;
  std::uint64_t factors_bytes = 0;
  std::vector<std::uint64_t> bitmap;
};

/// "<spec identity> shard=K/N" (K 1-based), as a checkpoint records it.
std::string checkpoint_identity(const SieveSpec& spec, unsigned shard_index, unsigned shard_count);

void save_checkpoint(const std::string& path, const GeneralizedSieve& sieve, const std::string& identity,
                     std::uint64_t factors_bytes);

/// The checkpoint at `path`, or nothing when there is no such file. Throws
/// Error when the file cannot be read, is damaged, or belongs to other parameters.
std::optional<SieveCheckpoint> load_checkpoint(const std::string& path, const std::string& identity,
                                               std::uint64_t candidate_count);

}  // namespace tk::primes
