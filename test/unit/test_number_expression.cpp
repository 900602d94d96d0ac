// Unit tests for the number and expression parser, against GMP arithmetic.
#include <gtest/gtest.h>

#include "io/error.hpp"
#include "primes/candidate.hpp"
#include "primes/number_expression.hpp"

using namespace tk::primes;

TEST(NumberExpression, DecimalHexAndOperators) {
  EXPECT_EQ(parse_number("12345678901234567890123").value, mpz_class("12345678901234567890123"));
  EXPECT_EQ(parse_number("0xff").value, 255);
  EXPECT_EQ(parse_number("2^10-1").value, 1023);
  EXPECT_EQ(parse_number("2**10+1").value, 1025);
  EXPECT_EQ(parse_number("2^3^2").value, 512);  // right associative
  EXPECT_EQ(parse_number("(2^127+1)/3").value, ((mpz_class(1) << 127) + 1) / 3);
  EXPECT_EQ(parse_number("10!+1").value, 3628801);
  EXPECT_EQ(parse_number("13#-1").value, 30029);
  EXPECT_EQ(parse_number(" 7 * 3 % 5 ").value, 1);
  EXPECT_EQ(parse_number("-(5)+12").value, 7);
}

TEST(NumberExpression, KeepsTheKbncShape) {
  const Number n = parse_number("778965587811*2^36627-1");
  ASSERT_TRUE(n.form);
  EXPECT_EQ(n.form->k, 778965587811UL);
  EXPECT_EQ(n.form->b, 2u);
  EXPECT_EQ(n.form->n, 36627u);
  EXPECT_EQ(n.form->c, -1);
  EXPECT_EQ(n.value, (mpz_class(778965587811UL) << 36627) - 1);
  const Number m = parse_number("5*10^20+3");
  ASSERT_TRUE(m.form);
  EXPECT_EQ(m.form->b, 10u);
  EXPECT_EQ(m.form->c, 3);
  EXPECT_FALSE(parse_number("(2^89-1)*3").form);
}

TEST(NumberExpression, RejectsMalformedText) {
  for (const char* bad : {"", "abc", "2^", "(2+3", "2+*3", "5/0", "7/2", "2^-1", "1e5", "12 34", "0x", "--"})
    EXPECT_THROW(parse_number(bad), tk::Error) << bad;
}

TEST(NumberExpression, RefusesNumbersAboveMaxBitsBeforeComputing) {
  EXPECT_THROW(parse_number("2^99999999999"), tk::Error);
  EXPECT_THROW(parse_number("2^1025", 1024), tk::Error);
  EXPECT_NO_THROW(parse_number("2^1023", 1024));
  EXPECT_THROW(parse_number("100000000!"), tk::Error);
  EXPECT_THROW(parse_number("(2^600)*(2^600)", 1024), tk::Error);
  EXPECT_THROW(parse_number(std::string(400, '9'), 1024), tk::Error);
  EXPECT_THROW(parse_number("75858", 16), tk::Error);  // the decimal fast path too
  EXPECT_NO_THROW(parse_number("65535", 16));
}

TEST(NumberExpression, DeepNestingIsAnErrorNotACrash) {
  std::string deep(100000, '(');
  deep += "1";
  deep += std::string(100000, ')');
  EXPECT_THROW(parse_number(deep), tk::Error);
}

TEST(NumberExpression, ErrorsNameTheColumn) {
  try {
    parse_number("12+x");
    FAIL();
  } catch (const tk::Error& e) {
    EXPECT_NE(std::string(e.what()).find("column 4"), std::string::npos) << e.what();
  }
}

TEST(Candidate, RecordsForTextInput) {
  EXPECT_EQ(record_from_number_text("97", 1000).dump(), R"({"number":"97"})");
  EXPECT_EQ(record_from_number_text("0x61", 1000).dump(), R"({"number":"97"})");
  EXPECT_EQ(record_from_number_text("3*2^10+1", 1000).dump(), R"({"k":3,"b":2,"n":10,"c":1})");
  EXPECT_EQ(record_from_number_text("2^10*3+1", 1000).dump(), R"({"k":3,"b":2,"n":10,"c":1})");
  EXPECT_EQ(record_from_number_text("10!+1", 1000).dump(), R"({"expr":"10!+1"})");
  EXPECT_EQ(record_from_number_text("12345678901234567890*2^100-1", 1000)["k"], "12345678901234567890");
}

TEST(Candidate, FormsExpandIntoTheirMembers) {
  auto members = [](const char* json) {
    std::vector<std::pair<std::uint64_t, std::int64_t>> out;
    for (const auto& m : candidate_from_record(tk::Record::parse(json), 1 << 20).members) out.emplace_back(m.n, m.c);
    return out;
  };
  using V = std::vector<std::pair<std::uint64_t, std::int64_t>>;
  EXPECT_EQ(members(R"({"k":3,"n":10,"form":"twin"})"), (V{{10, -1}, {10, 1}}));
  EXPECT_EQ(members(R"({"k":3,"n":10,"form":"sg"})"), (V{{10, -1}, {11, -1}}));
  EXPECT_EQ(members(R"({"k":3,"n":10,"form":"cc1","length":3})"), (V{{10, -1}, {11, -1}, {12, -1}}));
  EXPECT_EQ(members(R"({"k":3,"n":10,"form":"cc2","length":2})"), (V{{10, 1}, {11, 1}}));
  EXPECT_EQ(members(R"({"k":"3","n":"10","form":"proth"})"), (V{{10, 1}}));
  const auto c =
      candidate_from_record(tk::Record::parse(R"({"k":"16869987339975","n":171960,"form":"twin"})"), 1 << 20);
  EXPECT_EQ(c.members[1].number.value, (mpz_class("16869987339975") << 171960) + 1);
}

TEST(Candidate, IntegralFloatsBelow2To53AreIntegers) {
  const auto c = candidate_from_record(tk::Record::parse(R"({"k":3e0,"n":1e1,"c":-1})"), 1 << 20);
  EXPECT_EQ(c.members[0].number.value, 3 * 1024 - 1);
}

TEST(Candidate, MalformedRecordsAreErrors) {
  for (const char* bad :
       {R"({"id":1})", R"({"k":3})", R"({"k":3,"n":10})", R"({"k":3,"n":10,"form":"quad"})", R"({"k":0,"n":10,"c":1})",
        R"({"k":3,"n":-1,"c":1})", R"({"k":1e300,"n":1,"c":1})", R"({"k":3.5,"n":1,"c":1})", R"({"number":""})",
        R"({"number":true})", R"({"k":3,"n":10,"form":"cc1"})", R"({"k":3,"n":10,"c":1,"b":1})",
        R"({"k":3,"n":10,"form":"twin","b":3})"})
    EXPECT_THROW(candidate_from_record(tk::Record::parse(bad), 1 << 20), tk::Error) << bad;
}
