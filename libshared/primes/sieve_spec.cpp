/// @file sieve_spec.cpp
#include "primes/sieve_spec.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "io/error.hpp"
#include "primes/number.hpp"

namespace tk::primes {

namespace {

__extension__ typedef unsigned __int128 u128;

constexpr std::uint64_t kMaxCandidates = std::uint64_t(1) << 36;  // an 8 GiB bitmap
constexpr std::uint64_t kMaxPrime = std::uint64_t(1) << 62;
constexpr unsigned kMaxChain = 64;

}  // namespace

std::optional<SieveForm> sieve_form_from_name(const std::string& name) {
  if (name == "riesel") return SieveForm::riesel;
  if (name == "proth") return SieveForm::proth;
  if (name == "twin") return SieveForm::twin;
  if (name == "sg") return SieveForm::sg;
  if (name == "cc1") return SieveForm::cc1;
  if (name == "cc2") return SieveForm::cc2;
  return std::nullopt;
}

std::string SieveSpec::form_name() const {
  switch (form) {
    case SieveForm::riesel: return "riesel";
    case SieveForm::proth: return "proth";
    case SieveForm::twin: return "twin";
    case SieveForm::sg: return "sg";
    case SieveForm::cc1: return "cc1";
    case SieveForm::cc2: return "cc2";
  }
  return "?";
}

std::vector<SieveMember> SieveSpec::members() const {
  switch (form) {
    case SieveForm::riesel: return {{0, -1}};
    case SieveForm::proth: return {{0, +1}};
    case SieveForm::twin: return {{0, -1}, {0, +1}};
    case SieveForm::sg: return {{0, -1}, {1, -1}};
    case SieveForm::cc1:
    case SieveForm::cc2: {
      std::vector<SieveMember> chain;
      for (unsigned i = 0; i < length; ++i) chain.push_back({i, form == SieveForm::cc1 ? -1 : +1});
      return chain;
    }
  }
  return {};
}

std::string SieveSpec::candidates_identity() const {
  std::string text = fmt::format("form={} length={} n={} ", form_name(), length, n);
  return text +
         (parametrised ? fmt::format("h0={} c={} x={}:{}", h0, c, x_min, x_max) : fmt::format("k={}:{}", x_min, x_max));
}

std::string SieveSpec::identity() const { return candidates_identity() + fmt::format(" pmax={}", p_max); }

void SieveSpec::validate() const {
  // Every parameter is one of sieve's options: a bad one is a usage error naming it.
  const std::string range_option = parametrised ? "--x" : "--k";
  if (n == 0) throw UsageError("--n: the exponent n must be at least 1");
  if (n > 0xFFFFFFFFu - kMaxChain) throw UsageError(fmt::format("--n: the exponent n = {} is above 2^32 - 65", n));
  if ((form == SieveForm::cc1 || form == SieveForm::cc2) && (length < 2 || length > kMaxChain))
    throw UsageError(fmt::format("--length: a chain length must be 2 to {}, not {}", kMaxChain, length));
  if (x_max < x_min)
    throw UsageError(
        fmt::format("{}: the range {}:{} is empty (its end is below its start)", range_option, x_min, x_max));
  if (!parametrised && x_min == 0) throw UsageError("--k: k must start at 1 or more");
  if (parametrised && c == 0) throw UsageError("--c: c = 0 makes every k equal to h0");
  if (static_cast<u128>(c) * x_max + h0 > UINT64_MAX)
    throw UsageError("--h0, --c and --x: the largest k, h0 + c*x, does not fit in 64 bits");
  if (x_max - x_min >= kMaxCandidates)
    throw UsageError(fmt::format("{}: {} candidates are more than one run sieves (at most 2^36): split the range",
                                 range_option, x_max - x_min + 1));
  if (p_max < 3) throw UsageError("--pmax: the sieve bound must be at least 3");
  if (p_max > kMaxPrime) throw UsageError("--pmax: the sieve bound must be below 2^62");
}

void SieveSpec::check_riesel_condition() const {
  const auto all = members();
  if (std::none_of(all.begin(), all.end(), [](const SieveMember& m) { return m.c == -1; }))
    throw UsageError("--riesel-condition is about k*2^e-1 members, and " + form_name() + " has none");
  const bool single = x_min == x_max;
  const std::uint64_t k_first = k_at(x_min), k_last = k_at(x_max);
  for (const SieveMember& member : members()) {
    if (member.c != -1) continue;
    const std::uint64_t e = n + member.exponent_offset;
    // An even k is proved as k/2^t * 2^(e+t) - 1, whose k is odd. For one
    // candidate that form is checked; for a range, k < 2^e for the largest
    // k is enough: then k/2^t < 2^e <= 2^(e+t) for every k.
    KbncForm odd{k_last, 2, e, -1};
    if (single) make_k_odd(odd);
    if (odd.n < 64 && odd.k >= (std::uint64_t(1) << odd.n))
      throw UsageError(fmt::format("--riesel-condition: k = {} is not below 2^{}", odd.k.get_str(), odd.n));
    if (!single && !(parametrised && c % 13 == 0))
      throw UsageError("--riesel-condition: (13/N) = -1 for every x needs 13 to divide c");
    // N mod 13 is the same for every x; (13/N) = (N/13) since 13 = 1 mod 4.
    std::uint64_t power = 1;
    for (std::uint64_t i = 0; i < e % 12; ++i) power = power * 2 % 13;  // 2 has order 12 mod 13
    const std::uint64_t residue = (k_first % 13 * power + 12) % 13;
    const bool non_residue =
        residue == 2 || residue == 5 || residue == 6 || residue == 7 || residue == 8 || residue == 11;
    if (!non_residue)
      throw UsageError(fmt::format(
          "--riesel-condition: N = k*2^{}-1 is {} mod 13, so (13/N) is not -1: choose another h0", e, residue));
  }
}

std::string member_text(std::uint64_t k, std::uint64_t n, const SieveMember& member) {
  return fmt::format("{}*2^{}{}", k, n + member.exponent_offset, member.c < 0 ? "-1" : "+1");
}

}  // namespace tk::primes
