/// @file sieve_spec.hpp
/// @brief What a generalized sieve run sieves: a form (the members that must
/// all be prime), the exponent n, and the k values, either a plain range
/// (NewPGen's) or h0 + c*x over an x range (the "Prime Hunting" seed's).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace tk::primes {

enum class SieveForm { riesel, proth, twin, sg, cc1, cc2 };

/// One member of a form: k*2^(n + exponent_offset) + c.
struct SieveMember {
  unsigned exponent_offset = 0;
  int c = -1;
};

struct SieveSpec {
  SieveForm form = SieveForm::twin;
  unsigned length = 1;  ///< chain length for cc1/cc2
  std::uint64_t n = 0;
  bool parametrised = false;  ///< k = h0 + c*x; otherwise x is k itself
  std::uint64_t h0 = 0;
  std::uint64_t c = 1;
  std::uint64_t x_min = 0, x_max = 0;  ///< inclusive
  std::uint64_t p_max = 0;             ///< sieve with every prime up to this

  std::vector<SieveMember> members() const;
  std::uint64_t count() const { return x_max - x_min + 1; }
  std::uint64_t k_at(std::uint64_t x) const { return h0 + c * x; }
  /// "twin", "cc1", ... as records name the form.
  std::string form_name() const;
  /// One line that names every parameter that decides the survivors; a
  /// checkpoint or shard must match it to be combined with this run.
  std::string identity() const;
  /// identity() without pmax: the candidates, which shards sieved to
  /// different depths still share.
  std::string candidates_identity() const;

  /// Throws UsageError naming the option for an impossible or pointless
  /// parameter (one that makes every candidate composite, say).
  void validate() const;
  /// The seed's conditions for a Riesel (LLR) proof with D = 13 on every
  /// k*2^e-1 member: k odd, k < 2^e and (13/N) = -1 for every x; the last
  /// needs 13 | c so that N mod 13 does not depend on x. Throws UsageError
  /// naming --riesel-condition.
  void check_riesel_condition() const;
};

std::optional<SieveForm> sieve_form_from_name(const std::string& name);

/// "k*2^e-1" for one member, as factor files and ABC files write it.
std::string member_text(std::uint64_t k, std::uint64_t n, const SieveMember& member);

}  // namespace tk::primes
