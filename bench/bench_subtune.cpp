/// @file bench_subtune.cpp
/// @brief subtune's sub-tuning test, parts per CPU second on one core (goal:
/// 10 million), tk::quality::SubTuner (O(1) co-moment updates, cached t
/// critical values) against what a user writes with GSL: per part, refit the
/// run so far with gsl_fit_linear over x = 1..N, S_N from its sumsq, and the
/// critical value from gsl_cdf_tdist_Pinv(1 − α/2, 2(N − 1)) (the slope
/// test: t = |b|/√cov11 against Pinv(1 − α/2, N − 2)). Both must make the
/// same decision at every part and the same corrections (1e-9 relative);
/// else the benchmark aborts (bench::fail) and bench/run.sh exits 2.
///
/// Input: a closed loop on a lathe, generated here with a fixed seed:
/// nominal 40 mm, tool wear 0.4 µm per part, gauge-and-process noise σ 3 µm,
/// each correction of the control added to the set-up for the following
/// parts. Four cases: the paper's eq. (6) at α = 0.05 (short runs: its in-control
/// ARL is ≈ 6 parts; mean run 5.3 here) and at α = 1e-6 (still short, 14.5:
/// a wear of 0.13 σ per part is found within ~15 parts even so); then a
/// slow wear of 0.01 µm per part (1 µm per 100 parts), where runs are long
/// and the peer's O(N) refit per part shows: eq. (6) at α = 1e-6
/// (mean run ≈ 95) and the slope test at α = 1e-6 (≈ 290).
/// The peer runs on the first BENCH_SUBTUNE_PEER_PARTS parts (default 10^6),
/// ours on the same parts for the RESULT line and on all
/// BENCH_SUBTUNE_PARTS (default 10^7) for the parts/s FIGURE; the decision
/// check covers the peer's parts.
///
/// Then the tool end to end: `subtune FILE` over a bare column of 10^6 sizes
/// (BENCH_SUBTUNE_TOOL_PARTS; 0 skips), JSON Lines and --csv to /dev/null,
/// the child's CPU time (user + system): FIGURE lines, no peer. The tool is
/// $BUILD_DIR/subtune, else ../subtune next to this binary's folder.
/// Medians of BENCH_SUBTUNE_REPEATS (or BENCH_REPEATS, default 5) repeats.
#include <fcntl.h>
#include <gsl/gsl_cdf.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_fit.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "bench_common.hpp"
#include "quality/subtuning.hpp"

namespace {

using tk::quality::Decision;
using tk::quality::SubTuner;
using tk::quality::SubTuneSettings;
using tk::quality::TrendStatistic;

std::uint64_t env_count(const char* name, std::uint64_t fallback) {
  const char* text = std::getenv(name);
  return text ? std::strtoull(text, nullptr, 10) : fallback;
}

/// The lathe: size of part i (from 0) = nominal + wear·i + offset + noise,
/// the offset the sum of the control's corrections so far.
std::vector<double> closed_loop_stream(const SubTuneSettings& settings, double wear_mm, std::uint64_t parts,
                                       std::uint64_t seed) {
  constexpr double nominal_mm = 40, sigma_mm = 3e-3;
  std::mt19937_64 random(seed);
  std::normal_distribution<double> noise(0, sigma_mm);
  SubTuner tuner(settings);
  std::vector<double> sizes(parts);
  for (std::uint64_t i = 0; i < parts; ++i) {
    sizes[i] = nominal_mm + wear_mm * static_cast<double>(i) + tuner.offset() + noise(random);
    tuner.observe(sizes[i]);
  }
  return sizes;
}

/// What a timed run leaves: enough that neither side's work is optimised away
/// and that the sides can be compared cheaply.
struct Tally {
  std::uint64_t subtunes = 0, last_subtune = 0;
  double corrections = 0;
  void operator()(std::uint64_t part, Decision d, double correction) {
    if (d != Decision::subtune) return;
    ++subtunes, last_subtune = part, corrections += correction;
  }
};

/// The full trace, for the decision check.
struct Trace {
  std::vector<Decision> decisions;
  std::vector<double> corrections;  ///< one per sub-tune
  void operator()(std::uint64_t, Decision d, double correction) {
    decisions.push_back(d);
    if (d == Decision::subtune) corrections.push_back(correction);
  }
};

template <class Sink>
void run_ours(const SubTuneSettings& settings, const double* sizes, std::uint64_t parts, Sink& sink) {
  SubTuner tuner(settings);
  for (std::uint64_t i = 0; i < parts; ++i) {
    const tk::quality::SubTuneStep step = tuner.observe(sizes[i]);
    sink(i, step.decision, step.correction);
  }
}

/// The peer: the run's sizes kept, refitted from scratch at every part.
template <class Sink>
void run_gsl(const SubTuneSettings& settings, const double* sizes, std::uint64_t parts, Sink& sink) {
  const bool paper = settings.statistic == TrendStatistic::paper;
  std::vector<double> x, run;
  for (std::uint64_t i = 0; i < parts; ++i) {
    run.push_back(sizes[i]);
    const std::size_t n = run.size();
    if (x.size() < n) x.push_back(static_cast<double>(n));  // x = 1..N
    if (n < settings.min_parts) {
      sink(i, Decision::insufficient, 0);
      continue;
    }
    double c0, c1, cov00, cov01, cov11, sumsq;
    gsl_fit_linear(x.data(), 1, run.data(), 1, n, &c0, &c1, &cov00, &cov01, &cov11, &sumsq);
    const double nd = static_cast<double>(n);
    double t, t_crit;
    if (paper) {
      const double s = std::sqrt(sumsq / (nd - 1)), rise = nd * std::abs(c1);
      t = s > 0 ? rise / s * std::sqrt(nd / 2) : (rise > 0 ? INFINITY : 0.0);
      t_crit = gsl_cdf_tdist_Pinv(1 - settings.alpha / 2, 2 * (nd - 1));
    } else {
      t = cov11 > 0 ? std::abs(c1) / std::sqrt(cov11) : (c1 != 0 ? INFINITY : 0.0);
      t_crit = gsl_cdf_tdist_Pinv(1 - settings.alpha / 2, nd - 2);
    }
    if (t > t_crit) {
      sink(i, Decision::subtune, -nd * c1);
      run.clear();
    } else {
      sink(i, Decision::none, 0);
    }
  }
}

void check_same(const char* name, const Trace& ours, const Trace& peer) {
  for (std::size_t i = 0; i < std::min(ours.decisions.size(), peer.decisions.size()); ++i)
    if (ours.decisions[i] != peer.decisions[i])
      bench::fail(std::string(name) + ": SubTuner and the GSL refit decide differently at part " +
                  std::to_string(i + 1) + " (" + std::string(tk::quality::decision_name(ours.decisions[i])) + " / " +
                  std::string(tk::quality::decision_name(peer.decisions[i])) + ")");
  if (ours.decisions.size() != peer.decisions.size() || ours.corrections.size() != peer.corrections.size())
    bench::fail(std::string(name) + ": the two traces differ in length");
  double worst = 0;
  for (std::size_t k = 0; k < ours.corrections.size(); ++k) {
    const double a = ours.corrections[k], b = peer.corrections[k];
    const double relative = std::abs(a - b) / std::max(std::abs(b), 1e-300);
    worst = std::max(worst, relative);
    if (!(relative <= 1e-9))
      bench::fail(std::string(name) + ": correction " + std::to_string(k + 1) + " differs: " + std::to_string(a) +
                  " / " + std::to_string(b) + " mm");
  }
  std::printf("  %s: identical decisions on %zu parts, %zu sub-tunes, corrections within %.1e relative\n", name,
              ours.decisions.size(), ours.corrections.size(), worst);
}

const char* verdict(bool met) { return met ? "met" : "NOT met"; }

double range_low(const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()); }
double range_high(const std::vector<double>& v) { return *std::max_element(v.begin(), v.end()); }

struct Case {
  const char* name;
  SubTuneSettings settings;
  double wear_mm;  ///< per part
};

constexpr double kWearMm = 0.4e-3, kSlowWearMm = 0.01e-3;

void bench_case(const Case& c, std::uint64_t parts, std::uint64_t peer_parts, int repeats) {
  const std::vector<double> sizes = closed_loop_stream(c.settings, c.wear_mm, parts, 20240611);
  peer_parts = std::min(peer_parts, parts);
  {
    Trace ours, peer;
    run_ours(c.settings, sizes.data(), peer_parts, ours);
    run_gsl(c.settings, sizes.data(), peer_parts, peer);
    check_same(c.name, ours, peer);
  }
  Tally full;
  run_ours(c.settings, sizes.data(), parts, full);
  // Mean run length over the finished runs; the last, open run is left out.
  const double mean_run =
      full.subtunes ? static_cast<double>(full.last_subtune + 1) / static_cast<double>(full.subtunes) : NAN;
  std::printf("  %s: %llu parts, %llu sub-tunes, mean run length %.2f parts\n", c.name,
              static_cast<unsigned long long>(parts), static_cast<unsigned long long>(full.subtunes), mean_run);

  bench::Results results(std::string("subtune_gsl_") + c.name);
  for (int r = 0; r < repeats; ++r) {
    Tally ours, peer;
    const auto [t_ours, t_peer] = bench::time_interleaved([&] { run_ours(c.settings, sizes.data(), peer_parts, ours); },
                                                          [&] { run_gsl(c.settings, sizes.data(), peer_parts, peer); });
    if (ours.subtunes != peer.subtunes || ours.last_subtune != peer.last_subtune)
      bench::fail(std::string(c.name) + ": timed runs disagree");
    results.add(t_ours, t_peer);
  }
  std::vector<double> rates;
  for (int r = 0; r < repeats; ++r) {
    Tally again;
    const double seconds = bench::time_cpu([&] { run_ours(c.settings, sizes.data(), parts, again); });
    if (again.subtunes != full.subtunes || again.corrections != full.corrections)
      bench::fail(std::string(c.name) + ": a rerun differs");
    rates.push_back(static_cast<double>(parts) / seconds);
  }
  const double rate = bench::median(rates);
  std::printf(
      "FIGURE subtune_rate_%s %.1f million parts/s on one core (SubTuner::observe, %llu parts, mean run %.1f; CPU "
      "time, "
      "median of %d, range %.1f-%.1f; goal 10; %s)\n",
      c.name, rate / 1e6, static_cast<unsigned long long>(parts), mean_run, repeats, range_low(rates) / 1e6,
      range_high(rates) / 1e6, verdict(rate >= 10e6));
  std::printf("FIGURE subtune_mean_run_%s %.2f parts per run (%llu sub-tunes in %llu parts)\n", c.name, mean_run,
              static_cast<unsigned long long>(full.subtunes), static_cast<unsigned long long>(parts));
  results.report(1);
}

// ---- the tool end to end ---------------------------------------------------

std::filesystem::path find_tool() {
  namespace fs = std::filesystem;
  if (const char* dir = std::getenv("BUILD_DIR")) {
    const fs::path p = fs::path(dir) / "subtune";
    if (fs::exists(p)) return p;
  }
  std::error_code error;
  const fs::path self = fs::read_symlink("/proc/self/exe", error);
  if (!error) {
    const fs::path p = self.parent_path().parent_path() / "subtune";
    if (fs::exists(p)) return p;
  }
  bench::fail("the subtune tool is not built (cmake --build BUILD --target subtune), or set BUILD_DIR");
}

/// Runs argv with stdout to `out`; returns the child's user + system CPU seconds.
double run_child(const std::vector<std::string>& args, const std::string& out) {
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = 0;
  if (posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ) != 0) bench::fail("cannot start " + args[0]);
  posix_spawn_file_actions_destroy(&actions);
  int status = 0;
  rusage usage{};
  if (wait4(pid, &status, 0, &usage) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    bench::fail(args[0] + " failed (status " + std::to_string(status) + ")");
  const auto seconds = [](const timeval& t) {
    return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_usec) * 1e-6;
  };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

std::uint64_t count_occurrences(const std::string& path, const std::string& needle) {
  std::ifstream in(path);
  std::string line;
  std::uint64_t count = 0;
  while (std::getline(in, line))
    for (std::size_t at = line.find(needle); at != std::string::npos; at = line.find(needle, at + 1)) ++count;
  return count;
}

void bench_tool(std::uint64_t parts, int repeats) {
  namespace fs = std::filesystem;
  const fs::path tool = find_tool();
  const SubTuneSettings settings;  // the tool's defaults: the slope test at α = 0.05
  const std::vector<double> sizes = closed_loop_stream(settings, kWearMm, parts, 20240611);
  Tally expected;
  run_ours(settings, sizes.data(), parts, expected);

  const fs::path dir = fs::temp_directory_path() / ("bench_subtune." + std::to_string(getpid()));
  fs::create_directories(dir);
  const std::string input = (dir / "sizes.txt").string(), output = (dir / "out").string();
  {
    std::string text;
    char buffer[32];
    for (double s : sizes) {
      const auto end = std::to_chars(buffer, buffer + sizeof buffer, s).ptr;
      text.append(buffer, end).push_back('\n');
    }
    std::ofstream(input, std::ios::binary) << text;
  }
  // Once to a file: the tool must make the library's decisions.
  run_child({tool.string(), input}, output);
  const std::uint64_t jsonl_subtunes = count_occurrences(output, "\"subtune\"");
  run_child({tool.string(), "--csv", input}, output);
  const std::uint64_t csv_subtunes = count_occurrences(output, ",subtune,");
  std::printf("  tool %s, %llu sizes: %llu sub-tunes in the JSON Lines, %llu in the CSV, %llu from SubTuner\n",
              tool.c_str(), static_cast<unsigned long long>(parts), static_cast<unsigned long long>(jsonl_subtunes),
              static_cast<unsigned long long>(csv_subtunes), static_cast<unsigned long long>(expected.subtunes));
  if (jsonl_subtunes != expected.subtunes || csv_subtunes != expected.subtunes)
    bench::fail("the subtune tool's decisions differ from SubTuner's");

  for (const bool csv : {false, true}) {
    std::vector<std::string> args{tool.string()};
    if (csv) args.push_back("--csv");
    args.push_back(input);
    std::vector<double> rates;
    for (int r = 0; r < repeats; ++r) rates.push_back(static_cast<double>(parts) / run_child(args, "/dev/null"));
    const double rate = bench::median(rates);
    std::printf(
        "FIGURE subtune_tool_%s %.2f million parts/s (subtune FILE%s > /dev/null, %llu sizes, child CPU time, median "
        "of %d, "
        "range %.2f-%.2f; goal 10; %s)\n",
        csv ? "csv" : "jsonl", rate / 1e6, csv ? " --csv" : "", static_cast<unsigned long long>(parts), repeats,
        range_low(rates) / 1e6, range_high(rates) / 1e6, verdict(rate >= 10e6));
  }
  fs::remove_all(dir);
}

}  // namespace

int main() {
  gsl_set_error_handler_off();  // a failed inverse returns NaN, and the decision check catches it
  const int repeats = bench::repeats({"BENCH_SUBTUNE_REPEATS", "BENCH_REPEATS"}, 5);
  const std::uint64_t parts = env_count("BENCH_SUBTUNE_PARTS", 10'000'000);
  const std::uint64_t peer_parts = env_count("BENCH_SUBTUNE_PEER_PARTS", 1'000'000);
  const std::uint64_t tool_parts = env_count("BENCH_SUBTUNE_TOOL_PARTS", 1'000'000);
  if (parts == 0 || peer_parts == 0) bench::fail("BENCH_SUBTUNE_PARTS and BENCH_SUBTUNE_PEER_PARTS must be positive");
  std::printf(
      "bench_subtune: closed-loop lathe (40 mm, wear 0.4 or 0.01 um/part, sigma 3 um), SubTuner vs a GSL refit per "
      "part, "
      "%d repeats\n",
      repeats);

  SubTuneSettings paper;  // the paper's eq. (6), α = 0.05
  paper.statistic = TrendStatistic::paper;
  SubTuneSettings paper_strict = paper;
  paper_strict.alpha = 1e-6;
  SubTuneSettings slope_strict = paper_strict;
  slope_strict.statistic = TrendStatistic::slope;
  for (const Case& c :
       {Case{"paper", paper, kWearMm}, Case{"paper_a1e-6", paper_strict, kWearMm},
        Case{"paper_a1e-6_slow", paper_strict, kSlowWearMm}, Case{"slope_a1e-6_slow", slope_strict, kSlowWearMm}})
    bench_case(c, parts, peer_parts, repeats);

  if (tool_parts > 0) bench_tool(tool_parts, repeats);
  return 0;
}
