/// @file number_column.cpp
#include "io/number_column.hpp"

#include <optional>

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

class NumberColumnDecoder final : public LineDecoder {
 public:
  explicit NumberColumnDecoder(std::string field) : field_(std::move(field)) {}
  bool decode(std::string_view line, const Location& where, Record& out) override {
    line = trim(line);
    if (line.empty() || line.front() == '#') return false;
    const std::optional<double> value = whole_number(line);
    if (!value) {
      const std::string shown(line.substr(0, 40));
      throw Error("'" + shown + (line.size() > 40 ? "...'" : "'") + " is not a finite number (" + field_ + ", one per line)", where);
    }
    out = Record::object();
    out[field_] = *value;
    return true;
  }

 private:
  std::string field_;
};

}  // namespace

NativeFormatProbe number_column_probe(std::string field) {
  return [field = std::move(field)](std::string_view first_line) -> std::unique_ptr<LineDecoder> {
    if (!whole_number(trim(first_line))) return nullptr;
    return std::make_unique<NumberColumnDecoder>(field);
  };
}

}  // namespace tk::io
