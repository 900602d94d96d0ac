/// @file prime_text_formats.hpp
/// @brief NewPGen and ABC/ABCD files, as LLR and PFGW read them, mapped
/// onto the shared candidate records.
///
/// - NewPGen "depth:letter:chain:base[:mask]" then "k n" lines: one number
///   {"k","b","n","c"} for +1/-1 (any base; dual files give b^n+-k), or a
///   base-2 form: twin, sg, cc1/cc2 with "length". Where LLR and PFGW read
///   a header differently, LLR's reading is taken (see the .cpp).
/// - ABC "ABC expr [// comment]" then lines of signed decimal values for
///   $a, $b, ...; the values are substituted as text and the result read
///   with record_from_number_text. "K*2^N+1 & K*2^N-1" gives form twin and
///   "K*2^N-1 & 2*(K*2^N-1)+1" form sg; other '&' or '|' headers are errors.
/// - ABCD "ABCD expr [v1 v2 ...] [// comment]": the header is the first
///   candidate, each later line adds its deltas to the running values.
/// - ABC2 is refused: one header stands for many candidates.
/// Headers may recur anywhere and switch the format. Anything that has no
/// record shape is an Error at its line, never tested some other way.
#pragma once

#include <cstddef>
#include <memory>
#include <string_view>

#include "io/record_reader.hpp"

namespace tk::primes {

/// A decoder when `first_line` is a NewPGen or ABC/ABCD header, else nullptr.
std::unique_ptr<io::LineDecoder> probe_prime_text_format(std::string_view first_line, std::size_t max_bits);

}  // namespace tk::primes
