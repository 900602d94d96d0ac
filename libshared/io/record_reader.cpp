/// @file record_reader.cpp
#include "io/record_reader.hpp"

#include <unordered_set>

namespace tk::io {

namespace {

constexpr const char* kBlank = " \t\r\f\v";

bool is_blank(std::string_view line) { return line.find_first_not_of(kBlank) == std::string_view::npos; }

/// nlohmann's messages start with "[json.exception.parse_error.101] parse
/// error at line 1, column 7: ..."; keep the column and the reason.
std::string tidy_json_message(const std::string& what) {
  std::string text = what;
  if (auto close = text.find("] "); text.starts_with("[json.exception") && close != std::string::npos)
    text.erase(0, close + 2);
  if (auto at = text.find("at line 1, "); at != std::string::npos) text.erase(at, 11);
  return "invalid json: " + text;
}

}  // namespace

Record parse_json_object(std::string_view text, const Location& where) {
  Record value;
  try {
    value = Record::parse(text);
  } catch (const nlohmann::json::exception& e) {
    throw Error(tidy_json_message(e.what()), where);
  }
  if (!value.is_object()) throw Error("expected a json object", where);
  return value;
}

RecordReader::RecordReader(std::vector<std::string> paths, NativeFormatProbe probe)
    : paths_(std::move(paths)), probe_(std::move(probe)) {
  if (paths_.empty()) paths_.push_back("-");
}

Location RecordReader::where() const {
  if (!input_) return {};
  return input_->where();
}

double RecordReader::fraction_done() const {
  if (!input_ || input_->size() == 0) return -1.0;
  return static_cast<double>(input_->bytes_read()) / static_cast<double>(input_->size());
}

bool RecordReader::open_next_input() {
  input_.reset();
  format_ = InputFormat::unknown;
  decoder_.reset();
  csv_header_.clear();
  if (next_path_ == paths_.size()) return false;
  // Advance first: if opening fails, the next call moves on to the next file.
  const std::string& path = paths_[next_path_++];
  input_ = std::make_unique<InputFile>(path);
  return true;
}

void RecordReader::start_format(std::string_view first_line) {
  const auto start = first_line.find_first_not_of(kBlank);
  if (first_line[start] == '{') {
    format_ = InputFormat::json_lines;
    return;
  }
  if (probe_) decoder_ = probe_(first_line);
  if (decoder_) {
    format_ = InputFormat::native;
  } else {
    format_ = InputFormat::csv;
    header_pending_ = true;
  }
}

bool RecordReader::next(Record& out) {
  for (;;) {
    if (!input_ && !open_next_input()) return false;
    std::string_view line;
    if (!input_->next(line)) {
      input_.reset();
      continue;
    }
    if (is_blank(line)) continue;
    if (format_ == InputFormat::unknown) start_format(line);
    bool produced = false;
    switch (format_) {
      case InputFormat::json_lines: produced = next_json(line, out); break;
      case InputFormat::csv: produced = next_csv(line, out); break;
      case InputFormat::native: produced = decoder_->decode(line, input_->where(), out); break;
      case InputFormat::unknown: break;
    }
    if (produced) return true;
  }
}

bool RecordReader::next_json(std::string_view line, Record& out) {
  out = parse_json_object(line, input_->where());
  return true;
}

bool RecordReader::next_csv(std::string_view line, Record& out) {
  const Location at = input_->where();
  std::vector<std::string> fields = read_csv_row(line, *input_);
  if (header_pending_) {
    header_pending_ = false;
    if (!wanted_columns_.empty() && !names_columns(fields, wanted_columns_)) {
      const std::string shown(line.substr(0, 60));
      input_.reset();  // without its header, the rows cannot be read
      throw Error("'" + shown + (line.size() > 60 ? "...'" : "'") + " is not a csv header naming " +
                      describe_columns(wanted_columns_) + ", nor a json object",
                  at);
    }
    std::unordered_set<std::string> seen;
    for (const auto& name : fields) {
      if (name.empty()) throw Error("empty column name in csv header", at);
      if (!seen.insert(name).second) throw Error("duplicate column '" + name + "' in csv header", at);
    }
    csv_header_ = std::move(fields);
    return false;
  }
  if (fields.size() != csv_header_.size())
    throw Error(
        "expected " + std::to_string(csv_header_.size()) + " csv fields, found " + std::to_string(fields.size()), at);
  out = Record::object();
  for (std::size_t i = 0; i < fields.size(); ++i) out[csv_header_[i]] = std::move(fields[i]);
  return true;
}

}  // namespace tk::io
