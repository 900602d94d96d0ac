// Unit tests for the readers under hostile input: endless lines, NUL bytes,
// byte-order marks, signals during a blocked read, and first lines that are
// data rather than a CSV header.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <thread>

#include "io/csv.hpp"
#include "io/error.hpp"
#include "io/input_file.hpp"
#include "io/number_column.hpp"
#include "io/record_reader.hpp"
#include "io/stop_signal.hpp"
#include "primes/candidate_input.hpp"
#include "temp_file.hpp"
#include "threads/designation_input.hpp"

using tk::Error;
using tk::Record;
using namespace tk::io;
using tk::test::TempFile;

namespace {

// The line number and message of the error the next read throws.
std::pair<std::size_t, std::string> next_error(InputFile& input) {
  std::string_view line;
  try {
    input.next(line);
  } catch (const Error& e) {
    return {e.where().line, e.what()};
  }
  return {0, "no error"};
}

std::pair<std::size_t, std::string> first_record_error(const std::string& content, NativeFormatProbe probe,
                                                       ColumnSets wanted = {}) {
  TempFile file(content);
  RecordReader reader({file.path()}, std::move(probe));
  reader.expect_columns(std::move(wanted));
  Record record;
  try {
    while (reader.next(record)) {
    }
  } catch (const Error& e) {
    return {e.where().line, e.what()};
  }
  return {0, "no error"};
}

}  // namespace

// /dev/zero has no newline: the NUL must be seen as it arrives, not at the
// end of a line that never comes (before, this test never returned).
TEST(InputFaults, DevZeroFailsAtOnceWithLineOne) {
  InputFile input("/dev/zero");
  const auto [line, message] = next_error(input);
  EXPECT_EQ(line, 1u);
  EXPECT_NE(message.find("NUL"), std::string::npos) << message;
}

TEST(InputFaults, NulAfterGoodLinesNamesItsLineAndTheLinesBeforeAreRead) {
  TempFile file(std::string("one\ntwo\nth\0ree\nfour\n", 19));
  InputFile input(file.path());
  std::string_view line;
  ASSERT_TRUE(input.next(line));
  EXPECT_EQ(line, "one");
  ASSERT_TRUE(input.next(line));
  EXPECT_EQ(line, "two");
  EXPECT_EQ(next_error(input).first, 3u);
  ASSERT_TRUE(input.next(line));  // --skip-bad goes on after the bad line
  EXPECT_EQ(line, "four");
  EXPECT_EQ(input.line_number(), 4u);
}

// A line over the limit is skipped when it ends within another limit's
// worth, and the input is given up (one more error) when it does not.
TEST(InputFaults, OverlongLineIsSkippedOrTheInputGivenUp) {
  const std::size_t limit = 100000;  // 64 MiB in the tools
  {
    TempFile file(std::string(limit + 1000, 'y') + "\nnext\n");
    InputFile input(file.path(), limit);
    const auto [line, message] = next_error(input);
    EXPECT_EQ(line, 1u);
    EXPECT_EQ(message, "line longer than 100000 bytes");
    std::string_view text;
    ASSERT_TRUE(input.next(text));
    EXPECT_EQ(text, "next");
    EXPECT_EQ(input.line_number(), 2u);
  }
  {
    TempFile file(std::string(40 * limit, 'y') + "\nnever read\n");
    InputFile input(file.path(), limit);
    EXPECT_EQ(next_error(input).first, 1u);
    const auto [line, message] = next_error(input);
    EXPECT_EQ(line, 1u);
    EXPECT_NE(message.find("rest of the input is skipped"), std::string::npos) << message;
    std::string_view text;
    EXPECT_FALSE(input.next(text));
  }
}

TEST(InputFaults, ByteOrderMarkIsDroppedFromTheFirstLineOnly) {
  TempFile file("\xEF\xBB\xBFG0 X1\n\xEF\xBB\xBFM2\n");
  InputFile input(file.path());
  std::string_view line;
  ASSERT_TRUE(input.next(line));
  EXPECT_EQ(line, "G0 X1");
  ASSERT_TRUE(input.next(line));
  EXPECT_EQ(line, "\xEF\xBB\xBFM2");
}

// A read blocked on a pipe that no one writes to ends once a stop signal
// has been noticed (the tools' handlers call notice_stop_signal).
TEST(InputFaults, NoticedStopSignalEndsABlockedRead) {
  const auto fifo = std::filesystem::temp_directory_path() / ("tk_fifo_" + std::to_string(::getpid()));
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // The writer end stays open and silent, so a read would wait for ever.
  std::thread writer([&fifo] {
    std::ofstream silent(fifo);
    std::this_thread::sleep_for(std::chrono::seconds(3));
  });
  std::thread signaller([] {
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    notice_stop_signal(SIGTERM);
  });
  const auto start = std::chrono::steady_clock::now();
  std::string message;
  {
    InputFile input(fifo.string());
    message = next_error(input).second;
  }
  const auto waited = std::chrono::steady_clock::now() - start;
  signaller.join();
  writer.join();
  notice_stop_signal(0);
  std::filesystem::remove(fifo);
  EXPECT_NE(message.find("stopped by signal 15"), std::string::npos) << message;
  EXPECT_LT(waited, std::chrono::seconds(3));  // not when the writer went away
}

TEST(CsvHeader, AHeaderMustNameTheColumnsTheToolNeeds) {
  const ColumnSets needs{{"t", "load"}};
  EXPECT_EQ(first_record_error("t,load\n0,5\n", {}, needs).first, 0u);
  EXPECT_EQ(first_record_error("load,t,extra\n0,5,x\n", {}, needs).first, 0u);
  const auto [line, message] = first_record_error("garbage\n", {}, needs);
  EXPECT_EQ(line, 1u);
  EXPECT_NE(message.find("not a csv header naming 't' and 'load'"), std::string::npos) << message;
  EXPECT_EQ(first_record_error("t,x\n0,1\n", {}, needs).first, 1u);  // half a header is no header
}

TEST(CsvHeader, ColumnSetsAreDescribedAsAlternatives) {
  EXPECT_EQ(describe_columns({{"number"}, {"expr"}, {"k", "n"}}), "'number', 'expr' or 'k' and 'n'");
  EXPECT_TRUE(is_csv_header_for("k,\"n\",c", {{"number"}, {"k", "n"}}));
  EXPECT_FALSE(is_csv_header_for("k,\"n", {{"k", "n"}}));  // an open quote is no header
}

// A first line that is neither a value nor a header naming the field is a
// bad value at line 1 (before, it was taken as a header and nothing came out).
TEST(CsvHeader, ColumnInputsReportABadFirstValue) {
  const auto nan = first_record_error("NaN\n", number_column_probe("size"));
  EXPECT_EQ(nan.first, 1u);
  EXPECT_NE(nan.second.find("not a finite number"), std::string::npos) << nan.second;
  EXPECT_EQ(first_record_error("size\n1.5\n", number_column_probe("size")).first, 0u);
  EXPECT_EQ(first_record_error("part,size\n1,1.5\n", number_column_probe("size")).first, 0u);
}

// The candidate decoder keeps an expression as text for the tool to refuse
// at its line; before, "garbage" became a CSV header and no record came out.
TEST(CsvHeader, CandidateInputsTakeABadFirstLineAsData) {
  TempFile file("garbage\n7\n");
  RecordReader reader({file.path()}, tk::primes::candidate_format_probe(1u << 20));
  Record record;
  ASSERT_TRUE(reader.next(record));
  EXPECT_EQ(reader.where().line, 1u);
  EXPECT_EQ(record.value("expr", ""), "garbage") << record.dump();
  EXPECT_EQ(first_record_error("k,n,c\n3,5,-1\n", tk::primes::candidate_format_probe(1u << 20)).first, 0u);
  EXPECT_EQ(first_record_error("number\n7\n", tk::primes::candidate_format_probe(1u << 20)).first, 0u);
}

TEST(CsvHeader, DesignationInputsTakeABadFirstLineAsData) {
  TempFile file("garbage\nM10\n");
  RecordReader reader({file.path()}, tk::threads::designation_lines_probe("designation"));
  Record record;
  ASSERT_TRUE(reader.next(record));
  EXPECT_EQ(record["designation"], "garbage");  // threadcalc then refuses it at line 1
  EXPECT_EQ(reader.where().line, 1u);
}
