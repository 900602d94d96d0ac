/// @file sieve_output.cpp
#include "primes/sieve_output.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <optional>
#include <unordered_map>

#include "io/error.hpp"
#include "io/input_file.hpp"
#include "io/record_writer.hpp"
#include "primes/candidate_formats.hpp"

namespace tk::primes {

namespace {

constexpr std::uint64_t kMaxJsonInteger = std::uint64_t(1) << 53;
constexpr std::string_view kTrailerPrefix = "// sieve shard ";
constexpr std::string_view kTrailerEnd = ", complete";  // a trailer cut short lacks it
constexpr std::uint64_t kMaxShards = 1000000;           // as --shard allows

Record integer_field(std::uint64_t value) {
  return value < kMaxJsonInteger ? Record(value) : Record(std::to_string(value));
}

void write_text_survivors(const GeneralizedSieve& sieve, SieveOutputFormat format, std::uint64_t depth, std::FILE* out);

void write_records(const GeneralizedSieve& sieve, io::OutputFormat format, std::FILE* out) {
  const SieveSpec& spec = sieve.spec();
  io::RecordWriter writer(format, out);
  std::vector<std::string> fields{"k", "n", "form"};
  const bool chain = spec.form == SieveForm::cc1 || spec.form == SieveForm::cc2;
  if (chain) fields.push_back("length");
  if (spec.parametrised) fields.push_back("x");
  writer.declare_fields(fields);
  sieve.for_each_survivor([&](std::uint64_t offset) {
    const std::uint64_t x = spec.x_min + offset;
    Record record;
    record["k"] = integer_field(spec.k_at(x));
    record["n"] = spec.n;
    record["form"] = spec.form_name();
    if (chain) record["length"] = spec.length;
    if (spec.parametrised) record["x"] = integer_field(x);
    writer.write(record);
  });
  writer.flush();
}

}  // namespace

void write_survivors(const GeneralizedSieve& sieve, SieveOutputFormat format, std::uint64_t depth, std::FILE* out,
                     unsigned shard_index, unsigned shard_count) {
  const SieveSpec& spec = sieve.spec();
  if (format == SieveOutputFormat::json_lines || format == SieveOutputFormat::csv)
    write_records(sieve, format == SieveOutputFormat::csv ? io::OutputFormat::csv : io::OutputFormat::json_lines, out);
  else write_text_survivors(sieve, format, depth, out);
  if (shard_count <= 1) return;
  std::uint64_t candidates = 0;
  sieve.for_each_survivor([&](std::uint64_t) { ++candidates; });
  const std::string trailer =
      format_shard_trailer(ShardTrailer{shard_index, shard_count, candidates, spec.candidates_identity()}) + "\n";
  write_output_bytes(out, trailer);
  if (std::fflush(out) != 0) throw Error("cannot write the output");
}

void write_output_bytes(std::FILE* out, std::string_view bytes) {
  if (!bytes.empty() && std::fwrite(bytes.data(), 1, bytes.size(), out) != bytes.size())
    throw Error("cannot write the output");
}

std::string format_shard_trailer(const ShardTrailer& trailer) {
  return fmt::format("{}{}/{} of {}: {} candidates{}", kTrailerPrefix, trailer.index + 1, trailer.count, trailer.run,
                     trailer.candidates, kTrailerEnd);
}

bool looks_like_shard_trailer(std::string_view line) { return line.starts_with(kTrailerPrefix); }

std::optional<ShardTrailer> parse_shard_trailer(std::string_view line) {
  // Read from both ends: the run's text has colons of its own (k=1:3000).
  if (!looks_like_shard_trailer(line) || !line.ends_with(kTrailerEnd)) return std::nullopt;
  line.remove_prefix(kTrailerPrefix.size());
  line.remove_suffix(kTrailerEnd.size());
  auto number = [](std::string_view text) -> std::optional<std::uint64_t> {
    std::uint64_t value = 0;
    const auto [at, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || ec != std::errc() || at != text.data() + text.size()) return std::nullopt;
    return value;
  };
  const auto slash = line.find('/'), of = line.find(" of "), colon = line.rfind(": ");
  if (slash == std::string_view::npos || of == std::string_view::npos || colon == std::string_view::npos ||
      slash > of || of + 4 >= colon || !line.substr(colon).ends_with(" candidates"))
    return std::nullopt;
  const auto index = number(line.substr(0, slash)), count = number(line.substr(slash + 1, of - slash - 1));
  const auto candidates =
      number(line.substr(colon + 2, line.size() - colon - 2 - std::string_view(" candidates").size()));
  if (!index || !count || !candidates || *index < 1 || *index > *count || *count < 2 || *count > kMaxShards)
    return std::nullopt;
  return ShardTrailer{static_cast<unsigned>(*index - 1), static_cast<unsigned>(*count), *candidates,
                      std::string(line.substr(of + 4, colon - of - 4))};
}

namespace {

void write_text_survivors(const GeneralizedSieve& sieve, SieveOutputFormat format, std::uint64_t depth,
                          std::FILE* out) {
  const SieveSpec& spec = sieve.spec();
  fmt::memory_buffer buffer;
  auto flush_if_full = [&] {
    if (buffer.size() < (1u << 20)) return;
    write_output_bytes(out, {buffer.data(), buffer.size()});
    buffer.clear();
  };
  const bool single = spec.form == SieveForm::riesel || spec.form == SieveForm::proth;
  auto header = [&](CandidateHeader kind, std::uint64_t abcd_start) {
    fmt::format_to(std::back_inserter(buffer), "{}\n",
                   sieve_header_line({kind, sieve_header_key(spec, kind), depth, abcd_start}));
  };
  if (format == SieveOutputFormat::newpgen) {
    header(CandidateHeader::newpgen, 0);
    sieve.for_each_survivor([&](std::uint64_t offset) {
      fmt::format_to(std::back_inserter(buffer), "{} {}\n", spec.k_at(spec.x_min + offset), spec.n);
      flush_if_full();
    });
  } else if (format == SieveOutputFormat::abc) {
    header(CandidateHeader::abc, 0);
    sieve.for_each_survivor([&](std::uint64_t offset) {
      if (single) fmt::format_to(std::back_inserter(buffer), "{} {}\n", spec.k_at(spec.x_min + offset), spec.n);
      else fmt::format_to(std::back_inserter(buffer), "{}\n", spec.k_at(spec.x_min + offset));
      flush_if_full();
    });
  } else {
    std::optional<std::uint64_t> previous;
    sieve.for_each_survivor([&](std::uint64_t offset) {
      const std::uint64_t k = spec.k_at(spec.x_min + offset);
      if (!previous) header(CandidateHeader::abcd, k);
      else fmt::format_to(std::back_inserter(buffer), "{}\n", k - *previous);
      previous = k;
      flush_if_full();
    });
  }
  write_output_bytes(out, {buffer.data(), buffer.size()});
  if (std::fflush(out) != 0) throw Error("cannot write the output");
}

}  // namespace

std::string factor_line(const SieveSpec& spec, const SieveFactor& factor) {
  const std::uint64_t k = spec.k_at(spec.x_min + factor.offset);
  return fmt::format("{} | {}", factor.p, member_text(k, spec.n, spec.members()[factor.member]));
}

}  // namespace tk::primes
