/// @file transform_tests.cpp
/// @brief The base-2 powering and the Lucas U chain on TransformModulus:
/// per bit, the spectra of the residues, their squares and sums of
/// squares point by point, and one checked reduction per value kept.
#include "primes/transform_tests.hpp"

#include <vector>

#include "primes/transform_digits.hpp"
#include "primes/transform_reduction.hpp"

namespace tk::primes {

namespace {

bool stopped(const std::atomic<bool>* cancel) { return cancel && cancel->load(std::memory_order_relaxed); }

// The spectrum of one residue, split like the transform's arrays.
struct Spectrum {
  std::vector<double> re, im;
  explicit Spectrum(std::size_t points) : re(points), im(points) {}
};

std::int64_t mod_check(std::int64_t x) { return digits18::residue_product(x, 1); }

}  // namespace

std::optional<mpz_class> transform_power_of_two(const mpz_class& N, const mpz_class& exponent,
                                                const std::atomic<bool>* cancel) {
  if (exponent < 1) return std::nullopt;
  auto modulus = TransformModulus::create(N, 2);  // x^2 * 2
  if (!modulus) return std::nullopt;
  TransformModulus& m = *modulus;
  const std::size_t h = m.points();
  Spectrum x_spectrum(h);
  TransformModulus::Residue x = m.load(2), next;
  const mpz_srcptr e = exponent.get_mpz_t();
  for (mp_bitcnt_t bit = mpz_sizeinbase(e, 2) - 1; bit-- > 0;) {
    if (stopped(cancel)) return std::nullopt;
    const bool one = mpz_tstbit(e, bit) != 0;
    m.spectrum(x, x_spectrum.re.data(), x_spectrum.im.data());
    double *re = m.product_real(), *im = m.product_imaginary();
    const double *xr = x_spectrum.re.data(), *xi = x_spectrum.im.data();
    for (std::size_t j = 0; j < h; ++j) {
      re[j] = xr[j] * xr[j] - xi[j] * xi[j];
      im[j] = 2.0 * xr[j] * xi[j];
    }
    if (m.reduce(digits18::residue_product(x.check, x.check), one ? 2.0 : 1.0, next)) {
      std::swap(x, next);
    } else {  // GMP does this step
      mpz_class value = m.value(x);
      value *= value;
      if (one) value <<= 1;
      x = m.load(value % N);
    }
  }
  return m.value(x);
}

// With P = 1 (Hackman): U_2j = U_j (2 U_(j+1) - U_j), U_(2j+1) = U_(j+1)^2
// - Q U_j^2, U_(2j+2) = U_(2j+1) - Q U_2j, all sums of products, taken
// point by point in the spectrum; |U_2j+2| <= (1 + 4|Q|) times the largest
// product of two residues.
std::optional<std::pair<mpz_class, mpz_class>> transform_lucas_u(const mpz_class& N, long q, const mpz_class& k,
                                                                 const LucasStep& gmp_step,
                                                                 const std::atomic<bool>* cancel) {
  if (k < 1 || q > (1L << 20) || q < -(1L << 20)) return std::nullopt;
  const std::uint64_t spread = std::max<std::uint64_t>(3, 1 + 4 * static_cast<std::uint64_t>(q < 0 ? -q : q));
  auto modulus = TransformModulus::create(N, spread);
  if (!modulus) return std::nullopt;
  TransformModulus& m = *modulus;
  const std::size_t h = m.points();
  Spectrum us(h), ns(h);
  TransformModulus::Residue u = m.load(1), u_next = m.load(1), u_out, next_out;
  const double qd = static_cast<double>(q);
  const mpz_srcptr kk = k.get_mpz_t();
  for (mp_bitcnt_t bit = mpz_sizeinbase(kk, 2) - 1; bit-- > 0;) {
    if (stopped(cancel)) return std::nullopt;
    const bool odd = mpz_tstbit(kk, bit) != 0;
    m.spectrum(u, us.re.data(), us.im.data());
    m.spectrum(u_next, ns.re.data(), ns.im.data());
    const std::int64_t cu = u.check, cn = u_next.check;
    const std::int64_t c_even = digits18::residue_product(cu, 2 * cn - cu);
    const std::int64_t c_odd =
        mod_check(digits18::residue_product(cn, cn) - digits18::residue_product(q, digits18::residue_product(cu, cu)));
    const std::int64_t c_next = mod_check(c_odd - digits18::residue_product(q, c_even));
    // which: 0 = U_2j, 1 = U_2j+1, 2 = U_2j+2; each loop computes only
    // the products its value needs (the even one for 0 and 2, the odd for 1 and 2).
    auto combine = [&]<int which>() {
      double *re = m.product_real(), *im = m.product_imaginary();
      const double *ar = us.re.data(), *ai = us.im.data(), *br = ns.re.data(), *bi = ns.im.data();
      for (std::size_t j = 0; j < h; ++j) {
        double even_r = 0, even_i = 0, odd_r = 0, odd_i = 0;
        if constexpr (which != 1) {
          const double er = 2.0 * br[j] - ar[j], ei = 2.0 * bi[j] - ai[j];  // 2 U_(j+1) - U_j
          even_r = ar[j] * er - ai[j] * ei, even_i = ar[j] * ei + ai[j] * er;
        }
        if constexpr (which != 0) {
          odd_r = (br[j] * br[j] - bi[j] * bi[j]) - qd * (ar[j] * ar[j] - ai[j] * ai[j]);
          odd_i = 2.0 * (br[j] * bi[j] - qd * ar[j] * ai[j]);
        }
        re[j] = which == 0 ? even_r : which == 1 ? odd_r : odd_r - qd * even_r;
        im[j] = which == 0 ? even_i : which == 1 ? odd_i : odd_i - qd * even_i;
      }
    };
    if (odd) combine.template operator()<1>();
    else combine.template operator()<0>();
    bool ok = m.reduce(odd ? c_odd : c_even, 1.0, u_out);
    if (ok) {
      if (odd) combine.template operator()<2>();
      else combine.template operator()<1>();
      ok = m.reduce(odd ? c_next : c_odd, 1.0, next_out);
    }
    if (ok) {
      std::swap(u, u_out);
      std::swap(u_next, next_out);
    } else {  // GMP does this step
      mpz_class a = m.value(u), b = m.value(u_next);
      gmp_step(a, b, odd);
      u = m.load(a);
      u_next = m.load(b);
    }
  }
  return std::make_pair(m.value(u), m.value(u_next));
}

}  // namespace tk::primes
