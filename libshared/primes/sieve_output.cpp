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

namespace tk::primes {

namespace {

constexpr std::uint64_t kMaxJsonInteger = std::uint64_t(1) << 53;

Record integer_field(std::uint64_t value) {
  return value < kMaxJsonInteger ? Record(value) : Record(std::to_string(value));
}

/// The NewPGen header after "depth:".
std::string newpgen_shape(const SieveSpec& spec) {
  switch (spec.form) {
    case SieveForm::riesel: return "M:1:2:2";
    case SieveForm::proth: return "P:1:2:1";
    case SieveForm::twin: return "T:0:2:3";
    case SieveForm::sg: return "S:0:2:10";
    case SieveForm::cc1: return spec.length == 2 ? "S:0:2:10" : fmt::format("1:{}:2:1066", spec.length);
    case SieveForm::cc2: return spec.length == 2 ? "C:0:2:5" : fmt::format("2:{}:2:1045", spec.length);
  }
  return {};
}

/// The ABC/ABCD expression; single forms in ABC keep n as $b.
std::string abc_expression(const SieveSpec& spec, bool n_as_variable) {
  const std::uint64_t n = spec.n;
  switch (spec.form) {
    case SieveForm::riesel: return n_as_variable ? "$a*2^$b-1" : fmt::format("$a*2^{}-1", n);
    case SieveForm::proth: return n_as_variable ? "$a*2^$b+1" : fmt::format("$a*2^{}+1", n);
    case SieveForm::twin: return fmt::format("$a*2^{0}+1 & $a*2^{0}-1", n);
    case SieveForm::sg: return fmt::format("$a*2^{0}-1 & 2*($a*2^{0}-1)+1", n);
    case SieveForm::cc1:
    case SieveForm::cc2: {
      std::string text;
      for (const SieveMember& member : spec.members())
        text += fmt::format("{}$a*2^{}{}", text.empty() ? "" : " & ", n + member.exponent_offset, member.c < 0 ? "-1" : "+1");
      return text;
    }
  }
  return {};
}

void write_text(std::FILE* out, const fmt::memory_buffer& buffer) {
  if (buffer.size() && std::fwrite(buffer.data(), 1, buffer.size(), out) != buffer.size())
    throw Error("cannot write the output");
}

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

void write_survivors(const GeneralizedSieve& sieve, SieveOutputFormat format, std::uint64_t depth, std::FILE* out) {
  const SieveSpec& spec = sieve.spec();
  if (format == SieveOutputFormat::json_lines || format == SieveOutputFormat::csv)
    return write_records(sieve, format == SieveOutputFormat::csv ? io::OutputFormat::csv : io::OutputFormat::json_lines, out);

  fmt::memory_buffer buffer;
  auto flush_if_full = [&] {
    if (buffer.size() < (1u << 20)) return;
    write_text(out, buffer);
    buffer.clear();
  };
  const bool single = spec.form == SieveForm::riesel || spec.form == SieveForm::proth;
  if (format == SieveOutputFormat::newpgen) {
    fmt::format_to(std::back_inserter(buffer), "{}:{}\n", depth, newpgen_shape(spec));
    sieve.for_each_survivor([&](std::uint64_t offset) {
      fmt::format_to(std::back_inserter(buffer), "{} {}\n", spec.k_at(spec.x_min + offset), spec.n);
      flush_if_full();
    });
  } else if (format == SieveOutputFormat::abc) {
    fmt::format_to(std::back_inserter(buffer), "ABC {} // Sieved to {}\n", abc_expression(spec, single), depth);
    sieve.for_each_survivor([&](std::uint64_t offset) {
      if (single) fmt::format_to(std::back_inserter(buffer), "{} {}\n", spec.k_at(spec.x_min + offset), spec.n);
      else fmt::format_to(std::back_inserter(buffer), "{}\n", spec.k_at(spec.x_min + offset));
      flush_if_full();
    });
  } else {
    std::optional<std::uint64_t> previous;
    sieve.for_each_survivor([&](std::uint64_t offset) {
      const std::uint64_t k = spec.k_at(spec.x_min + offset);
      if (!previous)
        fmt::format_to(std::back_inserter(buffer), "ABCD {} [{}] // Sieved to {}\n", abc_expression(spec, false), k, depth);
      else
        fmt::format_to(std::back_inserter(buffer), "{}\n", k - *previous);
      previous = k;
      flush_if_full();
    });
  }
  write_text(out, buffer);
  if (std::fflush(out) != 0) throw Error("cannot write the output");
}

std::string factor_line(const SieveSpec& spec, const SieveFactor& factor) {
  const std::uint64_t k = spec.k_at(spec.x_min + factor.offset);
  return fmt::format("{} | {}", factor.p, member_text(k, spec.n, spec.members()[factor.member]));
}

// ---------------------------------------------------------------- merge

namespace {

enum class TextKind { json_lines, csv, newpgen, abc, abcd };

struct ShardFile {
  TextKind kind = TextKind::json_lines;
  std::string header_key;               ///< the header without its depth
  std::optional<std::uint64_t> depth;   ///< sieve bound the header records
  std::vector<std::string> lines;       ///< candidate lines (ABCD: k values in decimal)
};

std::uint64_t parse_depth(std::string_view text, const Location& where) {
  std::uint64_t value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || text.empty()) throw Error("the sieve depth '" + std::string(text) + "' is not a number", where);
  return value;
}

/// Splits "... // Sieved to D" into the text before it and D.
void split_sieved_to(std::string_view header, ShardFile& shard, const Location& where) {
  const auto mark = header.rfind(" // Sieved to ");
  if (mark == std::string_view::npos) throw Error("abc header without '// Sieved to': not written by sieve", where);
  shard.header_key = std::string(header.substr(0, mark));
  shard.depth = parse_depth(header.substr(mark + 14), where);
}

ShardFile read_shard(const std::string& path) {
  io::InputFile input(path);
  ShardFile shard;
  std::string_view line;
  bool first = true;
  std::optional<std::uint64_t> previous_k;
  while (input.next(line)) {
    if (line.empty()) continue;
    const Location where = input.where();
    if (first) {
      first = false;
      if (line.front() == '{') {
        shard.kind = TextKind::json_lines;
      } else if (line.starts_with("ABCD ")) {
        shard.kind = TextKind::abcd;
        split_sieved_to(line, shard, where);
        const auto open = shard.header_key.rfind(" ["), close = shard.header_key.rfind(']');
        if (open == std::string::npos || close == std::string::npos || close < open)
          throw Error("abcd header without a [k] start value", where);
        previous_k = parse_depth(std::string_view(shard.header_key).substr(open + 2, close - open - 2), where);
        if (close + 1 != shard.header_key.size()) throw Error("abcd header has text after its [k] start value", where);
        shard.lines.push_back(std::to_string(*previous_k));
        shard.header_key.erase(open);
        continue;
      } else if (line.starts_with("ABC ")) {
        shard.kind = TextKind::abc;
        split_sieved_to(line, shard, where);
        continue;
      } else if (const auto colon = line.find(':'); colon != std::string_view::npos && colon > 0 &&
                 line.substr(0, colon).find_first_not_of("0123456789") == std::string_view::npos) {
        shard.kind = TextKind::newpgen;
        shard.depth = parse_depth(line.substr(0, colon), where);
        shard.header_key = std::string(line.substr(colon + 1));
        continue;
      } else {
        shard.kind = TextKind::csv;
        shard.header_key = std::string(line);
        continue;
      }
    }
    if (shard.kind == TextKind::abcd) {
      const std::uint64_t delta = parse_depth(line, where);
      if (delta == 0 || *previous_k + delta < *previous_k) throw Error("abcd difference must be positive and keep k below 2^64", where);
      previous_k = *previous_k + delta;
      shard.lines.push_back(std::to_string(*previous_k));
    } else {
      shard.lines.emplace_back(line);
    }
  }
  return shard;
}

}  // namespace

void merge_sieve_outputs(const std::vector<std::string>& files, std::FILE* out) {
  if (files.empty()) throw UsageError("merge needs at least one shard output");
  std::vector<ShardFile> shards;
  for (const std::string& path : files) shards.push_back(read_shard(path));
  // An empty file is a shard without survivors, whatever format the run wrote:
  // the headers of the others must agree with the first that has content.
  auto has_content = [](const ShardFile& shard) { return !shard.header_key.empty() || !shard.lines.empty(); };
  const auto model_at = std::find_if(shards.begin(), shards.end(), has_content);
  const ShardFile* model = model_at == shards.end() ? &shards.front() : &*model_at;
  const std::string& model_path = files[static_cast<std::size_t>(model - shards.data())];
  std::optional<std::uint64_t> depth;
  std::unordered_map<std::string_view, std::size_t> seen;
  for (std::size_t i = 0; i < shards.size(); ++i) {
    const ShardFile& shard = shards[i];
    if (has_content(shard) && (shard.kind != model->kind || shard.header_key != model->header_key))
      throw Error("its header does not match " + model_path + "'s: not a shard of the same run", Location{files[i], 1});
    if (shard.depth) depth = depth ? std::min(*depth, *shard.depth) : *shard.depth;
    for (const std::string& line : shard.lines) {
      auto [it, inserted] = seen.try_emplace(line, 0);
      if (it->second == i) ++it->second;  // counts each line once per file
    }
  }

  fmt::memory_buffer buffer;
  auto kept = [&](const std::string& line) { return seen[line] == shards.size(); };
  switch (model->kind) {
    case TextKind::json_lines: break;
    case TextKind::csv:  // one run writes no header row when nothing survives
      if (std::any_of(model->lines.begin(), model->lines.end(), kept))
        fmt::format_to(std::back_inserter(buffer), "{}\n", model->header_key);
      break;
    case TextKind::newpgen: fmt::format_to(std::back_inserter(buffer), "{}:{}\n", *depth, model->header_key); break;
    case TextKind::abc: fmt::format_to(std::back_inserter(buffer), "{} // Sieved to {}\n", model->header_key, *depth); break;
    case TextKind::abcd: break;
  }
  std::optional<std::uint64_t> previous;
  for (const std::string& line : model->lines) {
    if (!kept(line)) continue;
    if (model->kind != TextKind::abcd) {
      fmt::format_to(std::back_inserter(buffer), "{}\n", line);
    } else {
      const std::uint64_t k = std::stoull(line);
      if (!previous) fmt::format_to(std::back_inserter(buffer), "{} [{}] // Sieved to {}\n", model->header_key, k, *depth);
      else fmt::format_to(std::back_inserter(buffer), "{}\n", k - *previous);
      previous = k;
    }
    if (buffer.size() > (1u << 20)) {
      write_text(out, buffer);
      buffer.clear();
    }
  }
  write_text(out, buffer);
  if (std::fflush(out) != 0) throw Error("cannot write the output");
}

}  // namespace tk::primes
