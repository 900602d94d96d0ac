/// @file prime_range.cpp
#include "primes/prime_range.hpp"

#include <primesieve.hpp>

#include <algorithm>
#include <charconv>
#include <string>

#include "concurrency/ordered_pool.hpp"

namespace tk::primes {

namespace {

/// Width of the intervals handed to worker threads when printing.
constexpr std::uint64_t kChunkWidth = std::uint64_t(1) << 26;
/// The largest prime below 2^64: primesieve cannot look past it.
constexpr std::uint64_t kLastPrime = 18446744073709551557ull;

std::string format_lines(std::uint64_t low, std::uint64_t high) {
  std::string text;
  high = std::min(high, kLastPrime);
  if (low > high) return text;
  primesieve::iterator it(low, high);
  char digits[24];
  for (std::uint64_t p = it.next_prime(); p <= high && p >= low; p = it.next_prime()) {
    const auto end = std::to_chars(digits, digits + sizeof digits, p).ptr;
    text.append(digits, end);
    text += '\n';
    if (p == high) break;  // asking for the prime after the last one fails
  }
  return text;
}

}  // namespace

std::uint64_t max_prime_bound() { return primesieve::get_max_stop(); }

std::uint64_t count_primes_between(std::uint64_t a, std::uint64_t b, unsigned threads) {
  primesieve::set_num_threads(static_cast<int>(std::max(1u, threads)));
  return primesieve::count_primes(a, b);
}

std::vector<std::uint64_t> primes_between(std::uint64_t a, std::uint64_t b) {
  std::vector<std::uint64_t> primes;
  primesieve::generate_primes(a, b, &primes);
  return primes;
}

std::vector<std::uint32_t> primes_between_32(std::uint32_t a, std::uint32_t b) {
  std::vector<std::uint32_t> primes;
  primesieve::generate_primes(a, b, &primes);
  return primes;
}

void prime_lines_between(std::uint64_t a, std::uint64_t b, unsigned threads,
                         const std::function<void(std::string_view)>& emit) {
  struct Chunk {
    std::uint64_t low, high;
  };
  OrderedPool<Chunk, std::string> pool(
      threads, [](Chunk& chunk) { return format_lines(chunk.low, chunk.high); },
      [&](std::string& text) { emit(text); });
  for (std::uint64_t low = a;;) {
    const std::uint64_t high = b - low < kChunkWidth ? b : low + kChunkWidth - 1;
    pool.submit(Chunk{low, high});
    if (high == b) break;
    low = high + 1;
  }
  pool.finish();
}

}  // namespace tk::primes
