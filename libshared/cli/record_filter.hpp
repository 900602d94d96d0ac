/// @file record_filter.hpp
/// @brief The driver of a record filter (mrtest, riesel): reads the records,
/// works on them on -j threads, and writes them in input order; --skip-bad,
/// the progress line, stop signals and the end's summary of what was skipped
/// are here once, and a tool supplies only its per-record work.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "cli/progress.hpp"
#include "cli/stop_signals.hpp"
#include "cli/tool_app.hpp"
#include "concurrency/ordered_pool.hpp"
#include "io/error.hpp"
#include "io/record.hpp"
#include "io/record_reader.hpp"
#include "io/record_writer.hpp"

namespace tk::cli {

/// A record as read; a tool's job type may derive from it to carry more.
struct RecordJob {
  Record record;
  Location where;
};

/// What the work made of a record; a tool's outcome type may derive from it.
struct RecordOutcome {
  Record record;  ///< written when `write` is set
  bool write = true;
  Location where;              ///< the record's, filled in by the driver
  std::optional<Error> error;  ///< the record's bad data, filled in by the driver
};

/// The tool's part. Only `work` is required.
template <class Job, class Outcome>
struct RecordFilterSteps {
  /// On the reading thread, in input order: false leaves the record out.
  std::function<bool(Job&)> take;
  /// On a worker thread. An Error it throws is the record's bad data.
  std::function<Outcome(Job&)> work;
  /// In input order, just before a record is written.
  std::function<void(Outcome&)> accept;
  /// A record that may take long goes to a worker at once rather than
  /// waiting for its batch to fill.
  std::function<bool(const Job&)> slow;
};

struct RecordFilterSettings {
  io::NativeFormatProbe probe;
  std::vector<std::string> fields;  ///< the output fields the work adds, in order
  bool skip_bad = false;
  /// Records per hand-over to the threads with -j 2 or more: a batch costs
  /// one hand-over, so small quick records go in batches.
  std::size_t batch_size = 1;
  const StopSignals* stop = nullptr;  ///< a caught signal ends the reading
};

/// The parts of a run that do not depend on the tool's types.
class RecordFilterRun {
 public:
  RecordFilterRun(ToolApp& tool, const RecordFilterSettings& settings);

  io::RecordReader& reader() { return reader_; }
  bool stopping() const { return settings_.stop && settings_.stop->caught() != 0; }
  /// A bad record, or a file that cannot be read (line 0): thrown without
  /// --skip-bad; with it, reported and counted, and the run goes on.
  void report_bad(const Error& error);
  /// One outcome, in input order: the progress line, its error, its record.
  void emit(RecordOutcome& outcome, const std::function<void()>& accept);
  /// The progress line cleared, the output flushed, "skipped N bad records";
  /// throws Error when a file could not be read (unless a signal stopped the run).
  void finish();

 private:
  ToolApp& tool_;
  const RecordFilterSettings& settings_;
  io::RecordReader reader_;
  io::RecordWriter writer_;
  Progress progress_;
  std::uint64_t done_ = 0, skipped_ = 0, unreadable_ = 0;
};

/// Seconds set on a record (to the microsecond), "members" kept last: it is
/// the bulky field.
void set_seconds(Record& record, double seconds);

/// Runs the filter over the tool's inputs to the end, or until a stop signal.
template <class Job, class Outcome>
void run_record_filter(ToolApp& tool, const RecordFilterSettings& settings,
                       const RecordFilterSteps<Job, Outcome>& steps) {
  RecordFilterRun run(tool, settings);
  auto work = [&](std::vector<Job>& batch) {
    std::vector<Outcome> outcomes(batch.size());
    for (std::size_t i = 0; i < batch.size(); ++i) {
      try {
        outcomes[i] = steps.work(batch[i]);
      } catch (const Error& e) {
        outcomes[i] = Outcome{};
        outcomes[i].error = Error(e.what(), batch[i].where);
      }
      outcomes[i].where = batch[i].where;
    }
    return outcomes;
  };
  auto emit = [&](std::vector<Outcome>& outcomes) {
    for (Outcome& outcome : outcomes)
      run.emit(outcome, [&] {
        if (steps.accept) steps.accept(outcome);
      });
  };
  const unsigned threads = tool.common().threads;
  OrderedPool<std::vector<Job>, std::vector<Outcome>> pool(threads, work, emit);
  // One thread works inline: no hand-over to save, and a slow producer's
  // records come out as they arrive.
  const std::size_t batch_size = threads > 1 ? settings.batch_size : 1;
  std::vector<Job> batch;
  auto submit_batch = [&] {
    if (!batch.empty()) pool.submit(std::move(batch));
    batch.clear();
  };
  while (!run.stopping()) {
    Job job;
    try {
      if (!run.reader().next(job.record)) break;
    } catch (const Error& e) {
      if (run.stopping()) break;  // the read was interrupted by the signal
      submit_batch();
      pool.finish();  // the records before the bad line are written first
      run.report_bad(e);
      continue;
    }
    job.where = run.reader().where();
    if (steps.take && !steps.take(job)) continue;
    const bool slow = steps.slow && steps.slow(job);
    batch.push_back(std::move(job));
    if (slow || batch.size() >= batch_size) submit_batch();
  }
  submit_batch();
  pool.finish();
  run.finish();
}

}  // namespace tk::cli
