/// @file number_column.cpp
#include "io/number_column.hpp"

#include <optional>

#include "io/csv.hpp"
#include "io/record_fields.hpp"
#include "io/text.hpp"

namespace tk::io {

namespace {

/// The finite number that is all of `text`, if it is one.
std::optional<double> whole_number(std::string_view text) {
  double value = 0;
  if (parse_number_text(text, value) != NumberText::ok) return std::nullopt;
  return value;
}

class ColumnDecoder final : public LineDecoder {
 public:
  ColumnDecoder(std::string field, ColumnValue value) : field_(std::move(field)), value_(std::move(value)) {}
  bool decode(std::string_view line, const Location& where, Record& out) override {
    line = trim(line);
    if (line.empty() || line.front() == '#') return false;
    out = Record::object();
    out[field_] = value_(line, where);
    return true;
  }

 private:
  std::string field_;
  ColumnValue value_;
};

}  // namespace

NativeFormatProbe column_probe(std::string field, std::function<bool(std::string_view)> recognise, ColumnValue value) {
  return [field = std::move(field), recognise = std::move(recognise),
          value = std::move(value)](std::string_view first_line) -> std::unique_ptr<LineDecoder> {
    // A first line that is neither a value nor a header naming the field is
    // a bad value, reported as such at line 1.
    if (!recognise(trim(first_line)) && is_csv_header_for(first_line, {{field}})) return nullptr;
    return std::make_unique<ColumnDecoder>(field, value);
  };
}

NativeFormatProbe number_column_probe(std::string field) {
  const auto number = [field](std::string_view line, const Location& where) -> Record {
    const std::optional<double> value = whole_number(line);
    if (!value) {
      const std::string shown(line.substr(0, 40));
      throw Error(
          "'" + shown + (line.size() > 40 ? "...'" : "'") + " is not a finite number (" + field + ", one per line)",
          where);
    }
    return *value;
  };
  return column_probe(
      field, [](std::string_view first) { return whole_number(first).has_value(); }, number);
}

}  // namespace tk::io
