/// @file big_tests.cpp
#include "primes/big_tests.hpp"

#include "primes/transform_tests.hpp"
#include "primes/weighted_tests.hpp"

namespace tk::primes {

namespace {

/// base^exponent mod N. With a special form: left-to-right binary powering,
/// where a base that fits a word multiplies in with one short product per
/// set bit, so a Fermat or Miller-Rabin test costs one squaring and one
/// cheap reduction per bit.
bool cancelled(const std::atomic<bool>* cancel) { return cancel && cancel->load(std::memory_order_relaxed); }

void power_mod(mpz_class& result, const mpz_class& base, const mpz_class& exponent, const Modulus& N,
               const std::atomic<bool>* cancel = nullptr) {
  if (!N.form()) {
    // No special form: base 2 on our transforms from kTransformPowerFromBits
    // on; else GMP's own Montgomery powering, which beats squaring plus
    // GMP's division (measured 345 vs 390 ms at 10,000 bits).
    if (base == 2 && mpz_sgn(exponent.get_mpz_t()) > 0 && transform_power_pays(N.value()))
      if (auto power = transform_power_of_two(N.value(), exponent, cancel)) {
        result = *power;
        return;
      }
    if (cancelled(cancel)) return;
    mpz_powm(result.get_mpz_t(), base.get_mpz_t(), exponent.get_mpz_t(), N.value().get_mpz_t());
    return;
  }
  mpz_ptr x = result.get_mpz_t();
  const mpz_srcptr e = exponent.get_mpz_t();
  mpz_class b = base;
  N.reduce(b.get_mpz_t());
  if (mpz_sgn(e) == 0) {
    result = 1;
    return;
  }
  const bool small = mpz_fits_ulong_p(b.get_mpz_t());
  const unsigned long word = small ? mpz_get_ui(b.get_mpz_t()) : 0;
  const bool two = small && word == 2;
  mpz_set(x, b.get_mpz_t());
  mpz_realloc2(x, 2 * N.bits() + 128);
  for (mp_bitcnt_t bit = mpz_sizeinbase(e, 2) - 1; bit-- > 0;) {
    if (cancelled(cancel)) return;
    mpz_mul(x, x, x);
    if (mpz_tstbit(e, bit)) {
      if (two) {
        mpz_mul_2exp(x, x, 1);
      } else if (small) {
        mpz_mul_ui(x, x, word);
      } else {
        N.reduce(x);
        mpz_mul(x, x, b.get_mpz_t());
      }
    }
    N.reduce(x);
  }
}

}  // namespace

LucasDoubler::LucasDoubler(const Modulus& N, long q) : n_(N), q_(q) {
  const std::size_t room = 2 * N.bits() + 128;
  for (mpz_class* z : {&high_, &low_, &square_, &diff_}) mpz_realloc2(z->get_mpz_t(), room);
}

// Residues stay in (-N, N): squares do not care about the sign.
void LucasDoubler::operator()(mpz_class& u, mpz_class& u_next, bool odd) {
  mpz_mul(high_.get_mpz_t(), u_next.get_mpz_t(), u_next.get_mpz_t());  // U_k+1^2
  mpz_sub(diff_.get_mpz_t(), u_next.get_mpz_t(), u.get_mpz_t());
  mpz_mul(low_.get_mpz_t(), diff_.get_mpz_t(), diff_.get_mpz_t());  // (U_k+1 - U_k)^2
  mpz_mul(square_.get_mpz_t(), u.get_mpz_t(), u.get_mpz_t());       // U_k^2
  mpz_sub(low_.get_mpz_t(), high_.get_mpz_t(), low_.get_mpz_t());   // U_2k
  if (q_ >= 0) mpz_submul_ui(high_.get_mpz_t(), square_.get_mpz_t(), static_cast<unsigned long>(q_));
  else mpz_addmul_ui(high_.get_mpz_t(), square_.get_mpz_t(), static_cast<unsigned long>(-q_));  // U_2k+1
  if (odd) {
    // k -> 2k+1: (U_2k+1, U_2k+2 = U_2k+1 - Q U_2k)
    mpz_mul_si(square_.get_mpz_t(), low_.get_mpz_t(), q_);
    mpz_sub(low_.get_mpz_t(), high_.get_mpz_t(), square_.get_mpz_t());
    n_.remainder(u.get_mpz_t(), high_.get_mpz_t());
    n_.remainder(u_next.get_mpz_t(), low_.get_mpz_t());
  } else {
    n_.remainder(u.get_mpz_t(), low_.get_mpz_t());
    n_.remainder(u_next.get_mpz_t(), high_.get_mpz_t());
  }
}

bool fermat_probable_prime(const Modulus& N, const mpz_class& base) {
  mpz_class b = base % N.value();
  if (b == 0) return true;
  if (const auto verdict = weighted_fermat_probable_prime(N, b)) return *verdict;
  mpz_class r;
  power_mod(r, b, N.value() - 1, N);
  return r == 1;
}

bool strong_probable_prime(const Modulus& N, const mpz_class& base, const std::atomic<bool>* cancel) {
  const mpz_class n_minus_1 = N.value() - 1;
  mpz_class b = base % N.value();
  if (b == 0) return true;
  if (const auto verdict = weighted_strong_probable_prime(N, b, cancel)) return *verdict;
  const mp_bitcnt_t s = mpz_scan1(n_minus_1.get_mpz_t(), 0);
  mpz_class d;
  mpz_tdiv_q_2exp(d.get_mpz_t(), n_minus_1.get_mpz_t(), s);
  mpz_class x;
  power_mod(x, b, d, N, cancel);
  if (x == 1 || x == n_minus_1) return true;
  for (mp_bitcnt_t r = 1; r < s; ++r) {
    mpz_mul(x.get_mpz_t(), x.get_mpz_t(), x.get_mpz_t());
    N.reduce(x.get_mpz_t());
    if (x == n_minus_1) return true;
    if (x == 1) return false;
  }
  return false;
}

SelfridgeChoice selfridge_d(const mpz_class& N) {
  SelfridgeChoice choice;
  for (std::int64_t d = 5;; d = d > 0 ? -(d + 2) : -d + 2) {
    const int j = mpz_si_kronecker(static_cast<long>(d), N.get_mpz_t());
    if (j == -1) {
      choice.d = d;
      return choice;
    }
    if (j == 0) {
      mpz_class g;
      mpz_gcd_ui(g.get_mpz_t(), N.get_mpz_t(), static_cast<unsigned long>(d < 0 ? -d : d));
      if (g != N) {
        choice.d = d;
        choice.factor = g;
        return choice;
      }
    }
    if (d == -15 && mpz_perfect_square_p(N.get_mpz_t())) return choice;
  }
}

// The first stage follows U_k and U_k+1 with only squarings (P = 1, after
// Hackman's scalar formulas):
//   U_2k   = U_k+1^2 - (U_k+1 - U_k)^2
//   U_2k+1 = U_k+1^2 - Q U_k^2
//   U_2k+2 = U_2k+1 - Q U_2k
// three squarings and two reductions per bit; then V_d = 2 U_d+1 - U_d.
// The steps V_{2^r d} use W_r = V_{2^r d} / Q^(2^(r-1) d), which obeys
// W_{r+1} = W_r^2 - 2 (one squaring per step, as in LLR), with
// Q^d = (V_d^2 - D U_d^2) / 4.
bool strong_lucas_probable_prime(const Modulus& N, std::int64_t d_param, mpz_class& factor,
                                 const std::atomic<bool>* cancel, bool* zero_at_last) {
  if (zero_at_last) *zero_at_last = false;
  const mpz_class& n = N.value();
  const mpz_class n_plus_1 = n + 1;
  const mp_bitcnt_t s = mpz_scan1(n_plus_1.get_mpz_t(), 0);
  mpz_class k;
  mpz_tdiv_q_2exp(k.get_mpz_t(), n_plus_1.get_mpz_t(), s);

  const std::size_t room = 2 * N.bits() + 128;
  const long q = static_cast<long>((1 - d_param) / 4);
  LucasDoubler doubler(N, q);
  mpz_class u = 1, u_next = 1;  // U_1 = U_2 = 1 for P = 1
  for (mpz_class* z : {&u, &u_next}) mpz_realloc2(z->get_mpz_t(), room);
  const auto on_transform =
      N.form() || !transform_lucas_pays(n)
          ? std::nullopt
          : transform_lucas_u(
                n, q, k, [&](mpz_class& a, mpz_class& b, bool odd) { doubler(a, b, odd); }, cancel);
  if (on_transform) {
    u = on_transform->first;
    u_next = on_transform->second;
  } else {
    for (mp_bitcnt_t bit = mpz_sizeinbase(k.get_mpz_t(), 2) - 1; bit-- > 0;) {
      if (cancelled(cancel)) return false;
      doubler(u, u_next, mpz_tstbit(k.get_mpz_t(), bit) != 0);
    }
  }
  if (cancelled(cancel)) return false;
  N.reduce(u.get_mpz_t());
  // V_d = 2 U_d+1 - P U_d.
  mpz_class v = 2 * u_next - u;
  N.reduce(v.get_mpz_t());
  const long dl = static_cast<long>(d_param);
  mpz_class uu, vv;
  auto halve = [&](mpz_class& x) {  // x/2 mod N for 0 <= x < N
    if (mpz_odd_p(x.get_mpz_t())) x += n;
    mpz_tdiv_q_2exp(x.get_mpz_t(), x.get_mpz_t(), 1);
  };
  if (u == 0 || v == 0) return true;
  if (s < 2) return false;

  // Q^k = (V^2 - D U^2) / 4, then W_1 = V_k^2 / Q^k - 2.
  mpz_mul(uu.get_mpz_t(), u.get_mpz_t(), u.get_mpz_t());
  mpz_mul(vv.get_mpz_t(), v.get_mpz_t(), v.get_mpz_t());
  mpz_class qk = vv;
  if (dl > 0) mpz_submul_ui(qk.get_mpz_t(), uu.get_mpz_t(), static_cast<unsigned long>(dl));
  else mpz_addmul_ui(qk.get_mpz_t(), uu.get_mpz_t(), static_cast<unsigned long>(-dl));
  N.reduce(qk.get_mpz_t());
  halve(qk);
  halve(qk);
  mpz_class inverse;
  if (!mpz_invert(inverse.get_mpz_t(), qk.get_mpz_t(), n.get_mpz_t())) {
    mpz_gcd(factor.get_mpz_t(), qk.get_mpz_t(), n.get_mpz_t());
    if (factor == n) factor = 0;
    return false;
  }
  N.reduce(vv.get_mpz_t());
  mpz_class w;
  mpz_realloc2(w.get_mpz_t(), room);
  mpz_mul(w.get_mpz_t(), vv.get_mpz_t(), inverse.get_mpz_t());
  w -= 2;
  N.reduce(w.get_mpz_t());
  // W_r = 0 for some r in 1..s-1 passes the test; r = s-1 is the last step.
  // On the weighted transform for a long chain, each W watched for 0.
  if (s > 2) {
    if (const auto tail = weighted_lucas_tail(N, w, s - 1, cancel)) {
      if (cancelled(cancel) || tail->zero_at == 0) return false;
      if (zero_at_last) *zero_at_last = tail->zero_at == s - 1;
      return true;
    }
  }
  for (mp_bitcnt_t r = 1;; ++r) {
    if (w == 0) {
      if (zero_at_last) *zero_at_last = r == s - 1;
      return true;
    }
    if (r + 1 >= s) return false;
    if (cancelled(cancel)) return false;
    mpz_mul(w.get_mpz_t(), w.get_mpz_t(), w.get_mpz_t());
    mpz_sub_ui(w.get_mpz_t(), w.get_mpz_t(), 2);
    N.reduce(w.get_mpz_t());
  }
}

}  // namespace tk::primes
