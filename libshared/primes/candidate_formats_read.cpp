/// @file candidate_formats_read.cpp
/// @brief NewPGen and ABC/ABCD files mapped onto the shared candidate
/// records. A header line (which may recur anywhere in a file, as LLR and
/// PFGW allow) decides how the data lines after it are read.
#include "primes/candidate_formats.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "io/error.hpp"
#include "io/text.hpp"
#include "primes/candidate.hpp"

namespace tk::primes {

namespace {

using io::trim;

constexpr std::uint64_t kMaxExponent = 0xFFFFFFFFu;  // n must fit 32 bits
constexpr std::uint64_t kMaxChainLength = 64;        // the most candidate_from_record accepts

/// Whitespace-separated words; stops after `limit` + 1 so a huge junk line
/// cannot make a huge vector.
std::vector<std::string_view> words(std::string_view text, std::size_t limit) {
  std::vector<std::string_view> out;
  std::size_t pos = 0;
  while (out.size() <= limit && (pos = text.find_first_not_of(" \t", pos)) != std::string_view::npos) {
    const std::size_t end = std::min(text.find_first_of(" \t", pos), text.size());
    out.push_back(text.substr(pos, end - pos));
    pos = end;
  }
  return out;
}

bool all_digits(std::string_view text) {
  return !text.empty() && text.find_first_not_of("0123456789") == std::string_view::npos;
}

std::optional<std::uint64_t> parse_u64(std::string_view text) {
  std::uint64_t value = 0;
  const bool fits =
      all_digits(text) && std::from_chars(text.data(), text.data() + text.size(), value).ec == std::errc();
  return fits ? std::optional(value) : std::nullopt;
}

/// Input text quoted in a message, cut short, control bytes shown as '?'.
std::string quoted(std::string_view text) {
  std::string out(text.substr(0, 60));
  for (char& ch : out)
    if (static_cast<unsigned char>(ch) < 0x20 || static_cast<unsigned char>(ch) >= 0x7f) ch = '?';
  return "'" + out + (text.size() > 60 ? "...'" : "'");
}

/// Decimal digits a value may have and still fit `max_bits` bits.
std::size_t max_decimal_digits(std::size_t max_bits) {
  return static_cast<std::size_t>(static_cast<double>(max_bits) * 0.30102999566398120) + 2;
}

/// Error unless k*b^n fits `max_bits` (the same estimate as evaluate_kbnc).
void check_size(const mpz_class& k, std::uint64_t b, std::uint64_t n, std::size_t max_bits) {
  const double bits = static_cast<double>(n) * std::log2(static_cast<double>(b)) +
                      static_cast<double>(mpz_sizeinbase(k.get_mpz_t(), 2));
  if (bits > static_cast<double>(max_bits) + 1)
    throw Error("number has about " + std::to_string(static_cast<std::uint64_t>(std::min(bits, 1e18))) +
                " bits, more than --max-bits " + std::to_string(max_bits));
}

/// k of a candidate: decimal digits (an optional '+'), positive, sized by max_bits.
mpz_class parse_k(std::string_view text, std::size_t max_bits) {
  if (text.starts_with('+')) text.remove_prefix(1);
  if (!all_digits(text)) throw Error("k " + quoted(text) + " is not a positive decimal integer");
  if (text.size() > max_decimal_digits(max_bits))
    throw Error("k has more bits than --max-bits " + std::to_string(max_bits));
  const mpz_class k(std::string(text), 10);
  if (k == 0) throw Error("k must be positive");
  return k;
}

std::uint64_t parse_n(std::string_view text) {
  if (text.starts_with('+')) text.remove_prefix(1);
  if (!all_digits(text)) throw Error("n " + quoted(text) + " is not a non-negative decimal integer");
  const auto n = parse_u64(text);
  if (!n || *n > kMaxExponent) throw Error("n " + quoted(text) + " does not fit 32 bits");
  return *n;
}

Record number_record(const mpz_class& k, std::uint64_t b, std::uint64_t n, std::int64_t c) {
  return Record{{"k", json_integer(k)}, {"b", b}, {"n", n}, {"c", c}};
}

Record form_record(const mpz_class& k, std::uint64_t n, const std::string& form, std::uint64_t length) {
  Record record{{"k", json_integer(k)}, {"n", n}, {"form", form}};
  if (form == "cc1" || form == "cc2") record["length"] = length;
  return record;
}

// ---------------------------------------------------------------- NewPGen

// Mask bits as NewPGen, LLR and PFGW name them (see the research note).
enum : std::uint64_t {
  kPlus = 0x1,
  kMinus = 0x2,
  k2Plus = 0x4,
  k2Minus = 0x8,
  k4Plus = 0x10,
  k4Minus = 0x20,
  kPrimorial = 0x40,
  kKSieve = 0x100,
  kNotGeneralised = 0x400,
  kDual = 0x8000,
  kOtherMembers = 0x80 | 0x200 | 0x800 | 0x1000,  // +5, AP, +7, 2k*b^n+3
};

/// What a NewPGen data line "k n" stands for, worked out once from the header.
struct NewPGenShape {
  std::uint64_t base = 2;
  std::int64_t offset = 0;          ///< the first member's exponent is n + offset
  std::optional<std::string> form;  ///< twin, sg, cc1, cc2; none for one number
  std::uint64_t length = 1;         ///< members of a cc1/cc2 chain
  std::int64_t c = 0;               ///< +1 or -1 of a single number
  bool dual = false;                ///< b^n + c*k instead of k*b^n + c
};

/// Members as (exponent offset, sign), from LLR's reading of the header.
/// Where LLR and PFGW disagree we follow LLR (llr2's primeContinue), since
/// LLR is the tester these files are usually fed to:
/// - a nonzero mask overrides the letter (PFGW lets the letter win), so
///   "M" with mask 1 is k*b^n+1; only a missing or zero mask reads the letter;
/// - with a mask, chain letters 1/2 start at n (llr2 dropped PRP.EXE's
///   n-1); without one, LLR, PRP.EXE and PFGW all start them at n-1;
/// - bit 0x100 is NewPGen's fixed-k label and changes no formula (llr2 and
///   PFGW agree; only llrCUDA 3.8.7 reads it as an extra 2k*b^n-3 member).
NewPGenShape parse_newpgen_header(std::string_view header) {
  std::vector<std::string_view> fields;
  for (std::size_t start = 0, colon = 0; colon != std::string_view::npos && fields.size() < 6; start = colon + 1) {
    colon = header.find(':', start);
    fields.push_back(header.substr(start, colon == std::string_view::npos ? colon : colon - start));
  }
  const std::string name = quoted(header);
  if (fields.size() < 4 || fields.size() > 5 || fields[1].size() != 1)
    throw Error("newpgen header " + name + " is not depth:letter:chain:base:mask");
  const auto depth = parse_u64(fields[0]), chain = parse_u64(fields[2]), base = parse_u64(fields[3]);
  const auto mask = fields.size() == 5 ? parse_u64(fields[4]) : std::optional<std::uint64_t>(0);
  if (!depth || !chain || !base || !mask)
    throw Error("newpgen header " + name + " needs decimal depth, chain, base and mask fields");
  const char letter = fields[1][0];
  if (std::string_view("PMTSCBJKYZ123A").find(letter) == std::string_view::npos)
    throw Error("newpgen header " + name + " has unknown letter " + quoted(fields[1]));
  if (*base < 2) throw Error("newpgen header " + name + " has base below 2");
  auto unsupported = [&](const std::string& why) {
    return Error("newpgen mode " + name + " is not supported: " + why);
  };

  std::vector<std::pair<std::int64_t, int>> members;
  std::uint64_t chain_length = std::max<std::uint64_t>(*chain, 1);  // LLR reads 0 as 1
  auto add_chain = [&](std::int64_t first, std::uint64_t length, int sign) {
    if (length > kMaxChainLength) throw unsupported("chains longer than 64");
    for (std::uint64_t i = 0; i < length; ++i) members.emplace_back(first + static_cast<std::int64_t>(i), sign);
  };
  const std::uint64_t bits = *mask;
  if (bits == 0) {
    switch (letter) {
      case 'P':
      case 'M': add_chain(0, 1, letter == 'P' ? +1 : -1); break;
      case 'T':
        add_chain(0, 1, -1);
        add_chain(0, 1, +1);
        break;
      case 'S':
      case 'C': add_chain(0, 2, letter == 'C' ? +1 : -1); break;
      case '1':
      case '2': add_chain(-1, chain_length, letter == '2' ? +1 : -1); break;
      default: throw unsupported("letter " + std::string(1, letter) + " has no record shape");
    }
  } else {
    if (bits & kPrimorial) throw unsupported("primorial files");
    if (bits & kOtherMembers) throw unsupported("members other than k*b^n+1 and k*b^n-1");
    const std::uint64_t known = 0x3f | kKSieve | kNotGeneralised | kDual;
    if (bits & ~known) throw unsupported("unknown mask bits");
    // LLR tests these "either-or" combinations specially; no record says that.
    if ((bits & (kPlus | k2Minus | k2Plus | k4Plus)) == (kPlus | k2Minus | k2Plus | k4Plus) ||
        (bits & (kMinus | k2Minus | k2Plus | k4Minus)) == (kMinus | k2Minus | k2Plus | k4Minus))
      throw unsupported("lucky plus/minus");
    if (letter == 'S' || letter == 'C' || letter == 'B') chain_length = 2;  // as LLR forces
    if (chain_length > 1) {  // LLR lets the chain loop step n and ignores the 2x/4x bits
      if (bits & kMinus) add_chain(0, chain_length, -1);
      if (bits & kPlus) add_chain(0, chain_length, +1);
    } else {
      const std::pair<std::uint64_t, std::pair<std::int64_t, int>> kBits[] = {{kMinus, {0, -1}},  {kPlus, {0, +1}},
                                                                              {k2Minus, {1, -1}}, {k2Plus, {1, +1}},
                                                                              {k4Minus, {2, -1}}, {k4Plus, {2, +1}}};
      for (const auto& [bit, member] : kBits)
        if (bits & bit) members.push_back(member);
    }
  }
  if (members.empty()) throw unsupported("the mask selects no numbers");
  std::sort(members.begin(), members.end());

  NewPGenShape shape;
  shape.base = *base;
  shape.offset = members.front().first;
  shape.dual = (bits & kDual) != 0;
  bool one_sign_run = true;  // k*b^(n+i)+c for consecutive i, one c
  for (std::size_t i = 0; i < members.size(); ++i)
    one_sign_run = one_sign_run && members[i].second == members[0].second &&
                   members[i].first == shape.offset + static_cast<std::int64_t>(i);
  if (members.size() == 1) {
    // With 0x400 an offset doubles k instead of raising n: the same number in base 2 only.
    if ((bits & kNotGeneralised) && shape.offset != 0 && shape.base != 2)
      throw unsupported("2k/4k members outside base 2");
    shape.c = members[0].second;
  } else if (shape.base != 2) {
    throw unsupported("forms with several members are defined for base 2 only");
  } else if (one_sign_run) {
    shape.form = members[0].second < 0 ? (members.size() == 2 ? "sg" : "cc1") : "cc2";
    shape.length = members.size();
  } else if (members.size() == 2 && members[0].first == members[1].first) {
    shape.form = "twin";
  } else {
    throw unsupported("its members are not a twin, sophie germain pair or cunningham chain");
  }
  if (shape.dual && (shape.form || shape.offset != 0)) throw unsupported("dual files other than b^n+k or b^n-k");
  return shape;
}

Record newpgen_record(const NewPGenShape& shape, std::string_view line, std::size_t max_bits) {
  const auto fields = words(line, 2);
  if (fields.size() != 2) throw Error("newpgen data line must be 'k n'");
  const mpz_class k = parse_k(fields[0], max_bits);
  std::uint64_t n = parse_n(fields[1]);
  if (shape.offset < 0 && n < static_cast<std::uint64_t>(-shape.offset))
    throw Error("n must be at least 1: this chain starts at k*b^(n-1)");
  n = static_cast<std::uint64_t>(static_cast<std::int64_t>(n) + shape.offset);  // offset -1..2, n < 2^32
  if (shape.dual) {                                                             // b^n+k or b^n-k, as LLR's MODE_DUAL
    if (k >= (mpz_class(1) << 62)) throw Error("k of a dual newpgen file must be below 2^62");
    check_size(1, shape.base, n, max_bits);
    return number_record(1, shape.base, n, shape.c * mpz_get_si(k.get_mpz_t()));
  }
  check_size(k, shape.base, n + shape.length - 1, max_bits);
  if (shape.form) return form_record(k, n, *shape.form, shape.length);
  return number_record(k, shape.base, n, shape.c);
}

// ---------------------------------------------------------------- ABC, ABCD

/// An ABC or ABCD expression, ready for the values of its data lines.
struct AbcTemplate {
  std::string expression;           ///< placeholders lower-cased to $a..$z
  std::size_t variable_count = 0;   ///< values per data line: $a up to the highest letter used
  std::optional<std::string> form;  ///< twin, sg, cc1 or cc2 for PFGW's &-joined members
  std::uint64_t length = 2;         ///< members of the form
  std::string k_text, n_text;       ///< the form's k and n: a placeholder or digits
};

/// prefix K*2^N suffix, with K and N each a placeholder or digits.
std::optional<std::pair<std::string, std::string>> match_k2n(std::string_view text, std::string_view prefix,
                                                             std::string_view suffix) {
  if (text.size() < prefix.size() + suffix.size() || !text.starts_with(prefix) || !text.ends_with(suffix))
    return std::nullopt;
  text = text.substr(prefix.size(), text.size() - prefix.size() - suffix.size());
  const auto power = text.find("*2^");
  if (power == std::string_view::npos) return std::nullopt;
  const std::string_view k = text.substr(0, power), n = text.substr(power + 3);
  auto is_operand = [](std::string_view s) { return all_digits(s) || (s.size() == 2 && s[0] == '$' && s[1] >= 'a'); };
  if (!is_operand(k) || !is_operand(n)) return std::nullopt;
  return std::make_pair(std::string(k), std::string(n));
}

/// Sets t.form for the pairs twinsieve and sgsieve write, in either order:
/// K*2^N+1 & K*2^N-1 (twin) and K*2^N-1 & 2*(K*2^N-1)+1 (Sophie Germain).
bool match_pair(std::string_view first, std::string_view second, AbcTemplate& t) {
  struct Pattern {
    const char* form;
    std::string_view prefix1, suffix1, prefix2, suffix2;
  };
  static constexpr Pattern kPatterns[] = {{"twin", "", "+1", "", "-1"}, {"sg", "", "-1", "2*(", "-1)+1"}};
  for (int order = 0; order < 2; ++order, std::swap(first, second)) {
    for (const Pattern& p : kPatterns) {
      const auto one = match_k2n(first, p.prefix1, p.suffix1), other = match_k2n(second, p.prefix2, p.suffix2);
      if (!one || !other || *one != *other) continue;
      t.form = p.form;
      std::tie(t.k_text, t.n_text) = *one;
      return true;
    }
  }
  return false;
}

/// Sets t.form for a chain K*2^N+c & K*2^(N+1)+c & ... (one c, numeric
/// exponents that run on by one, in any order), as sieve writes chains.
bool match_chain(const std::vector<std::string>& parts, AbcTemplate& t) {
  std::optional<std::pair<std::string, std::string>> first;
  std::vector<std::uint64_t> exponents;
  const std::string_view sign =
      std::string_view(parts.front()).substr(std::max<std::size_t>(parts.front().size(), 2) - 2);
  if (sign != "-1" && sign != "+1") return false;
  for (const std::string& part : parts) {
    const auto kn = match_k2n(part, "", sign);
    if (!kn || !all_digits(kn->second) || (first && kn->first != first->first)) return false;
    const auto n = parse_u64(kn->second);
    if (!n || *n > kMaxExponent) return false;
    if (!first) first = kn;
    exponents.push_back(*n);
  }
  std::sort(exponents.begin(), exponents.end());
  for (std::size_t i = 1; i < exponents.size(); ++i)
    if (exponents[i] != exponents[0] + i) return false;
  t.form = sign == "+1" ? "cc2" : (parts.size() == 2 ? "sg" : "cc1");
  t.length = parts.size();
  t.k_text = first->first;
  t.n_text = std::to_string(exponents[0]);
  return true;
}

AbcTemplate parse_abc_expression(std::string_view text) {
  AbcTemplate t;
  int highest = -1;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char ch = text[i];
    if (ch == '$') {
      const char next = i + 1 < text.size() ? text[i + 1] : '\0';
      const bool lower = next >= 'a' && next <= 'z', upper = next >= 'A' && next <= 'Z';
      if (!lower && !upper) throw Error("'$' must be followed by a letter a-z in abc expression " + quoted(text));
      const char letter = lower ? next : static_cast<char>(next - 'A' + 'a');  // PFGW reads $A as $a
      highest = std::max(highest, letter - 'a');
      t.expression += '$';
      t.expression += letter;
      ++i;
    } else if (std::string_view("0123456789+-*/%^()!#&| \t").find(ch) == std::string_view::npos) {
      throw Error("abc expression " + quoted(text) + " uses " + quoted(std::string_view(&ch, 1)) +
                  ", which is not supported");
    } else {
      t.expression += ch;
    }
  }
  if (trim(t.expression).empty()) throw Error("abc header has no expression");
  if (highest < 0) throw Error("abc expression " + quoted(text) + " has no $a..$z variable");
  t.variable_count = static_cast<std::size_t>(highest) + 1;
  if (t.expression.find('|') != std::string::npos)
    throw Error("abc headers joining expressions with '|' are not supported");
  if (t.expression.find('&') != std::string::npos) {
    std::vector<std::string> parts;
    for (std::size_t start = 0, amp = 0; amp != std::string::npos; start = amp + 1) {
      amp = t.expression.find('&', start);
      parts.push_back(t.expression.substr(start, amp == std::string::npos ? amp : amp - start));
      std::erase_if(parts.back(), [](char ch) { return ch == ' ' || ch == '\t'; });
    }
    const bool pair = parts.size() == 2 && match_pair(parts[0], parts[1], t);
    if (!pair && (parts.size() > kMaxChainLength || !match_chain(parts, t)))
      throw Error("abc header " + quoted(text) +
                  " joins expressions with '&'; only K*2^N+1 & K*2^N-1 (twin), K*2^N-1 & 2*(K*2^N-1)+1"
                  " (sophie germain) and chains K*2^N+c & K*2^(N+1)+c & ... are supported");
  }
  t.expression = std::string(trim(t.expression));
  return t;
}

/// Signed decimal values, one per variable, as a data line (or an ABCD
/// header's brackets) gives them.
std::vector<std::string> abc_values(std::string_view text, std::size_t count, std::size_t max_bits) {
  if (text.find(':') != std::string_view::npos) throw Error("separate values with spaces, not ':'");
  const auto fields = words(text, count);
  if (fields.size() != count)
    throw Error("expected " + std::to_string(count) + " values ($a...), found " +
                (fields.size() > count ? "more" : std::to_string(fields.size())));
  std::vector<std::string> values;
  for (std::string_view field : fields) {
    const std::string_view digits = field.substr(field[0] == '+' || field[0] == '-' ? 1 : 0);
    if (!all_digits(digits)) throw Error("value " + quoted(field) + " is not a decimal integer");
    if (digits.size() > max_decimal_digits(max_bits))
      throw Error("value has more bits than --max-bits " + std::to_string(max_bits));
    values.emplace_back(field);
  }
  return values;
}

/// PFGW substitutes values as text: "$a*2^$b$c" with "+1" for $c is k*2^n+1.
std::string substitute(std::string_view pattern, const std::vector<std::string>& values, std::size_t max_bits) {
  std::size_t length = 0;
  for (std::size_t i = 0; i < pattern.size(); ++i) length += pattern[i] == '$' ? values[pattern[++i] - 'a'].size() : 1;
  // A sane expression's text is not much longer than its value's digits.
  if (length > pattern.size() + 4 * max_decimal_digits(max_bits))
    throw Error("expression with its values is too long for --max-bits " + std::to_string(max_bits));
  std::string out;
  out.reserve(length);
  for (std::size_t i = 0; i < pattern.size(); ++i) {
    if (pattern[i] == '$') out += values[pattern[++i] - 'a'];
    else out += pattern[i];
  }
  return out;
}

Record abc_record(const AbcTemplate& t, const std::vector<std::string>& values, std::size_t max_bits) {
  if (!t.form) return record_from_number_text(substitute(t.expression, values, max_bits), max_bits);
  const mpz_class k = parse_k(substitute(t.k_text, values, max_bits), max_bits);
  const std::uint64_t n = parse_n(substitute(t.n_text, values, max_bits));
  check_size(k, 2, *t.form == "twin" ? n : n + t.length - 1, max_bits);
  return form_record(k, n, *t.form, t.length);
}

// ---------------------------------------------------------------- the decoder

/// The header text after its keyword and before any "// comment".
std::string_view header_body(std::string_view text, std::size_t keyword_length) {
  text.remove_prefix(keyword_length);
  return trim(text.substr(0, text.find("//")));
}

class PrimeTextDecoder final : public io::LineDecoder {
 public:
  explicit PrimeTextDecoder(std::size_t max_bits) : max_bits_(max_bits) {}

  bool decode(std::string_view line, const Location& where, Record& out) override {
    return with_location(where, [&] { return decode_line(trim(line), out); });
  }

 private:
  enum class Mode { none, newpgen, abc, abcd };

  bool decode_line(std::string_view text, Record& out) {
    if (text.empty() || text.starts_with("//")) return false;
    const CandidateHeader kind = candidate_header_kind(text);
    if (kind != CandidateHeader::none) mode_ = Mode::none;  // until the new header proves valid
    switch (kind) {
      case CandidateHeader::newpgen:
        newpgen_ = parse_newpgen_header(text);
        mode_ = Mode::newpgen;
        return false;
      case CandidateHeader::abc:
        abc_ = parse_abc_expression(header_body(text, 3));
        mode_ = Mode::abc;
        return false;
      case CandidateHeader::abcd:  // the header itself is the first candidate
        start_abcd(header_body(text, 4));
        out = abc_record(abc_, running_text(), max_bits_);
        return true;
      // One ABC2 header stands for many candidates; a LineDecoder yields one per line.
      case CandidateHeader::abc2: throw Error("abc2 files are not supported");
      case CandidateHeader::none: break;
    }
    switch (mode_) {
      case Mode::none: throw Error("data line without a valid newpgen, abc or abcd header before it");
      case Mode::newpgen: out = newpgen_record(newpgen_, text, max_bits_); return true;
      case Mode::abc: out = abc_record(abc_, abc_values(text, abc_.variable_count, max_bits_), max_bits_); return true;
      case Mode::abcd:
        apply_deltas(text);
        out = abc_record(abc_, running_text(), max_bits_);
        return true;
    }
    return false;
  }

  /// "ABCD expr [v1 v2 ...]": PFGW cuts the bracketed initial values out.
  void start_abcd(std::string_view body) {
    const auto open = body.find('['), close = body.find(']');
    if (open == std::string_view::npos || close == std::string_view::npos || close < open)
      throw Error("abcd header needs the initial values in [...]");
    if (!trim(body.substr(close + 1)).empty()) throw Error("unexpected text after ']' in abcd header");
    abc_ = parse_abc_expression(body.substr(0, open));
    running_.clear();
    for (const std::string& value : abc_values(body.substr(open + 1, close - open - 1), abc_.variable_count, max_bits_))
      running_.emplace_back(value.substr(value[0] == '+' ? 1 : 0), 10);
    mode_ = Mode::abcd;
  }

  /// Adds a line's deltas to the running values; a bad line changes none.
  void apply_deltas(std::string_view text) {
    std::vector<mpz_class> next = running_;
    const auto deltas = abc_values(text, abc_.variable_count, max_bits_);
    for (std::size_t i = 0; i < deltas.size(); ++i) {
      next[i] += mpz_class(deltas[i].substr(deltas[i][0] == '+' ? 1 : 0), 10);
      if (mpz_sizeinbase(next[i].get_mpz_t(), 2) > max_bits_)
        throw Error("running value of $" + std::string(1, static_cast<char>('a' + i)) + " exceeds --max-bits " +
                    std::to_string(max_bits_));
    }
    running_ = std::move(next);
  }

  std::vector<std::string> running_text() const {
    std::vector<std::string> text;
    for (const mpz_class& value : running_) text.push_back(value.get_str());
    return text;
  }

  std::size_t max_bits_;
  Mode mode_ = Mode::none;
  NewPGenShape newpgen_;
  AbcTemplate abc_;
  std::vector<mpz_class> running_;  ///< ABCD: current $a, $b, ...
};

}  // namespace

std::unique_ptr<io::LineDecoder> probe_candidate_format(std::string_view first_line, std::size_t max_bits) {
  if (candidate_header_kind(trim(first_line)) == CandidateHeader::none) return nullptr;
  return std::make_unique<PrimeTextDecoder>(max_bits);
}

}  // namespace tk::primes
