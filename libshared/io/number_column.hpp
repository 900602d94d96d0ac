/// @file number_column.hpp
/// @brief Inputs that are a bare column of numbers, as gauges and data
/// loggers write them: each line becomes a record with one named field.
#pragma once

#include <string>

#include "io/record_reader.hpp"

namespace tk::io {

/// Recognises an input whose first non-blank line is one finite number and
/// reads every line as {field: number}; blank lines and lines starting with
/// '#' are skipped. Any other first line (a CSV header) gives nullptr.
NativeFormatProbe number_column_probe(std::string field);

}  // namespace tk::io
