/// @file bench_riesel.cpp
/// @brief The LLR proof of 778965587811*2^36627-1 (the seed's number: 7.73 s
/// there) against PARI's ispseudoprime on the same number in the same run.
/// Goal: at most 1.2 s on one core, so a ratio of at least 6.5 against
/// PARI's ~8 s. With BENCH_RIESEL_BIG=1 also times the proof of the Jarai
/// twin member 16869987339975*2^171960-1 (goal: at most 45 s) with the
/// FFT squaring and with GMP's, in the same run: LLR is not packaged in
/// Debian, so GMP's arithmetic is the peer timed here.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "bench_common.hpp"
#include "primes/riesel_proof.hpp"

int main() {
  using namespace tk::primes;
  const int repeats = bench::repeats({"BENCH_RIESEL_REPEATS", "BENCH_REPEATS"}, 3);
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
  results.report(6.5);
  if (std::getenv("BENCH_RIESEL_BIG") && std::string(std::getenv("BENCH_RIESEL_BIG")) == "1") {
    ProofOptions fft, gmp;
    fft.arithmetic = Arithmetic::fft;
    gmp.arithmetic = Arithmetic::gmp;
    ProofResult by_fft, by_gmp;
    const double fft_seconds = bench::time_cpu([&] { by_fft = llr_prove(16869987339975, 171960, LlrStart::llr, fft); });
    const double gmp_seconds = bench::time_cpu([&] { by_gmp = llr_prove(16869987339975, 171960, LlrStart::llr, gmp); });
    if (by_fft.verdict != Verdict::prime || by_gmp.verdict != Verdict::prime)
      bench::fail("16869987339975*2^171960-1 is not proved prime");
    std::printf("FIGURE llr_171960 %.1f s with the FFT (length %zu, %llu squares redone), %.1f s with GMP: ratio %.2f "
                "(one run; goal at most 45 s)\n",
                fft_seconds, by_fft.fft_length, static_cast<unsigned long long>(by_fft.fft_fallbacks), gmp_seconds,
                gmp_seconds / fft_seconds);
  }
  return 0;
}
