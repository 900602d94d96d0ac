/// @file record_reader.hpp
/// @brief Reads records from files or stdin: JSON Lines or CSV, detected per
/// input from its first non-blank byte, or a tool's native text format.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "io/csv.hpp"
#include "io/error.hpp"
#include "io/input_file.hpp"
#include "io/record.hpp"

namespace tk::io {

/// Turns lines of a tool's native text format (plain numbers, NewPGen, ...)
/// into records. The first non-blank line is passed to decode() too.
class LineDecoder {
 public:
  virtual ~LineDecoder() = default;
  /// Fills `out` and returns true, or returns false for a line that holds no
  /// record (a header or comment). Throws Error for a malformed line.
  virtual bool decode(std::string_view line, const Location& where, Record& out) = 0;
};

/// Looks at the first non-blank line of an input that is not JSON and
/// returns a decoder if it recognises the tool's own format; otherwise the
/// input is read as CSV with a header row.
using NativeFormatProbe = std::function<std::unique_ptr<LineDecoder>(std::string_view first_line)>;

enum class InputFormat { unknown, json_lines, csv, native };

class RecordReader {
 public:
  explicit RecordReader(std::vector<std::string> paths, NativeFormatProbe probe = {});

  /// The columns a CSV header must name (any one set), so that a first line
  /// that is data, not a header, is an error at line 1 instead of a header
  /// that no row follows. The input is given up after such an error.
  void expect_columns(ColumnSets wanted) { wanted_columns_ = std::move(wanted); }

  /// Reads the next record. Returns false at the end of the last input.
  /// A malformed record throws Error naming file and line; calling next()
  /// again continues after it (for --skip-bad).
  bool next(Record& out);

  /// Where the record last returned (or the error last thrown) came from.
  Location where() const;
  /// Fraction of the current input consumed, or a negative value when unknown.
  double fraction_done() const;

 private:
  bool open_next_input();
  bool next_json(std::string_view line, Record& out);
  bool next_csv(std::string_view line, Record& out);
  void start_format(std::string_view first_line);

  std::vector<std::string> paths_;
  std::size_t next_path_ = 0;
  NativeFormatProbe probe_;
  std::unique_ptr<InputFile> input_;
  InputFormat format_ = InputFormat::unknown;
  std::unique_ptr<LineDecoder> decoder_;
  std::vector<std::string> csv_header_;
  ColumnSets wanted_columns_;
  bool header_pending_ = false;
};

/// Parses one JSON object from text; Error (with `where`) otherwise.
Record parse_json_object(std::string_view text, const Location& where);

}  // namespace tk::io
