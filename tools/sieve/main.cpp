/// @file main.cpp
/// @brief sieve: primes in an interval, and the generalized sieve for
/// twin, Sophie Germain, Cunningham-chain, Riesel and Proth searches.
#include <fmt/format.h>

#include <cmath>

#include "cli/number_option.hpp"
#include "cli/stop_signals.hpp"
#include "cli/tool_app.hpp"
#include "io/error.hpp"
#include "io/record_writer.hpp"
#include "primes/generalized_sieve.hpp"
#include "primes/prime_range.hpp"
#include "primes/sieve_output.hpp"
#include "primes/sieve_run.hpp"

namespace {

struct FormOptions {
  std::string n, k, h0, c, x, pmax, shard = "1/1", factors, checkpoint;
  unsigned length = 2;
  double min_rate = 0, checkpoint_seconds = 300, rate_window = 60;
  bool newpgen = false, abc = false, abcd = false, resume = false, riesel_condition = false;
};

tk::primes::SieveSpec spec_from(tk::primes::SieveForm form, const FormOptions& o) {
  tk::primes::SieveSpec spec;
  spec.form = form;
  spec.length = form == tk::primes::SieveForm::cc1 || form == tk::primes::SieveForm::cc2 ? o.length : 1;
  spec.n = tk::cli::parse_count(o.n, "--n");
  spec.p_max = tk::cli::parse_count(o.pmax, "--pmax");
  const bool seed_form = !o.h0.empty() || !o.c.empty() || !o.x.empty();
  if (seed_form == !o.k.empty()) throw tk::UsageError("give either --k A:B or --h0, --c and --x A:B");
  if (seed_form) {
    if (o.h0.empty() || o.c.empty() || o.x.empty()) throw tk::UsageError("--h0, --c and --x go together");
    spec.parametrised = true;
    spec.h0 = tk::cli::parse_count(o.h0, "--h0");
    spec.c = tk::cli::parse_count(o.c, "--c");
    std::tie(spec.x_min, spec.x_max) = tk::cli::parse_range(o.x, "--x");
  } else {
    std::tie(spec.x_min, spec.x_max) = tk::cli::parse_range(o.k, "--k");
  }
  spec.validate();
  if (o.riesel_condition) spec.check_riesel_condition();
  return spec;
}

void run_form(tk::cli::ToolApp& tool, tk::primes::SieveForm form, const FormOptions& o) {
  const tk::primes::SieveSpec spec = spec_from(form, o);
  if (o.min_rate < 0 || !(o.min_rate == o.min_rate)) throw tk::UsageError("--min-rate must be a non-negative number");
  if (!(o.checkpoint_seconds > 0)) throw tk::UsageError("--checkpoint-every must be a positive number of seconds");
  if (!(o.rate_window > 0) || !std::isfinite(o.rate_window))
    throw tk::UsageError("--rate-window must be a positive, finite number of seconds");
  tk::primes::SieveRunOptions run;
  run.tool_name = tool.name();
  run.threads = tool.common().threads;
  std::tie(run.shard_index, run.shard_count) = tk::cli::parse_shard(o.shard, "--shard");
  run.factors_path = o.factors;
  run.checkpoint_path = o.checkpoint;
  run.checkpoint_seconds = o.checkpoint_seconds;
  run.resume = o.resume;
  run.min_rate = o.min_rate;
  run.rate_window_seconds = o.rate_window;
  run.progress = tool.show_progress();
  const tk::cli::StopSignals stop;
  run.stop_signal = stop.signal();

  tk::primes::GeneralizedSieve sieve(spec);
  const auto outcome = tk::primes::run_sieve(sieve, run, [&](const std::string& text) { tool.warn(text); });
  if (stop.caught()) {
    const char* saved =
        o.checkpoint.empty() ? "; no --checkpoint, so the work is lost" : "; checkpoint saved, continue with --resume";
    if (!sieve.small_primes_done())
      stop.die("sieve",
               fmt::format(" while the primes up to 2^20 sieved, after {} of {} segments{}", sieve.next_segment(),
                           (sieve.spec().count() + sieve.kSegmentBits - 1) / sieve.kSegmentBits, saved));
    stop.die("sieve", fmt::format(" after p = {}{}", sieve.sieved_to(), saved));
  }
  if (outcome.rate_stopped)
    tool.warn(fmt::format("removal rate fell below --min-rate: stopped at p = {}", outcome.depth));
  using Format = tk::primes::SieveOutputFormat;
  const Format format = o.newpgen                                           ? Format::newpgen
                        : o.abc                                             ? Format::abc
                        : o.abcd                                            ? Format::abcd
                        : tool.output_format() == tk::io::OutputFormat::csv ? Format::csv
                                                                            : Format::json_lines;
  tk::primes::write_survivors(sieve, format, outcome.depth, stdout, run.shard_index, run.shard_count);
}

void run_primes(tk::cli::ToolApp& tool, const std::string& from_text, const std::string& to_text, bool count,
                bool json) {
  const std::uint64_t from = tk::cli::parse_count(from_text, "A");
  const std::uint64_t to = tk::cli::parse_count(to_text, "B");
  if (to < from) throw tk::UsageError(fmt::format("the interval {}..{} is empty: B is below A", from, to));
  if (to > tk::primes::max_prime_bound())
    throw tk::UsageError(fmt::format("B must be at most {}", tk::primes::max_prime_bound()));
  const unsigned threads = tool.common().threads;
  const bool records = json || tool.output_format() == tk::io::OutputFormat::csv;
  if (count) {
    const std::uint64_t total = tk::primes::count_primes_between(from, to, threads);
    if (!records) {
      std::printf("%llu\n", static_cast<unsigned long long>(total));
      return;
    }
    tk::io::RecordWriter writer(tool.output_format(), stdout);
    writer.declare_fields({"from", "to", "count"});
    writer.write(tk::Record{{"from", from}, {"to", to}, {"count", total}});
    writer.flush();
    return;
  }
  if (!records) {
    tk::primes::prime_lines_between(from, to, threads, [](std::string_view text) {
      if (std::fwrite(text.data(), 1, text.size(), stdout) != text.size()) throw tk::Error("cannot write the output");
    });
    return;
  }
  tk::io::RecordWriter writer(tool.output_format(), stdout);
  writer.declare_fields({"number"});
  tk::primes::prime_lines_between(from, to, threads, [&](std::string_view text) {
    for (std::size_t start = 0; start < text.size();) {
      const std::size_t end = text.find('\n', start);
      const std::string_view digits = text.substr(start, end - start);
      const std::uint64_t p = std::stoull(std::string(digits));
      writer.write(
          tk::Record{{"number", p < (std::uint64_t(1) << 53) ? tk::Record(p) : tk::Record(std::string(digits))}});
      start = end + 1;
    }
  });
  writer.flush();
}

}  // namespace

int main(int argc, char** argv) {
  tk::cli::ToolApp tool(
      "sieve",
      "Sieve of Eratosthenes for an interval, and the generalized sieve that removes k*2^n+-1 "
      "candidates with a small factor before twin, Sophie Germain, Cunningham-chain, Riesel or "
      "Proth searches.",
      "Examples:\n  sieve primes 1 1e10 --count\n  sieve twin --n 171960 --k 1:1e9 --pmax 1e9 -j 2 --newpgen\n"
      "  sieve sg --n 4000 --h0 15 --c 30030 --x 1:2^20 --pmax 1e8\n"
      "  sieve cc2 --n 256000 --h0 0 --c 30030 --x 1:1e6 --pmax 134217689   (the paper's Cc22 project)\n"
      "  sieve merge shard1.npg shard2.npg\n"
      "See sieve(1).");
  CLI::App& app = tool.app();
  tool.add_threads_option();
  app.require_subcommand(1);

  std::string from_text, to_text;
  bool count = false, json = false;
  CLI::App* primes = app.add_subcommand("primes", "print or count the primes in [A, B] (libprimesieve)");
  primes->add_option("A", from_text, "start of the interval (digits, 1e9, 2^40)")->required();
  primes->add_option("B", to_text, "end of the interval, inclusive")->required();
  primes->add_flag("--count", count, "print how many primes there are instead of the primes");
  primes->add_flag("--json", json, "write records ({\"number\": p}, or from/to/count) instead of plain lines");

  FormOptions form_options;
  struct Named {
    const char* name;
    tk::primes::SieveForm form;
    const char* help;
  };
  const Named forms[] = {
      {"twin", tk::primes::SieveForm::twin, "twins k*2^n-1 and k*2^n+1"},
      {"sg", tk::primes::SieveForm::sg, "Sophie Germain pairs k*2^n-1 and k*2^(n+1)-1"},
      {"cc1", tk::primes::SieveForm::cc1, "Cunningham chains of the first kind k*2^(n+i)-1, i < --length"},
      {"cc2", tk::primes::SieveForm::cc2, "Cunningham chains of the second kind k*2^(n+i)+1, i < --length"},
      {"riesel", tk::primes::SieveForm::riesel, "Riesel numbers k*2^n-1"},
      {"proth", tk::primes::SieveForm::proth, "Proth numbers k*2^n+1"},
  };
  std::vector<std::pair<CLI::App*, tk::primes::SieveForm>> form_commands;
  for (const Named& named : forms) {
    CLI::App* sub = app.add_subcommand(named.name, std::string("sieve ") + named.help);
    FormOptions& o = form_options;
    sub->add_option("--n", o.n, "the exponent n")->required()->type_name("N");
    sub->add_option("--k", o.k, "plain k range A:B (NewPGen's)")->type_name("A:B");
    sub->add_option("--h0", o.h0, "k = h0 + c*x, the paper's (h0 + c*x)*2^(n+i)+-1; k may be even")->type_name("H");
    sub->add_option("--c", o.c, "step of k per x, usually a primorial")->type_name("C");
    sub->add_option("--x", o.x, "x range A:B for k = h0 + c*x")->type_name("A:B");
    sub->add_option("--pmax", o.pmax, "sieve with every prime up to this bound")->required()->type_name("P");
    if (named.form == tk::primes::SieveForm::cc1 || named.form == tk::primes::SieveForm::cc2)
      sub->add_option("--length", o.length, "chain length (2 to 64)")->capture_default_str()->type_name("L");
    sub->add_option("--min-rate", o.min_rate, "stop early once fewer than this many candidates per second are removed")
        ->type_name("R");
    sub->add_option("--rate-window", o.rate_window, "seconds over which --min-rate is measured")
        ->capture_default_str()
        ->type_name("S");
    sub->add_option("--factors", o.factors, "append 'p | k*2^n+-1' for every removal to FILE")->type_name("FILE");
    sub->add_option("--checkpoint", o.checkpoint, "save the state to FILE every few minutes and on SIGINT/SIGTERM")
        ->type_name("FILE");
    sub->add_option("--checkpoint-every", o.checkpoint_seconds, "seconds between checkpoints")
        ->capture_default_str()
        ->type_name("S");
    sub->add_flag("--resume", o.resume, "continue from the --checkpoint FILE (start afresh when it does not exist)");
    sub->add_option("--shard", o.shard, "sieve only block K of every N blocks of large primes (K/N)")
        ->capture_default_str()
        ->type_name("K/N");
    sub->add_flag("--riesel-condition", o.riesel_condition,
                  "require the paper's Riesel conditions on every k*2^e-1 member (k made odd below 2^e, (13/N) = -1)");
    auto* newpgen = sub->add_flag("--newpgen", o.newpgen, "write a NewPGen file (LLR and PFGW read it)");
    auto* abc = sub->add_flag("--abc", o.abc, "write an ABC file (PFGW)");
    auto* abcd = sub->add_flag("--abcd", o.abcd, "write an ABCD file (PFGW; k as differences)");
    newpgen->excludes(abc)->excludes(abcd);
    abc->excludes(abcd);
    form_commands.emplace_back(sub, named.form);
  }

  std::vector<std::string> shard_files;
  CLI::App* merge = app.add_subcommand("merge", "intersect the outputs of --shard runs into what one run writes");
  merge->add_option("SHARD", shard_files, "shard outputs (any one format)")->required()->check(CLI::ExistingFile);

  for (CLI::App* sub : app.get_subcommands({})) sub->fallthrough();  // -j, --csv, -q after the subcommand

  return tool.run(argc, argv, [&] {
    if (primes->parsed()) return run_primes(tool, from_text, to_text, count, json);
    if (merge->parsed()) return tk::primes::merge_sieve_outputs(shard_files, stdout);
    for (const auto& [sub, form] : form_commands) {
      if (!sub->parsed()) continue;
      if (tool.common().csv && (form_options.newpgen || form_options.abc || form_options.abcd))
        throw tk::UsageError("--csv cannot be combined with --newpgen, --abc or --abcd");
      return run_form(tool, form, form_options);
    }
  });
}
