/// @file bench_kbnc.cpp
/// @brief BPSW on the k*2^n-1 prime 778965587811*2^36627-1: our test_number
/// (special-form reduction) against PARI's ispseudoprime run through
/// `gp -q`, timed inside gp with getabstime() so gp's start-up is left out.
/// Goal: ratio (PARI time / our time) >= 4. Also checks the composite
/// 778965587811*2^36629-1 once.
#include <array>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <sstream>
#include <string>
#include <utility>

#include "bench_common.hpp"
#include "primes/primality.hpp"

namespace {

constexpr std::uint64_t kK = 778965587811;

tk::primes::Number kbnc_number(std::uint64_t n) {
  const tk::primes::KbncForm form{kK, 2, n, -1};
  return {tk::primes::evaluate_kbnc(form, std::size_t{1} << 20), form};
}

std::string kbnc_text(std::uint64_t n) { return tk::primes::kbnc_text({kK, 2, n, -1}); }

struct OurRun {
  bool prime = false;  ///< probable prime or better
  double seconds = 0;
  std::string witness;
};

OurRun ours(const tk::primes::Number& number) {
  tk::primes::TestOutcome outcome;
  const double seconds = bench::time_cpu([&] { outcome = tk::primes::test_number(number, tk::primes::TestPlan{}); });
  return {outcome.verdict >= tk::primes::Verdict::probable_prime, seconds, outcome.witness};
}

std::pair<bool, double> pari(const std::string& expression) { return bench::pari_ispseudoprime(expression); }

void check_agree(const std::string& text, bool mine, bool theirs, bool expected) {
  if (mine != expected || theirs != expected)
    bench::fail(text + ": ours says " + (mine ? "prime" : "composite") + ", PARI says " +
                (theirs ? "prime" : "composite") + ", expected " + (expected ? "prime" : "composite"));
}

}  // namespace

int main() {
  const int repeats = bench::repeats({"BENCH_KBNC_REPEATS", "BENCH_REPEATS"}, 3);
  const auto prime = kbnc_number(36627);
  const std::string prime_text = kbnc_text(36627);
  std::printf("bench_kbnc: %s (%zu bits), test_number vs PARI ispseudoprime, %d repeats\n", prime_text.c_str(),
              mpz_sizeinbase(prime.value.get_mpz_t(), 2), repeats);

  bench::Results results("bench_kbnc");
  for (int r = 0; r < repeats; ++r) {
    OurRun mine;
    std::pair<bool, double> theirs;
    if (r % 2 == 0) {
      mine = ours(prime);
      theirs = pari(prime_text);
    } else {
      theirs = pari(prime_text);
      mine = ours(prime);
    }
    check_agree(prime_text, mine.prime, theirs.first, true);
    results.add(mine.seconds, theirs.second);
  }

  const std::string composite_text = kbnc_text(36629);
  const auto mine = ours(kbnc_number(36629));
  const auto theirs = pari(composite_text);
  check_agree(composite_text, mine.prime, theirs.first, false);
  std::printf(
      "  composite %s: both say composite (ours: %s); ours %.4f s  peer %.4f s  ratio %.1f (once, not in "
      "the median)\n",
      composite_text.c_str(), mine.witness.c_str(), mine.seconds, theirs.second, theirs.second / mine.seconds);
  results.report(4.0);
}
