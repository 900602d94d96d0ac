/// @file modulus.cpp
#include "primes/modulus.hpp"

#include "primes/number.hpp"

namespace tk::primes {

std::optional<SpecialForm> detect_special_form(const mpz_class& N, std::optional<std::int64_t> c_hint) {
  if (N <= 0) return std::nullopt;
  auto try_c = [&](std::int64_t c) -> std::optional<SpecialForm> {
    KbncForm form{N - c, 2, 0, c};
    if (form.k <= 0) return std::nullopt;
    make_k_odd(form);
    if (mpz_sizeinbase(form.k.get_mpz_t(), 2) > 64) return std::nullopt;
    // 2^n >= 2^64 > k: one round of the shift reduction removes about n bits.
    if (form.n < 64) return std::nullopt;
    return SpecialForm{mpz_get_ui(form.k.get_mpz_t()), form.n, c};
  };
  if (c_hint && *c_hint != 0 && *c_hint > -(std::int64_t{1} << 31) && *c_hint < (std::int64_t{1} << 31))
    if (auto form = try_c(*c_hint)) return form;
  if (auto form = try_c(-1)) return form;
  return try_c(1);
}

Modulus::Modulus(const mpz_class& N) : Modulus(N, SpecialForm{}) {}

Modulus::Modulus(const mpz_class& N, const SpecialForm& form) : n_(N), bits_(mpz_sizeinbase(N.get_mpz_t(), 2)) {
  if (form.n > 0) form_ = form;
  // Room for a square plus a word, so reductions never reallocate.
  mpz_realloc2(quotient_.get_mpz_t(), 2 * bits_ + 128);
  mpz_realloc2(scratch_.get_mpz_t(), 2 * bits_ + 128);
}

void Modulus::reduce(mpz_t x) const {
  if (!form_) {
    mpz_mod(x, x, n_.get_mpz_t());
    return;
  }
  reduce_special(x);
}

void Modulus::remainder(mpz_ptr out, mpz_srcptr in) const {
  if (!form_) {
    mpz_tdiv_r(out, in, n_.get_mpz_t());
    return;
  }
  mpz_set(out, in);
  reduce_special(out);
}

// With N = k*2^n + c, k*2^n = -c (mod N). Split x = q*2^n + r and
// q = q1*k + q0; then x = q1*(-c) + q0*2^n + r (mod N), about n bits
// shorter. Two or three rounds bring x below a few N.
void Modulus::reduce_special(mpz_t x) const {
  const SpecialForm& f = *form_;
  const bool negative = mpz_sgn(x) < 0;
  if (negative) mpz_neg(x, x);
  mpz_ptr q = quotient_.get_mpz_t();
  const std::size_t limit = f.n + 66;  // beyond this x is surely >= 2N
  while (mpz_sizeinbase(x, 2) > limit) {
    mpz_tdiv_q_2exp(q, x, f.n);
    mpz_tdiv_r_2exp(x, x, f.n);
    const unsigned long q0 = f.k == 1 ? 0 : mpz_tdiv_q_ui(q, q, f.k);
    if (q0 != 0) {
      mpz_ptr t = scratch_.get_mpz_t();
      mpz_set_ui(t, q0);
      mpz_mul_2exp(t, t, f.n);
      mpz_add(x, x, t);
    }
    if (f.c == -1) {
      mpz_add(x, x, q);
    } else if (f.c == 1) {
      mpz_sub(x, x, q);
    } else if (f.c < 0) {
      mpz_addmul_ui(x, q, static_cast<unsigned long>(-f.c));
    } else {
      mpz_submul_ui(x, q, static_cast<unsigned long>(f.c));
    }
    if (mpz_sgn(x) < 0) {
      mpz_mod(x, x, n_.get_mpz_t());  // rare: only when c > 0; x is now short
      break;
    }
  }
  // x is now below about 2^66 * N. Usually (c = -1 and x < 2N or so) a
  // subtraction or two finish; otherwise one short division.
  if (mpz_sizeinbase(x, 2) <= bits_ + 1) {
    while (mpz_cmp(x, n_.get_mpz_t()) >= 0) mpz_sub(x, x, n_.get_mpz_t());
  } else {
    mpz_tdiv_r(x, x, n_.get_mpz_t());
  }
  if (negative && mpz_sgn(x) != 0) mpz_sub(x, n_.get_mpz_t(), x);
}

}  // namespace tk::primes
