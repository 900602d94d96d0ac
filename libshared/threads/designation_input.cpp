#include "threads/designation_input.hpp"

#include <cctype>

#include "io/number_column.hpp"
#include "io/text.hpp"

namespace tk::threads {

io::NativeFormatProbe designation_lines_probe(std::string field) {
  // "M30x2-6g", "M 10", or a comment before the first one.
  const auto recognise = [](std::string_view first) {
    if (first.starts_with('#')) return true;
    if (first.size() < 2 || (first[0] != 'M' && first[0] != 'm')) return false;
    const std::string_view after = io::trim(first.substr(1));
    return !after.empty() && std::isdigit(static_cast<unsigned char>(after.front()));
  };
  const auto text = [](std::string_view line, const Location&) { return Record(std::string(line)); };
  return io::column_probe(std::move(field), recognise, text);
}

}  // namespace tk::threads
