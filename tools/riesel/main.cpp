/// @file main.cpp
/// @brief riesel: proves k*2^n-1 (Lucas-Lehmer-Riesel) and k*2^n+1 (Proth)
/// prime or composite, as a pipeline filter that cron can restart.
#include <chrono>
#include <memory>

#include "cli/number_option.hpp"
#include "cli/option_checks.hpp"
#include "cli/record_filter.hpp"
#include "cli/stop_signals.hpp"
#include "cli/tool_app.hpp"
#include "io/error.hpp"
#include "primes/candidate.hpp"
#include "primes/candidate_input.hpp"
#include "primes/candidate_proof.hpp"
#include "primes/llr_results.hpp"
#include "primes/number_expression.hpp"
#include "primes/proof_journal.hpp"

namespace {

using tk::Record;
using tk::primes::Verdict;

struct Job : tk::cli::RecordJob {
  std::string key;
  std::optional<std::string> finished;  ///< the journal's output line for a record proved before
};

/// `write` is unset when a signal cut the proof short: no verdict.
struct Outcome : tk::cli::RecordOutcome {
  std::string key;
  bool replayed = false;
  std::vector<std::string> log_lines;
};

}  // namespace

int main(int argc, char** argv) {
  tk::cli::ToolApp tool("riesel",
                        "Prove k*2^n-1 (Lucas-Lehmer-Riesel) and k*2^n+1 (Proth) prime or composite: reads "
                        "sieve or mrtest records, NewPGen/ABC files or expressions, and adds verdict, test, P or a, "
                        "res64 and seconds.",
                        "Numbers of other shapes get BPSW and at best probable-prime.\nSee riesel(1).");
  std::string start = "llr", state_dir, shard = "1/1", arithmetic = "auto";
  double checkpoint_seconds = 300;
  bool skip_bad = false, require_proof = false;
  std::size_t max_bits = tk::primes::kDefaultMaxBits;
  unsigned proof_threads = 1;
  CLI::App& app = tool.app();
  app.add_option("--start", start, "llr (LLR's choice of P) or d13 (the seed's D = 13, P = 11)")
      ->check(CLI::IsMember({"llr", "d13"}))
      ->capture_default_str()
      ->type_name("NAME");
  app.add_option("--arithmetic", arithmetic,
                 "auto, gmp (GMP's multiplication) or fft (the weighted transform, every square verified); auto takes "
                 "the FFT from " +
                     std::to_string(tk::primes::kFftMinBits) + " bits on")
      ->check(CLI::IsMember({"auto", "gmp", "fft"}))
      ->capture_default_str()
      ->type_name("NAME");
  app.add_option("--state", state_dir, "keep a lock, a journal, lresults.txt and checkpoints in DIR; a re-run resumes")
      ->type_name("DIR");
  CLI::Option* checkpoint_every = app.add_option("--checkpoint-every", checkpoint_seconds,
                                                 "seconds between checkpoints of a running proof (with --state)")
                                      ->check(tk::cli::number_check(tk::cli::NumberDomain::positive))
                                      ->capture_default_str()
                                      ->type_name("S");
  app.add_option("--shard", shard, "prove only candidates K, K+N, K+2N, ... (K/N)")
      ->capture_default_str()
      ->type_name("K/N");
  app.add_flag("--require-proof", require_proof,
               "a number with no LLR or Proth proof (k >= 2^n, n too small, another shape) is an error, not BPSW");
  app.add_flag("--skip-bad", skip_bad, "report malformed records on stderr and go on");
  app.add_option("--max-bits", max_bits, "refuse numbers larger than this many bits")
      ->check(CLI::Range(std::size_t{2}, std::size_t{1} << 32))
      ->type_name("BITS");
  tool.add_threads_option();
  app.add_option("-t,--proof-threads", proof_threads,
                 "split each proof's squarings over N threads where the transform is long enough to gain (as "
                 "LLR's -t; -j J -t N uses J*N threads)")
      ->check(CLI::Range(1u, 64u))
      ->capture_default_str()
      ->type_name("N");
  tool.add_input_files();

  return tool.run(argc, argv, [&] {
    // Named, not a structured binding: clang 14 (make fuzz) cannot capture those in a lambda.
    const std::pair<unsigned, unsigned> slot_of_count = tk::cli::parse_shard(shard, "--shard");
    const unsigned shard_slot = slot_of_count.first, shard_count = slot_of_count.second;
    // Checkpoints live in the state directory: without one the option would do nothing.
    if (checkpoint_every->count() && state_dir.empty()) throw tk::UsageError("--checkpoint-every needs --state");

    std::unique_ptr<tk::primes::ProofJournal> journal;
    if (!state_dir.empty())
      journal = std::make_unique<tk::primes::ProofJournal>(state_dir,
                                                           [&](const std::string& problem) { tool.warn(problem); });
    const tk::cli::StopSignals stop;

    tk::primes::ProofPlan plan;
    plan.start = start == "d13" ? tk::primes::LlrStart::d13 : tk::primes::LlrStart::llr;
    plan.require_proof = require_proof;
    plan.options_for = [&](const std::string& member) {
      tk::primes::ProofOptions options;
      options.cancel = stop.cancel();
      options.report_every = 1000;
      options.arithmetic = arithmetic == "gmp"   ? tk::primes::Arithmetic::gmp
                           : arithmetic == "fft" ? tk::primes::Arithmetic::fft
                                                 : tk::primes::Arithmetic::automatic;
      options.threads = proof_threads;
      if (!journal) return options;
      const std::string name = member + " start=" + start;
      options.resume_from = journal->load_checkpoint(
          name, [&](const std::string& problem) { tool.warn(problem + ": proving " + member + " from the start"); });
      options.resume_rejected = [&, name, member](const std::string& why) {
        tool.warn(journal->checkpoint_path(name) + ": checkpoint " + why + ": proving " + member + " from the start");
      };
      auto last = std::make_shared<std::chrono::steady_clock::time_point>(std::chrono::steady_clock::now());
      options.progress = [&, name, last](const tk::primes::ProofState& state) {
        const auto now = std::chrono::steady_clock::now();
        if (stop.caught() || std::chrono::duration<double>(now - *last).count() >= checkpoint_seconds) {
          journal->save_checkpoint(name, state);
          *last = now;
        }
        return true;
      };
      return options;
    };

    tk::cli::RecordFilterSteps<Job, Outcome> steps;
    std::uint64_t index = 0;
    steps.take = [&](Job& job) {
      if (index++ % shard_count != shard_slot) return false;
      // Invalid UTF-8 in a passed-through field must not stop the run: replace it in the key.
      job.key = "start=" + start + " " + job.record.dump(-1, ' ', false, tk::Record::error_handler_t::replace);
      if (journal) job.finished = journal->finished(job.key);
      return true;
    };
    steps.work = [&](Job& job) {
      Outcome out;
      out.key = job.key;
      if (stop.caught()) {  // stopping: queued records do not start
        out.write = false;
        return out;
      }
      if (job.finished) {
        out.record = Record::parse(*job.finished);
        out.replayed = true;
        return out;
      }
      const auto started = std::chrono::steady_clock::now();
      const tk::primes::Candidate candidate = tk::primes::candidate_from_record(job.record, max_bits);
      auto member_started = started;
      const Verdict verdict =
          tk::primes::prove_candidate(candidate, plan, job.record, [&](const tk::primes::MemberProof& proof) {
            const auto now = std::chrono::steady_clock::now();
            if (proof.verdict != Verdict::unknown)
              out.log_lines.push_back(
                  tk::primes::llr_result_line(proof, std::chrono::duration<double>(now - member_started).count()));
            if (journal && proof.verdict != Verdict::unknown)
              journal->remove_checkpoint(proof.text + " start=" + start);
            member_started = now;
          });
      if (verdict == Verdict::unknown && !stop.caught())  // never write a verdict that was not computed
        throw tk::Error("the proof stopped without a verdict");
      out.write = verdict != Verdict::unknown;  // a signal cut it short: the checkpoint has it
      tk::cli::set_seconds(job.record,
                           std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count());
      out.record = std::move(job.record);
      return out;
    };
    steps.accept = [&](Outcome& out) {
      if (journal && !out.replayed)
        journal->record_finished(out.key, out.record.dump(-1, ' ', false, tk::Record::error_handler_t::replace),
                                 out.log_lines);
    };

    tk::cli::RecordFilterSettings settings;
    settings.probe = tk::primes::candidate_format_probe(max_bits);
    settings.fields = {"verdict", "test", "P", "a", "res64", "witness", "seconds", "members"};
    settings.skip_bad = skip_bad;
    settings.stop = &stop;
    tk::cli::run_record_filter(tool, settings, steps);
    if (stop.caught()) stop.die("riesel", journal ? "; state saved, run again with the same --state to continue" : "");
  });
}
