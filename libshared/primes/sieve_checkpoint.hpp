/// @file sieve_checkpoint.hpp
/// @brief Saving and resuming a generalized sieve. The file is written to a
/// temporary name, synced and renamed over the old one, so a crash at any
/// moment leaves either the previous or the new checkpoint, never half of
/// one. It holds the run's parameters (checked on resume), the shard, the
/// next block of primes, the factors file's length at that point, the
/// segments the small primes have sieved (version 2) and the survivors in
/// them as varint gaps, closed by a checksum.
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
  std::uint64_t next_segment = 0;  ///< version 1 files: every segment
  std::uint64_t factors_bytes = 0;
  SieveBitmap bitmap;
};

/// "<spec identity> shard=K/N" (K 1-based), as a checkpoint records it.
std::string checkpoint_identity(const SieveSpec& spec, unsigned shard_index, unsigned shard_count);

void save_checkpoint(const std::string& path, const GeneralizedSieve& sieve, const std::string& identity,
                     std::uint64_t factors_bytes);

/// The checkpoint at `path`, or nothing when there is no such file. Throws
/// Error when the file cannot be read, is damaged, or belongs to other parameters.
std::optional<SieveCheckpoint> load_checkpoint(const std::string& path, const std::string& identity,
                                               std::uint64_t candidate_count);

/// The temporary save_checkpoint writes next to `path`.
std::string checkpoint_temporary(const std::string& path);

}  // namespace tk::primes
