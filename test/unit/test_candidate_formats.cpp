/// @file test_candidate_formats.cpp
/// @brief Unit tests of the NewPGen and ABC/ABCD decoders: headers from the
/// files real sieves write, the records they map to, the values those
/// records stand for (checked against GMP directly), and the errors.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <chrono>
#include <iterator>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "io/error.hpp"
#include "primes/candidate.hpp"
#include "primes/candidate_formats.hpp"
#include "primes/number_expression.hpp"

namespace {

using tk::Error;
using tk::Location;
using tk::Record;
using tk::primes::candidate_from_record;
using tk::primes::kDefaultMaxBits;
using tk::primes::probe_candidate_format;

struct Decoded {
  std::vector<Record> records;
  std::vector<std::pair<std::size_t, std::string>> errors;  ///< line and message
};

/// Feeds `text` to a decoder as RecordReader does: blank lines are skipped
/// and the first other line picks the decoder. Errors are collected and
/// decoding goes on, as under --skip-bad.
Decoded decode_text(std::string_view text, std::size_t max_bits = kDefaultMaxBits) {
  Decoded decoded;
  std::unique_ptr<tk::io::LineDecoder> decoder;
  std::size_t line_number = 0;
  for (std::size_t start = 0; start <= text.size();) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = text.substr(start, end - start);
    start = end + 1;
    ++line_number;
    if (line.find_first_not_of(" \t") == std::string_view::npos) continue;
    if (!decoder) {
      decoder = probe_candidate_format(line, max_bits);
      if (!decoder) {
        ADD_FAILURE() << "first line not recognised: " << line;
        return decoded;
      }
    }
    Record record;
    try {
      if (decoder->decode(line, Location{"input.txt", line_number}, record)) {
        // Expressions are checked where they are computed, as mrtest's
        // workers do next; an error there belongs to the same line.
        try {
          candidate_from_record(record, max_bits);
        } catch (const Error& e) {
          decoded.errors.emplace_back(line_number, e.what());
          continue;
        }
        decoded.records.push_back(record);
      }
    } catch (const Error& e) {
      EXPECT_EQ(e.where().file, "input.txt");
      decoded.errors.emplace_back(e.where().line, e.what());
    }
  }
  return decoded;
}

/// The single error of `text`, or a test failure.
std::pair<std::size_t, std::string> only_error(std::string_view text, std::size_t max_bits = kDefaultMaxBits) {
  const Decoded decoded = decode_text(text, max_bits);
  EXPECT_EQ(decoded.errors.size(), 1u) << text;
  return decoded.errors.empty() ? std::make_pair(std::size_t{0}, std::string()) : decoded.errors.front();
}

/// k*b^n+c computed with GMP alone.
mpz_class kbnc(const mpz_class& k, unsigned long b, unsigned long n, long c) {
  mpz_class power;
  mpz_ui_pow_ui(power.get_mpz_t(), b, n);
  return k * power + c;
}

/// The value of a one-number record, as the testers will read it.
mpz_class value_of(const Record& record) {
  const auto candidate = candidate_from_record(record, kDefaultMaxBits);
  EXPECT_EQ(candidate.members.size(), 1u);
  return candidate.members.at(0).number.value;
}

Record kbnc_record(std::uint64_t k, std::uint64_t b, std::uint64_t n, std::int64_t c) {
  return Record{{"k", k}, {"b", b}, {"n", n}, {"c", c}};
}

Record form_record(std::uint64_t k, std::uint64_t n, const std::string& form, std::uint64_t length = 0) {
  Record record{{"k", k}, {"n", n}, {"form", form}};
  if (length) record["length"] = length;
  return record;
}

// ------------------------------------------------------------------ probing

TEST(PrimeTextProbe, RecognisesHeadersOnly) {
  for (const char* header : {"1000000000:P:1:2:257", "1:M:1:2", "  5000000:P:1:2:1", "ABC $a*2^$b+1",
                             "ABCD $a*2^9+1 [3]", "ABC2 $a*2^$b+1", "12:junk"})
    EXPECT_NE(probe_candidate_format(header, 64), nullptr) << header;
  for (const char* other : {"k,n", "3*2^10-1", "12345", "{\"k\":3}", "ABCDE,x", "abc $a", "// comment", ":P:1:2:1", ""})
    EXPECT_EQ(probe_candidate_format(other, 64), nullptr) << other;
}

// ------------------------------------------------------------------ NewPGen

TEST(NewPGenText, SrsieveFixedKProthAndRiesel) {
  // srsieve/srfile write_newpgen_k: 257 = PLUS|KSIEVE, 258 = MINUS|KSIEVE.
  Decoded plus = decode_text("1000000000:P:1:2:257\n27 1000\n27 1012\n");
  ASSERT_TRUE(plus.errors.empty());
  ASSERT_EQ(plus.records.size(), 2u);
  EXPECT_EQ(plus.records[0], kbnc_record(27, 2, 1000, 1));
  EXPECT_EQ(plus.records[1], kbnc_record(27, 2, 1012, 1));
  EXPECT_EQ(value_of(plus.records[1]), kbnc(27, 2, 1012, 1));
  Decoded minus = decode_text("1000000000:M:1:2:258\n27 1000\n");
  ASSERT_EQ(minus.records.size(), 1u);
  EXPECT_EQ(minus.records[0], kbnc_record(27, 2, 1000, -1));
}

TEST(NewPGenText, FbncsieveAndLlrReadmeExamples) {
  EXPECT_EQ(decode_text("5000000:P:1:2:1\n3 1000\n15 1000\n").records.at(1), kbnc_record(15, 2, 1000, 1));
  EXPECT_EQ(decode_text("1:P:1:2:1\n5 7\n").records.at(0), kbnc_record(5, 2, 7, 1));
  EXPECT_EQ(decode_text("1:M:1:2:2\n5 7\n").records.at(0), kbnc_record(5, 2, 7, -1));
  // The task's own end-to-end example.
  EXPECT_EQ(decode_text("1000:M:1:2:2\n3 10\n").records.at(0), kbnc_record(3, 2, 10, -1));
}

TEST(NewPGenText, OtherBasesGiveKbnc) {
  const Decoded decoded = decode_text("1000000:P:1:5:1\n4 100\n1000000:M:1:10:2\n12 33\n");
  ASSERT_EQ(decoded.records.size(), 2u);
  EXPECT_EQ(decoded.records[0], kbnc_record(4, 5, 100, 1));
  EXPECT_EQ(value_of(decoded.records[1]), kbnc(12, 10, 33, -1));
}

TEST(NewPGenText, TwinsieveTwins) {
  const Decoded decoded = decode_text("123456789:T:0:2:3\n16869987339975 171960\n");
  ASSERT_EQ(decoded.records.size(), 1u);
  EXPECT_EQ(decoded.records[0], form_record(16869987339975u, 171960, "twin"));
}

TEST(NewPGenText, SgsieveSophieGermain) {
  EXPECT_EQ(decode_text("123456789:S:0:2:10\n1 1000\n").records.at(0), form_record(1, 1000, "sg"));
  // 0x40A = MINUS|2MINUS|NOTGENERALISED: k*2^n-1 & 2k*2^n-1, the same pair in base 2.
  EXPECT_EQ(decode_text("123456789:S:0:2:1034\n7 500\n").records.at(0), form_record(7, 500, "sg"));
  // Letter-only (4-field) header.
  EXPECT_EQ(decode_text("123456789:S:0:2\n7 500\n").records.at(0), form_record(7, 500, "sg"));
}

TEST(NewPGenText, CunninghamChains) {
  EXPECT_EQ(decode_text("123456789:C:0:2:5\n9 77\n").records.at(0), form_record(9, 77, "cc2", 2));
  // With a mask LLR starts chain letters at n (llr2 dropped PRP.EXE's n-1).
  EXPECT_EQ(decode_text("1000:1:3:2:42\n9 77\n").records.at(0), form_record(9, 77, "cc1", 3));
  EXPECT_EQ(decode_text("1000:2:3:2:21\n9 77\n").records.at(0), form_record(9, 77, "cc2", 3));
  EXPECT_EQ(decode_text("1000:1:5:2:2\n9 77\n").records.at(0), form_record(9, 77, "cc1", 5));
  // Without a mask LLR, PRP.EXE and PFGW all start them at n-1.
  EXPECT_EQ(decode_text("1000:1:4:2\n9 77\n").records.at(0), form_record(9, 76, "cc1", 4));
  EXPECT_EQ(decode_text("1000:2:3:2:0\n9 77\n").records.at(0), form_record(9, 76, "cc2", 3));
  EXPECT_NE(only_error("1000:1:4:2\n9 0\n").second.find("at least 1"), std::string::npos);
}

TEST(NewPGenText, MaskOverridesLetterAsLlrDoes) {
  // 'M' says minus but mask 1 is PLUS: LLR tests k*2^n+1 (PFGW would test -1).
  EXPECT_EQ(decode_text("2000000:M:0:2:1\n3 100\n").records.at(0), kbnc_record(3, 2, 100, 1));
  // Without a mask the letter decides.
  EXPECT_EQ(decode_text("2000000:M:0:2\n3 100\n").records.at(0), kbnc_record(3, 2, 100, -1));
}

TEST(NewPGenText, DualFilesAreBnPlusMinusK) {
  EXPECT_EQ(decode_text("1000:P:1:2:32769\n7 100\n").records.at(0), kbnc_record(1, 2, 100, 7));
  EXPECT_EQ(value_of(decode_text("1000:M:1:2:32770\n7 100\n").records.at(0)), kbnc(1, 2, 100, -7));
}

TEST(NewPGenText, BigKBecomesDecimalString) {
  const std::string k = "123456789012345678901234567890";
  const Decoded decoded = decode_text("1000:P:1:2:1\n" + k + " 64\n");
  ASSERT_EQ(decoded.records.size(), 1u);
  EXPECT_EQ(decoded.records[0]["k"], k);
  EXPECT_EQ(value_of(decoded.records[0]), kbnc(mpz_class(k), 2, 64, 1));
}

TEST(NewPGenText, UnsupportedModesAreRejectedAtTheHeader) {
  struct Case {
    const char* header;
    const char* reason;
  } cases[] = {
      {"1000:B:1:2:15", "not supported"},         // BiTwin
      {"1000:J:1:2:11", "not supported"},         // Twin/SG
      {"1000:K:1:2:7", "not supported"},          // Twin/CC
      {"1000:Y:1:2:29", "lucky"},                 // 0x1D
      {"1000:Z:1:2:46", "lucky"},                 // 0x2E
      {"1000:P:1:2:65", "primorial"},             // 0x41
      {"1000:T:1:2:131", "members other"},        // 3-tuple 0x83
      {"1000:A:1:2:512", "members other"},        // AP
      {"1000:T:0:3:3", "base 2 only"},            // twins in base 3
      {"1000:S:0:3:1034", "base 2 only"},         // SG in base 3
      {"1000:B:1:2", "not supported"},            // letter without mask
      {"1000:P:1:2:256", "selects no numbers"},   // KSIEVE alone
      {"1000:P:1:2:16385", "unknown mask bits"},  // 0x4000
      {"1000:1:65:2:2", "longer than 64"},
      {"1000:Q:1:2:1", "unknown letter"},
      {"1000:P:1", "depth:letter:chain:base:mask"},
      {"1000:P:1:2:1:9", "depth:letter:chain:base:mask"},
      {"1000:PP:1:2:1", "depth:letter:chain:base:mask"},
      {"1000:P:1:1:1", "base below 2"},
      {"1000:P:1:x:1", "decimal"},
      {"1000:P:1:2:99999999999999999999", "decimal"},
  };
  for (const Case& c : cases) {
    const Decoded decoded = decode_text(std::string(c.header) + "\n3 10\n");
    EXPECT_TRUE(decoded.records.empty()) << c.header;
    ASSERT_EQ(decoded.errors.size(), 2u) << c.header;
    EXPECT_EQ(decoded.errors[0].first, 1u);
    EXPECT_NE(decoded.errors[0].second.find(c.reason), std::string::npos) << decoded.errors[0].second;
    // Data after a rejected header is an error too, never tested some other way.
    EXPECT_EQ(decoded.errors[1].first, 2u);
    EXPECT_NE(decoded.errors[1].second.find("without a valid"), std::string::npos);
  }
  EXPECT_NE(only_error("1000:B:1:2:15\n").second.find("newpgen mode '1000:B:1:2:15' is not supported"),
            std::string::npos);
}

TEST(NewPGenText, BadDataLinesNameTheirLine) {
  const Decoded decoded = decode_text(
      "1000:P:1:2:1\n3 10\n3\n3 x\n-3 10\n0 10\n3 10 7\n3 4294967296\n3 -1\n5 12\n"
      "3 99999999999999999999999\n");
  ASSERT_EQ(decoded.records.size(), 2u);  // lines 2 and 10
  EXPECT_EQ(decoded.records[1], kbnc_record(5, 2, 12, 1));
  std::vector<std::size_t> lines;
  for (const auto& error : decoded.errors) lines.push_back(error.first);
  EXPECT_EQ(lines, (std::vector<std::size_t>{3, 4, 5, 6, 7, 8, 9, 11}));
  EXPECT_NE(decoded.errors[5].second.find("32 bits"), std::string::npos);
}

TEST(NewPGenText, SizesAreBoundedByMaxBits) {
  EXPECT_NE(only_error("1000:P:1:2:1\n3 4294967295\n", 1000).second.find("max-bits"), std::string::npos);
  EXPECT_NE(only_error("1000:P:1:10:1\n3 400\n", 1000).second.find("max-bits"), std::string::npos);
  EXPECT_NE(only_error("1000:P:1:2:1\n" + std::string(400, '7') + " 1\n", 1000).second.find("max-bits"),
            std::string::npos);
  EXPECT_EQ(decode_text("1000:P:1:2:1\n3 990\n", 1000).records.size(), 1u);
}

TEST(NewPGenText, CommentsAndCrLfAndHeadersMidFile) {
  const Decoded decoded = decode_text("1000:P:1:2:1\r\n// note\n3 10\r\n\n1000:T:0:2:3\n5 20\nABC $a*3^$b-1\n2 5\n");
  ASSERT_TRUE(decoded.errors.empty()) << decoded.errors.front().second;
  ASSERT_EQ(decoded.records.size(), 3u);
  EXPECT_EQ(decoded.records[0], kbnc_record(3, 2, 10, 1));
  EXPECT_EQ(decoded.records[1], form_record(5, 20, "twin"));
  EXPECT_EQ(decoded.records[2], kbnc_record(2, 3, 5, -1));
}

// ------------------------------------------------------------------ ABC

TEST(AbcText, KbncHeadersFromThePfgwDocs) {
  EXPECT_EQ(decode_text("ABC $a*2^$b+1 // Sieved to 1000000000\n3 1000\n").records.at(0), kbnc_record(3, 2, 1000, 1));
  const Decoded signs = decode_text("ABC $a*3^1000$b // Sieved to 10000000\n2 +1\n2 -1\n");
  ASSERT_EQ(signs.records.size(), 2u);
  EXPECT_EQ(signs.records[0], kbnc_record(2, 3, 1000, 1));
  EXPECT_EQ(signs.records[1], kbnc_record(2, 3, 1000, -1));
  EXPECT_EQ(decode_text("ABC $a*$b^$c$d\n3 2 1000 +1\n").records.at(0), kbnc_record(3, 2, 1000, 1));
  // fbncsieve: one k per line.
  EXPECT_EQ(decode_text("ABC $a*7^5000-1 // Sieved to 1e9\n4\n").records.at(0), kbnc_record(4, 7, 5000, -1));
  // PFGW reads $A as $a.
  EXPECT_EQ(decode_text("ABC $A*2^$B-1\n3 10\n").records.at(0), kbnc_record(3, 2, 10, -1));
}

TEST(AbcText, SubstitutedValuesMatchGmp) {
  const std::string big_k = "98765432109876543210987654321098765432109";
  const Decoded decoded = decode_text("ABC $a*2^$b-1\n" + big_k + " 2000\nABC ($a^$b-1)/($a-1)\n10 17\n7 23\n" +
                                      "ABC $a^$b+$c\n13 40 " + big_k + "\nABC $a\n" + big_k + "\n");
  ASSERT_TRUE(decoded.errors.empty()) << decoded.errors.front().second;
  ASSERT_EQ(decoded.records.size(), 5u);
  EXPECT_EQ(decoded.records[0]["k"], big_k);
  EXPECT_EQ(value_of(decoded.records[0]), kbnc(mpz_class(big_k), 2, 2000, -1));
  EXPECT_EQ(value_of(decoded.records[1]), mpz_class(kbnc(1, 10, 17, -1) / 9));
  EXPECT_EQ(value_of(decoded.records[2]), mpz_class(kbnc(1, 7, 23, -1) / 6));
  EXPECT_EQ(value_of(decoded.records[3]), mpz_class(kbnc(1, 13, 40, 0) + mpz_class(big_k)));
  EXPECT_EQ(decoded.records[4], Record({{"number", big_k}}));
}

TEST(AbcText, TwinPairsMapToTwinForm) {
  for (const char* header : {"ABC $a*2^$b+1 & $a*2^$b-1", "ABC $a*2^$b-1 & $a*2^$b+1", "ABC $a*2^$b+1&$a*2^$b-1 // x"})
    EXPECT_EQ(decode_text(std::string(header) + "\n45 1000\n").records.at(0), form_record(45, 1000, "twin")) << header;
  // twinsieve's fixed-n form, one k per line.
  const Decoded fixed_n = decode_text("ABC $a*2^1000+1 & $a*2^1000-1 // Sieved to 5000000\n4\n");
  EXPECT_EQ(fixed_n.records.at(0), form_record(4, 1000, "twin"));
}

TEST(AbcText, ChainsAsSieveWritesThem) {
  EXPECT_EQ(decode_text("ABC $a*2^10-1 & $a*2^11-1 & $a*2^12-1 // Sieved to 99\n153\n").records.at(0),
            form_record(153, 10, "cc1", 3));
  EXPECT_EQ(decode_text("ABC $a*2^11+1 & $a*2^10+1\n39\n").records.at(0), form_record(39, 10, "cc2", 2));
  EXPECT_EQ(decode_text("ABC $a*2^10-1 & $a*2^11-1\n141\n").records.at(0), form_record(141, 10, "sg"));
  EXPECT_EQ(decode_text("ABCD $a*2^7+1 & $a*2^8+1 & $a*2^9+1 [3]\n2\n").records.at(1), form_record(5, 7, "cc2", 3));
  for (const char* header : {"ABC $a*2^10-1 & $a*2^12-1", "ABC $a*2^10-1 & $a*2^11+1 & $a*2^12-1",
                             "ABC $a*2^10-1 & $b*2^11-1", "ABC $a*2^10-1 & $a*2^10-1"})
    EXPECT_EQ(only_error(std::string(header) + "\n").first, 1u) << header;
}

TEST(AbcText, OtherCombinationsAreRejected) {
  for (const char* header : {"ABC $a*2^$b+1 | $a*2^$b-1", "ABC $a*2^$b+1 & $a*2^$b+3", "ABC $a*2^$b+1 & $a*3^$b-1",
                             "ABC $a*2^$b+1 & $a*2^$b-1 & $a*2^($b+1)-1", "ABC $a*2^$b+1 & $c*2^$b-1",
                             "ABC $a*2^$b+1 &", "ABC $a*2^$b+1 && $a*2^$b-1"}) {
    const auto [line, message] = only_error(std::string(header) + "\n");
    EXPECT_EQ(line, 1u) << header;
    EXPECT_TRUE(message.find("'&'") != std::string::npos || message.find("'|'") != std::string::npos)
        << header << ": " << message;
  }
}

TEST(AbcText, MalformedHeadersAreRejected) {
  EXPECT_NE(only_error("ABC\n").second.find("no expression"), std::string::npos);
  EXPECT_NE(only_error("ABC // comment only\n").second.find("no expression"), std::string::npos);
  EXPECT_NE(only_error("ABC 3*2^100+1\n").second.find("no $a..$z"), std::string::npos);
  EXPECT_NE(only_error("ABC $1*2^$b+1\n").second.find("'$' must be followed"), std::string::npos);
  EXPECT_NE(only_error("ABC DivPhi($a*2^$b+1)\n").second.find("not supported"), std::string::npos);
  EXPECT_NE(only_error("ABC $a*2^$b+1\x01\n").second.find("'?'"), std::string::npos);
  const Decoded abc2 = decode_text("ABC2 $a*2^$b+1\na: from 1 to 9\nb: in { 100 200 }\n");
  ASSERT_FALSE(abc2.errors.empty());
  EXPECT_EQ(abc2.errors[0], std::make_pair(std::size_t{1}, std::string("abc2 files are not supported")));
  EXPECT_TRUE(abc2.records.empty());
}

TEST(AbcText, BadDataLinesNameTheirLine) {
  const Decoded decoded = decode_text(
      "ABC $a*2^$b+1 // Sieved\n"
      "3 100\n"       // 2 ok
      "3\n"           // 3 too few
      "3 100 5\n"     // 4 too many
      "3 x\n"         // 5 not a number
      "3 1e5\n"       // 6 not a decimal integer
      "3 -5\n"        // 7 negative exponent
      "3 +\n"         // 8 sign only
      "// comment\n"  // 9 skipped
      "\n"            // 10 blank
      "5 200\n");     // 11 ok
  ASSERT_EQ(decoded.records.size(), 2u);
  EXPECT_EQ(decoded.records[1], kbnc_record(5, 2, 200, 1));
  std::vector<std::size_t> lines;
  for (const auto& error : decoded.errors) lines.push_back(error.first);
  EXPECT_EQ(lines, (std::vector<std::size_t>{3, 4, 5, 6, 7, 8}));
  EXPECT_NE(decoded.errors[0].second.find("expected 2 values"), std::string::npos);
  EXPECT_NE(decoded.errors[2].second.find("'x'"), std::string::npos);
}

TEST(AbcText, TwinValuesAreChecked) {
  const Decoded decoded = decode_text("ABC $a*2^$b+1 & $a*2^$b-1\n0 10\n-3 10\n3 4294967296\n3 10\n");
  ASSERT_EQ(decoded.records.size(), 1u);
  ASSERT_EQ(decoded.errors.size(), 3u);
  EXPECT_NE(decoded.errors[0].second.find("positive"), std::string::npos);
  EXPECT_NE(decoded.errors[2].second.find("32 bits"), std::string::npos);
}

TEST(AbcText, SizesAreBoundedByMaxBits) {
  EXPECT_NE(only_error("ABC $a*2^$b+1\n3 5000\n", 1000).second.find("max-bits"), std::string::npos);
  EXPECT_NE(only_error("ABC $a+1\n" + std::string(500, '9') + "\n", 1000).second.find("max-bits"), std::string::npos);
  EXPECT_NE(only_error("ABC $a^$a^$a^$a\n9\n", 1000).second.find("max-bits"), std::string::npos);
  // Many copies of a big value: refused before the text is built.
  std::string many = "ABC $a";
  for (int i = 0; i < 50; ++i) many += "+$a";
  EXPECT_NE(only_error(many + "\n" + std::string(290, '9') + "\n", 1000).second.find("too long"), std::string::npos);
  EXPECT_NE(only_error("ABC $a*2^$b+1 & $a*2^$b-1\n3 1000\n", 1000).second.find("max-bits"), std::string::npos);
}

TEST(AbcText, LaterHeaderRestarts) {
  const Decoded decoded = decode_text("ABC $a*2^$b+1\n3 10\nABC $a*5^7-1\n8\n8 9\n");
  ASSERT_EQ(decoded.records.size(), 2u);
  EXPECT_EQ(decoded.records[1], kbnc_record(8, 5, 7, -1));
  ASSERT_EQ(decoded.errors.size(), 1u);
  EXPECT_EQ(decoded.errors[0].first, 5u);
  // A bad later header stops its data from being read with the old one.
  const Decoded bad = decode_text("ABC $a*2^$b+1\n3 10\nABC $a*2^$b+1 | $a*2^$b-1\n3 10\n");
  EXPECT_EQ(bad.records.size(), 1u);
  EXPECT_EQ(bad.errors.size(), 2u);
}

// ------------------------------------------------------------------ ABCD

TEST(AbcdText, NoteExampleWithTwoBlocks) {
  const Decoded decoded =
      decode_text("ABCD $a*2^1000+1 & $a*2^1000-1  [3] // Sieved to 1000000\n2\n6\nABCD $a*2^1001+1 [5]\n10\n");
  ASSERT_TRUE(decoded.errors.empty()) << decoded.errors.front().second;
  ASSERT_EQ(decoded.records.size(), 5u);
  EXPECT_EQ(decoded.records[0], form_record(3, 1000, "twin"));
  EXPECT_EQ(decoded.records[1], form_record(5, 1000, "twin"));
  EXPECT_EQ(decoded.records[2], form_record(11, 1000, "twin"));
  EXPECT_EQ(decoded.records[3], kbnc_record(5, 2, 1001, 1));
  EXPECT_EQ(decoded.records[4], kbnc_record(15, 2, 1001, 1));
  EXPECT_EQ(value_of(decoded.records[4]), kbnc(15, 2, 1001, 1));
}

TEST(AbcdText, SeveralVariablesAccumulate) {
  const Decoded decoded = decode_text("ABCD $a*2^$b-1 [3 1000]\n2 10\n-4 0\n0 +5\n");
  ASSERT_TRUE(decoded.errors.empty()) << decoded.errors.front().second;
  ASSERT_EQ(decoded.records.size(), 4u);
  EXPECT_EQ(decoded.records[1], kbnc_record(5, 2, 1010, -1));
  EXPECT_EQ(decoded.records[2], kbnc_record(1, 2, 1010, -1));
  EXPECT_EQ(decoded.records[3], kbnc_record(1, 2, 1015, -1));
}

TEST(AbcdText, SgsieveAndFixedKHeaders) {
  const Decoded sg = decode_text("ABCD $a*2^5000-1 & 2*($a*2^5000-1)+1 [15] // Sieved to 1e9\n6\n");
  ASSERT_EQ(sg.records.size(), 2u);
  EXPECT_EQ(sg.records[1], form_record(21, 5000, "sg"));
  // PRPNet's fixed-k form: deltas on n.
  const Decoded fixed_k = decode_text("ABCD 3*2^$a+1 [100]\n12\n");
  ASSERT_EQ(fixed_k.records.size(), 2u);
  EXPECT_EQ(fixed_k.records[1], kbnc_record(3, 2, 112, 1));
}

TEST(AbcdText, ErrorsLeaveTheRunningValuesAlone) {
  const Decoded decoded = decode_text("ABCD $a*2^$b+1 [3 100]\n2\n2 x\n2 0 0\n2 0\n");
  ASSERT_EQ(decoded.records.size(), 2u);
  EXPECT_EQ(decoded.records[1], kbnc_record(5, 2, 100, 1));  // the bad lines changed nothing
  std::vector<std::size_t> lines;
  for (const auto& error : decoded.errors) lines.push_back(error.first);
  EXPECT_EQ(lines, (std::vector<std::size_t>{2, 3, 4}));
}

TEST(AbcdText, MalformedHeadersAreRejected) {
  EXPECT_NE(only_error("ABCD $a*2^9+1\n").second.find("[...]"), std::string::npos);
  EXPECT_NE(only_error("ABCD $a*2^9+1 [3\n").second.find("[...]"), std::string::npos);
  EXPECT_NE(only_error("ABCD $a*2^$b+1 [3:1000]\n").second.find("spaces"), std::string::npos);
  EXPECT_NE(only_error("ABCD $a*2^$b+1 [3]\n").second.find("expected 2 values"), std::string::npos);
  EXPECT_NE(only_error("ABCD $a*2^9+1 [3] junk\n").second.find("after ']'"), std::string::npos);
  // Data after a bad ABCD header is refused, not read with a stale block.
  const Decoded decoded = decode_text("ABCD $a*2^9+1 [3]\n2\nABCD $a*2^9+1 []\n2\n");
  EXPECT_EQ(decoded.records.size(), 2u);
  ASSERT_EQ(decoded.errors.size(), 2u);
  EXPECT_EQ(decoded.errors[1].first, 4u);
}

TEST(AbcdText, RunningValuesAreBounded) {
  std::string text = "ABCD $a+1 [" + std::string(300, '9') + "]\n";
  for (int i = 0; i < 20; ++i) text += std::string(300, '9') + "\n";
  const Decoded decoded = decode_text(text, 1000);
  EXPECT_FALSE(decoded.errors.empty());
  EXPECT_NE(decoded.errors.back().second.find("max-bits"), std::string::npos);
}

// ------------------------------------------------------------------ robustness

/// Random lines built from the characters these formats use, behind each
/// kind of header: every outcome must be a record or a tk::Error.
TEST(PrimeTextRobustness, RandomLinesOnlyEverThrowError) {
  std::mt19937 rng(12345);
  const std::string alphabet = "0123456789 :$abczABCD&|[]/+-*^()!#%\t.xPMTSC\x01\xff";
  const char* tokens[] = {"*2^", "+1", "-1", " & ", "2*(", "-1)+1", "$a", "$b", "[", "]", ":", "//", "ABC "};
  const char* headers[] = {"1000:P:1:2:1",
                           "1000:T:0:2:3",
                           "1000:1:3:2:42",
                           "ABC $a*2^$b+1",
                           "ABC $a*2^$b+1 & $a*2^$b-1",
                           "ABCD $a*2^$b$c [3 10 +1]",
                           "ABC $a^$b%$c!"};
  const auto start = std::chrono::steady_clock::now();
  for (int round = 0; round < 3000; ++round) {
    auto decoder = probe_candidate_format(headers[round % std::size(headers)], 4096);
    ASSERT_NE(decoder, nullptr);
    Record record;
    for (int i = 0; i < 12; ++i) {
      std::string line;
      const std::size_t length = rng() % 40;
      for (std::size_t j = 0; j < length; ++j) {
        if (rng() % 3 == 0) line += tokens[rng() % std::size(tokens)];
        else line += alphabet[rng() % alphabet.size()];
      }
      if (rng() % 4 == 0) line = std::string(headers[rng() % std::size(headers)]).substr(0, rng() % 30) + line;
      try {
        if (i == 0) decoder->decode(headers[round % std::size(headers)], Location{"f", 1}, record);
        decoder->decode(line, Location{"f", 2}, record);
      } catch (const Error& e) {
        EXPECT_EQ(e.where().line, 2u) << line;
      } catch (const std::exception& e) {
        ADD_FAILURE() << "non-tk exception '" << e.what() << "' for line: " << line;
      }
    }
  }
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(60));
}

TEST(PrimeTextRobustness, HugeJunkLinesAreCheap) {
  const std::string junk(4u << 20, '7');
  const std::string spaced = [] {
    std::string s;
    for (int i = 0; i < (1 << 20); ++i) s += "1 ";
    return s;
  }();
  for (const char* header : {"1000:P:1:2:1", "ABC $a*2^$b+1", "ABCD $a*2^$b+1 [3 10]"}) {
    auto decoder = probe_candidate_format(header, kDefaultMaxBits);
    Record record;
    decoder->decode(header, Location{"f", 1}, record);
    for (const std::string* line : {&junk, &spaced}) {
      const auto start = std::chrono::steady_clock::now();
      EXPECT_THROW(decoder->decode(*line, Location{"f", 2}, record), Error) << header;
      EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5)) << header;
    }
  }
}

}  // namespace
