/// @file number_column.hpp
/// @brief Inputs that are a bare column, one value per line, as gauges and
/// data loggers write numbers or order systems write thread designations:
/// each line becomes a record with one named field.
#pragma once

#include <functional>
#include <string>
#include <string_view>

#include "io/record_reader.hpp"

namespace tk::io {

/// A line's value (the line trimmed, never blank or a '#' comment); throws
/// Error at `where` for a line that holds no value.
using ColumnValue = std::function<Record(std::string_view line, const Location& where)>;

/// Recognises an input whose first non-blank line (trimmed) `recognise`
/// accepts, and reads every line as {field: value(line)}; blank lines and
/// lines starting with '#' are skipped. A first line that `recognise`
/// refuses is a CSV header (nullptr) if it names `field`, else a bad value.
NativeFormatProbe column_probe(std::string field, std::function<bool(std::string_view)> recognise, ColumnValue value);

/// A column of finite numbers: the first non-blank line must be one.
NativeFormatProbe number_column_probe(std::string field);

}  // namespace tk::io
