/// @file fuzz_sieve_checkpoint.cpp
/// @brief libFuzzer target: bytes as a sieve checkpoint file, read back with
/// tk::primes::load_checkpoint.
///
/// A checkpoint ends in the 64-bit FNV-1a checksum of everything before it,
/// so a random mutation almost always fails that check. Every input is
/// therefore loaded twice from a reused in-memory file:
///   1. as it is (the magic and checksum checks themselves), and
///   2. with its last 8 bytes replaced by the correct checksum of the bytes
///      before them (shorter inputs get one appended), so the fuzzer reaches
///      the identity line, the fixed fields and the survivor gaps.
/// Both are loaded with the identity of the `twin` seeds (kIdentity) and
/// 5000 candidates, as `sieve twin --n 1000 --k 1:5000 --pmax 1e4 --resume`
/// would. The repaired copy is also loaded with the identity it carries
/// itself (its second line) and a candidate count taken from the input's
/// last byte (which the repair overwrites, so it is free to choose): 0..127
/// as it is, above that up to ~130000 (bitmaps stay below 17 KiB).
///
/// tk::Error is the expected rejection; any other exception, crash,
/// sanitizer report, hang or huge allocation is a bug.
///
/// Oracles (switch off by name with TK_FUZZ_SKIP=a,b while a finding is open):
///   identity   a loaded checkpoint carries the identity asked for
///   bitmap     its bitmap has (count+63)/64 words, no bit at or above count
///   bitmap     ... and no bit in a segment the small primes have not sieved
///              (next_segment, version 2), and blocks only after every segment
///   roundtrip  the checkpoint re-encoded as save_checkpoint writes it (version
///              2) loads back to the same fields and bitmap
#include <sys/mman.h>
#include <unistd.h>

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <string_view>

#include "fuzz_common.hpp"
#include "io/error.hpp"
#include "primes/sieve_checkpoint.hpp"

namespace {

using tk::fuzz::MemoryFile;

constexpr std::string_view kMagic = "toolkit-sieve-checkpoint 2\n";
constexpr std::string_view kMagicVersion1 = "toolkit-sieve-checkpoint 1\n";  // still read: all segments done
constexpr std::uint64_t kSegmentBits = std::uint64_t(1) << 21;
/// `sed -n 2p` of the seeds made by `sieve twin --n 1000 --k 1:5000 --pmax 1e4 --checkpoint F`.
const std::string kIdentity = "form=twin length=1 n=1000 k=1:5000 pmax=10000 shard=1/1";
constexpr std::uint64_t kCandidates = 5000;

/// FNV-1a 64, as the checkpoint's trailer (reimplemented, not shared, so a
/// change of the library's checksum shows as a seed that no longer loads).
std::uint64_t fnv1a(std::string_view bytes) {
  std::uint64_t hash = 0xcbf29ce484222325ull;
  for (unsigned char byte : bytes) hash = (hash ^ byte) * 0x100000001b3ull;
  return hash;
}

void put_u64(std::string& out, std::uint64_t value) {
  for (int i = 0; i < 8; ++i) out += static_cast<char>((value >> (8 * i)) & 0xff);
}

void put_varint(std::string& out, std::uint64_t value) {
  while (value >= 0x80) {
    out += static_cast<char>((value & 0x7f) | 0x80);
    value >>= 7;
  }
  out += static_cast<char>(value);
}

/// The bytes with a correct checksum in their last 8 (appended when shorter).
std::string with_checksum(std::string_view bytes) {
  std::string body(bytes.size() >= 8 ? bytes.substr(0, bytes.size() - 8) : bytes);
  put_u64(body, fnv1a(body));
  return body;
}

/// What save_checkpoint writes for this state.
std::string encode(const tk::primes::SieveCheckpoint& checkpoint) {
  std::string bytes(kMagic);
  bytes += checkpoint.identity + "\n";
  put_u64(bytes, checkpoint.next_block);
  put_u64(bytes, checkpoint.factors_bytes);
  put_u64(bytes, checkpoint.next_segment);
  std::uint64_t survivors = 0;
  for (std::uint64_t word : checkpoint.bitmap) survivors += static_cast<std::uint64_t>(std::popcount(word));
  put_u64(bytes, survivors);
  std::uint64_t previous = 0;
  for (std::size_t w = 0; w < checkpoint.bitmap.size(); ++w)
    for (std::uint64_t word = checkpoint.bitmap[w]; word; word &= word - 1) {
      const std::uint64_t offset = 64 * w + static_cast<std::uint64_t>(std::countr_zero(word));
      put_varint(bytes, offset - previous);
      previous = offset;
    }
  put_u64(bytes, fnv1a(bytes));
  return bytes;
}

std::optional<tk::primes::SieveCheckpoint> load(MemoryFile& file, std::string_view bytes, const std::string& identity,
                                                std::uint64_t count) {
  file.assign(bytes);
  try {
    return tk::primes::load_checkpoint(file.path(), identity, count);
  } catch (const tk::Error&) {
    return std::nullopt;
  }
}

void check(const tk::primes::SieveCheckpoint& checkpoint, const std::string& identity, std::uint64_t count,
           MemoryFile& file) {
  if (checkpoint.identity != identity && tk::fuzz::oracle_enabled("identity"))
    tk::fuzz::invariant_failed("identity", "loaded '" + checkpoint.identity + "' when asked for '" + identity + "'");
  if (tk::fuzz::oracle_enabled("bitmap")) {
    if (checkpoint.bitmap.size() != (count + 63) / 64)
      tk::fuzz::invariant_failed(
          "bitmap", std::to_string(checkpoint.bitmap.size()) + " words for " + std::to_string(count) + " candidates");
    if (count % 64 && (checkpoint.bitmap.back() >> (count % 64)) != 0)
      tk::fuzz::invariant_failed("bitmap", "a survivor at or above the candidate count " + std::to_string(count));
    const std::uint64_t segments = (count + kSegmentBits - 1) / kSegmentBits;
    if (checkpoint.next_segment > segments || (checkpoint.next_segment < segments && checkpoint.next_block != 0))
      tk::fuzz::invariant_failed("bitmap", "segment " + std::to_string(checkpoint.next_segment) + " of " +
                                               std::to_string(segments) + " with block " +
                                               std::to_string(checkpoint.next_block));
    for (std::size_t w = checkpoint.next_segment * kSegmentBits / 64; w < checkpoint.bitmap.size(); ++w)
      if (checkpoint.bitmap[w] != 0) tk::fuzz::invariant_failed("bitmap", "a survivor in a segment not yet sieved");
  }
  if (tk::fuzz::oracle_enabled("roundtrip")) {
    const auto again = load(file, encode(checkpoint), identity, count);
    if (!again) tk::fuzz::invariant_failed("roundtrip", "the re-encoded checkpoint does not load");
    if (again->identity != checkpoint.identity || again->next_block != checkpoint.next_block ||
        again->next_segment != checkpoint.next_segment || again->factors_bytes != checkpoint.factors_bytes ||
        again->bitmap != checkpoint.bitmap)
      tk::fuzz::invariant_failed("roundtrip", "the re-encoded checkpoint loads to another state");
  }
}

/// 0..127 as they are (empty, single-word and word-boundary bitmaps), then
/// steps of 1000 up to 129000.
std::uint64_t derived_count(unsigned char byte) { return byte < 128 ? byte : std::uint64_t(byte - 127) * 1000; }

void run(std::string_view bytes) {
  static MemoryFile file("fuzz-checkpoint");

  if (auto checkpoint = load(file, bytes, kIdentity, kCandidates)) check(*checkpoint, kIdentity, kCandidates, file);

  const std::string repaired = with_checksum(bytes);
  if (auto checkpoint = load(file, repaired, kIdentity, kCandidates)) check(*checkpoint, kIdentity, kCandidates, file);

  // The identity the input carries, so the body is reached whatever its line 2 says.
  const bool magic = repaired.compare(0, kMagic.size(), kMagic) == 0 ||
                     repaired.compare(0, kMagicVersion1.size(), kMagicVersion1) == 0;
  if (repaired.size() > kMagic.size() && magic) {
    const std::size_t end = repaired.find('\n', kMagic.size());
    if (end != std::string::npos) {
      const std::string own = repaired.substr(kMagic.size(), end - kMagic.size());
      const std::uint64_t count = derived_count(bytes.empty() ? 0 : static_cast<unsigned char>(bytes.back()));
      if (auto checkpoint = load(file, repaired, own, count)) check(*checkpoint, own, count, file);
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // No catch beyond tk::Error: any other exception reaches std::terminate
  // while its throw site is still on the stack, so the report shows it.
  run(std::string_view(reinterpret_cast<const char*>(data), size));
  return 0;
}
