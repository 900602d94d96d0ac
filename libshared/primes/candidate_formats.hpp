/// @file candidate_formats.hpp
/// @brief NewPGen, ABC and ABCD candidate files, as LLR and PFGW read them:
/// the one place that knows their header grammar, for reading
/// (candidate_formats_read.cpp, mrtest and riesel) and for writing and
/// reading back what sieve writes (candidate_formats.cpp; sieve_output and
/// sieve_merge use it).
///
/// Reading, mapped onto the shared candidate records:
/// - NewPGen "depth:letter:chain:base[:mask]" then "k n" lines: one number
///   {"k","b","n","c"} for +1/-1 (any base; dual files give b^n+-k), or a
///   base-2 form: twin, sg, cc1/cc2 with "length". Where LLR and PFGW read
///   a header differently, LLR's reading is taken (see the read .cpp).
/// - ABC "ABC expr [// comment]" then lines of signed decimal values for
///   $a, $b, ...; the values are substituted as text and the result read
///   with record_from_number_text. "K*2^N+1 & K*2^N-1" gives form twin and
///   "K*2^N-1 & 2*(K*2^N-1)+1" form sg; other '&' or '|' headers are errors.
/// - ABCD "ABCD expr [v1 v2 ...] [// comment]": the header is the first
///   candidate, each later line adds its deltas to the running values.
/// - ABC2 is refused: one header stands for many candidates.
/// Headers may recur anywhere and switch the format. Anything that has no
/// record shape is an Error at its line, never tested some other way.
///
/// Writing (sieve's survivors, one k per line at a fixed n):
/// - NewPGen "depth:letter:chain:2:mask": T/3 twin, M/2 riesel, P/1 proth,
///   S/10 Sophie Germain, C/5 second-kind pair, 1/1066 and 2/1045 with the
///   chain length for longer chains; then "k n" lines.
/// - ABC "ABC expr // Sieved to depth"; '&' joins a form's members.
/// - ABCD "ABCD expr [k0] // Sieved to depth", then differences of k.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

#include "io/error.hpp"
#include "io/record_reader.hpp"
#include "primes/sieve_spec.hpp"

namespace tk::primes {

enum class CandidateHeader { none, newpgen, abc, abcd, abc2 };

/// Which header `line` (trimmed) is, as LLR tells them apart: the first
/// word ABC, ABCD or ABC2, or "<digits>:" for NewPGen.
CandidateHeader candidate_header_kind(std::string_view line);

// ---------------------------------------------------------------- reading

/// A decoder when `first_line` is a NewPGen or ABC/ABCD header, else nullptr.
std::unique_ptr<io::LineDecoder> probe_candidate_format(std::string_view first_line, std::size_t max_bits);

// ------------------------------------------------- sieve's headers, both ways

/// A sieve output header without its depth (and, for ABCD, without its
/// first k): NewPGen's text after "depth:", "ABC expr" or "ABCD expr".
struct SieveHeader {
  CandidateHeader kind = CandidateHeader::none;
  std::string key;
  std::uint64_t depth = 0;       ///< the sieve bound the header records
  std::uint64_t abcd_start = 0;  ///< ABCD: the first candidate's k
};

/// The key sieve writes for `spec` in a NewPGen, ABC or ABCD file.
std::string sieve_header_key(const SieveSpec& spec, CandidateHeader kind);

/// The header line (no newline) of `header`.
std::string sieve_header_line(const SieveHeader& header);

/// Reads a header line that sieve wrote (the first line of a shard):
/// kind none when `line` is no NewPGen, ABC or ABCD header; Error at
/// `where` when it is one but lacks the depth (or ABCD's [k]) sieve writes.
SieveHeader parse_sieve_header(std::string_view line, const Location& where);

/// A line after sieve's ABCD header: the difference to the previous k.
std::uint64_t parse_abcd_difference(std::string_view line, const Location& where);

}  // namespace tk::primes
