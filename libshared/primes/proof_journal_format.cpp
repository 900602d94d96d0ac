/// @file proof_journal_format.cpp
#include "primes/proof_journal_format.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <charconv>

#include "io/checksum.hpp"
#include "io/error.hpp"
#include "io/record.hpp"

namespace tk::primes {

namespace {

constexpr std::string_view kCheckpointMagic = "riesel-checkpoint 1";
/// Fields riesel writes into a record; all others are the input's.
constexpr std::array<std::string_view, 8> kOwnedFields = {"verdict", "test",    "P",       "a",
                                                          "res64",   "witness", "seconds", "members"};

std::string checksum_text(std::string_view bytes) { return fmt::format("{:016x}", io::fnv1a(bytes)); }

/// Decimal digits as riesel writes them (no sign, blanks or leading zeros), within 64 bits.
std::optional<std::uint64_t> parse_count(std::string_view text) {
  std::uint64_t value = 0;
  if (text.empty() || text.size() > 20 || (text.size() > 1 && text[0] == '0') ||
      !std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; }))
    return std::nullopt;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

std::vector<std::string_view> split(std::string_view text, char separator) {
  std::vector<std::string_view> parts;
  for (std::size_t start = 0;;) {
    const std::size_t end = text.find(separator, start);
    parts.push_back(text.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start));
    if (end == std::string_view::npos) return parts;
    start = end + 1;
  }
}

Record parse_json(std::string_view text) { return Record::parse(text.begin(), text.end(), nullptr, false); }

Record without_owned_fields(Record record) {
  for (std::string_view field : kOwnedFields) record.erase(std::string(field));
  return record;
}

/// Whether record[field] is a string among `names`.
bool one_of(const Record& record, const char* field, std::initializer_list<std::string_view> names) {
  const auto value = record.find(field);
  if (value == record.end() || !value->is_string()) return false;
  const std::string& text = value->get_ref<const std::string&>();
  return std::find(names.begin(), names.end(), text) != names.end();
}

[[noreturn]] void refuse(const std::string& why) { throw Error(why); }

}  // namespace

std::string journal_line(const JournalEntry& entry) {
  const Record lines(entry.log_lines);
  const std::string body = fmt::format("{}\t{}\t{}\t{}", entry.key, entry.output, entry.log_offset,
                                       lines.dump(-1, ' ', false, Record::error_handler_t::replace));
  return body + "\t" + checksum_text(body);
}

JournalEntry parse_journal_line(std::string_view line) {
  const std::vector<std::string_view> fields = split(line, '\t');
  if (fields.size() == 2) refuse("has no checksum (written by an older riesel)");
  if (fields.size() != 5) refuse(fmt::format("has {} fields, not 5", fields.size()));
  const std::string_view body = line.substr(0, line.size() - fields[4].size() - 1);
  if (fields[4] != checksum_text(body)) refuse("fails its checksum");

  JournalEntry entry;
  entry.key = fields[0];
  entry.output = fields[1];
  const std::string_view key = fields[0];
  const Record input = key.size() > 10 ? parse_json(key.substr(10)) : Record();
  if (!(key.starts_with("start=llr ") || key.starts_with("start=d13 ")) || !input.is_object())
    refuse("holds no valid key");
  const Record output = parse_json(fields[1]);
  if (!output.is_object() || !one_of(output, "verdict", {"prime", "composite", "probable-prime"}) ||
      !one_of(output, "test", {"llr", "proth", "trial", "bpsw"}))
    refuse("holds no valid verdict");
  if (without_owned_fields(output) != without_owned_fields(input)) refuse("holds the output of another record");
  const auto offset = parse_count(fields[2]);
  if (!offset) refuse("holds no valid lresults.txt offset");
  entry.log_offset = *offset;
  const Record lines = parse_json(fields[3]);
  if (!lines.is_array()) refuse("holds no valid lresults.txt lines");
  for (const Record& text : lines) {
    if (!text.is_string()) refuse("holds no valid lresults.txt lines");
    const std::string& log_line = text.get_ref<const std::string&>();
    if (log_line.empty() || log_line.find_first_of("\r\n") != std::string::npos)
      refuse("holds no valid lresults.txt lines");
    entry.log_lines.push_back(log_line);
  }
  return entry;
}

JournalText read_journal(std::string_view text) {
  JournalText journal;
  std::uint64_t number = 0;
  for (std::size_t start = 0; start < text.size();) {
    const std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) break;  // torn by a kill mid-append
    ++number;
    const std::string_view line = text.substr(start, end - start);
    try {
      journal.entries.push_back(parse_journal_line(line));
    } catch (const Error& e) {
      journal.refused.push_back({number, std::string(line), e.what()});
    }
    start = end + 1;
    journal.whole_bytes = start;
  }
  return journal;
}

std::string log_text(const JournalEntry& entry) {
  std::string text;
  for (const std::string& line : entry.log_lines) text += line + "\n";
  return text;
}

std::optional<std::string> log_completion(std::string_view written, const JournalEntry& entry) {
  const std::string all = log_text(entry);
  if (written.size() >= all.size() || !std::string_view(all).starts_with(written)) return std::nullopt;
  return all.substr(written.size());
}

std::string checkpoint_text(const std::string& member, const ProofState& state) {
  const std::string body =
      fmt::format("{}\n{}\n{}\n{}\n", kCheckpointMagic, member, state.iteration, state.value.get_str(16));
  return body + checksum_text(body) + "\n";
}

ProofState parse_checkpoint(std::string_view text, const std::string& member) {
  std::vector<std::string_view> lines = split(text, '\n');
  if (lines.size() < 6 || !lines.back().empty()) refuse("is truncated");
  if (lines.size() > 6) refuse("has lines after its checksum");
  if (lines[0] != kCheckpointMagic) refuse("is not a riesel checkpoint");
  if (lines[4] != checksum_text(text.substr(0, text.size() - lines[4].size() - 1))) refuse("fails its checksum");
  if (lines[1] != member) refuse("belongs to " + std::string(lines[1]));
  ProofState state;
  const auto iteration = parse_count(lines[2]);
  if (!iteration) refuse("holds no valid iteration");
  state.iteration = *iteration;
  // Lower-case hex without leading zeros, as checkpoint_text writes it.
  const std::string_view hex = lines[3];
  if (hex.empty() || (hex.size() > 1 && hex[0] == '0') ||
      !std::all_of(hex.begin(), hex.end(), [](char c) { return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'); }) ||
      state.value.set_str(std::string(hex), 16) != 0)
    refuse("holds no valid residue");
  return state;
}

}  // namespace tk::primes
