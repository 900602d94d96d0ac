/// @file csv.cpp
#include "io/csv.hpp"

#include "io/error.hpp"

namespace tk::io {

std::vector<std::string> read_csv_row(std::string_view first_line, InputFile& input) {
  std::vector<std::string> fields;
  std::string field;
  const Location start = input.where();
  std::string_view line = first_line;
  std::size_t i = 0;
  bool quoted = false;       // inside a quoted field
  bool after_quote = false;  // a quoted field just closed
  for (;;) {
    if (i == line.size()) {
      if (!quoted) break;
      // A quoted field continues on the next physical line.
      std::string_view more;
      if (!input.next(more)) throw Error("unterminated quoted field at end of input", start);
      field += '\n';
      line = more;
      i = 0;
      continue;
    }
    const char ch = line[i++];
    if (quoted) {
      if (ch != '"') {
        field += ch;
      } else if (i < line.size() && line[i] == '"') {
        field += '"';
        ++i;
      } else {
        quoted = false;
        after_quote = true;
      }
    } else if (ch == ',') {
      fields.push_back(std::move(field));
      field.clear();
      after_quote = false;
    } else if (after_quote) {
      throw Error("unexpected text after a closing quote in a csv field", input.where());
    } else if (ch == '"' && field.empty()) {
      quoted = true;
    } else {
      field += ch;
    }
  }
  fields.push_back(std::move(field));
  return fields;
}

void append_csv_field(std::string& out, std::string_view field) {
  const bool needs_quotes = field.find_first_of(",\"\r\n") != std::string_view::npos ||
                            (!field.empty() && (field.front() == ' ' || field.back() == ' '));
  if (!needs_quotes) {
    out += field;
    return;
  }
  out += '"';
  for (char ch : field) {
    if (ch == '"') out += '"';
    out += ch;
  }
  out += '"';
}

}  // namespace tk::io
