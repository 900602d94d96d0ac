#include "threads/designation_input.hpp"

#include <cctype>
#include <memory>

#include "io/text.hpp"

namespace tk::threads {
namespace {

class DesignationLines : public io::LineDecoder {
 public:
  explicit DesignationLines(std::string field) : field_(std::move(field)) {}
  bool decode(std::string_view line, const Location&, Record& out) override {
    line = io::trim(line);
    if (line.empty() || line.front() == '#') return false;
    out = Record::object();
    out[field_] = std::string(line);
    return true;
  }

 private:
  std::string field_;
};

}  // namespace

io::NativeFormatProbe designation_lines_probe(std::string field) {
  return [field = std::move(field)](std::string_view first) -> std::unique_ptr<io::LineDecoder> {
    first = io::trim(first);
    const bool designation = first.size() >= 2 && (first[0] == 'M' || first[0] == 'm') &&
                             std::isdigit(static_cast<unsigned char>(io::trim(first.substr(1)).front()));
    if (!designation && !first.starts_with('#')) return nullptr;
    return std::make_unique<DesignationLines>(field);
  };
}

}  // namespace tk::threads
