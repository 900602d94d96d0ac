/// @file sieve_checkpoint.cpp
#include "primes/sieve_checkpoint.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>

#include "io/atomic_file.hpp"
#include "io/checksum.hpp"
#include "io/error.hpp"

namespace tk::primes {

namespace {

constexpr std::string_view kMagic = "toolkit-sieve-checkpoint 2\n";
constexpr std::string_view kMagicVersion1 = "toolkit-sieve-checkpoint 1\n";  // no segment count: all done

void put_varint(std::string& out, std::uint64_t value) {
  while (value >= 0x80) {
    out += static_cast<char>((value & 0x7f) | 0x80);
    value >>= 7;
  }
  out += static_cast<char>(value);
}

void put_u64(std::string& out, std::uint64_t value) {
  for (int i = 0; i < 8; ++i) out += static_cast<char>((value >> (8 * i)) & 0xff);
}

class Reader {
 public:
  Reader(const std::string& bytes, std::size_t end, const std::string& path) : bytes_(bytes), end_(end), path_(path) {}
  std::uint64_t u64() {
    need(8);
    std::uint64_t value = 0;
    for (int i = 0; i < 8; ++i)
      value |= static_cast<std::uint64_t>(static_cast<unsigned char>(bytes_[pos_ + i])) << (8 * i);
    pos_ += 8;
    return value;
  }
  std::uint64_t varint() {
    std::uint64_t value = 0;
    for (int shift = 0; shift < 64; shift += 7) {
      need(1);
      const auto byte = static_cast<unsigned char>(bytes_[pos_++]);
      value |= static_cast<std::uint64_t>(byte & 0x7f) << shift;
      if (!(byte & 0x80)) return value;
    }
    throw damaged();
  }
  std::string line() {
    const std::size_t end = bytes_.find('\n', pos_);
    if (end == std::string::npos || end >= end_) throw damaged();
    std::string text = bytes_.substr(pos_, end - pos_);
    pos_ = end + 1;
    return text;
  }
  bool at_end() const { return pos_ == end_; }
  Error damaged() const { return Error("checkpoint is damaged or not a sieve checkpoint", Location{path_, 0}); }

 private:
  void need(std::size_t count) {
    if (end_ - pos_ < count) throw damaged();
  }
  const std::string& bytes_;
  std::size_t end_, pos_ = 0;
  const std::string& path_;
};

}  // namespace

std::string checkpoint_identity(const SieveSpec& spec, unsigned shard_index, unsigned shard_count) {
  return fmt::format("{} shard={}/{}", spec.identity(), shard_index + 1, shard_count);
}

void save_checkpoint(const std::string& path, const GeneralizedSieve& sieve, const std::string& identity,
                     std::uint64_t factors_bytes) {
  std::string bytes(kMagic);
  bytes += identity + "\n";
  put_u64(bytes, sieve.next_block());
  put_u64(bytes, factors_bytes);
  put_u64(bytes, sieve.next_segment());
  const std::size_t survivors_at = bytes.size();
  put_u64(bytes, 0);  // the count of settled survivors, filled in below
  std::uint64_t previous = 0, survivors = 0;
  sieve.for_each_survivor([&](std::uint64_t offset) {
    put_varint(bytes, offset - previous);
    previous = offset;
    ++survivors;
  });
  std::string count;
  put_u64(count, survivors);
  bytes.replace(survivors_at, count.size(), count);
  put_u64(bytes, io::fnv1a(bytes));

  io::write_file_atomically(path, bytes, checkpoint_temporary(path));
}

std::string checkpoint_temporary(const std::string& path) { return path + ".tmp"; }

std::optional<SieveCheckpoint> load_checkpoint(const std::string& path, const std::string& identity,
                                               std::uint64_t candidate_count) {
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) {
    if (errno == ENOENT) return std::nullopt;
    throw errno_error(path, "open the checkpoint", errno);
  }
  std::string bytes;
  char chunk[65536];
  for (std::size_t got; (got = std::fread(chunk, 1, sizeof chunk, file)) > 0;) bytes.append(chunk, got);
  const bool read_error = std::ferror(file) != 0;
  std::fclose(file);
  if (read_error) throw errno_error(path, "read the checkpoint", errno);

  Reader whole(bytes, bytes.size(), path);
  const bool version1 = bytes.compare(0, kMagicVersion1.size(), kMagicVersion1) == 0;
  if (bytes.size() < kMagic.size() + 8 || (!version1 && bytes.compare(0, kMagic.size(), kMagic) != 0))
    throw whole.damaged();
  std::uint64_t stored = 0;
  for (std::size_t i = 0; i < 8; ++i)
    stored |= static_cast<std::uint64_t>(static_cast<unsigned char>(bytes[bytes.size() - 8 + i])) << (8 * i);
  if (stored != io::fnv1a(bytes.substr(0, bytes.size() - 8))) throw whole.damaged();

  Reader in(bytes, bytes.size() - 8, path);
  in.line();  // magic
  SieveCheckpoint checkpoint;
  checkpoint.identity = in.line();
  if (checkpoint.identity != identity)
    throw Error(
        fmt::format("checkpoint was written for other parameters ({}); this run is {}", checkpoint.identity, identity),
        Location{path, 0});
  checkpoint.next_block = in.u64();
  checkpoint.factors_bytes = in.u64();
  const std::uint64_t segments =
      (candidate_count + GeneralizedSieve::kSegmentBits - 1) / GeneralizedSieve::kSegmentBits;
  checkpoint.next_segment = version1 ? segments : in.u64();
  if (checkpoint.next_segment > segments || (checkpoint.next_segment < segments && checkpoint.next_block > 0))
    throw in.damaged();
  const std::uint64_t settled = std::min(candidate_count, checkpoint.next_segment * GeneralizedSieve::kSegmentBits);
  const std::uint64_t survivors = in.u64();
  if (survivors > settled) throw in.damaged();
  checkpoint.bitmap.assign((candidate_count + 63) / 64, 0);
  std::uint64_t offset = 0;
  for (std::uint64_t i = 0; i < survivors; ++i) {
    const std::uint64_t gap = in.varint();
    if (gap > settled || (i > 0 && gap == 0) || (offset += gap) >= settled) throw in.damaged();
    checkpoint.bitmap[offset / 64] |= std::uint64_t(1) << (offset % 64);
  }
  if (!in.at_end()) throw in.damaged();
  return checkpoint;
}

}  // namespace tk::primes
