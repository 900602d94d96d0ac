// Unit tests for the shared record I/O: line reading, CSV, JSON Lines,
// format detection and the writer.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "io/csv.hpp"
#include "io/error.hpp"
#include "io/input_file.hpp"
#include "io/number_column.hpp"
#include "io/record_fields.hpp"
#include "io/record_reader.hpp"
#include "io/record_writer.hpp"
#include "temp_file.hpp"

using tk::Error;
using tk::Record;
using namespace tk::io;

namespace {

using tk::test::TempFile;

std::vector<Record> read_all(const std::string& content, NativeFormatProbe probe = {}) {
  TempFile file(content);
  RecordReader reader({file.path()}, std::move(probe));
  std::vector<Record> out;
  Record r;
  while (reader.next(r)) out.push_back(r);
  return out;
}

std::string write_all(const std::vector<Record>& records, OutputFormat format, std::vector<std::string> declared = {}) {
  // The memory stream is closed (and its buffer freed) even when write throws.
  struct Stream {
    char* buffer = nullptr;
    size_t size = 0;
    std::FILE* file = open_memstream(&buffer, &size);
    ~Stream() {
      if (file) std::fclose(file);
      std::free(buffer);
    }
  } stream;
  RecordWriter writer(format, stream.file);
  writer.declare_fields(std::move(declared));
  for (const auto& r : records) writer.write(r);
  writer.flush();
  std::fclose(stream.file);
  stream.file = nullptr;
  return std::string(stream.buffer, stream.size);
}

}  // namespace

TEST(InputFile, SplitsLinesAndCountsThem) {
  TempFile file("a\r\nbb\n\nlast");
  InputFile input(file.path());
  std::string_view line;
  std::vector<std::string> lines;
  while (input.next(line)) lines.emplace_back(line);
  EXPECT_EQ(lines, (std::vector<std::string>{"a", "bb", "", "last"}));
  EXPECT_EQ(input.line_number(), 4u);
}

TEST(InputFile, LinesLongerThanTheBufferSurvive) {
  const std::string long_line(3u << 20, 'x');
  TempFile file(long_line + "\nshort\n");
  InputFile input(file.path());
  std::string_view line;
  ASSERT_TRUE(input.next(line));
  EXPECT_EQ(line.size(), long_line.size());
  ASSERT_TRUE(input.next(line));
  EXPECT_EQ(line, "short");
}

TEST(InputFile, NulByteIsAnErrorWithItsLine) {
  TempFile file(std::string("ok\nbad\0line\n", 12));
  InputFile input(file.path());
  std::string_view line;
  ASSERT_TRUE(input.next(line));
  try {
    input.next(line);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.where().line, 2u);
    EXPECT_NE(std::string(e.what()).find("binary"), std::string::npos);
  }
}

TEST(InputFile, MissingFileNamesTheFile) {
  try {
    InputFile input("/nonexistent/file.txt");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.located_message().rfind("/nonexistent/file.txt: cannot open", 0), 0u);
  }
}

TEST(Csv, QuotedFieldsWithCommasQuotesAndNewlines) {
  TempFile file("\"a,b\",\"say \"\"hi\"\"\",\"two\nlines\",plain\n");
  InputFile input(file.path());
  std::string_view line;
  ASSERT_TRUE(input.next(line));
  const auto fields = read_csv_row(line, input);
  EXPECT_EQ(fields, (std::vector<std::string>{"a,b", "say \"hi\"", "two\nlines", "plain"}));
}

TEST(Csv, UnterminatedQuoteIsAnError) {
  TempFile file("\"open,field\n");
  InputFile input(file.path());
  std::string_view line;
  ASSERT_TRUE(input.next(line));
  EXPECT_THROW(read_csv_row(line, input), Error);
}

TEST(Csv, QuotingRoundTrips) {
  std::string out;
  append_csv_field(out, "a,\"b\"");
  EXPECT_EQ(out, "\"a,\"\"b\"\"\"");
}

TEST(RecordReader, DetectsJsonLinesAndKeepsKeyOrder) {
  const auto records = read_all("\n{\"z\":1,\"a\":\"x\"}\n\n{\"b\":[1,2]}\n");
  ASSERT_EQ(records.size(), 2u);
  EXPECT_EQ(records[0].begin().key(), "z");
  EXPECT_EQ(records[1]["b"][1], 2);
}

TEST(RecordReader, DetectsCsvWithHeader) {
  const auto records = read_all("number,id\r\n97,a\r\n\"100\",\"b,c\"\r\n");
  ASSERT_EQ(records.size(), 2u);
  EXPECT_EQ(records[0]["number"], "97");
  EXPECT_EQ(records[1]["id"], "b,c");
}

TEST(RecordReader, CsvFieldCountMismatchNamesTheLine) {
  try {
    read_all("a,b\n1,2\n3\n");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.where().line, 3u);
    EXPECT_STREQ(e.what(), "expected 2 csv fields, found 1");
  }
}

TEST(RecordReader, BadJsonNamesTheLineAndCanContinue) {
  TempFile file("{\"a\":1}\n{\"a\":\n[1]\n{\"a\":3}\n");
  RecordReader reader({file.path()});
  Record r;
  ASSERT_TRUE(reader.next(r));
  int errors = 0;
  std::vector<std::size_t> lines;
  for (;;) {
    try {
      if (!reader.next(r)) break;
      EXPECT_EQ(r["a"], 3);
    } catch (const Error& e) {
      ++errors;
      lines.push_back(e.where().line);
    }
  }
  EXPECT_EQ(errors, 2);
  EXPECT_EQ(lines, (std::vector<std::size_t>{2, 3}));
}

TEST(RecordReader, NativeProbeClaimsItsFormat) {
  struct Upper : LineDecoder {
    bool decode(std::string_view line, const tk::Location&, Record& out) override {
      out = Record::object();
      out["line"] = std::string(line);
      return true;
    }
  };
  auto probe = [](std::string_view first) -> std::unique_ptr<LineDecoder> {
    if (first.starts_with("#native")) return std::make_unique<Upper>();
    return nullptr;
  };
  const auto records = read_all("#native\nx\n", probe);
  ASSERT_EQ(records.size(), 2u);
  EXPECT_EQ(records[1]["line"], "x");
}

TEST(RecordReader, ReadsSeveralFilesEachWithItsOwnFormat) {
  TempFile json("{\"n\":1}\n"), csv("n\n2\n");
  RecordReader reader({json.path(), csv.path()});
  Record r;
  ASSERT_TRUE(reader.next(r));
  EXPECT_EQ(r["n"], 1);
  ASSERT_TRUE(reader.next(r));
  EXPECT_EQ(r["n"], "2");
  EXPECT_EQ(reader.where().file, csv.path());
  EXPECT_FALSE(reader.next(r));
}

TEST(NumberColumn, BareNumbersBecomeOneFieldRecords) {
  const auto records = read_all("40.012\n\n# gauge 2\n+39.998\n", number_column_probe("size"));
  ASSERT_EQ(records.size(), 2u);
  EXPECT_EQ(records[0]["size"].get<double>(), 40.012);
  EXPECT_EQ(records[1]["size"].get<double>(), 39.998);
  EXPECT_EQ(read_all("size\n40.1\n", number_column_probe("size"))[0]["size"], "40.1");  // a CSV header: not claimed
  try {
    read_all("40.0\ninf\n", number_column_probe("size"));
    FAIL() << "inf was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.where().line, 2u);
    EXPECT_NE(std::string(e.what()).find("not a finite number"), std::string::npos);
  }
}

TEST(RecordWriter, RowCellsMatchTheRecordPath) {
  // write_row and write() of the same record, in both formats; a name that needs escaping.
  struct Stream {
    char* buffer = nullptr;
    size_t size = 0;
    std::FILE* file = open_memstream(&buffer, &size);
    ~Stream() { std::free(buffer); }
  };
  const std::vector<std::string> names{"x", "n", "word", "flag", "gap", "say \"hi\""};
  Record record = Record::object();
  record["x"] = 0.1, record["n"] = -7, record["word"] = "subtune", record["flag"] = true,
  record["gap"] = NAN;  // NaN: null in JSON, empty in CSV, either way
  record["say \"hi\""] = 2.5e-300;
  const Cell row[] = {Cell::real(0.1),     Cell::integer(-7), Cell::text("subtune"),
                      Cell::boolean(true), Cell::real(NAN),   Cell::real(2.5e-300)};
  for (const OutputFormat format : {OutputFormat::json_lines, OutputFormat::csv}) {
    Stream fast;
    {
      RecordWriter writer(format, fast.file);
      writer.declare_fields(names);
      writer.write_row(row);
      writer.flush();
      const Cell too_many[7] = {};
      EXPECT_THROW(writer.write_row(too_many), Error);
    }
    std::fclose(fast.file);
    EXPECT_EQ(std::string(fast.buffer, fast.size), write_all({record}, format, names))
        << (format == OutputFormat::csv ? "csv" : "json");
  }
}

TEST(RecordWriter, JsonLinesAreCompactAndRoundTripDoubles) {
  Record r = Record::object();
  r["x"] = 0.1;
  r["big"] = "123456789012345678901234567890";
  r["n"] = 42;
  const std::string text = write_all({r}, OutputFormat::json_lines);
  EXPECT_EQ(text, "{\"x\":0.1,\"big\":\"123456789012345678901234567890\",\"n\":42}\n");
  EXPECT_EQ(Record::parse(text)["x"].get<double>(), 0.1);
}

TEST(RecordWriter, CsvPutsDeclaredFieldsLastAndLeavesGapsEmpty) {
  Record a = Record::object(), b = Record::object();
  a["id"] = "a";
  a["verdict"] = "prime";
  b["id"] = "b,c";
  b["witness"] = "base 2";
  b["verdict"] = "composite";
  const std::string text = write_all({a, b}, OutputFormat::csv, {"verdict", "witness"});
  EXPECT_EQ(text, "id,verdict,witness\na,prime,\n\"b,c\",composite,base 2\n");
}

TEST(RecordWriter, CsvRejectsAFieldOutsideTheHeader) {
  Record a = Record::object(), b = Record::object();
  a["id"] = 1;
  b["other"] = 2;
  EXPECT_THROW(write_all({a, b}, OutputFormat::csv), Error);
}

TEST(RecordFields, NumbersFromJsonAndCsvText) {
  const tk::Location where{"pos.csv", 7};
  const tk::Record record = tk::Record::parse(R"({"x": 1.5, "y": "-2e3", "z": "+4", "t": "", "n": null, "s": "abc",
                                                 "b": true, "i": "inf", "big": "1e400", "nan": "nan"})");
  EXPECT_EQ(tk::io::number_field(record, "x", where), 1.5);
  EXPECT_EQ(tk::io::number_field(record, "y", where), -2000);
  EXPECT_EQ(tk::io::number_field(record, "z", where), 4);
  EXPECT_FALSE(tk::io::optional_number_field(record, "t", where));
  EXPECT_FALSE(tk::io::optional_number_field(record, "n", where));
  EXPECT_FALSE(tk::io::optional_number_field(record, "missing", where));
  auto message = [&](const char* key) {
    try {
      tk::io::number_field(record, key, where);
    } catch (const tk::Error& e) {
      return e.located_message();
    }
    return std::string("no error");
  };
  EXPECT_EQ(message("missing"), "pos.csv:7: missing field 'missing'");
  EXPECT_EQ(message("s"), "pos.csv:7: field 's' is not a number: 'abc'");
  EXPECT_EQ(message("b"), "pos.csv:7: field 'b' is not a number");
  EXPECT_EQ(message("i"), "pos.csv:7: field 'i' is not finite");
  EXPECT_EQ(message("nan"), "pos.csv:7: field 'nan' is not finite");
  EXPECT_EQ(message("big"), "pos.csv:7: field 'big' is out of range: '1e400'");
}

namespace {

TEST(RecordFile, WritesBothFormatsAndNamesTheFileOnErrors) {
  const std::string path = (std::filesystem::temp_directory_path() / "tk_record_file_test.csv").string();
  {
    tk::io::RecordFile file(path, tk::io::OutputFormat::csv);
    file.declare_fields({"t", "x"});
    const double values[] = {0.5, 3};
    file.write_numbers(values, 0b10);
    file.write(tk::Record{{"t", 1}, {"x", "a,b"}});
    file.close();
  }
  std::ifstream in(path);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text, "t,x\n0.5,3\n1,\"a,b\"\n");
  std::filesystem::remove(path);
  try {
    tk::io::RecordFile bad("/nonexistent-dir/trace.jsonl", tk::io::OutputFormat::json_lines);
    FAIL() << "no error";
  } catch (const tk::Error& e) {
    EXPECT_EQ(e.located_message().rfind("/nonexistent-dir/trace.jsonl: ", 0), 0u) << e.located_message();
  }
}

}  // namespace
