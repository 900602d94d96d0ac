/// @file test_gcode_writer.cpp
/// @brief motion::gcode_writer: any text becomes one plain RS274NGC comment, numbers print one way
/// (rs274 itself judges the writers' programs in toolkit_rs274_oracle.bats).
#include <gtest/gtest.h>

#include <string>

#include "motion/gcode.hpp"
#include "motion/gcode_writer.hpp"

using tk::motion::gcode_comment;
using tk::motion::kMaxCommentBytes;

namespace {

/// Parentheses only at the ends, no control byte, within the length.
void expect_plain_comment(const std::string& comment) {
  ASSERT_GE(comment.size(), 2u);
  EXPECT_EQ(comment.front(), '(');
  EXPECT_EQ(comment.back(), ')');
  EXPECT_LE(comment.size(), kMaxCommentBytes);
  const std::string body = comment.substr(1, comment.size() - 2);
  for (unsigned char c : body) {
    EXPECT_NE(c, '(');
    EXPECT_NE(c, ')');
    EXPECT_GE(c, 0x20);
    EXPECT_NE(c, 0x7f);
  }
  // gcode-pulse's lexer reads it as a comment and nothing else.
  const tk::motion::GcodeLine line = tk::motion::lex_gcode_line("G0 X1 " + comment);
  EXPECT_EQ(line.words.size(), 2u) << comment;
  EXPECT_TRUE(line.message.empty()) << comment;
}

}  // namespace

TEST(GcodeComment, ParenthesesBecomeBrackets) {
  EXPECT_EQ(gcode_comment("part (v2).dxf"), "(part [v2].dxf)");
  EXPECT_EQ(gcode_comment("ap*sqrt(i/n))("), "(ap*sqrt[i/n]][)");
}

TEST(GcodeComment, ControlBytesBecomeSpaces) { EXPECT_EQ(gcode_comment("a\nb\r\tc\x7f"), "(a b  c )"); }

TEST(GcodeComment, EveryByteGivesAPlainComment) {
  for (int byte = 1; byte < 256; ++byte) {
    const std::string text = std::string("a") + static_cast<char>(byte) + "b";
    SCOPED_TRACE(byte);
    expect_plain_comment(gcode_comment(text));
  }
}

TEST(GcodeComment, DirectivesAreQuoted) {
  for (const char* text :
       {"MSG, hi", "msg,hi", "  Debug,#<x>", "print,x", "LOG,x", "logopen,f", "logappend,f", "logclose", "py,import os",
        "pyrun,x", "pyreload", "abort,x", "probeopen f", "probeclose", "AXIS,hide"}) {
    const std::string comment = gcode_comment(text);
    EXPECT_EQ(comment, std::string("(\"") + text + "\")");
    expect_plain_comment(comment);
  }
  // Words that only begin like a directive, or a directive word later on, stay as they are.
  for (const char* text : {"message, hi", "logs, x", "mm, absolute", "threadcalc: msg, x", "debugger"})
    EXPECT_EQ(gcode_comment(text), std::string("(") + text + ")");
}

TEST(GcodeComment, LongTextIsCutAtACharacterBoundary) {
  std::string text;
  for (int i = 0; i < 200; ++i) text += "\xc3\xa9";  // é, two bytes each
  const std::string comment = gcode_comment(text);
  expect_plain_comment(comment);
  EXPECT_EQ(comment.substr(comment.size() - 4), "...)");
  const std::string kept = comment.substr(1, comment.size() - 5);
  EXPECT_EQ(kept.size() % 2, 0u);
  EXPECT_EQ(kept, text.substr(0, kept.size()));
  EXPECT_EQ(gcode_comment(std::string(kMaxCommentBytes - 2, 'a')), "(" + std::string(kMaxCommentBytes - 2, 'a') + ")");
  EXPECT_EQ(gcode_comment(std::string(kMaxCommentBytes - 1, 'a')).size(), kMaxCommentBytes);
}

// Expected texts worked out by hand: rounding to nearest, no "-0".
TEST(GcodeNumber, FixedMicronsKeepSixPlacesAndNeverPrintMinusZero) {
  using tk::motion::gcode_number;
  using tk::motion::kFixedMicrons;
  EXPECT_EQ(gcode_number(1.5, kFixedMicrons), "1.500000");
  EXPECT_EQ(gcode_number(-12.3456789, kFixedMicrons), "-12.345679");
  EXPECT_EQ(gcode_number(0.0, kFixedMicrons), "0.000000");
  EXPECT_EQ(gcode_number(-0.0, kFixedMicrons), "0.000000");
  EXPECT_EQ(gcode_number(-4e-7, kFixedMicrons), "0.000000");
  EXPECT_EQ(gcode_number(-6e-7, kFixedMicrons), "-0.000001");
}

TEST(GcodeNumber, TrimmedTenthMicronsDropTrailingZeros) {
  using tk::motion::gcode_number;
  using tk::motion::kTrimmedTenthMicrons;
  EXPECT_EQ(gcode_number(1.5, kTrimmedTenthMicrons), "1.5");
  EXPECT_EQ(gcode_number(100, kTrimmedTenthMicrons), "100");
  EXPECT_EQ(gcode_number(-30.25, kTrimmedTenthMicrons), "-30.25");
  EXPECT_EQ(gcode_number(12.34567, kTrimmedTenthMicrons), "12.3457");
  EXPECT_EQ(gcode_number(-4e-5, kTrimmedTenthMicrons), "0");
  EXPECT_EQ(gcode_number(-6e-5, kTrimmedTenthMicrons), "-0.0001");
}

TEST(GcodeWriter, LinesCarryTheirCommentsMadeSafeAndNumbersReadBackAsPrinted) {
  tk::motion::GcodeWriter out(tk::motion::kFixedMicrons);
  out.comment("part (v2)");
  out.line("G0 X" + out.number(1.0 / 3), "msg, hello");
  out.line("M2");
  EXPECT_EQ(out.text(), "(part [v2])\nG0 X0.333333 (\"msg, hello\")\nM2\n");
  const tk::motion::PrintedNumber third = out.printed(1.0 / 3);
  EXPECT_EQ(third.text, "0.333333");
  EXPECT_EQ(third.value, 0.333333);
}
