/// @file candidate_input.hpp
/// @brief Reading candidates from any input the prime tools accept: JSON
/// Lines, CSV, NewPGen and ABC/ABCD files, or one number per line.
#pragma once

#include <cstddef>
#include <memory>
#include <string_view>

#include "io/csv.hpp"
#include "io/record_reader.hpp"

namespace tk::primes {

/// Recognises the prime tools' text formats from an input's first non-blank
/// line; for a CSV header it returns nullptr.
io::NativeFormatProbe candidate_format_probe(std::size_t max_bits);

/// The columns a CSV header of candidates must name: number, expr, or k and n.
io::ColumnSets candidate_columns();

/// One number or expression per line; blank lines and lines starting with
/// '#' or '//' are skipped.
class NumberLineDecoder : public io::LineDecoder {
 public:
  explicit NumberLineDecoder(std::size_t max_bits) : max_bits_(max_bits) {}
  bool decode(std::string_view line, const Location& where, Record& out) override;

 private:
  std::size_t max_bits_;
};

}  // namespace tk::primes
