/// @file test_sieve_headers.cpp
/// @brief candidate_formats' two directions agree: every NewPGen, ABC and
/// ABCD header sieve writes reads back (merge) to what was written, and the
/// reader LLR's and PFGW's rules follow (mrtest, riesel) takes it for the
/// numbers of the form, checked against the forms' definitions computed
/// here with GMP.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "io/error.hpp"
#include "primes/candidate.hpp"
#include "primes/candidate_formats.hpp"
#include "primes/sieve_spec.hpp"

namespace {

using tk::Location;
using tk::primes::CandidateHeader;
using tk::primes::SieveForm;
using tk::primes::SieveHeader;
using tk::primes::SieveSpec;

struct FormCase {
  SieveForm form;
  unsigned length;
  std::vector<std::pair<int, int>> members;  ///< (exponent offset, c) by the form's definition
};

const std::vector<FormCase> kForms = {
    {SieveForm::riesel, 1, {{0, -1}}},        {SieveForm::proth, 1, {{0, +1}}},
    {SieveForm::twin, 2, {{0, -1}, {0, +1}}}, {SieveForm::sg, 2, {{0, -1}, {1, -1}}},
    {SieveForm::cc1, 2, {{0, -1}, {1, -1}}},  {SieveForm::cc1, 4, {{0, -1}, {1, -1}, {2, -1}, {3, -1}}},
    {SieveForm::cc2, 2, {{0, +1}, {1, +1}}},  {SieveForm::cc2, 3, {{0, +1}, {1, +1}, {2, +1}}},
};

std::vector<mpz_class> sorted_values(std::vector<mpz_class> values) {
  std::sort(values.begin(), values.end());
  return values;
}

TEST(SieveHeaders, WhatSieveWritesReadsBackAndStandsForTheFormsNumbers) {
  constexpr std::uint64_t kN = 61, kK = 105, kDepth = 123456789;
  for (const FormCase& f : kForms) {
    SieveSpec spec;
    spec.form = f.form;
    spec.n = kN;
    spec.length = f.length;
    std::vector<mpz_class> expected;
    for (const auto& [offset, c] : f.members) {
      mpz_class power;
      mpz_ui_pow_ui(power.get_mpz_t(), 2, kN + offset);
      expected.push_back(kK * power + c);
    }
    for (CandidateHeader kind : {CandidateHeader::newpgen, CandidateHeader::abc, CandidateHeader::abcd}) {
      const SieveHeader written{kind, tk::primes::sieve_header_key(spec, kind), kDepth, kK};
      const std::string line = tk::primes::sieve_header_line(written);
      SCOPED_TRACE(line);
      EXPECT_EQ(tk::primes::candidate_header_kind(line), kind);

      const SieveHeader read = tk::primes::parse_sieve_header(line, Location{"shard.txt", 1});
      EXPECT_EQ(read.kind, kind);
      EXPECT_EQ(read.key, written.key);
      EXPECT_EQ(read.depth, kDepth);
      if (kind == CandidateHeader::abcd) {
        EXPECT_EQ(read.abcd_start, kK);
      }

      // The reader: the header, then the data line sieve writes for k (ABCD's header is k itself).
      auto decoder = tk::primes::probe_candidate_format(line, 4096);
      ASSERT_NE(decoder, nullptr);
      tk::Record record;
      bool decoded = decoder->decode(line, Location{"c.txt", 1}, record);
      if (kind != CandidateHeader::abcd) {
        EXPECT_FALSE(decoded);
        const bool single = f.form == SieveForm::riesel || f.form == SieveForm::proth;
        const std::string data = kind == CandidateHeader::abc && !single
                                     ? std::to_string(kK)
                                     : std::to_string(kK) + " " + std::to_string(kN);
        decoded = decoder->decode(data, Location{"c.txt", 2}, record);
      }
      ASSERT_TRUE(decoded);
      const auto candidate = tk::primes::candidate_from_record(record, 4096);
      std::vector<mpz_class> values;
      for (const auto& member : candidate.members) values.push_back(member.number.value);
      EXPECT_EQ(sorted_values(values), sorted_values(expected)) << record.dump();
    }
  }
}

TEST(SieveHeaders, HeadersWithoutWhatSieveWritesAreRefusedAtTheirLine) {
  const Location where{"shard.txt", 1};
  EXPECT_EQ(tk::primes::parse_sieve_header("k,n,form", where).kind, CandidateHeader::none);
  EXPECT_EQ(tk::primes::parse_sieve_header("{\"k\":3}", where).kind, CandidateHeader::none);
  for (const char* line : {"ABC $a*2^5+1", "ABCD $a*2^5+1 [3]", "ABCD $a*2^5+1 // Sieved to 9",
                           "ABCD $a*2^5+1 [3] x // Sieved to 9", "ABC $a*2^5+1 // Sieved to 9x", "ABC2 $a*2^5+1"}) {
    try {
      tk::primes::parse_sieve_header(line, where);
      ADD_FAILURE() << "accepted: " << line;
    } catch (const tk::Error& e) {
      EXPECT_EQ(e.where().line, 1u) << e.what();
      EXPECT_EQ(e.where().file, "shard.txt");
    }
  }
}

}  // namespace
