/// @file modulus.hpp
/// @brief A big modulus N with its fastest reduction: N = k*2^n + c with
/// small k and c reduces with shifts, one division by k and adds; any other
/// N uses GMP's division.
#pragma once

#include <gmpxx.h>

#include <cstdint>
#include <optional>

namespace tk::primes {

/// N = k * 2^n + c with 1 <= k < 2^64 odd, |c| < 2^31, and 2^n > k.
struct SpecialForm {
  std::uint64_t k = 1;
  std::uint64_t n = 0;
  std::int64_t c = 0;
};

/// Finds k*2^n+c in N for c = -1 or +1 (or the given c) when k fits a word.
std::optional<SpecialForm> detect_special_form(const mpz_class& N, std::optional<std::int64_t> c_hint = {});

class Modulus {
 public:
  explicit Modulus(const mpz_class& N);
  Modulus(const mpz_class& N, const SpecialForm& form);

  const mpz_class& value() const { return n_; }
  const std::optional<SpecialForm>& form() const { return form_; }
  std::size_t bits() const { return bits_; }

  /// x := x mod N, with 0 <= x < N; x may be negative or as large as N^2 * 2^64.
  void reduce(mpz_t x) const;
  /// out := a number congruent to `in` with |out| < N (its sign may be
  /// negative). `out` and `in` must differ: hot loops that square into a
  /// scratch value and reduce back avoid GMP's copies for aliased operands.
  void remainder(mpz_ptr out, mpz_srcptr in) const;

 private:
  void reduce_special(mpz_t x) const;

  mpz_class n_;
  std::optional<SpecialForm> form_;
  std::size_t bits_;
  mutable mpz_class quotient_, scratch_;
};

}  // namespace tk::primes
