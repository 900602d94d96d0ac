/// @file bench_riesel.cpp
/// @brief The LLR proof of 778965587811*2^36627-1 (the seed's number: 7.73 s
/// there) against PARI's ispseudoprime on the same number in the same run
/// (issue 23's goal: at most 0.5 s, a ratio of at least 20). Then the
/// squaring alone, the weighted transform (WeightedSquaring) against the
/// zero-padded FFT it replaced (FftSquaring), interleaved in one run, at
/// both sizes: ms per squaring and their ratio. With BENCH_RIESEL_BIG=1
/// also times the whole proof of the Jarai twin member
/// 16869987339975*2^171960-1 (goal: at most 15 s) and GMP's on it.
/// BENCH_RIESEL_SPLIT=1 prints instead the table of one squaring split
/// over BENCH_RIESEL_THREADS threads (default 2) against one thread
/// (WeightedSquaring::use_threads), wall time, at several n
/// (BENCH_RIESEL_SPLIT_NS="36627 171960 ..." to choose).
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "bench_common.hpp"
#include "primes/fft_plans.hpp"
#include "primes/fft_squaring.hpp"
#include "primes/riesel_proof.hpp"
#include "primes/right_angle_transform.hpp"
#include "primes/weighted_squaring.hpp"

namespace {

using namespace tk::primes;

// The same random residue below N = k*2^n + c for every run.
mpz_class random_residue(const SpecialForm& form) {
  mpz_class N = form.k;
  N <<= static_cast<mp_bitcnt_t>(form.n);
  N += form.c;
  gmp_randclass random(gmp_randinit_default);
  random.seed(23);
  return random.get_z_range(N);
}

// Milliseconds per squaring of each squarer on the same random residue,
// `rounds` squarings a turn, turns interleaved; medians.
void compare_squarers(std::uint64_t k, std::uint64_t n, int rounds, int repeats) {
  const SpecialForm form{k, n, -1};
  auto weighted = WeightedSquaring::create(form);
  auto padded = FftSquaring::create(form);
  if (!weighted || !padded) bench::fail("no squarer for the benchmark number");
  const mpz_class x = random_residue(form);
  weighted->load(x);
  padded->load(x);
  bench::Results results("bench_riesel_square_" + std::to_string(n));
  for (int r = 0; r < repeats; ++r) {
    const auto [ours, peer] = bench::time_interleaved(
        [&] {
          for (int i = 0; i < rounds; ++i) weighted->square_minus(2);
        },
        [&] {
          for (int i = 0; i < rounds; ++i) padded->square_minus(2);
        });
    results.add(ours / rounds * 1e3, peer / rounds * 1e3);
  }
  mpz_class a, b;
  weighted->store(a);
  padded->store(b);
  if (a != b) bench::fail("the two squarers disagree after the same squarings");
  std::printf(
      "FIGURE square_%llu ms per squaring (medians above: weighted, padded FFT): lengths %zu and %zu, digits "
      "up to %d and %d bits, %llu and %llu squares redone, worst rounding %.3f and %.3f\n",
      static_cast<unsigned long long>(n), weighted->transform_length(), padded->transform_length(),
      weighted->digit_bits(), padded->digit_bits(), static_cast<unsigned long long>(weighted->fallbacks()),
      static_cast<unsigned long long>(padded->fallbacks()), weighted->worst_roundoff(), padded->worst_roundoff());
  results.report(1.0);
}

// Microseconds per acyclic square of `length` real points (half of them
// zero), our right-angle transform against FFTW's real transforms, turns
// interleaved; medians.
void compare_transforms(std::size_t length, int rounds, int repeats, RightAngleSquarer::Simd simd) {
  auto ours = RightAngleSquarer::create(length, simd);
  if (!ours) return;
  const RealFftPlans* plans = real_fft_plans(length);
  double* input = fftw_alloc_real(length);
  double* output = fftw_alloc_real(length);
  fftw_complex* spectrum = fftw_alloc_complex(length / 2 + 1);
  for (std::size_t j = 0; j < length; ++j)
    input[j] = j < length / 2 ? static_cast<double>((j * 7919) % 65536) - 32768.0 : 0.0;
  bench::Results results("bench_riesel_transform_" + std::to_string(length));
  for (int r = 0; r < repeats; ++r) {
    const auto [mine, fftw] = bench::time_interleaved(
        [&] {
          for (int i = 0; i < rounds; ++i) ours->square(input, output);
        },
        [&] {
          for (int i = 0; i < rounds; ++i) square_by_real_fft(*plans, input, spectrum, output, length);
        });
    results.add(mine / rounds * 1e6, fftw / rounds * 1e6);
  }
  std::printf("FIGURE transform_%zu us per acyclic square (medians above: ours with %d lanes, FFTW)\n", length,
              ours->lanes());
  results.report(1.0);
  fftw_free(input);
  fftw_free(output);
  fftw_free(spectrum);
}

double wall_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// Wall milliseconds per squaring of 16869987339975*2^n-1 on one thread
// and split over `threads`, turns in the order one, split, split, one;
// medians of `repeats`. The split must leave the same digits.
void compare_split(std::uint64_t n, unsigned threads, int repeats) {
  const SpecialForm form{16869987339975, n, -1};
  auto one = WeightedSquaring::create(form);
  // The same length and digits as `one` (create() times its candidates and
  // may pick another length for a second squarer): n / (m - 1/2) bits give m.
  auto split =
      one ? WeightedSquaring::create_with(form, one->transform_length(),
                                          static_cast<double>(n) / (static_cast<double>(one->low_digits()) - 0.5))
          : nullptr;
  if (!one || !split || !split->use_threads(threads)) {
    std::printf("  n = %llu: no split squaring at this size\n", static_cast<unsigned long long>(n));
    return;
  }
  const mpz_class x = random_residue(form);
  one->load(x);
  split->load(x);
  const int rounds = static_cast<int>(std::max<std::uint64_t>(20, 200000000 / n));
  auto time_rounds = [&](WeightedSquaring& squarer) {
    const double start = wall_seconds();
    for (int i = 0; i < rounds; ++i) squarer.square_minus(2);
    return (wall_seconds() - start) / rounds * 1e3;
  };
  std::vector<double> single, many, ratio;
  for (int r = 0; r < repeats; ++r) {
    const double a = time_rounds(*one), b = time_rounds(*split), c = time_rounds(*split), d = time_rounds(*one);
    single.push_back((a + d) / 2);
    many.push_back((b + c) / 2);
    ratio.push_back(single.back() / many.back());
  }
  if (one->held_digits() != split->held_digits()) bench::fail("the split squaring left other digits");
  std::printf("| %8llu | %7zu | %8.4f | %8.4f | %5.2f (%.2f-%.2f) |\n", static_cast<unsigned long long>(n),
              one->transform_length(), bench::median(single), bench::median(many), bench::median(ratio),
              *std::min_element(ratio.begin(), ratio.end()), *std::max_element(ratio.begin(), ratio.end()));
  std::fflush(stdout);
}

}  // namespace

int main() {
  const int repeats = bench::repeats({"BENCH_RIESEL_REPEATS", "BENCH_REPEATS"}, 3);
  if (const char* widths = std::getenv("BENCH_RIESEL_TRANSFORMS")) {  // "avx2", else the widest
    const auto simd = std::string(widths) == "avx2" ? RightAngleSquarer::Simd::avx2 : RightAngleSquarer::Simd::best;
    for (std::size_t length : {4096, 6144, 9216, 16384, 18432, 36864})
      compare_transforms(length, 20000000 / length, 5, simd);
    return 0;
  }
  if (const char* split = std::getenv("BENCH_RIESEL_SPLIT"); split && std::string(split) == "1") {
    const char* chosen = std::getenv("BENCH_RIESEL_SPLIT_NS");
    std::istringstream ns(chosen ? chosen : "36627 171960 600011 1200007 3000017");
    const char* wanted = std::getenv("BENCH_RIESEL_THREADS");
    const unsigned threads = wanted ? static_cast<unsigned>(std::atoi(wanted)) : 2;
    std::printf(
        "bench_riesel: one squaring on 1 and %u threads, wall ms per squaring, medians of %d (order 1, %u, "
        "%u, 1)\n| n | length | 1 thread | %u threads | speed-up (min-max) |\n",
        threads, repeats, threads, threads, threads);
    for (std::uint64_t n = 0; ns >> n;) compare_split(n, threads, repeats);
    return 0;
  }
  const std::uint64_t k = 778965587811, n = 36627;
  std::printf("bench_riesel: LLR proof of %llu*2^%llu-1 vs PARI ispseudoprime, %d repeats\n",
              static_cast<unsigned long long>(k), static_cast<unsigned long long>(n), repeats);
  bench::Results results("bench_riesel");
  const std::string text = std::to_string(k) + "*2^" + std::to_string(n) + "-1";
  for (int r = 0; r < repeats; ++r) {
    ProofResult proof;
    const double ours = bench::time_cpu([&] { proof = llr_prove(k, n, LlrStart::llr); });
    const auto [pari_prime, pari_seconds] = bench::pari_ispseudoprime(text);
    if (proof.verdict != Verdict::prime || !pari_prime) bench::fail(text + ": the proof or PARI does not say prime");
    results.add(ours, pari_seconds);
  }
  results.report(20.0);

  std::printf(
      "bench_riesel: squaring alone, weighted transform vs the padded FFT, %d repeats (the \"s\" below are ms per "
      "squaring)\n",
      2 * repeats + 1);
  compare_squarers(k, n, 2000, 2 * repeats + 1);
  compare_squarers(16869987339975, 171960, 300, 2 * repeats + 1);

  if (std::getenv("BENCH_RIESEL_BIG") && std::string(std::getenv("BENCH_RIESEL_BIG")) == "1") {
    ProofOptions fft, gmp;
    fft.arithmetic = Arithmetic::fft;
    gmp.arithmetic = Arithmetic::gmp;
    ProofResult by_fft, by_gmp;
    const double fft_seconds = bench::time_cpu([&] { by_fft = llr_prove(16869987339975, 171960, LlrStart::llr, fft); });
    const double gmp_seconds = bench::time_cpu([&] { by_gmp = llr_prove(16869987339975, 171960, LlrStart::llr, gmp); });
    if (by_fft.verdict != Verdict::prime || by_gmp.verdict != Verdict::prime)
      bench::fail("16869987339975*2^171960-1 is not proved prime");
    std::printf(
        "FIGURE llr_171960 %.1f s with the weighted transform (length %zu, %llu squares redone, %.4f ms per "
        "squaring), %.1f s with GMP: ratio %.2f (one run; goal at most 15 s)\n",
        fft_seconds, by_fft.fft_length, static_cast<unsigned long long>(by_fft.fft_fallbacks),
        fft_seconds / static_cast<double>(by_fft.iterations) * 1e3, gmp_seconds, gmp_seconds / fft_seconds);
  }
  return 0;
}
