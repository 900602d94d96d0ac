/// @file candidate_input.cpp
#include "primes/candidate_input.hpp"

#include "io/csv.hpp"
#include "io/text.hpp"
#include "primes/candidate.hpp"
#include "primes/candidate_formats.hpp"
#include "primes/number_expression.hpp"

namespace tk::primes {

using io::trim;

io::ColumnSets candidate_columns() { return {{"number"}, {"expr"}, {"k", "n"}}; }

bool NumberLineDecoder::decode(std::string_view line, const Location& where, Record& out) {
  const std::string_view text = trim(line);
  if (text.empty() || text.starts_with("#") || text.starts_with("//")) return false;
  try {
    out = record_from_number_text(text, max_bits_);
  } catch (const Error& e) {
    throw Error(e.what(), where);
  }
  return true;
}

io::NativeFormatProbe candidate_format_probe(std::size_t max_bits) {
  return [max_bits](std::string_view first_line) -> std::unique_ptr<io::LineDecoder> {
    if (auto decoder = probe_candidate_format(first_line, max_bits)) return decoder;
    const std::string_view text = trim(first_line);
    // A CSV header must name the fields candidate_from_record reads;
    // anything else is a number line, and a bad one says so at line 1.
    if (io::is_csv_header_for(text, candidate_columns())) return nullptr;
    return std::make_unique<NumberLineDecoder>(max_bits);
  };
}

}  // namespace tk::primes
