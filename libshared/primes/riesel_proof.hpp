/// @file riesel_proof.hpp
/// @brief Deterministic primality proofs for k*2^n-1 (Lucas-Lehmer-Riesel)
/// and k*2^n+1 (Proth), with k odd and k < 2^n; every squaring reduces
/// with the special form's shifts (Modulus), never a general division.
///
/// LLR (Riesel's theorem, Rodseth's choice of P): N = k*2^n-1 is prime iff
/// u_(n-2) = 0 (mod N), u_0 = V_k(P) mod N, u_i = u_(i-1)^2 - 2, for a P
/// with (P-2 / N) = 1 and (P+2 / N) = -1. LLR's choice: P = 4 when 3 does
/// not divide k, else the first such P >= 3. The seed's choice ("Prime
/// Hunting"): D = 13, that is P = 11 (P^2 - 4 = 9*13), when (13/N) = -1.
/// Proth: N = k*2^n+1 is prime iff a^((N-1)/2) = -1 (mod N) for an a with
/// (a / N) = -1.
#pragma once

#include <gmpxx.h>

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "primes/primality.hpp"

namespace tk::primes {

enum class LlrStart { llr, d13 };

/// How the squarings run: GMP's multiplication, the verified FFT
/// (FftSquaring), or automatic (the FFT from kFftMinBits on, where it is
/// faster here).
enum class Arithmetic { automatic, gmp, fft };
constexpr std::size_t kFftMinBits = 24000;

/// Where a proof stands: the next iteration to run and its value mod N.
struct ProofState {
  std::uint64_t iteration = 0;
  mpz_class value;
};

struct ProofOptions {
  /// Called every `report_every` iterations with the state reached (to save
  /// a checkpoint); return false to stop (the proof then has no verdict).
  /// A set `cancel` stops the proof at the next report, after this call.
  std::function<bool(const ProofState&)> progress;
  std::uint64_t report_every = 10000;
  const std::atomic<bool>* cancel = nullptr;
  /// A saved state to go on from. It is used only when it can be one of
  /// this proof's states (an iteration with squarings left to do, a residue
  /// below N); otherwise `resume_rejected` hears why and the proof starts
  /// from the beginning.
  std::optional<ProofState> resume_from;
  std::function<void(const std::string& why)> resume_rejected;
  Arithmetic arithmetic = Arithmetic::automatic;
  /// Threads each squaring of the weighted transform is split over, from
  /// transform length `split_from_length` on (0: the measured crossover,
  /// WeightedSquaring::split_from_length()); the result is the same.
  /// Paced (WeightedSquaring::use_threads): the split stops while one
  /// thread is faster; off in tests that must exercise the split.
  unsigned threads = 1;
  std::size_t split_from_length = 0;
  bool paced_split = true;
  /// Tests only: called with the value at each end of a Gerbicz block (Proth)
  /// or before each Jacobi check (LLR) of a proof on the FFT; may alter it
  /// (an injected error) and says so.
  std::function<bool(std::uint64_t iteration, mpz_class& value)> corrupt_for_tests;
};

struct ProofResult {
  Verdict verdict = Verdict::unknown;  ///< unknown when stopped
  std::uint64_t parameter = 0;         ///< P (LLR) or a (Proth)
  std::uint64_t res64 = 0;             ///< low 64 bits of the last residue
  std::uint64_t iterations = 0;
  std::size_t fft_length = 0;       ///< 0 when GMP squared
  std::uint64_t fft_fallbacks = 0;  ///< squares the FFT failed to verify, redone by GMP
  std::uint64_t check_restarts =
      0;  ///< on the FFT: failed Gerbicz (Proth) or Jacobi (LLR) checks, redone from the last verified state
};

/// P for k*2^n-1 as `start` chooses it; nothing when no P up to a bound
/// fits (then N is a square or has a small factor).
std::optional<std::uint64_t> llr_parameter(std::uint64_t k, std::uint64_t n, LlrStart start);

/// k odd, 1 <= k < 2^n, n >= 2.
ProofResult llr_prove(std::uint64_t k, std::uint64_t n, LlrStart start, const ProofOptions& options = {});

/// a for k*2^n+1: the first a >= 3 with (a / N) = -1; nothing for a square.
std::optional<std::uint64_t> proth_base(std::uint64_t k, std::uint64_t n);

/// k odd, 1 <= k < 2^n, n >= 1.
ProofResult proth_prove(std::uint64_t k, std::uint64_t n, const ProofOptions& options = {});

}  // namespace tk::primes
