/// @file records.cpp
/// @brief threadcalc's default mode: a record per thread member, from
/// designations given as arguments or read from records.
#include <fmt/format.h>

#include "io/record_reader.hpp"
#include "io/record_writer.hpp"
#include "modes.hpp"
#include "threads/designation_input.hpp"

namespace threadcalc {

namespace {

/// Parses and evaluates one designation; errors get `where`.
std::vector<ThreadResult> evaluate_text(const std::string& text, const Options& o, const tk::Location& where) {
  return tk::with_location(where, [&] {
    const ThreadDesignation designation = parse_designation(text);
    std::vector<ThreadResult> results;
    for (const ThreadMember& member : members_of(designation, o.choice))
      results.push_back(evaluate(designation, member, o.turning));
    return results;
  });
}

}  // namespace

void write_records(const std::vector<std::string>& designations, const std::vector<std::string>& inputs,
                   const Options& o, const tk::cli::ToolApp& tool) {
  tk::io::RecordWriter writer(tool.output_format());
  std::vector<std::string> fields = report_fields();
  // Designations from arguments make a record of their own; from records,
  // the designation's column stays where the input has it.
  if (!designations.empty()) fields.insert(fields.begin(), o.field);
  writer.declare_fields(fields);
  const auto emit = [&](const tk::Record& input, const std::string& text, const tk::Location& where) {
    for (const ThreadResult& result : evaluate_text(text, o, where)) {
      tk::Record record = input;
      add_fields(record, result, o.decimals);
      tk::with_location(where, [&] { writer.write(record); });
      warn_all(result, where, tool);
    }
  };
  if (!designations.empty()) {
    for (std::size_t i = 0; i < designations.size(); ++i)
      emit(tk::Record{{o.field, designations[i]}}, designations[i], {fmt::format("argument {}", i + 1), 0});
    writer.flush();
    return;
  }
  tk::io::RecordReader reader(inputs, designation_lines_probe(o.field));
  tk::Record record;
  while (reader.next(record)) {
    const tk::Location where = reader.where();
    const auto it = record.find(o.field);
    if (it == record.end() || !it->is_string() || it->get<std::string>().empty())
      throw tk::Error(fmt::format("no '{}' field with a designation", o.field), where);
    emit(record, it->get<std::string>(), where);
  }
  writer.flush();
}

}  // namespace threadcalc
