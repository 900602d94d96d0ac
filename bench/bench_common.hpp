/// @file bench_common.hpp
/// @brief What every benchmark shares: the repeat count from the
/// environment, a CPU-time clock, medians, loud failure and the report
/// lines that bench/run.sh reads.
#pragma once

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <initializer_list>
#include <memory>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace bench {

/// Repeats from the first of `vars` that is set to a positive number, else `fallback`.
inline int repeats(std::initializer_list<const char*> vars, int fallback) {
  for (const char* var : vars)
    if (const char* text = std::getenv(var)) {
      const int value = std::atoi(text);
      if (value > 0) return value;
    }
  return fallback;
}

/// CPU seconds used by this process: less disturbed by other jobs on a
/// shared machine than wall time, and what PARI's getabstime() measures.
inline double cpu_seconds() {
  timespec now{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + static_cast<double>(now.tv_nsec) * 1e-9;
}

template <class F>
double time_cpu(F&& work) {
  const double start = cpu_seconds();
  work();
  return cpu_seconds() - start;
}

/// Mean CPU seconds of `ours` and of `peer`, run in the order ours, peer,
/// peer, ours: a machine that speeds up or slows down steadily during the
/// repeat affects both sides alike.
template <class Ours, class Peer>
std::pair<double, double> time_interleaved(Ours&& ours, Peer&& peer) {
  const double a = time_cpu(ours), b = time_cpu(peer), c = time_cpu(peer), d = time_cpu(ours);
  return {(a + d) / 2, (b + c) / 2};
}

inline double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t mid = values.size() / 2;
  return values.size() % 2 ? values[mid] : (values[mid - 1] + values[mid]) / 2;
}

/// Prints the message and aborts: the two sides disagree, or a peer failed.
[[noreturn]] inline void fail(const std::string& message) {
  std::fprintf(stderr, "\n*** BENCHMARK INVALID: %s ***\n\n", message.c_str());
  std::fflush(stdout);
  std::abort();
}

/// Times of ours and of the peer, one pair per repeat.
class Results {
 public:
  explicit Results(std::string name) : name_(std::move(name)) {}

  void add(double ours, double peer) {
    ours_.push_back(ours);
    peer_.push_back(peer);
    ratio_.push_back(peer / ours);
    std::printf("  repeat %zu: ours %.4f s  peer %.4f s  ratio %.3f\n", ours_.size(), ours, peer, peer / ours);
    std::fflush(stdout);
  }

  /// The line run.sh collects: name, medians of ours, peer and ratio, goal.
  void report(double goal) const {
    std::printf("RESULT %s %.6f %.6f %.4f %.2f %zu\n", name_.c_str(), median(ours_), median(peer_), median(ratio_),
                goal, ratio_.size());
  }

 private:
  std::string name_;
  std::vector<double> ours_, peer_, ratio_;
};

/// PARI's ispseudoprime verdict on a gp expression and the CPU seconds gp
/// reports for that call alone (getabstime, so gp's start-up is left out).
inline std::pair<bool, double> pari_ispseudoprime(const std::string& expression) {
  const char* gp = std::getenv("BENCH_GP");
  const std::string command = std::string("echo 'N=") + expression +
                              "; t=getabstime(); r=ispseudoprime(N); print(r, \" \", getabstime()-t)' | " +
                              (gp ? gp : "gp") + " -q -f 2>&1";
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  if (!pipe) fail("cannot run: " + command);
  std::string output;
  std::array<char, 256> buffer{};
  while (std::fgets(buffer.data(), buffer.size(), pipe.get())) output += buffer.data();
  std::istringstream fields(output);
  int verdict = -1;
  long milliseconds = -1;
  if (!(fields >> verdict >> milliseconds) || (verdict != 0 && verdict != 1) || milliseconds < 0)
    fail("unexpected output from gp: " + output);
  return {verdict == 1, static_cast<double>(milliseconds) / 1000};
}

}  // namespace bench
