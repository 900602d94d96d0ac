/// @file record_filter.cpp
#include "cli/record_filter.hpp"

#include <cmath>

namespace tk::cli {

RecordFilterRun::RecordFilterRun(ToolApp& tool, const RecordFilterSettings& settings)
    : tool_(tool),
      settings_(settings),
      reader_(tool.common().inputs, settings.probe),
      writer_(tool.output_format()),
      progress_(tool.name(), tool.show_progress()) {
  writer_.declare_fields(settings.fields);
}

void RecordFilterRun::report_bad(const Error& error) {
  if (!settings_.skip_bad) throw error;
  // A file that cannot be read at all (line 0) still fails the run at the end.
  if (error.where().line == 0) ++unreadable_;
  else ++skipped_;
  tool_.warn(error.located_message());
}

void RecordFilterRun::emit(RecordOutcome& outcome, const std::function<void()>& accept) {
  ++done_;
  progress_.update(done_, reader_.fraction_done());
  if (outcome.error) return report_bad(*outcome.error);
  if (!outcome.write) return;
  accept();
  try {
    writer_.write(outcome.record);
  } catch (const Error& e) {
    throw Error(e.what(), outcome.where);  // e.g. a field that is not a CSV column
  }
}

void RecordFilterRun::finish() {
  progress_.finish();
  writer_.flush();
  if (skipped_) tool_.warn("skipped " + std::to_string(skipped_) + " bad record" + (skipped_ == 1 ? "" : "s"));
  if (unreadable_ && !stopping())
    throw Error(std::to_string(unreadable_) + " input file" + (unreadable_ == 1 ? " was" : "s were") + " not read");
}

void set_seconds(Record& record, double seconds) {
  Record members;
  if (record.contains("members")) {
    members = std::move(record["members"]);
    record.erase("members");
  }
  record.erase("seconds");
  record["seconds"] = std::round(seconds * 1e6) / 1e6;
  if (!members.is_null()) record["members"] = std::move(members);
}

}  // namespace tk::cli
