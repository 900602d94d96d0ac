// LLR's lresults.txt lines (LLR 4.0.6, Llr.c): write_timer prints "%.3f sec."
// from one second on and "%.3f ms." of the milliseconds below, choosing on
// the unrounded time; fixed durations, never a clock.
#include <gtest/gtest.h>

#include "primes/llr_results.hpp"

using tk::primes::llr_result_line;
using tk::primes::llr_time_text;
using tk::primes::MemberProof;
using tk::primes::Verdict;

TEST(LlrResults, TimesBelowOneSecondAreMilliseconds) {
  EXPECT_EQ(llr_time_text(0.0), "0.000 ms.");
  EXPECT_EQ(llr_time_text(0.000061), "0.061 ms.");
  EXPECT_EQ(llr_time_text(0.0125), "12.500 ms.");
  EXPECT_EQ(llr_time_text(0.25), "250.000 ms.");
  // Below one second before rounding: LLR writes 1000.000 ms., not 1.000 sec.
  EXPECT_EQ(llr_time_text(0.9999996), "1000.000 ms.");
}

TEST(LlrResults, TimesFromOneSecondAreSeconds) {
  EXPECT_EQ(llr_time_text(1.0), "1.000 sec.");
  EXPECT_EQ(llr_time_text(2.5), "2.500 sec.");
  EXPECT_EQ(llr_time_text(4182.25), "4182.250 sec.");
}

namespace {
MemberProof composite(const char* test, std::uint64_t parameter, std::uint64_t res64) {
  MemberProof proof;
  proof.verdict = Verdict::composite;
  proof.test = test;
  proof.parameter = parameter;
  proof.res64 = res64;
  proof.name = "1338*2^1000-1";
  proof.text = "669*2^1001-1";
  return proof;
}
}  // namespace

TEST(LlrResults, LinesNameTheNumberAsGiven) {
  MemberProof prime;
  prime.verdict = Verdict::prime;
  prime.test = "llr";
  prime.name = "6*2^10-1";
  prime.text = "3*2^11-1";
  prime.digits = 4;
  EXPECT_EQ(llr_result_line(prime, 0.0125), "6*2^10-1 is prime! (4 decimal digits)  Time : 12.500 ms.");
  EXPECT_EQ(llr_result_line(composite("llr", 3, 0x101B21C3F1DDCFB4), 2.5),
            "1338*2^1000-1 is not prime.  LLR Res64: 101B21C3F1DDCFB4  Time : 2.500 sec.");
}

TEST(LlrResults, ProthResidueIsLlrsPlusOneWithItsBase) {
  // LLR prints a^((N-1)/2) mod N plus one, "Base-a " unless a = 3, and a period.
  EXPECT_EQ(llr_result_line(composite("proth", 3, 0x00000000000000FF), 0.5),
            "1338*2^1000-1 is not prime.  Proth RES64: 0000000000000100.  Time : 500.000 ms.");
  EXPECT_EQ(llr_result_line(composite("proth", 7, 0xFFFFFFFFFFFFFFFF), 1.5),
            "1338*2^1000-1 is not prime.  Base-7 Proth RES64: 0000000000000000.  Time : 1.500 sec.");
}
