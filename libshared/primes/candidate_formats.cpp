/// @file candidate_formats.cpp
/// @brief The header grammar of NewPGen, ABC and ABCD files: telling the
/// headers apart, and the headers sieve writes and merges read back.
#include "primes/candidate_formats.hpp"

#include <fmt/format.h>

#include <charconv>

namespace tk::primes {

namespace {

constexpr std::string_view kSievedTo = " // Sieved to ";

/// NewPGen's "letter:chain:base:mask" for a sieve form.
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
        text += fmt::format("{}$a*2^{}{}", text.empty() ? "" : " & ", n + member.exponent_offset,
                            member.c < 0 ? "-1" : "+1");
      return text;
    }
  }
  return {};
}

std::uint64_t parse_depth(std::string_view text, const Location& where) {
  std::uint64_t value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || text.empty())
    throw Error("the sieve depth '" + std::string(text) + "' is not a number", where);
  return value;
}

/// Splits "... // Sieved to D" into the text before it and D.
void split_sieved_to(std::string_view line, SieveHeader& header, const Location& where) {
  const auto mark = line.rfind(kSievedTo);
  if (mark == std::string_view::npos) throw Error("abc header without '// Sieved to': not written by sieve", where);
  header.key = std::string(line.substr(0, mark));
  header.depth = parse_depth(line.substr(mark + kSievedTo.size()), where);
}

}  // namespace

CandidateHeader candidate_header_kind(std::string_view text) {
  const std::string_view word = text.substr(0, text.find_first_of(" \t"));
  if (word == "ABC") return CandidateHeader::abc;
  if (word == "ABCD") return CandidateHeader::abcd;
  if (word == "ABC2") return CandidateHeader::abc2;
  // LLR takes any line that starts "<digits>:" for a NewPGen header.
  const auto digits_end = text.find_first_not_of("0123456789");
  if (digits_end != 0 && digits_end != std::string_view::npos && text[digits_end] == ':')
    return CandidateHeader::newpgen;
  return CandidateHeader::none;
}

std::string sieve_header_key(const SieveSpec& spec, CandidateHeader kind) {
  const bool single = spec.form == SieveForm::riesel || spec.form == SieveForm::proth;
  switch (kind) {
    case CandidateHeader::newpgen: return newpgen_shape(spec);
    case CandidateHeader::abc: return "ABC " + abc_expression(spec, single);
    case CandidateHeader::abcd: return "ABCD " + abc_expression(spec, false);
    default: return {};
  }
}

std::string sieve_header_line(const SieveHeader& header) {
  switch (header.kind) {
    case CandidateHeader::newpgen: return fmt::format("{}:{}", header.depth, header.key);
    case CandidateHeader::abc: return fmt::format("{}{}{}", header.key, kSievedTo, header.depth);
    case CandidateHeader::abcd:
      return fmt::format("{} [{}]{}{}", header.key, header.abcd_start, kSievedTo, header.depth);
    default: return {};
  }
}

SieveHeader parse_sieve_header(std::string_view line, const Location& where) {
  SieveHeader header;
  header.kind = candidate_header_kind(line);
  switch (header.kind) {
    case CandidateHeader::newpgen: {
      const auto colon = line.find(':');
      header.depth = parse_depth(line.substr(0, colon), where);
      header.key = std::string(line.substr(colon + 1));
      break;
    }
    case CandidateHeader::abc: split_sieved_to(line, header, where); break;
    case CandidateHeader::abcd: {
      split_sieved_to(line, header, where);
      const auto open = header.key.rfind(" ["), close = header.key.rfind(']');
      if (open == std::string::npos || close == std::string::npos || close < open)
        throw Error("abcd header without a [k] start value", where);
      header.abcd_start = parse_depth(std::string_view(header.key).substr(open + 2, close - open - 2), where);
      if (close + 1 != header.key.size()) throw Error("abcd header has text after its [k] start value", where);
      header.key.erase(open);
      break;
    }
    case CandidateHeader::abc2: throw Error("abc2 header: not written by sieve", where);
    case CandidateHeader::none: break;
  }
  return header;
}

std::uint64_t parse_abcd_difference(std::string_view line, const Location& where) { return parse_depth(line, where); }

}  // namespace tk::primes
