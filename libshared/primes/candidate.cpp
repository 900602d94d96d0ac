/// @file candidate.cpp
#include "primes/candidate.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "io/error.hpp"
#include "primes/number_expression.hpp"

namespace tk::primes {

namespace {

constexpr std::uint64_t kMaxSafeJsonInteger = (std::uint64_t{1} << 53) - 1;

/// An integer field as JSON number or decimal string.
mpz_class integer_field(const Record& record, const char* name, std::size_t max_bits) {
  const auto found = record.find(name);
  if (found == record.end()) throw Error(std::string("missing field '") + name + "'");
  const Record& value = *found;
  if (value.is_number_unsigned()) return mpz_class(value.get<unsigned long>());
  if (value.is_number_integer()) return mpz_class(value.get<long>());
  if (value.is_number_float()) {
    const double d = value.get<double>();
    if (!std::isfinite(d) || d != std::floor(d)) throw Error(std::string("field '") + name + "' is not an integer");
    // 1e5 is an integer written as a float; above 2^53 digits may be lost.
    if (std::fabs(d) <= static_cast<double>(kMaxSafeJsonInteger)) return mpz_class(d);
    throw Error(std::string("field '") + name +
                "' is too large for a json number; write it as a string of decimal digits");
  }
  if (!value.is_string()) throw Error(std::string("field '") + name + "' must be an integer or a string of digits");
  const std::string& text = value.get_ref<const std::string&>();
  if (text.empty()) throw Error(std::string("field '") + name + "' is empty");
  return parse_number(text, max_bits).value;
}

std::uint64_t word_field(const Record& record, const char* name, std::uint64_t max) {
  const mpz_class v = integer_field(record, name, 128);
  if (v < 0 || v > mpz_class(static_cast<unsigned long>(max)))
    throw Error(std::string("field '") + name + "' out of range 0.." + std::to_string(max));
  return mpz_get_ui(v.get_mpz_t());
}

std::int64_t small_signed_field(const Record& record, const char* name) {
  const mpz_class v = integer_field(record, name, 128);
  if (abs(v) >= (mpz_class(1) << 62)) throw Error(std::string("field '") + name + "' out of range");
  return mpz_get_si(v.get_mpz_t());
}

Member make_member(const mpz_class& k, std::uint64_t b, std::uint64_t n, std::int64_t c, std::size_t max_bits) {
  Member m;
  m.n = n;
  m.c = c;
  KbncForm form{k, b, n, c};
  m.number.value = evaluate_kbnc(form, max_bits);
  m.number.form = form;
  return m;
}

}  // namespace

bool is_known_form(const std::string& name) {
  static const char* const kForms[] = {"riesel", "proth", "twin", "sg", "cc1", "cc2"};
  return std::find(std::begin(kForms), std::end(kForms), name) != std::end(kForms);
}

Record json_integer(const mpz_class& value) {
  if (value >= 0 && value <= mpz_class(static_cast<unsigned long>(kMaxSafeJsonInteger)))
    return Record(mpz_get_ui(value.get_mpz_t()));
  if (value < 0 && value >= -mpz_class(static_cast<unsigned long>(kMaxSafeJsonInteger)))
    return Record(mpz_get_si(value.get_mpz_t()));
  return Record(value.get_str());
}

Candidate candidate_from_record(const Record& record, std::size_t max_bits) {
  Candidate candidate;
  if (record.contains("number") || record.contains("expr")) {
    const char* field = record.contains("number") ? "number" : "expr";
    const Record& value = record[field];
    Member m;
    if (value.is_string()) {
      if (value.get_ref<const std::string&>().empty()) throw Error(std::string("field '") + field + "' is empty");
      m.number = parse_number(value.get_ref<const std::string&>(), max_bits);
    } else {
      m.number.value = integer_field(record, field, max_bits);
    }
    candidate.members.push_back(std::move(m));
    return candidate;
  }
  if (!record.contains("k") || !record.contains("n"))
    throw Error("record needs 'number', 'expr', or 'k' and 'n' (with 'c' or 'form')");
  const mpz_class k = integer_field(record, "k", max_bits);
  if (k < 1) throw Error("field 'k' must be positive");
  const std::uint64_t n = word_field(record, "n", max_bits);

  if (record.contains("form")) {
    if (!record["form"].is_string()) throw Error("field 'form' must be a string");
    const std::string form = record["form"].get<std::string>();
    if (!is_known_form(form)) throw Error("unknown form '" + form + "' (expected riesel, proth, twin, sg, cc1 or cc2)");
    if (record.contains("b") && word_field(record, "b", ~std::uint64_t{0}) != 2)
      throw Error("forms are defined for base 2 only");
    candidate.form = form;
    auto add = [&](std::uint64_t exponent, std::int64_t c) {
      candidate.members.push_back(make_member(k, 2, exponent, c, max_bits));
    };
    if (form == "riesel") add(n, -1);
    else if (form == "proth") add(n, 1);
    else if (form == "twin") {
      add(n, -1);
      add(n, 1);
    } else if (form == "sg") {
      add(n, -1);
      add(n + 1, -1);
    } else {
      const std::uint64_t length = word_field(record, "length", 64);
      if (length < 1) throw Error("field 'length' must be at least 1");
      for (std::uint64_t i = 0; i < length; ++i) add(n + i, form == "cc1" ? -1 : 1);
    }
    return candidate;
  }
  if (!record.contains("c")) throw Error("record with 'k' and 'n' needs 'c' or 'form'");
  const std::uint64_t b = record.contains("b") ? word_field(record, "b", ~std::uint64_t{0}) : 2;
  if (b < 2) throw Error("field 'b' must be at least 2");
  candidate.members.push_back(make_member(k, b, n, small_signed_field(record, "c"), max_bits));
  return candidate;
}

namespace {

/// The text as digit runs and operators ("**" read as '^'), spaces dropped;
/// empty when anything else occurs.
std::vector<std::string_view> kbnc_tokens(std::string_view text) {
  std::vector<std::string_view> tokens;
  for (std::size_t i = 0; i < text.size();) {
    const char ch = text[i];
    if (ch == ' ' || ch == '\t') {
      ++i;
    } else if (std::isdigit(static_cast<unsigned char>(ch))) {
      std::size_t end = i;
      while (end < text.size() && std::isdigit(static_cast<unsigned char>(text[end]))) ++end;
      tokens.push_back(text.substr(i, end - i));
      i = end;
    } else if (text.substr(i, 2) == "**") {
      tokens.push_back("^");
      i += 2;
    } else if (ch == '*' || ch == '^' || ch == '+' || ch == '-') {
      tokens.push_back(text.substr(i, 1));
      ++i;
    } else {
      return {};
    }
  }
  return tokens;
}

/// k*b^n+c, b^n*k+c or b^n+c read from the text alone, without computing
/// the number: the reader thread only sorts lines, the workers compute.
std::optional<KbncForm> match_kbnc_text(std::string_view text) {
  const auto t = kbnc_tokens(text);
  auto is_number = [&](std::size_t i) { return i < t.size() && std::isdigit(static_cast<unsigned char>(t[i][0])); };
  auto is_op = [&](std::size_t i, char op) { return i < t.size() && t[i].size() == 1 && t[i][0] == op; };
  std::string_view k = "1", b, n, c, sign;
  if (t.size() == 7 && is_number(0) && is_op(1, '*') && is_number(2) && is_op(3, '^') && is_number(4)) {
    k = t[0], b = t[2], n = t[4];  // k*b^n+c
  } else if (t.size() == 7 && is_number(0) && is_op(1, '^') && is_number(2) && is_op(3, '*') && is_number(4)) {
    b = t[0], n = t[2], k = t[4];  // b^n*k+c
  } else if (t.size() == 5 && is_number(0) && is_op(1, '^') && is_number(2)) {
    b = t[0], n = t[2];  // b^n+c
  } else {
    return std::nullopt;
  }
  sign = t[t.size() - 2];
  c = t.back();
  if ((sign != "+" && sign != "-") || !is_number(t.size() - 1)) return std::nullopt;
  if (b.size() > 19 || n.size() > 19 || c.size() > 18) return std::nullopt;  // word-sized parts only
  KbncForm form;
  form.k.set_str(std::string(k), 10);
  form.b = std::stoull(std::string(b));
  form.n = std::stoull(std::string(n));
  form.c = std::stoll(std::string(c)) * (sign == "-" ? -1 : 1);
  if (form.k < 1 || form.b < 2 || form.c == 0) return std::nullopt;
  return form;
}

}  // namespace

Record record_from_number_text(std::string_view text, std::size_t max_bits) {
  Record record = Record::object();
  if (auto form = match_kbnc_text(text)) {
    evaluate_kbnc_bits_check(*form, max_bits);
    record["k"] = json_integer(form->k);
    record["b"] = form->b;
    record["n"] = form->n;
    record["c"] = form->c;
  } else if (text.find_first_not_of("0123456789") == std::string_view::npos ||
             ((text.starts_with("0x") || text.starts_with("0X")) &&
              text.find_first_not_of("0123456789abcdefABCDEF", 2) == std::string_view::npos)) {
    record["number"] = parse_number(text, max_bits).value.get_str();
  } else {
    record["expr"] = std::string(text);  // evaluated (and checked) by whoever tests it
  }
  return record;
}

Verdict test_candidate(const Candidate& candidate, const TestPlan& plan, Record& record) {
  for (const char* owned : {"verdict", "test", "witness", "members"}) record.erase(owned);
  Verdict overall = Verdict::prime;
  std::string witness;
  Record members = Record::array();
  for (const Member& member : candidate.members) {
    const TestOutcome outcome = test_number(member.number, plan);
    overall = std::min(overall, outcome.verdict);
    if (candidate.form) {
      Record entry = Record::object();
      entry["n"] = member.n;
      entry["c"] = member.c;
      entry["verdict"] = std::string(verdict_name(outcome.verdict));
      if (!outcome.witness.empty()) entry["witness"] = outcome.witness;
      members.push_back(std::move(entry));
    } else {
      witness = outcome.witness;
    }
    if (outcome.verdict == Verdict::composite) break;  // a form stops at its first composite
  }
  record["verdict"] = std::string(verdict_name(overall));
  record["test"] = std::string(test_name(plan.kind));
  if (!witness.empty()) record["witness"] = witness;
  if (candidate.form) record["members"] = std::move(members);
  return overall;
}

}  // namespace tk::primes
