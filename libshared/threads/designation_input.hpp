/// @file designation_input.hpp
/// @brief threadcalc's own input format: a bare list of designations, one
/// per line, as they come out of an order system or a drawing's title block.
#pragma once

#include <string>

#include "io/record_reader.hpp"

namespace tk::threads {

/// Recognises an input whose first non-blank line starts with M (or m) and
/// a digit, or with '#': every line then becomes {field: the line}, blank
/// lines and '#' comments skipped, commas kept (M1,6 is a decimal comma).
/// Any other first line (a CSV header) gives nullptr.
io::NativeFormatProbe designation_lines_probe(std::string field);

}  // namespace tk::threads
