/// @file bench_u64.cpp
/// @brief is_prime_u64 against FLINT's n_is_prime on 10^6 random odd 64-bit
/// numbers (fixed seed). Goal: ratio (FLINT time / our time) >= 1.
#include <flint/ulong_extras.h>

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "bench_common.hpp"
#include "primes/prime64.hpp"

namespace {

constexpr std::size_t kCount = 1'000'000;

/// Verdicts of `test` for every number, as 0/1 bytes.
template <class Test>
std::vector<unsigned char> run(const std::vector<std::uint64_t>& numbers, Test test) {
  std::vector<unsigned char> verdicts(numbers.size());
  for (std::size_t i = 0; i < numbers.size(); ++i) verdicts[i] = test(numbers[i]) ? 1 : 0;
  return verdicts;
}

void check_agree(const std::vector<std::uint64_t>& numbers, const std::vector<unsigned char>& ours,
                 const std::vector<unsigned char>& peer) {
  for (std::size_t i = 0; i < numbers.size(); ++i)
    if (ours[i] != peer[i])
      bench::fail("is_prime_u64(" + std::to_string(numbers[i]) + ") = " + std::to_string(ours[i]) +
                  " but n_is_prime says " + std::to_string(peer[i]));
}

}  // namespace

int main() {
  const int repeats = bench::repeats({"BENCH_U64_REPEATS", "BENCH_REPEATS"}, 5);
  std::mt19937_64 random(20240601);
  std::vector<std::uint64_t> numbers(kCount);
  for (auto& n : numbers) n = random() | 1;

  auto ours = [&] { return run(numbers, [](std::uint64_t n) { return tk::primes::is_prime_u64(n); }); };
  auto peer = [&] { return run(numbers, [](std::uint64_t n) { return n_is_prime(n) != 0; }); };

  // Untimed warm-up that also checks every verdict once.
  const auto expected = ours();
  check_agree(numbers, expected, peer());
  std::size_t primes = 0;
  for (unsigned char v : expected) primes += v;
  std::printf(
      "bench_u64: %zu random odd 64-bit numbers (%zu primes), is_prime_u64 vs FLINT n_is_prime, %d repeats of "
      "ours-peer-peer-ours\n",
      kCount, primes, repeats);

  bench::Results results("bench_u64");
  for (int r = 0; r < repeats; ++r) {
    std::vector<std::vector<unsigned char>> mine, theirs;  // the verdicts of every run
    const auto [t_ours, t_peer] =
        bench::time_interleaved([&] { mine.push_back(ours()); }, [&] { theirs.push_back(peer()); });
    for (const auto& m : mine)
      for (const auto& t : theirs) check_agree(numbers, m, t);
    results.add(t_ours, t_peer);
  }
  results.report(1.0);
}
