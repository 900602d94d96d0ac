/// @file bench_fuzzyfeed.cpp
/// @brief fuzzyfeed's law, samples per second through FeedOverride::step
/// with no I/O (goal: 20 million a second on one core, both variants), and
/// the command line end to end (JSON Lines and CSV in, out to /dev/null),
/// records per second. Medians of BENCH_FUZZYFEED_REPEATS (or
/// BENCH_REPEATS, default 5) runs; FIGURE lines for bench/run.sh.
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "bench_common.hpp"
#include "machining/feed_override.hpp"

namespace {

using namespace tk::machining;

/// Loads like a spindle's: stretches at one level (idle, light, near M_z,
/// overload) with measurement noise, clipped to 0-100 %.
std::vector<double> spindle_loads(std::size_t count) {
  std::mt19937_64 random(2026);
  std::normal_distribution<double> noise(0, 3);
  const double levels[] = {5, 35, 58, 62, 90, 100};
  std::vector<double> loads(count);
  double level = 60;
  for (std::size_t i = 0; i < count; ++i) {
    if (i % 500 == 0) level = levels[random() % 6];
    loads[i] = std::clamp(level + noise(random), 0.0, 100.0);
  }
  return loads;
}

/// Runs the law over the loads; returns a checksum so the loop is not optimised away.
double run_law(const FeedOverrideParams& params, const std::vector<double>& loads) {
  FeedOverride law(params);
  double sum = 0;
  for (const double load : loads) sum += law.step(load).override_pct;
  return sum;
}

/// CPU seconds of the children this process waited for.
double children_cpu_seconds() {
  rusage usage{};
  getrusage(RUSAGE_CHILDREN, &usage);
  return static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
         static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec) * 1e-6;
}

std::string tool_path(const char* argv0) {
  if (const char* build = std::getenv("BUILD_DIR")) return std::string(build) + "/fuzzyfeed";
  std::string self = argv0;
  const auto slash = self.rfind('/');
  return (slash == std::string::npos ? std::string(".") : self.substr(0, slash)) + "/../fuzzyfeed";
}

/// Records per CPU second of `fuzzyfeed ARGS FILE > /dev/null`.
double cli_rate(const std::string& tool, const std::string& args, const std::string& file, std::size_t records) {
  const std::string command = "'" + tool + "' " + args + " '" + file + "' > /dev/null";
  const double before = children_cpu_seconds();
  const int status = std::system(command.c_str());
  if (status == -1 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) bench::fail("failed: " + command);
  return static_cast<double>(records) / (children_cpu_seconds() - before);
}

}  // namespace

int main(int, char** argv) {
  const int repeats = bench::repeats({"BENCH_FUZZYFEED_REPEATS", "BENCH_REPEATS"}, 5);
  const std::size_t samples = 20'000'000;
  const std::vector<double> loads = spindle_loads(samples);
  std::printf("bench_fuzzyfeed: the law over %zu spindle-load samples (no I/O), %d repeats; then the CLI\n", samples,
              repeats);

  FeedOverrideParams original, modified;
  modified.variant = OverrideVariant::modified;  // k 0.1, p 0.1, d 25
  for (const auto& [name, params] : {std::pair{"original", original}, std::pair{"modified", modified}}) {
    std::vector<double> rates;
    double first_checksum = 0;
    for (int r = 0; r < repeats; ++r) {
      double checksum = 0;
      const double seconds = bench::time_cpu([&] { checksum = run_law(params, loads); });
      if (r == 0) first_checksum = checksum;
      if (checksum != first_checksum || !(checksum > 0))
        bench::fail("the law gave different overrides on the same loads");
      rates.push_back(static_cast<double>(samples) / seconds);
      std::printf("  %s repeat %d: %.1f million samples/s\n", name, r + 1, rates.back() / 1e6);
    }
    const double median = bench::median(rates);
    std::printf("FIGURE fuzzyfeed_law_%s %.1f million samples/s (median of %d; goal 20; %s)\n", name, median / 1e6,
                repeats, median >= 20e6 ? "met" : "NOT met");
  }

  // The command line: 1,000,000 records as JSON Lines and as CSV.
  const std::string tool = tool_path(argv[0]);
  if (access(tool.c_str(), X_OK) != 0) {
    std::printf("FIGURE fuzzyfeed_cli not measured: %s not found (set BUILD_DIR)\n", tool.c_str());
    return 0;
  }
  const std::size_t records = 1'000'000;
  char json_path[] = "/tmp/bench_fuzzyfeed_XXXXXX";
  const int fd = mkstemp(json_path);
  if (fd < 0) bench::fail("cannot create a temporary file");
  close(fd);
  const std::string csv_path = std::string(json_path) + ".csv";
  {
    std::FILE* json = std::fopen(json_path, "w");
    std::FILE* csv = std::fopen(csv_path.c_str(), "w");
    if (!json || !csv) bench::fail("cannot write the temporary files");
    std::fputs("t,load,feed\n", csv);
    for (std::size_t i = 0; i < records; ++i) {
      std::fprintf(json, "{\"t\":%.3f,\"load\":%.4f,\"feed\":0.4}\n", static_cast<double>(i) * 0.008, loads[i]);
      std::fprintf(csv, "%.3f,%.4f,0.4\n", static_cast<double>(i) * 0.008, loads[i]);
    }
    std::fclose(json);
    std::fclose(csv);
  }
  for (const auto& [label, args, file] :
       {std::tuple{"json", "", std::string(json_path)}, std::tuple{"csv", "--csv", csv_path},
        std::tuple{"json_modified", "--variant modified", std::string(json_path)}}) {
    std::vector<double> rates;
    for (int r = 0; r < repeats; ++r) rates.push_back(cli_rate(tool, args, file, records));
    std::printf("FIGURE fuzzyfeed_cli_%s %.2f million records/s (CPU time, median of %d, %zu records)\n", label,
                bench::median(rates) / 1e6, repeats, records);
  }
  std::remove(json_path);
  std::remove(csv_path.c_str());
  return 0;
}
