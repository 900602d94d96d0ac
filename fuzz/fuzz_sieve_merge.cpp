/// @file fuzz_sieve_merge.cpp
/// @brief libFuzzer target: bytes as 1-3 shard outputs of `sieve`, merged
/// with tk::primes::merge_sieve_outputs as `sieve merge` does (sieve_merge.cpp).
///
/// The input is split at its first two 0x1E bytes (ASCII record separator)
/// into up to three files (a third file keeps any further 0x1E bytes), each
/// written to a reused in-memory file. The merge reads them as JSON Lines,
/// CSV, NewPGen, ABC or ABCD (chosen by each file's first line), checks that
/// their headers agree and writes the intersection to /dev/null.
///
/// tk::Error (and UsageError, derived from it) is the expected rejection;
/// any other exception, crash, sanitizer report, hang or huge allocation is
/// a bug.
///
/// A merge takes only finished shard outputs: each file ends with the line
/// "// sieve shard K/N of RUN: S candidates, complete" after S candidates,
/// and the files are shards 1..N of one RUN, each once. The seeds named
/// shards*_trailer are such sets. When a merge succeeds:
///
/// Oracles (switch off by name with TK_FUZZ_SKIP=a,b while a finding is open):
///   cut        it fails once any one file is cut short (by more than its
///              final newline): a shard killed while writing never merges
///   missing    with two or more files it fails without the last one
///   duplicate  it fails with the first file given twice
#include <sys/mman.h>
#include <unistd.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include "fuzz_common.hpp"
#include "io/error.hpp"
#include "primes/sieve_output.hpp"

namespace {

using tk::fuzz::MemoryFile;
using tk::fuzz::null_output;

constexpr std::size_t kMaxShards = 3;

/// merge_sieve_outputs to /dev/null; true when it succeeds.
bool merges(const std::vector<std::string>& paths) {
  try {
    tk::primes::merge_sieve_outputs(paths, null_output());
  } catch (const tk::Error&) {
    return false;
  }
  return true;
}

/// Each file cut before the last byte of its last line (where the trailer
/// ends), and halfway to it, must be refused.
void check_cut(std::vector<std::string> paths, const std::vector<std::string_view>& parts) {
  static MemoryFile cut("fuzz-shard-cut");
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const std::string_view whole = parts[i];
    const std::size_t last = whole.find_last_not_of("\r\n");
    if (last == std::string_view::npos) continue;
    for (std::size_t size : {last / 2, last}) {
      cut.assign(whole.substr(0, size));
      const std::string original = paths[i];
      paths[i] = cut.path();
      if (merges(paths))
        tk::fuzz::invariant_failed("cut", "file " + std::to_string(i + 1) + " cut to " + std::to_string(size) + " of " +
                                              std::to_string(whole.size()) + " bytes still merges");
      paths[i] = original;
    }
  }
}

void run(std::string_view bytes) {
  static std::array<MemoryFile, kMaxShards> files{MemoryFile("fuzz-shard-1"), MemoryFile("fuzz-shard-2"),
                                                  MemoryFile("fuzz-shard-3")};
  std::vector<std::string> paths;
  std::vector<std::string_view> parts;
  for (std::size_t i = 0; i < kMaxShards; ++i) {
    const std::size_t split = i + 1 < kMaxShards ? bytes.find('\x1e') : std::string_view::npos;
    parts.push_back(bytes.substr(0, split));
    files[i].assign(parts.back());
    paths.push_back(files[i].path());
    if (split == std::string_view::npos) break;
    bytes.remove_prefix(split + 1);
  }
  if (!merges(paths)) return;
  if (tk::fuzz::oracle_enabled("cut")) check_cut(paths, parts);
  if (paths.size() >= 2 && tk::fuzz::oracle_enabled("missing") &&
      merges(std::vector<std::string>(paths.begin(), paths.end() - 1)))
    tk::fuzz::invariant_failed("missing", "the merge succeeds without its last file");
  if (tk::fuzz::oracle_enabled("duplicate")) {
    std::vector<std::string> twice(paths);
    twice.push_back(paths.front());
    if (merges(twice)) tk::fuzz::invariant_failed("duplicate", "the merge succeeds with its first file given twice");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // No catch beyond tk::Error: any other exception reaches std::terminate
  // while its throw site is still on the stack, so the report shows it.
  run(std::string_view(reinterpret_cast<const char*>(data), size));
  return 0;
}
