/// @file primality.cpp
#include "primes/primality.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <future>
#include <random>

#include "primes/big_tests.hpp"
#include "primes/modulus.hpp"
#include "primes/montgomery64.hpp"
#include "primes/prime64.hpp"
#include "primes/trial_division.hpp"

namespace tk::primes {

std::string_view verdict_name(Verdict verdict) {
  switch (verdict) {
    case Verdict::composite: return "composite";
    case Verdict::unknown: return "unknown";
    case Verdict::probable_prime: return "probable-prime";
    case Verdict::prime_if_grh: return "prime-if-grh";
    case Verdict::prime: return "prime";
  }
  return "unknown";
}

std::string_view test_name(TestKind kind) {
  switch (kind) {
    case TestKind::trial: return "trial";
    case TestKind::fermat: return "fermat";
    case TestKind::miller_rabin: return "mr";
    case TestKind::mr_grh: return "mr-grh";
    case TestKind::lucas: return "lucas";
    case TestKind::bpsw: return "bpsw";
  }
  return "bpsw";
}

std::optional<TestKind> parse_test_kind(std::string_view text) {
  if (text == "trial") return TestKind::trial;
  if (text == "fermat") return TestKind::fermat;
  if (text == "mr" || text == "miller-rabin") return TestKind::miller_rabin;
  if (text == "mr-grh") return TestKind::mr_grh;
  if (text == "lucas") return TestKind::lucas;
  if (text == "bpsw") return TestKind::bpsw;
  return std::nullopt;
}

std::uint64_t default_trial_bound(std::size_t bits) {
  // Enough to drop most composites cheaply, never more than ~1% of a test.
  if (bits <= 64) return 61;
  const std::uint64_t scaled = static_cast<std::uint64_t>(bits) * bits / 8;
  return std::clamp<std::uint64_t>(scaled, 1000, std::uint64_t{1} << 20);
}

std::uint64_t grh_last_base(const mpz_class& n) {
  long exponent = 0;
  const long double mantissa = mpz_get_d_2exp(&exponent, n.get_mpz_t());  // n = mantissa * 2^exponent
  const long double ln_n = std::log(mantissa) + static_cast<long double>(exponent) * std::log(2.0L);
  const long double bound = 2 * ln_n * ln_n;
  // The rounding errors above are a few units in the 64-bit mantissa's last
  // place; the margin covers them with room to spare (at 2^26 bits, where
  // the bound is 4.3e15, it adds at most one base).
  const long double margin = 1e-6L + bound * 1e-16L;
  // 2^62 bases would take longer than anyone waits; above it, only the cap matters.
  const std::uint64_t last =
      bound >= 0x1p62L ? std::uint64_t{1} << 62 : static_cast<std::uint64_t>(std::floor(bound + margin));
  const mpz_class largest = n - 2;
  return mpz_cmp_ui(largest.get_mpz_t(), last) < 0 ? mpz_get_ui(largest.get_mpz_t()) : last;
}

namespace {

TestOutcome composite(std::string witness) { return {Verdict::composite, std::move(witness)}; }

std::string base_witness(std::uint64_t base) { return "base " + std::to_string(base); }

/// Theorem 2.3 of "Prime Hunting": under GRH an odd composite n > 8 that is
/// no prime power has a Miller-Rabin witness below 2 (ln n)^2. So: no
/// perfect power, then every base from 2 to grh_last_base(n). When those
/// are all the bases up to n - 2, the pass is a proof with no hypothesis.
/// `passes(a)` runs Miller-Rabin to base a. Odd n > 2.
template <class StrongTest>
TestOutcome grh_miller_rabin(const mpz_class& n, StrongTest&& passes) {
  if (mpz_perfect_power_p(n.get_mpz_t())) return composite("perfect power");
  const std::uint64_t last = grh_last_base(n);
  for (std::uint64_t a = 2; a <= last; ++a)
    if (!passes(a)) return composite(base_witness(a));
  return {n - 2 <= last ? Verdict::prime : Verdict::prime_if_grh, {}};
}

/// Bases for Fermat / Miller-Rabin: the chosen ones, then random ones drawn
/// from a generator seeded by --seed and the number itself, so results do
/// not depend on thread scheduling.
std::vector<mpz_class> choose_bases(const mpz_class& n, const TestPlan& plan) {
  std::vector<mpz_class> bases;
  for (std::uint64_t b : plan.bases) bases.emplace_back(static_cast<unsigned long>(b));
  if (plan.bases.empty() && plan.random_bases == 0) bases.emplace_back(2);
  if (plan.random_bases && n > 4) {
    gmp_randclass random(gmp_randinit_mt);
    mpz_class seed = n;
    seed ^= mpz_class(static_cast<unsigned long>(plan.seed));
    random.seed(seed);
    const mpz_class span = n - 3;  // bases in [2, n - 2]
    for (unsigned i = 0; i < plan.random_bases; ++i) bases.push_back(random.get_z_range(span) + 2);
  }
  return bases;
}

std::string witness_text(const mpz_class& base) { return "base " + base.get_str(); }

TestOutcome test_u64(std::uint64_t n, const TestPlan& plan) {
  if (n == 2) return {Verdict::prime, {}};
  if (n % 2 == 0) return composite("factor 2");
  const std::uint64_t bound = plan.trial_bound.value_or(default_trial_bound(64));
  if (bound >= 3) {
    if (std::uint64_t f = small_factor_u64(n, bound)) return composite("factor " + std::to_string(f));
    // No factor up to sqrt(n): trial division has proved n prime.
    if (static_cast<u128>(bound) * bound >= n) return {Verdict::prime, {}};
  }
  auto lucas = [&]() -> std::optional<TestOutcome> {
    std::uint64_t factor = 0;
    const std::int64_t d = selfridge_d_u64(n, factor);
    if (d == 0) return composite("square");
    if (factor) return composite("factor " + std::to_string(factor));
    if (!strong_lucas_probable_prime_u64(n, d)) return composite("lucas D=" + std::to_string(d));
    return std::nullopt;
  };
  switch (plan.kind) {
    case TestKind::trial: return {Verdict::unknown, {}};
    case TestKind::fermat:
    case TestKind::miller_rabin:
      for (const mpz_class& base : choose_bases(n, plan)) {
        const std::uint64_t b = mpz_get_ui(base.get_mpz_t());
        const bool pass =
            plan.kind == TestKind::fermat ? fermat_probable_prime_u64(n, b) : strong_probable_prime_u64(n, b);
        if (!pass) return composite(base_witness(b));
      }
      return {Verdict::probable_prime, {}};
    case TestKind::mr_grh:
      return grh_miller_rabin(mpz_class(static_cast<unsigned long>(n)),
                              [n](std::uint64_t a) { return strong_probable_prime_u64(n, a); });
    case TestKind::lucas:
      if (auto failed = lucas()) return *failed;
      return {Verdict::probable_prime, {}};
    case TestKind::bpsw:
      if (!strong_probable_prime_u64(n, 2)) return composite(base_witness(2));
      if (auto failed = lucas()) return *failed;
      return {Verdict::prime, {}};  // BPSW has no pseudoprime below 2^64
  }
  return {};
}

/// What the Lucas half found: a composite witness, or a pass that for
/// N = k*2^n - 1 may also be a proof of primality.
struct LucasOutcome {
  std::optional<TestOutcome> failure;
  bool proves_prime = false;
};

/// BPSW with the Lucas half on a second thread; verdicts and witnesses are
/// those of the sequential order (see test_big).
template <class Lucas>
TestOutcome split_bpsw(const Modulus& modulus, Lucas& lucas, bool lucas_first) {
  std::atomic<bool> cancel_lucas{false}, cancel_base2{false};
  // Modulus keeps scratch space, so each thread reduces with its own copy.
  const Modulus lucas_modulus = modulus.form() ? Modulus(modulus.value(), *modulus.form()) : Modulus(modulus.value());
  auto lucas_result = std::async(std::launch::async, [&] {
    LucasOutcome outcome = lucas(lucas_modulus, &cancel_lucas);
    // Lucas first: its failure or proof decides, the base-2 test can stop.
    if (lucas_first && (outcome.failure || outcome.proves_prime)) cancel_base2 = true;
    return outcome;
  });
  // Should the base-2 test throw (out of memory), stop the Lucas thread
  // rather than wait for its full run in the future's destructor.
  struct CancelOnExit {
    std::atomic<bool>& flag;
    ~CancelOnExit() { flag = true; }
  } guard{cancel_lucas};
  const bool base2_passed = strong_probable_prime(modulus, 2, &cancel_base2);
  if (!base2_passed && !lucas_first) cancel_lucas = true;
  const LucasOutcome lucas_outcome = lucas_result.get();
  if (lucas_first) {
    if (lucas_outcome.failure) return *lucas_outcome.failure;
    if (lucas_outcome.proves_prime) return {Verdict::probable_prime, {}};
  }
  if (!base2_passed) return composite(base_witness(2));
  if (lucas_outcome.failure) return *lucas_outcome.failure;
  return {Verdict::probable_prime, {}};
}

TestOutcome test_big(const Number& number, const TestPlan& plan) {
  const mpz_class& n = number.value;
  if (mpz_even_p(n.get_mpz_t())) return composite("factor 2");
  const std::uint64_t bound = plan.trial_bound.value_or(default_trial_bound(mpz_sizeinbase(n.get_mpz_t(), 2)));
  if (bound >= 3)
    if (std::uint64_t f = trial_factor(number, bound)) return composite("factor " + std::to_string(f));
  if (plan.kind == TestKind::trial) return {Verdict::unknown, {}};

  std::optional<SpecialForm> special;
  if (number.form && number.form->b == 2 && mpz_fits_ulong_p(number.form->k.get_mpz_t()))
    special = detect_special_form(n, number.form->c);
  else special = detect_special_form(n);
  const Modulus modulus = special ? Modulus(n, *special) : Modulus(n);

  // N = k*2^n - 1 with 2^n > k: N + 1 = k*2^n, so the Lucas half ends in the
  // LLR iteration W -> W^2 - 2 on V_k(P', 1), P' = 1/Q - 2. When (Q/N) = -1,
  // Rodseth's criterion holds ((P'-2 / N) = 1, (P'+2 / N) = -1), and
  // W_{n-1} = 0 proves N prime; a prime passes Miller-Rabin, so that half
  // can be skipped. Such numbers therefore run Lucas first.
  // (k = 2^64 - 1 with n = 64 is the one shape here with 2^n - 1 <= k, where
  // the criterion's bound p >= 2^n - 1 on prime factors is not enough.)
  const bool riesel_shape = special && special->c == -1 && (special->n > 64 || special->k < ~std::uint64_t{0});
  auto lucas = [&](const Modulus& m, const std::atomic<bool>* cancel) -> LucasOutcome {
    const SelfridgeChoice choice = selfridge_d(n);
    if (choice.d == 0) return {composite("square")};
    if (choice.factor != 0) return {composite("factor " + choice.factor.get_str())};
    mpz_class factor = 0;
    bool zero_at_last = false;
    if (!strong_lucas_probable_prime(m, choice.d, factor, cancel, &zero_at_last))
      return {composite(factor != 0 ? "factor " + factor.get_str() : "lucas D=" + std::to_string(choice.d))};
    const long q = static_cast<long>((1 - choice.d) / 4);
    return {std::nullopt, riesel_shape && zero_at_last && mpz_si_kronecker(q, n.get_mpz_t()) == -1};
  };
  switch (plan.kind) {
    case TestKind::trial: break;
    case TestKind::fermat:
    case TestKind::miller_rabin:
      for (const mpz_class& base : choose_bases(n, plan)) {
        const bool pass =
            plan.kind == TestKind::fermat ? fermat_probable_prime(modulus, base) : strong_probable_prime(modulus, base);
        if (!pass) return composite(witness_text(base));
      }
      return {Verdict::probable_prime, {}};
    case TestKind::mr_grh:
      return grh_miller_rabin(
          n, [&](std::uint64_t a) { return strong_probable_prime(modulus, mpz_class(static_cast<unsigned long>(a))); });
    case TestKind::lucas:
      if (auto outcome = lucas(modulus, nullptr); outcome.failure) return *outcome.failure;
      return {Verdict::probable_prime, {}};
    case TestKind::bpsw:
      if (plan.split_bits && modulus.bits() >= plan.split_bits) return split_bpsw(modulus, lucas, riesel_shape);
      if (riesel_shape) {
        const LucasOutcome outcome = lucas(modulus, nullptr);
        if (outcome.failure) return *outcome.failure;
        if (outcome.proves_prime) return {Verdict::probable_prime, {}};
        if (!strong_probable_prime(modulus, 2)) return composite(base_witness(2));
        return {Verdict::probable_prime, {}};
      }
      if (!strong_probable_prime(modulus, 2)) return composite(base_witness(2));
      if (auto outcome = lucas(modulus, nullptr); outcome.failure) return *outcome.failure;
      return {Verdict::probable_prime, {}};
  }
  return {Verdict::unknown, {}};
}

}  // namespace

TestOutcome test_number(const Number& number, const TestPlan& plan) {
  const mpz_class& n = number.value;
  if (n < 2) return composite("n < 2");
  if (mpz_sizeinbase(n.get_mpz_t(), 2) <= 64) {
    std::uint64_t value = 0;
    mpz_export(&value, nullptr, -1, sizeof value, 0, 0, n.get_mpz_t());
    return test_u64(value, plan);
  }
  return test_big(number, plan);
}

}  // namespace tk::primes
