/// @file llr_results.hpp
/// @brief The lines riesel appends to lresults.txt, in the shapes LLR 4.0.6
/// (Jean Penné) writes them, so results can be matched line by line.
#pragma once

#include <string>

#include "primes/candidate_proof.hpp"

namespace tk::primes {

/// LLR's time field: "1.234 sec." from one second on, "123.456 ms." below
/// (the choice is made on the unrounded time, as LLR's write_timer does).
std::string llr_time_text(double seconds);

/// The results line of one member proof, naming the member as its input
/// wrote it (proof.name), with the time `seconds` it took.
std::string llr_result_line(const MemberProof& proof, double seconds);

}  // namespace tk::primes
