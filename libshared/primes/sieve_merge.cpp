/// @file sieve_merge.cpp
/// @brief `sieve merge`: the intersection of the outputs of every shard of
/// one run. A file is taken only when it is a finished shard output: its
/// last line is the shard trailer (which a run killed while writing never
/// reaches), the candidates before it are as many as the trailer says, and
/// its run and shard count match the other files'. Shards must each come
/// once and none may be missing, or the intersection would keep candidates
/// that the missing shard removes.
#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <string_view>
#include <unordered_map>

#include "io/error.hpp"
#include "io/input_file.hpp"
#include "primes/candidate_formats.hpp"
#include "primes/sieve_output.hpp"

namespace tk::primes {

namespace {

enum class TextKind { json_lines, csv, candidates };

struct ShardFile {
  TextKind kind = TextKind::json_lines;
  CandidateHeader header = CandidateHeader::none;  ///< NewPGen, ABC or ABCD when kind is candidates
  std::string header_key;                          ///< the header without its depth
  std::optional<std::uint64_t> depth;              ///< sieve bound the header records
  std::vector<std::string> lines;                  ///< candidate lines (ABCD: k values in decimal)
  ShardTrailer trailer;
  Location trailer_at;
};

ShardFile read_shard(const std::string& path) {
  io::InputFile input(path);
  ShardFile shard;
  std::string_view line;
  bool first = true;
  std::optional<std::uint64_t> previous_k;
  std::optional<ShardTrailer> trailer;
  while (input.next(line)) {
    if (line.empty()) continue;
    const Location where = input.where();
    if (trailer) throw Error("text after the '// sieve shard' line, which a shard output ends with", where);
    if (looks_like_shard_trailer(line)) {
      trailer = parse_shard_trailer(line);
      if (!trailer) throw Error("its '// sieve shard' line is cut short or damaged", where);
      shard.trailer_at = where;
      continue;
    }
    if (first) {
      first = false;
      if (line.front() == '{') {
        shard.kind = TextKind::json_lines;
      } else if (const SieveHeader header = parse_sieve_header(line, where); header.kind != CandidateHeader::none) {
        shard.kind = TextKind::candidates;
        shard.header = header.kind;
        shard.header_key = header.key;
        shard.depth = header.depth;
        if (shard.header == CandidateHeader::abcd) {
          previous_k = header.abcd_start;
          shard.lines.push_back(std::to_string(*previous_k));
        }
        continue;
      } else {
        shard.kind = TextKind::csv;
        shard.header_key = std::string(line);
        continue;
      }
    }
    if (shard.header == CandidateHeader::abcd) {
      const std::uint64_t delta = parse_abcd_difference(line, where);
      if (delta == 0 || *previous_k + delta < *previous_k)
        throw Error("abcd difference must be positive and keep k below 2^64", where);
      previous_k = *previous_k + delta;
      shard.lines.push_back(std::to_string(*previous_k));
    } else {
      shard.lines.emplace_back(line);
    }
  }
  if (!trailer)
    throw Error(
        "ends without the '// sieve shard K/N of ...: S candidates, complete' line that a finished --shard run "
        "writes last: cut short, or not the output of a --shard run",
        Location{path, input.line_number()});
  if (trailer->candidates != shard.lines.size())
    throw Error(fmt::format("holds {} candidates where its last line says {}: damaged", shard.lines.size(),
                            trailer->candidates),
                shard.trailer_at);
  shard.trailer = std::move(*trailer);
  return shard;
}

/// Every shard of one run, each once.
void check_one_run(const std::vector<ShardFile>& shards, const std::vector<std::string>& files) {
  const ShardTrailer& model = shards.front().trailer;
  std::vector<std::optional<std::size_t>> file_of(model.count);
  for (std::size_t i = 0; i < shards.size(); ++i) {
    const ShardTrailer& trailer = shards[i].trailer;
    if (trailer.run != model.run || trailer.count != model.count)
      throw Error(
          fmt::format("shard {}/{} of {}, but {} is shard {}/{} of {}: not shards of one run", trailer.index + 1,
                      trailer.count, trailer.run, files.front(), model.index + 1, model.count, model.run),
          shards[i].trailer_at);
    if (const auto other = file_of[trailer.index])
      throw Error(
          fmt::format("shard {}/{} again: {} is that shard too", trailer.index + 1, trailer.count, files[*other]),
          shards[i].trailer_at);
    file_of[trailer.index] = i;
  }
  std::string missing;
  for (std::size_t k = 0; k < file_of.size(); ++k)
    if (!file_of[k]) missing += fmt::format("{}{}/{}", missing.empty() ? "" : ", ", k + 1, model.count);
  if (!missing.empty())
    throw Error(
        fmt::format("shard{} {} of {} missing: a merge needs every shard of the run, or it keeps candidates "
                    "that a missing shard removes",
                    missing.find(',') == std::string::npos ? "" : "s", missing, model.run));
}

}  // namespace

void merge_sieve_outputs(const std::vector<std::string>& files, std::FILE* out) {
  if (files.empty()) throw UsageError("merge needs at least one shard output");
  std::vector<ShardFile> shards;
  for (const std::string& path : files) shards.push_back(read_shard(path));
  check_one_run(shards, files);
  // A shard without survivors may hold only its trailer, whatever format the
  // run wrote: the headers of the others must agree with the first that has content.
  auto has_content = [](const ShardFile& shard) { return !shard.header_key.empty() || !shard.lines.empty(); };
  const auto model_at = std::find_if(shards.begin(), shards.end(), has_content);
  const ShardFile* model = model_at == shards.end() ? &shards.front() : &*model_at;
  const std::string& model_path = files[static_cast<std::size_t>(model - shards.data())];
  std::optional<std::uint64_t> depth;
  std::unordered_map<std::string_view, std::size_t> seen;
  for (std::size_t i = 0; i < shards.size(); ++i) {
    const ShardFile& shard = shards[i];
    if (has_content(shard) &&
        (shard.kind != model->kind || shard.header != model->header || shard.header_key != model->header_key))
      throw Error("its header does not match " + model_path + "'s: not a shard of the same run", Location{files[i], 1});
    if (shard.depth) depth = depth ? std::min(*depth, *shard.depth) : *shard.depth;
    for (const std::string& line : shard.lines) {
      auto [it, inserted] = seen.try_emplace(line, 0);
      if (it->second == i) ++it->second;  // counts each line once per file
    }
  }

  fmt::memory_buffer buffer;
  auto kept = [&](const std::string& line) { return seen[line] == shards.size(); };
  auto write_header = [&](std::uint64_t abcd_start) {
    fmt::format_to(std::back_inserter(buffer), "{}\n",
                   sieve_header_line({model->header, model->header_key, *depth, abcd_start}));
  };
  switch (model->kind) {
    case TextKind::json_lines: break;
    case TextKind::csv:  // one run writes no header row when nothing survives
      if (std::any_of(model->lines.begin(), model->lines.end(), kept))
        fmt::format_to(std::back_inserter(buffer), "{}\n", model->header_key);
      break;
    case TextKind::candidates:  // ABCD's header holds its first k
      if (model->header != CandidateHeader::abcd) write_header(0);
      break;
  }
  std::optional<std::uint64_t> previous;
  for (const std::string& line : model->lines) {
    if (!kept(line)) continue;
    if (model->header != CandidateHeader::abcd) {
      fmt::format_to(std::back_inserter(buffer), "{}\n", line);
    } else {
      const std::uint64_t k = std::stoull(line);
      if (!previous) write_header(k);
      else fmt::format_to(std::back_inserter(buffer), "{}\n", k - *previous);
      previous = k;
    }
    if (buffer.size() > (1u << 20)) {
      write_output_bytes(out, {buffer.data(), buffer.size()});
      buffer.clear();
    }
  }
  write_output_bytes(out, {buffer.data(), buffer.size()});
  if (std::fflush(out) != 0) throw Error("cannot write the output");
}

}  // namespace tk::primes
