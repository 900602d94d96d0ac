/// @file record_writer.cpp
#include "io/record_writer.hpp"

#include <stdio_ext.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>

#include <fmt/compile.h>
#include <fmt/format.h>

#include "io/csv.hpp"
#include "io/error.hpp"

namespace tk::io {

namespace {

// Seconds on a clock of a few milliseconds' resolution: enough to flush
// every 0.2 s, and several times cheaper than the precise one, which
// matters at millions of records a second.
double coarse_now() {
  timespec now{};
  clock_gettime(CLOCK_MONOTONIC_COARSE, &now);
  return static_cast<double>(now.tv_sec) + static_cast<double>(now.tv_nsec) * 1e-9;
}

}  // namespace

RecordWriter::RecordWriter(OutputFormat format, std::FILE* out)
    : format_(format), out_(out), interactive_(isatty(fileno(out)) != 0), last_flush_(coarse_now()) {}

std::string cell_text(const Record& value) {
  switch (value.type()) {
    case Record::value_t::string: return value.get<std::string>();
    case Record::value_t::null: return {};
    case Record::value_t::number_float:  // NaN and inf: empty, as JSON's dump writes them null
      return std::isfinite(value.get<double>()) ? value.dump() : std::string();
    default: return value.dump();
  }
}

Record cell_value(const Cell& cell) {
  switch (cell.kind) {
    case Cell::Kind::number: return cell.number;  // non-finite: written null or empty
    case Cell::Kind::integer: return cell.whole;
    case Cell::Kind::boolean: return cell.whole != 0;
    case Cell::Kind::word: return std::string(cell.word);
  }
  return nullptr;
}

RecordWriter::~RecordWriter() {
  try {
    write_pending();  // records decided before an error stay written
  } catch (const Error&) {
  }
}

void RecordWriter::emit(const std::string& text) {
  if (pending_.size() + text.size() > kWriteChunk) write_pending();
  pending_ += text;
  const double now = coarse_now();
  if (interactive_ || now - last_flush_ > 0.2) {
    flush();
    last_flush_ = now;
  } else if (pending_.size() >= kWriteChunk) {
    write_pending();
  }
}

void RecordWriter::write_pending() {
  if (pending_.empty()) return;
  if (__fpending(out_) != 0 && std::fflush(out_) != 0)  // bytes someone else wrote go first, on their own
    throw Error(std::string("write error: ") + std::strerror(errno));
  const std::size_t size = pending_.size();
  const bool written = std::fwrite(pending_.data(), 1, size, out_) == size;
  pending_.clear();  // not again from the destructor after an error
  // The stream's buffer gets whole records only and hands them on at once.
  if (!written || std::fflush(out_) != 0) throw Error(std::string("write error: ") + std::strerror(errno));
}

void RecordWriter::flush() {
  write_pending();
  if (std::fflush(out_) != 0) throw Error(std::string("write error: ") + std::strerror(errno));
}

void RecordWriter::write(const Record& record) {
  if (format_ == OutputFormat::csv) {
    write_csv(record);
    return;
  }
  line_ = record.dump(-1, ' ', false, Record::error_handler_t::replace);
  line_ += '\n';
  emit(line_);
}

void RecordWriter::write_csv(const Record& record) {
  line_.clear();
  if (columns_.empty()) {
    // Pass-through fields in input order, then the tool's own in declared order.
    for (const auto& item : record.items())
      if (std::find(declared_.begin(), declared_.end(), item.key()) == declared_.end()) columns_.push_back(item.key());
    columns_.insert(columns_.end(), declared_.begin(), declared_.end());
    for (std::size_t i = 0; i < columns_.size(); ++i) {
      if (i) line_ += ',';
      append_csv_field(line_, columns_[i]);
    }
    line_ += '\n';
  }
  for (const auto& item : record.items())
    if (std::find(columns_.begin(), columns_.end(), item.key()) == columns_.end())
      throw Error("csv output: field '" + item.key() + "' is not among the columns set by the first record");
  for (std::size_t i = 0; i < columns_.size(); ++i) {
    if (i) line_ += ',';
    auto found = record.find(columns_[i]);
    if (found != record.end()) append_csv_field(line_, cell_text(*found));
  }
  line_ += '\n';
  emit(line_);
}

void RecordWriter::declare_fields(std::vector<std::string> names) {
  declared_ = std::move(names);
  json_keys_.clear();
  for (const std::string& name : declared_) json_keys_.push_back(Record(name).dump() + ':');
}

template <class AppendCell>
void RecordWriter::write_declared(std::size_t count, const AppendCell& append) {
  if (count > declared_.size()) throw Error(fmt::format("{} values for {} declared fields", count, declared_.size()));
  line_.clear();
  if (format_ == OutputFormat::csv) {
    if (columns_.empty()) {  // the header, once, whichever of write() and the fast paths comes first
      columns_ = declared_;
      for (std::size_t i = 0; i < columns_.size(); ++i) {
        if (i) line_ += ',';
        append_csv_field(line_, columns_[i]);
      }
      line_ += '\n';
    }
    if (count > columns_.size())
      throw Error(
          fmt::format("csv output: {} values for the {} columns set by the first record", count, columns_.size()));
    for (std::size_t i = 0; i < count; ++i) {
      if (i) line_ += ',';
      append(i, line_);
    }
  } else {
    line_ += '{';
    for (std::size_t i = 0; i < count; ++i) {
      if (i) line_ += ',';
      line_ += json_keys_[i];
      append(i, line_);
    }
    line_ += '}';
  }
  line_ += '\n';
  emit(line_);
}

namespace {

void append_number(std::string& line, double v, bool json) {
  if (!std::isfinite(v)) {  // as write() does: JSON null, an empty CSV cell
    if (json) line += "null";
    return;
  }
  fmt::format_to(std::back_inserter(line), FMT_COMPILE("{}"), v);
}

}  // namespace

void RecordWriter::write_numbers(std::span<const double> values, std::uint64_t integers) {
  const bool json = format_ == OutputFormat::json_lines;
  write_declared(values.size(), [&](std::size_t i, std::string& line) {
    if (integers >> i & 1 && std::isfinite(values[i]))
      fmt::format_to(std::back_inserter(line), FMT_COMPILE("{}"), static_cast<long long>(values[i]));
    else append_number(line, values[i], json);
  });
}

void RecordWriter::write_row(std::span<const Cell> cells) {
  const bool json = format_ == OutputFormat::json_lines;
  write_declared(cells.size(), [&](std::size_t i, std::string& line) {
    const Cell& c = cells[i];
    switch (c.kind) {
      case Cell::Kind::number: append_number(line, c.number, json); break;
      case Cell::Kind::integer: fmt::format_to(std::back_inserter(line), FMT_COMPILE("{}"), c.whole); break;
      case Cell::Kind::boolean: line += c.whole ? "true" : "false"; break;
      case Cell::Kind::word:
        if (json) line += '"';
        line += c.word;
        if (json) line += '"';
        break;
    }
  });
}

}  // namespace tk::io

namespace tk::io {

RecordFile::RecordFile(const std::string& path, OutputFormat format)
    : file_(path), writer_(std::make_unique<RecordWriter>(format, file_.stream())) {}

RecordFile::~RecordFile() = default;

void RecordFile::write(const Record& record) {
  try {
    writer_->write(record);
  } catch (const Error& e) {
    throw Error(e.what(), Location{file_.path(), 0});
  }
}

void RecordFile::write_numbers(std::span<const double> values, std::uint64_t integers) {
  try {
    writer_->write_numbers(values, integers);
  } catch (const Error& e) {
    throw Error(e.what(), Location{file_.path(), 0});
  }
}

void RecordFile::close() {
  try {
    writer_->flush();
  } catch (const Error& e) {
    throw Error(e.what(), Location{file_.path(), 0});
  }
  file_.commit();
}

}  // namespace tk::io
