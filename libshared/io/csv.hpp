/// @file csv.hpp
/// @brief RFC 4180 CSV: splitting a row (quoted fields may span lines) and
/// quoting a field for output.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/input_file.hpp"

namespace tk::io {

/// Splits the row that starts with `first_line` into fields, pulling more
/// lines from `input` while a quoted field is still open. Throws Error for
/// an unterminated quote or text after a closing quote.
std::vector<std::string> read_csv_row(std::string_view first_line, InputFile& input);

/// The fields of a one-line row, or nothing when it is not valid CSV.
std::optional<std::vector<std::string>> split_csv_line(std::string_view line);

/// What a CSV header must name for a tool to use its rows: any one of the
/// sets, all of its columns ({{"number"}, {"expr"}, {"k", "n"}}).
using ColumnSets = std::vector<std::vector<std::string>>;
bool names_columns(const std::vector<std::string>& header, const ColumnSets& wanted);
/// Whether `line` is a one-line CSV header naming one of the sets.
bool is_csv_header_for(std::string_view line, const ColumnSets& wanted);
/// "'number', 'expr' or 'k' and 'n'"
std::string describe_columns(const ColumnSets& wanted);

/// Appends `field` to `out`, quoted when it holds a comma, quote, CR or LF
/// or starts or ends with a space.
void append_csv_field(std::string& out, std::string_view field);

}  // namespace tk::io
