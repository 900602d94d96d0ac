/// @file main.cpp
/// @brief mrtest: decides whether numbers are prime, as a pipeline filter.
#include <atomic>
#include <chrono>
#include <set>

#include "cli/record_filter.hpp"
#include "cli/tool_app.hpp"
#include "io/error.hpp"
#include "primes/candidate.hpp"
#include "primes/candidate_input.hpp"
#include "primes/number_expression.hpp"
#include "primes/trial_division.hpp"

namespace {

using tk::Record;
using tk::primes::Verdict;

// Small numbers travel to the worker threads in batches, so that -j pays
// one hand-over per batch rather than per number; a number that may take
// long goes at once, so that it does not hold up the others.
constexpr std::size_t kBatchSize = 64;

bool likely_slow(const Record& record) {
  for (const char* field : {"number", "expr"}) {
    auto found = record.find(field);
    if (found != record.end() && found->is_string()) {
      const auto& text = found->get_ref<const std::string&>();
      return text.size() > 40 || text.find_first_of("^*!#") != std::string::npos;
    }
  }
  auto n = record.find("n");
  return n == record.end() || !n->is_number_unsigned() || n->get<std::uint64_t>() > 256;
}

}  // namespace

int main(int argc, char** argv) {
  tk::cli::ToolApp tool("mrtest",
                        "Decide whether numbers are prime: reads numbers, expressions, NewPGen/ABC files or "
                        "records, and adds verdict, test, witness and seconds to each record.",
                        "Verdicts: prime (proved: BPSW below 2^64, or trial division), prime-if-grh (--test "
                        "mr-grh: proved if the Generalised Riemann Hypothesis holds), probable-prime, composite "
                        "(with witness), unknown (trial division only).\nSee mrtest(1).");
  std::string test = "bpsw";
  std::vector<std::uint64_t> bases;
  unsigned rounds = 0;
  std::uint64_t seed = 0;
  std::optional<std::uint64_t> trial_bound;
  std::vector<std::string> keep;
  bool skip_bad = false;
  std::size_t max_bits = tk::primes::kDefaultMaxBits;

  CLI::App& app = tool.app();
  app.add_option("-t,--test", test,
                 "bpsw (default), mr, mr-grh (every base below 2(ln N)^2: a proof if GRH holds; slow, see "
                 "mrtest(1)), fermat, lucas or trial")
      ->type_name("NAME")
      ->check(CLI::IsMember({"bpsw", "mr", "miller-rabin", "mr-grh", "fermat", "lucas", "trial"}));
  app.add_option("-b,--bases", bases, "bases for mr and fermat, e.g. 2,3,5 (default 2)")
      ->type_name("LIST")
      ->delimiter(',')
      ->allow_extra_args(false)  // "-b 2,3 FILE": FILE is not a base
      ->check(CLI::Range(std::uint64_t{2}, ~std::uint64_t{0}));
  app.add_option("-r,--rounds", rounds, "extra random bases for mr and fermat")
      ->check(CLI::Range(0u, 100000u))
      ->type_name("N");
  app.add_option("--seed", seed, "seed for the random bases (with each number, fixes them)")->type_name("S");
  app.add_option("--trial-bound", trial_bound, "trial division by primes up to B (0: none; default by size)")
      ->check(CLI::Range(std::uint64_t{0}, std::uint64_t{1} << 32))
      ->type_name("B");
  app.add_option("-k,--keep", keep,
                 "pass on only records with these verdicts: prime, prime-if-grh, probable, composite, unknown")
      ->type_name("LIST")
      ->delimiter(',')
      ->allow_extra_args(false)
      ->check(CLI::IsMember({"prime", "prime-if-grh", "probable", "probable-prime", "composite", "unknown"}));
  app.add_flag("--skip-bad", skip_bad, "report malformed records on stderr and go on");
  app.add_option("--max-bits", max_bits, "refuse numbers larger than this many bits (default 2^26)")
      ->check(CLI::Range(std::size_t{2}, std::size_t{1} << 32))
      ->type_name("BITS");
  tool.add_threads_option();
  tool.add_input_files();

  return tool.run(argc, argv, [&] {
    tk::primes::TestPlan plan;
    plan.kind = *tk::primes::parse_test_kind(test);
    plan.bases = bases;
    plan.random_bases = rounds;
    plan.seed = seed;
    plan.trial_bound = trial_bound;
    tk::primes::small_primes();  // the trial-division table, built before any timing
    if ((!bases.empty() || rounds) && plan.kind != tk::primes::TestKind::miller_rabin &&
        plan.kind != tk::primes::TestKind::fermat)
      throw tk::UsageError("--bases and --rounds go with --test mr or --test fermat");

    std::set<Verdict> wanted;
    for (const auto& name : keep) {
      if (name == "prime") wanted.insert(Verdict::prime);
      else if (name == "composite") wanted.insert(Verdict::composite);
      else if (name == "unknown") wanted.insert(Verdict::unknown);
      else if (name == "prime-if-grh") wanted.insert(Verdict::prime_if_grh);
      else wanted.insert(Verdict::probable_prime);
    }

    // A big number tested while other threads sit idle splits its BPSW over
    // two threads; when every thread has work, splitting would only
    // oversubscribe the cores.
    const unsigned threads = tool.common().threads;
    std::atomic<unsigned> busy{0};
    tk::cli::RecordFilterSteps<tk::cli::RecordJob, tk::cli::RecordOutcome> steps;
    steps.work = [&](tk::cli::RecordJob& job) {
      struct Busy {  // counted while the test runs, even if it throws
        std::atomic<unsigned>& count;
        explicit Busy(std::atomic<unsigned>& c) : count(c) { ++count; }
        ~Busy() { --count; }
      } running(busy);
      const auto start = std::chrono::steady_clock::now();
      const tk::primes::Candidate candidate = tk::primes::candidate_from_record(job.record, max_bits);
      tk::primes::TestPlan job_plan = plan;
      if (threads > 1 && busy.load() < threads) job_plan.split_bits = tk::primes::kDefaultSplitBits;
      const Verdict verdict = tk::primes::test_candidate(candidate, job_plan, job.record);
      tk::cli::set_seconds(job.record, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
      tk::cli::RecordOutcome out;
      out.record = std::move(job.record);
      out.write = wanted.empty() || wanted.count(verdict);
      return out;
    };
    steps.slow = [](const tk::cli::RecordJob& job) { return likely_slow(job.record); };

    tk::cli::RecordFilterSettings settings;
    settings.probe = tk::primes::candidate_format_probe(max_bits);
    settings.fields = {"verdict", "test", "witness", "seconds", "members"};
    settings.skip_bad = skip_bad;
    settings.batch_size = kBatchSize;
    tk::cli::run_record_filter(tool, settings, steps);
  });
}
