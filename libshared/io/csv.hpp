/// @file csv.hpp
/// @brief RFC 4180 CSV: splitting a row (quoted fields may span lines) and
/// quoting a field for output.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "io/input_file.hpp"

namespace tk::io {

/// Splits the row that starts with `first_line` into fields, pulling more
/// lines from `input` while a quoted field is still open. Throws Error for
/// an unterminated quote or text after a closing quote.
std::vector<std::string> read_csv_row(std::string_view first_line, InputFile& input);

/// Appends `field` to `out`, quoted when it holds a comma, quote, CR or LF
/// or starts or ends with a space.
void append_csv_field(std::string& out, std::string_view field);

}  // namespace tk::io
