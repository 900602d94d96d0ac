/// @file csv.cpp
#include "io/csv.hpp"

#include <algorithm>

#include "io/error.hpp"

namespace tk::io {

namespace {

// The row parser; `more` supplies the next physical line while a quoted
// field is open, and `at` says where the row is, for errors.
template <class NextLine, class Where>
std::vector<std::string> split_row(std::string_view first_line, NextLine more, Where at) {
  std::vector<std::string> fields;
  std::string field;
  const Location start = at();
  std::string_view line = first_line;
  std::size_t i = 0;
  bool quoted = false;       // inside a quoted field
  bool after_quote = false;  // a quoted field just closed
  for (;;) {
    if (i == line.size()) {
      if (!quoted) break;
      // A quoted field continues on the next physical line.
      std::string_view next_line;
      if (!more(next_line)) throw Error("unterminated quoted field at end of input", start);
      field += '\n';
      line = next_line;
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
      throw Error("unexpected text after a closing quote in a csv field", at());
    } else if (ch == '"' && field.empty()) {
      quoted = true;
    } else {
      field += ch;
    }
  }
  fields.push_back(std::move(field));
  return fields;
}

}  // namespace

std::vector<std::string> read_csv_row(std::string_view first_line, InputFile& input) {
  return split_row(
      first_line, [&input](std::string_view& line) { return input.next(line); }, [&input] { return input.where(); });
}

std::optional<std::vector<std::string>> split_csv_line(std::string_view line) {
  try {
    return split_row(
        line, [](std::string_view&) { return false; }, [] { return Location{}; });
  } catch (const Error&) {
    return std::nullopt;
  }
}

bool names_columns(const std::vector<std::string>& header, const ColumnSets& wanted) {
  const auto has = [&header](const std::string& name) {
    return std::find(header.begin(), header.end(), name) != header.end();
  };
  return std::any_of(wanted.begin(), wanted.end(),
                     [&has](const std::vector<std::string>& set) { return std::all_of(set.begin(), set.end(), has); });
}

bool is_csv_header_for(std::string_view line, const ColumnSets& wanted) {
  const std::optional<std::vector<std::string>> fields = split_csv_line(line);
  return fields && names_columns(*fields, wanted);
}

std::string describe_columns(const ColumnSets& wanted) {
  std::string text;
  for (std::size_t i = 0; i < wanted.size(); ++i) {
    if (i > 0) text += i + 1 == wanted.size() ? " or " : ", ";
    for (std::size_t j = 0; j < wanted[i].size(); ++j) {
      if (j > 0) text += j + 1 == wanted[i].size() ? " and " : ", ";
      text += "'" + wanted[i][j] + "'";
    }
  }
  return text;
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
