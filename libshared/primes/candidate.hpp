/// @file candidate.hpp
/// @brief The records the prime tools share (see DESIGN.md): one number as
/// {"number": ...} or {"k","b","n","c"}, or a form such as
/// {"k","n","form":"twin"} whose members must all be prime.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "io/record.hpp"
#include "primes/number.hpp"
#include "primes/primality.hpp"

namespace tk::primes {

struct Member {
  std::uint64_t n = 0;  ///< exponent of this member (forms only)
  std::int64_t c = 0;   ///< +1 or -1 (forms only)
  Number number;
};

struct Candidate {
  std::optional<std::string> form;  ///< "twin", "sg", ...; none for one number
  std::vector<Member> members;
};

/// The forms of DESIGN.md: riesel, proth, twin, sg, cc1, cc2.
bool is_known_form(const std::string& name);

/// Reads a candidate from a record. Throws Error (no location) for missing
/// or malformed fields, or a number larger than `max_bits`.
Candidate candidate_from_record(const Record& record, std::size_t max_bits);

/// A record for a number written in text: {"number": decimal} for plain
/// integers, {"k","b","n","c"} for k*b^n+c, {"expr": text} otherwise.
Record record_from_number_text(std::string_view text, std::size_t max_bits);

/// Writes k as a JSON number below 2^53 and as a decimal string above.
Record json_integer(const mpz_class& value);

/// Tests every member in order, stopping at the first composite, and adds
/// `verdict`, `test`, `witness` (composites), and for forms `members`.
/// Fields the record already had with these names are replaced.
Verdict test_candidate(const Candidate& candidate, const TestPlan& plan, Record& record);

}  // namespace tk::primes
