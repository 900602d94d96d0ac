/// @file candidate_proof.hpp
/// @brief Proves the members of a shared candidate record: LLR for
/// k*2^n-1 and Proth for k*2^n+1 when k < 2^n (an even k is first
/// normalised to k/2, n+1); any other number gets mrtest's BPSW and at
/// best "probable-prime", never "prime".
#pragma once

#include <functional>
#include <string>

#include "primes/candidate.hpp"
#include "primes/riesel_proof.hpp"

namespace tk::primes {

struct ProofPlan {
  LlrStart start = LlrStart::llr;
  /// A member with no LLR or Proth proof (k >= 2^n, n too small, another
  /// shape) is an Error instead of a BPSW probable-prime, unless trial
  /// division finds a factor.
  bool require_proof = false;
  /// Options for the proof of one member, named by its normalised text
  /// "k*2^n-1", k odd (checkpoint hooks, cancellation); may be empty.
  std::function<ProofOptions(const std::string& member)> options_for;
};

struct MemberProof {
  Verdict verdict = Verdict::unknown;
  std::string test;                    ///< llr, proth, bpsw or trial
  std::string text;                    ///< the member as "k*2^n+c" after normalising k (checkpoint names)
  std::string name;                    ///< the member as its input wrote it (even k kept): results lines
  std::uint64_t parameter = 0;         ///< P (llr) or a (proth)
  std::optional<std::uint64_t> res64;  ///< composites of llr and proth
  std::string witness;                 ///< "factor p" for a small factor
  std::uint64_t n = 0;                 ///< exponent after normalising
  std::uint64_t digits = 0;            ///< decimal digits of the number
};

MemberProof prove_member(const Member& member, const ProofPlan& plan);

/// Proves every member in order, stopping at the first composite, and adds
/// verdict, test, P or a, res64 (composites) and, for forms, members.
/// `on_member` sees each member's proof as it is finished (for logs).
Verdict prove_candidate(const Candidate& candidate, const ProofPlan& plan, Record& record,
                        const std::function<void(const MemberProof&)>& on_member = {});

}  // namespace tk::primes
