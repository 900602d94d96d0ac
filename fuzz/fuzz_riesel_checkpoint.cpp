/// @file fuzz_riesel_checkpoint.cpp
/// @brief libFuzzer target: bytes as a riesel --state checkpoint, read back
/// with tk::primes::parse_checkpoint and, when read, resumed by the proof.
///
/// A checkpoint's fifth line is the FNV-1a checksum of the four before it,
/// which a random mutation almost always breaks, so every input is read
/// twice: as it is, and with everything after its fourth newline replaced
/// by the correct checksum line. Both are read as the checkpoint of
/// kMember; the repaired copy also as that of the member on its own second
/// line, so the iteration and residue checks are reached whatever it names.
///
/// tk::Error is the expected rejection; any other exception, crash,
/// sanitizer report or hang is a bug.
///
/// Oracles (switch off by name with TK_FUZZ_SKIP=a,b while a finding is open):
///   canonical  a checkpoint that is read is byte for byte what
///              checkpoint_text writes for the state read (nothing else passes)
///   resume     a member k*2^n+-1 (n <= 2048) resumed from the state: the
///              proof refuses the state exactly when its iteration is not in
///              1 .. squarings-1 or its residue is not below N, and a refused
///              state leaves the true verdict (3*2^391-1 is prime)
#include <cinttypes>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

#include <fmt/format.h>

#include "fuzz_common.hpp"
#include "io/checksum.hpp"
#include "io/error.hpp"
#include "primes/proof_journal_format.hpp"
#include "primes/riesel_proof.hpp"

namespace {

using tk::primes::ProofState;

/// A prime (OEIS A002235) small enough to prove in well under a millisecond.
const std::string kMember = "3*2^391-1 start=llr";

/// The bytes up to their fourth newline and a correct checksum line after them.
std::string with_checksum(std::string_view bytes) {
  std::size_t end = 0;
  for (int line = 0; line < 4; ++line) {
    const std::size_t newline = bytes.find('\n', end);
    if (newline == std::string_view::npos) return std::string(bytes);
    end = newline + 1;
  }
  const std::string body(bytes.substr(0, end));
  return body + fmt::format("{:016x}\n", tk::io::fnv1a(body));
}

/// The proof resumed from `state`, when `member` is "k*2^n-1 start=..." or "k*2^n+1 start=..." with a small n.
void check_resume(const std::string& member, const ProofState& state) {
  std::uint64_t k = 0, n = 0;
  char sign = 0;
  int used = 0;
  if (std::sscanf(member.c_str(), "%" SCNu64 "*2^%" SCNu64 "%c1 start=%*s%n", &k, &n, &sign, &used) != 3 || used == 0)
    return;
  if ((sign != '-' && sign != '+') || k % 2 == 0 || n < 2 || n > 2048 || (n < 64 && k >= (std::uint64_t(1) << n)))
    return;
  const std::uint64_t squarings = sign == '-' ? n - 2 : n - 1;
  const mpz_class N = (mpz_class(k) << static_cast<mp_bitcnt_t>(n)) + (sign == '-' ? -1 : 1);
  tk::primes::ProofOptions options;
  options.resume_from = state;
  bool refused = false;
  options.resume_rejected = [&](const std::string&) { refused = true; };
  tk::primes::ProofResult result;
  try {
    result = sign == '-' ? tk::primes::llr_prove(k, n, tk::primes::LlrStart::llr, options)
                         : tk::primes::proth_prove(k, n, options);
  } catch (const tk::Error&) {
    return;
  }
  if (!tk::fuzz::oracle_enabled("resume") || !result.parameter) return;  // no P or a: nothing resumed
  const bool outside = state.iteration == 0 || state.iteration >= squarings || state.value < 0 || state.value >= N;
  if (refused != outside)
    tk::fuzz::invariant_failed("resume", fmt::format("iteration {} of {} {}: refused {}", state.iteration, squarings,
                                                     state.value >= N ? "(residue >= N)" : "", refused));
  if (refused && member == kMember && result.verdict != tk::primes::Verdict::prime)
    tk::fuzz::invariant_failed("resume", "a refused state changed the verdict of a prime");
}

void load(std::string_view bytes, const std::string& member) {
  ProofState state;
  try {
    state = tk::primes::parse_checkpoint(bytes, member);
  } catch (const tk::Error&) {
    return;
  }
  if (tk::fuzz::oracle_enabled("canonical") && tk::primes::checkpoint_text(member, state) != bytes)
    tk::fuzz::invariant_failed("canonical", "read a checkpoint that checkpoint_text would not write");
  check_resume(member, state);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  load(bytes, kMember);
  const std::string repaired = with_checksum(bytes);
  load(repaired, kMember);
  const std::size_t first = repaired.find('\n'),
                    second = first == std::string::npos ? first : repaired.find('\n', first + 1);
  if (second != std::string::npos) load(repaired, repaired.substr(first + 1, second - first - 1));
  return 0;
}
