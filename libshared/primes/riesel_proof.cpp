/// @file riesel_proof.cpp
#include "primes/riesel_proof.hpp"

#include <fmt/format.h>

#include "io/error.hpp"
#include "primes/fft_squaring.hpp"
#include "primes/gerbicz_check.hpp"
#include "primes/jacobi_check.hpp"
#include "primes/modulus.hpp"
#include "primes/weighted_squaring.hpp"

namespace tk::primes {

namespace {

constexpr std::uint64_t kMaxParameter = 1000;

mpz_class kbnc(std::uint64_t k, std::uint64_t n, int c) {
  mpz_class value = k;
  value <<= static_cast<mp_bitcnt_t>(n);
  return value + c;
}

int jacobi(std::int64_t a, const mpz_class& N) {
  const mpz_class top = a;
  return mpz_jacobi(top.get_mpz_t(), N.get_mpz_t());
}

bool reports_now(const ProofState& state, const ProofOptions& options) {
  return options.report_every && state.iteration % options.report_every == 0 && state.iteration;
}

/// Squares `value` (|value| < N) m times modulo N, subtracting `minus` each
/// time; reports and honours cancellation between rounds.
bool square_rounds_gmp(const Modulus& N, ProofState& state, std::uint64_t last, long minus,
                       const ProofOptions& options) {
  mpz_class square;
  for (; state.iteration < last; ++state.iteration) {
    if (reports_now(state, options)) {
      const bool cancelled = options.cancel && options.cancel->load(std::memory_order_relaxed);
      if (options.progress) {
        N.reduce(state.value.get_mpz_t());
        if (!options.progress(state)) return false;
      }
      if (cancelled) return false;  // after progress has seen (and saved) the state
    }
    mpz_mul(square.get_mpz_t(), state.value.get_mpz_t(), state.value.get_mpz_t());
    if (minus) mpz_sub_ui(square.get_mpz_t(), square.get_mpz_t(), static_cast<unsigned long>(minus));
    N.remainder(state.value.get_mpz_t(), square.get_mpz_t());
  }
  N.reduce(state.value.get_mpz_t());
  return true;
}

template <class Squarer>
bool square_rounds_fft(Squarer& fft, std::uint64_t& iteration, std::uint64_t last, long minus,
                       const ProofOptions& options, bool report) {
  for (; iteration < last; ++iteration) {
    if (report && iteration % options.report_every == 0 && iteration) {
      const bool cancelled = options.cancel && options.cancel->load(std::memory_order_relaxed);
      if (options.progress) {
        ProofState state{iteration, {}};
        fft.store(state.value);
        if (!options.progress(state)) return false;
      }
      if (cancelled) return false;
    }
    fft.square_minus(static_cast<unsigned long>(minus));
  }
  return true;
}

/// Proth's squarings (minus 0) go through Gerbicz's check, LLR's (x^2 - 2)
/// through the Jacobi check of the Lucas sequence.
template <class Squarer>
bool square_rounds_fft(Squarer& fft, const Modulus& N, ProofState& state, std::uint64_t last, long minus,
                       const ProofOptions& options, ProofResult& result) {
  if (options.report_every == 0) {
    ProofOptions quiet = options;
    quiet.report_every = std::uint64_t{1} << 62;
    return square_rounds_fft(fft, N, state, last, minus, quiet, result);
  }
  CheckedSquarer squarer;
  squarer.square_to = [&](std::uint64_t& iteration, std::uint64_t to, bool report) {
    return square_rounds_fft(fft, iteration, to, minus, options, report);
  };
  squarer.load = [&](const mpz_class& x) { fft.load(x); };
  squarer.store = [&](mpz_class& x) { fft.store(x); };
  // A resumed LLR may start at iteration 0 only from u_0, which the
  // Jacobi identity does not cover: its first check comes after squarings.
  const GerbiczOutcome outcome =
      minus != 0 ? jacobi_checked_squarings(squarer, N.value(), state.value, state.iteration, last, kJacobiCheckEvery,
                                            options.corrupt_for_tests)
                 : gerbicz_squarings(squarer, N, state.value, state.iteration, last,
                                     gerbicz_plan(last - state.iteration), options.corrupt_for_tests);
  result.check_restarts = outcome.restarts;
  return outcome.finished;
}

/// Runs the rounds in the arithmetic the options ask for; the value enters
/// and leaves reduced to [0, N).
bool square_rounds(const Modulus& N, ProofState& state, std::uint64_t last, long minus, const ProofOptions& options,
                   ProofResult& result) {
  N.reduce(state.value.get_mpz_t());
  if (options.arithmetic == Arithmetic::gmp || (options.arithmetic == Arithmetic::automatic && N.bits() < kFftMinBits))
    return square_rounds_gmp(N, state, last, minus, options);
  // The weighted transform where k fits it (k < 2^56), else the padded FFT
  // with GMP's reduction; neither for n < 64: GMP squares those.
  auto run = [&](auto& squarer) {
    const bool finished = square_rounds_fft(squarer, N, state, last, minus, options, result);
    result.fft_length = squarer.transform_length();
    result.fft_fallbacks = squarer.fallbacks();
    return finished;
  };
  if (auto weighted = WeightedSquaring::create(*N.form())) {
    const std::size_t from =
        options.split_from_length ? options.split_from_length : WeightedSquaring::split_from_length();
    if (weighted->transform_length() >= from) weighted->use_threads(options.threads, options.paced_split);
    return run(*weighted);
  }
  if (auto fft = FftSquaring::create(*N.form())) return run(*fft);
  return square_rounds_gmp(N, state, last, minus, options);
}

std::uint64_t low_64_bits(const mpz_class& value) {
  std::uint64_t low = 0;
  for (std::size_t limb = 0; limb * GMP_NUMB_BITS < 64 && limb < mpz_size(value.get_mpz_t()); ++limb)
    low |= static_cast<std::uint64_t>(mpz_getlimbn(value.get_mpz_t(), static_cast<mp_size_t>(limb)))
           << (limb * GMP_NUMB_BITS);
  return low;
}

/// The saved state to resume from, when it fits a proof of N that squares
/// up to iteration `last`: never one that would skip every squaring.
std::optional<ProofState> usable_resume(const ProofOptions& options, const mpz_class& N, std::uint64_t last) {
  if (!options.resume_from) return std::nullopt;
  const ProofState& state = *options.resume_from;
  std::string why;
  if (state.iteration == 0 || state.iteration >= last)
    why = fmt::format("iteration {} is outside this proof ({} squarings)", state.iteration, last);
  else if (state.value < 0 || state.value >= N) why = "residue is not below N";
  if (why.empty()) return state;
  if (options.resume_rejected) options.resume_rejected(why);
  return std::nullopt;
}

void check_form(std::uint64_t k, std::uint64_t n, std::uint64_t min_n) {
  if (k % 2 == 0 || k == 0) throw Error("k must be odd and positive");
  if (n < min_n) throw Error("n must be at least " + std::to_string(min_n));
  if (n < 64 && k >= (std::uint64_t(1) << n)) throw Error("k must be below 2^n");
}

}  // namespace

std::optional<std::uint64_t> llr_parameter(std::uint64_t k, std::uint64_t n, LlrStart start) {
  const mpz_class N = kbnc(k, n, -1);
  if (start == LlrStart::d13) {
    if (jacobi(13, N) == -1) return 11;
    return std::nullopt;
  }
  if (k % 3 != 0) return 4;  // (3/N) = -1 whenever 3 does not divide N (n >= 2)
  for (std::uint64_t p = 3; p <= kMaxParameter; ++p)
    if (jacobi(static_cast<std::int64_t>(p) - 2, N) == 1 && jacobi(static_cast<std::int64_t>(p) + 2, N) == -1) return p;
  return std::nullopt;
}

ProofResult llr_prove(std::uint64_t k, std::uint64_t n, LlrStart start, const ProofOptions& options) {
  check_form(k, n, 2);
  const mpz_class value = kbnc(k, n, -1);
  const Modulus N(value, SpecialForm{k, n, -1});
  ProofResult result;
  const auto parameter = llr_parameter(k, n, start);
  if (!parameter) {
    if (start == LlrStart::d13) throw Error("(13/N) is not -1, so the seed's D = 13 start does not apply");
    result.verdict = Verdict::composite;  // no P up to the bound: N is a square or has a small factor
    return result;
  }
  result.parameter = *parameter;
  ProofState state;
  if (const auto resume = usable_resume(options, value, n - 2)) {
    state = *resume;
  } else {
    // u_0 = V_k(P): the ladder keeps (V_m, V_m+1), doubling m bit by bit.
    mpz_class low = 2, high = *parameter, product;
    for (int bit = 63 - __builtin_clzll(k); bit >= 0; --bit) {
      product = low * high - static_cast<long>(*parameter);
      if ((k >> bit) & 1) {
        low = product;
        high = high * high - 2;
      } else {
        high = product;
        low = low * low - 2;
      }
      N.reduce(low.get_mpz_t());
      N.reduce(high.get_mpz_t());
    }
    state.value = low;
  }
  if (!square_rounds(N, state, n - 2, 2, options, result)) return result;
  result.iterations = state.iteration;
  result.res64 = low_64_bits(state.value);
  result.verdict = state.value == 0 ? Verdict::prime : Verdict::composite;
  return result;
}

std::optional<std::uint64_t> proth_base(std::uint64_t k, std::uint64_t n) {
  const mpz_class N = kbnc(k, n, +1);
  for (std::uint64_t a = 3; a <= kMaxParameter; ++a)
    if (jacobi(static_cast<std::int64_t>(a), N) == -1) return a;
  return std::nullopt;
}

ProofResult proth_prove(std::uint64_t k, std::uint64_t n, const ProofOptions& options) {
  check_form(k, n, 1);
  const mpz_class value = kbnc(k, n, +1);
  const Modulus N(value, SpecialForm{k, n, +1});
  ProofResult result;
  const auto base = proth_base(k, n);
  if (!base) {
    result.verdict = Verdict::composite;
    return result;
  }
  result.parameter = *base;
  ProofState state;
  if (const auto resume = usable_resume(options, value, n - 1)) {
    state = *resume;
  } else {
    mpz_class power;
    const mpz_class a = *base, exponent = k;
    mpz_powm(power.get_mpz_t(), a.get_mpz_t(), exponent.get_mpz_t(), value.get_mpz_t());  // a^k: k has 64 bits at most
    state.value = power;
  }
  if (!square_rounds(N, state, n - 1, 0, options, result)) return result;  // a^(k*2^(n-1))
  result.iterations = state.iteration;
  result.res64 = low_64_bits(state.value);
  result.verdict = state.value == value - 1 ? Verdict::prime : Verdict::composite;
  return result;
}

}  // namespace tk::primes
