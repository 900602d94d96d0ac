/// @file record_writer.hpp
/// @brief Writes records as JSON Lines (default) or CSV with a header row.
#pragma once

#include <cstdint>
#include <cstdio>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "io/atomic_file.hpp"
#include "io/record.hpp"

namespace tk::io {

enum class OutputFormat { json_lines, csv };

/// One value of RecordWriter::write_row(): a number (non-finite: null), a
/// whole number, a word (a JSON string; it must need no escaping), or true/false.
struct Cell {
  enum class Kind : std::uint8_t { number, integer, word, boolean };
  Kind kind = Kind::number;
  double number = 0;
  long long whole = 0;
  std::string_view word = {};

  static Cell real(double v) { return {Kind::number, v, 0, {}}; }
  static Cell integer(long long v) { return {Kind::integer, 0, v, {}}; }
  static Cell text(std::string_view w) { return {Kind::word, 0, 0, w}; }
  static Cell boolean(bool b) { return {Kind::boolean, 0, b, {}}; }
};

/// One writer for every tool. JSON Lines writes each record as one compact
/// object. CSV takes its columns from the first record plus the fields the
/// tool declares, so records that lack an optional field still line up.
/// Output is buffered but flushed at least every 0.2 s (and per record on a
/// terminal) so slow pipelines show results as they come. The buffer hands
/// the stream whole records, at most kWriteChunk bytes at a time (one
/// record when it is longer), flushed at once: a process killed at any
/// moment leaves whole lines, and a pipe gets each chunk in one piece
/// (POSIX makes writes of up to PIPE_BUF bytes atomic). A longer record is
/// one write when the stream's buffer holds it (ToolApp gives stdout 64 KiB).
class RecordWriter {
 public:
  static constexpr std::size_t kWriteChunk = 4096;  ///< PIPE_BUF on Linux

  explicit RecordWriter(OutputFormat format, std::FILE* out = stdout);
  /// Writes the records still buffered (errors ignored: see flush()).
  ~RecordWriter();
  RecordWriter(const RecordWriter&) = delete;
  RecordWriter& operator=(const RecordWriter&) = delete;

  /// Fields the tool may add to records, in output order.
  void declare_fields(std::vector<std::string> names);

  /// Throws Error on a write failure, or (CSV) for a field that is not a
  /// column. Non-finite numbers are written null (JSON) or empty (CSV).
  void write(const Record& record);
  /// Fast path for long numeric streams (pulses, time series): one number
  /// per declared field, in order; bit i of `integers` marks value i as an
  /// integer. The same output as write() of the equivalent record, without
  /// building one.
  void write_numbers(std::span<const double> values, std::uint64_t integers);
  /// The fast path for records of mixed cells: one per declared field, in
  /// order (Error for more cells than fields). As write_numbers, a whole
  /// double is written without ".0" (write() writes 0.0): the same number.
  void write_row(std::span<const Cell> cells);
  /// Flushes and reports a write error as Error.
  void flush();

 private:
  void write_csv(const Record& record);
  /// One line of `count` declared fields, cell i written by append(i, line).
  template <class AppendCell>
  void write_declared(std::size_t count, const AppendCell& append);
  void emit(const std::string& text);
  /// The buffered records to the stream, flushed; Error on a write failure.
  void write_pending();

  OutputFormat format_;
  std::FILE* out_;
  bool interactive_;
  std::vector<std::string> declared_;
  std::vector<std::string> json_keys_;  ///< the declared names as JSON keys, "name": (escaped), for the fast paths
  std::vector<std::string> columns_;
  std::string line_;
  std::string pending_;    ///< whole records not yet handed to out_
  double last_flush_ = 0;  ///< seconds, CLOCK_MONOTONIC_COARSE
};

/// Records in a file of their own beside the main output (a trace of a
/// simulation): the same formats, every error naming the file. The file
/// appears when close() succeeds, whole (an AtomicFile): until then, and
/// after an error or a kill, `path` keeps what it held before.
class RecordFile {
 public:
  /// Error naming `path` when it cannot be written.
  RecordFile(const std::string& path, OutputFormat format);
  /// Without close(): the records are dropped and `path` is left as it was.
  ~RecordFile();
  RecordFile(const RecordFile&) = delete;
  RecordFile& operator=(const RecordFile&) = delete;

  void declare_fields(std::vector<std::string> names) { writer_->declare_fields(std::move(names)); }
  void write(const Record& record);
  void write_numbers(std::span<const double> values, std::uint64_t integers);
  /// Flushes, syncs and puts the file in place; Error naming it on a write failure.
  void close();

 private:
  AtomicFile file_;
  std::unique_ptr<RecordWriter> writer_;  ///< after file_: destroyed before it
};

/// A record field as CSV cell text: strings raw, numbers and booleans as in
/// JSON, null and non-finite numbers as empty, arrays and objects as compact JSON.
std::string cell_text(const Record& value);

/// The record value of a write_row() cell, for a record that carries other fields too.
Record cell_value(const Cell& cell);

}  // namespace tk::io
