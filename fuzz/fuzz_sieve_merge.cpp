/// @file fuzz_sieve_merge.cpp
/// @brief libFuzzer target: bytes as 1-3 shard outputs of `sieve`, merged
/// with tk::primes::merge_sieve_outputs as `sieve merge` does.
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
/// Oracles (switch off by name with TK_FUZZ_SKIP=a,b while a finding is open):
///   empty_shard  JSON Lines and ABCD are the formats in which a shard with
///                no survivors is an empty file. So when a merge whose first
///                file with content starts with '{' or "ABCD " succeeds, it
///                must also succeed with an empty file before and after the
///                others, and write nothing (the intersection is empty).
#include <sys/mman.h>
#include <unistd.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <optional>
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

/// The first line InputFile would not skip: split at LF, one trailing CR dropped.
std::string_view first_line(std::string_view bytes) {
  while (!bytes.empty()) {
    const std::size_t newline = bytes.find('\n');
    std::string_view line = bytes.substr(0, newline);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (!line.empty()) return line;
    if (newline == std::string_view::npos) break;
    bytes.remove_prefix(newline + 1);
  }
  return {};
}

/// merge_sieve_outputs into memory; the error message when it throws.
std::optional<std::string> merge_to_text(const std::vector<std::string>& paths, std::string& text) {
  char* data = nullptr;
  std::size_t size = 0;
  std::FILE* out = open_memstream(&data, &size);
  if (!out) std::abort();
  std::optional<std::string> error;
  try {
    tk::primes::merge_sieve_outputs(paths, out);
  } catch (const tk::Error& e) {
    error = e.located_message();
  }
  std::fclose(out);
  text.assign(data, size);
  std::free(data);
  return error;
}

void check_empty_shard(const std::vector<std::string>& paths, const std::vector<std::string_view>& parts) {
  static MemoryFile empty("fuzz-shard-empty");
  std::string_view model;
  for (std::string_view part : parts)
    if (!(model = first_line(part)).empty()) break;
  if (!model.empty() && model.front() != '{' && !model.starts_with("ABCD ")) return;
  empty.assign({});
  std::vector<std::string> before{empty.path()}, after(paths);
  before.insert(before.end(), paths.begin(), paths.end());
  after.push_back(empty.path());
  for (const auto* files : {&before, &after}) {
    std::string text;
    if (const auto error = merge_to_text(*files, text))
      tk::fuzz::invariant_failed("empty_shard", std::string("with an empty shard ") +
                                                    (files == &before ? "first" : "last") + ": " + *error);
    if (!text.empty())
      tk::fuzz::invariant_failed("empty_shard", std::string("with an empty shard ") +
                                                    (files == &before ? "first" : "last") + " the merge wrote " +
                                                    std::to_string(text.size()) + " bytes");
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
  try {
    tk::primes::merge_sieve_outputs(paths, null_output());
  } catch (const tk::Error&) {
    return;
  }
  if (tk::fuzz::oracle_enabled("empty_shard")) check_empty_shard(paths, parts);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // No catch beyond tk::Error: any other exception reaches std::terminate
  // while its throw site is still on the stack, so the report shows it.
  run(std::string_view(reinterpret_cast<const char*>(data), size));
  return 0;
}
