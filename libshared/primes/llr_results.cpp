/// @file llr_results.cpp
#include "primes/llr_results.hpp"

#include <fmt/format.h>

#include <cstdint>

namespace tk::primes {

std::string llr_time_text(double seconds) {
  if (seconds >= 1.0) return fmt::format("{:.3f} sec.", seconds);
  return fmt::format("{:.3f} ms.", seconds * 1000.0);
}

namespace {

/// What follows "is not prime." for an LLR or Proth composite. LLR's Proth
/// residue is a^((N-1)/2) mod N plus one (it compares that sum with N), and
/// LLR 4 names the base when it is not 3 and ends the residue with a period.
std::string residue_text(const MemberProof& proof) {
  if (proof.test == "llr") return fmt::format("LLR Res64: {:016X}", *proof.res64);
  const std::uint64_t plus_one = *proof.res64 + 1;  // below N, so the low 64 bits just wrap
  const std::string base = proof.parameter == 3 ? std::string() : fmt::format("Base-{} ", proof.parameter);
  return fmt::format("{}Proth RES64: {:016X}.", base, plus_one);
}

}  // namespace

std::string llr_result_line(const MemberProof& proof, double seconds) {
  const std::string time = "Time : " + llr_time_text(seconds);
  if (proof.verdict == Verdict::prime)
    return fmt::format("{} is prime! ({} decimal digits)  {}", proof.name, proof.digits, time);
  if (proof.verdict == Verdict::probable_prime)
    return fmt::format("{} is a BPSW probable prime. ({} decimal digits)  {}", proof.name, proof.digits, time);
  if (proof.res64) return fmt::format("{} is not prime.  {}  {}", proof.name, residue_text(proof), time);
  return fmt::format("{} is not prime.  {}  {}", proof.name, proof.witness.empty() ? "BPSW" : proof.witness, time);
}

}  // namespace tk::primes
