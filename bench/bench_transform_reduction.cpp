/// @file bench_transform_reduction.cpp
/// @brief Where the transform loops of a generic N (transform_tests.hpp)
/// pay: per-operation times at 9,966 bits (GMP's mpn_sqr and mpn_tdiv_qr
/// against our spectrum and checked Barrett reduction), then, size by
/// size, the base-2 powering against mpz_powm and the Lucas U chain
/// against GMP's three squarings and two divisions per bit (LucasDoubler,
/// the loop big_tests.cpp runs otherwise). Prints CPU microseconds per bit; the
/// crossovers kTransformPowerFromBits and kTransformLucasFromBits
/// (transform_tests.hpp) are read off the table.
#include <gmpxx.h>

#include <cstdio>
#include <vector>

#include "bench_common.hpp"
#include "primes/big_tests.hpp"
#include "primes/transform_digits.hpp"
#include "primes/transform_reduction.hpp"
#include "primes/transform_tests.hpp"

namespace {

using namespace tk::primes;

mpz_class random_odd(unsigned long bits, gmp_randclass& random) {
  mpz_class n = random.get_z_bits(bits);
  mpz_setbit(n.get_mpz_t(), bits - 1);
  mpz_setbit(n.get_mpz_t(), 0);
  return n;
}

// Microseconds per call of work(), the median of `runs` timings of `calls` calls.
template <class F>
double microseconds(int runs, int calls, F&& work) {
  std::vector<double> times;
  for (int r = 0; r < runs; ++r)
    times.push_back(bench::time_cpu([&] {
                      for (int c = 0; c < calls; ++c) work();
                    }) *
                    1e6 / calls);
  return bench::median(times);
}

void per_operation(gmp_randclass& random) {
  const mpz_class N = random_odd(9966, random);
  const mp_size_t limbs = static_cast<mp_size_t>(mpz_size(N.get_mpz_t()));
  const mpz_class x = random.get_z_range(N);
  std::vector<mp_limb_t> a(static_cast<std::size_t>(limbs), 0), square(2 * static_cast<std::size_t>(limbs)),
      quotient(static_cast<std::size_t>(limbs) + 1), remainder(static_cast<std::size_t>(limbs));
  mpz_export(a.data(), nullptr, -1, sizeof(mp_limb_t), 0, 0, x.get_mpz_t());
  const mp_limb_t* n = mpz_limbs_read(N.get_mpz_t());
  const double sqr = microseconds(7, 2000, [&] { mpn_sqr(square.data(), a.data(), limbs); });
  const double divide = microseconds(
      7, 2000, [&] { mpn_tdiv_qr(quotient.data(), remainder.data(), 0, square.data(), 2 * limbs, n, limbs); });
  auto m = TransformModulus::create(N, 5);
  if (!m) bench::fail("no transform for 9,966 bits on this CPU");
  auto residue = m->load(x), out = residue;
  std::vector<double> re(m->points()), im(m->points());
  const double spectrum = microseconds(7, 2000, [&] { m->spectrum(residue, re.data(), im.data()); });
  const double reduce = microseconds(7, 2000, [&] {
    for (std::size_t j = 0; j < m->points(); ++j) {
      m->product_real()[j] = re[j] * re[j] - im[j] * im[j];
      m->product_imaginary()[j] = 2 * re[j] * im[j];
    }
    if (!m->reduce(digits18::residue_product(residue.check, residue.check), 1.0, out)) bench::fail("a check failed");
  });
  std::printf(
      "9966 bits, us per call (medians of 7): mpn_sqr %.2f  mpn_tdiv_qr %.2f | ours: spectrum %.2f  "
      "square in the spectrum + checked Barrett reduction %.2f\n",
      sqr, divide, spectrum, reduce);
}

void crossover(gmp_randclass& random) {
  std::printf("bits   base 2: powm  ours  ratio | Lucas: GMP  ours  ratio   (us per bit, medians of 5)\n");
  for (unsigned long bits : {1000ul, 2000ul, 2500ul, 3000ul, 3500ul, 4000ul, 5000ul, 10000ul, 30000ul, 100000ul}) {
    const mpz_class N = random_odd(bits, random);
    const unsigned long exponent_bits = bits > 20000 ? 2000 : 4000;
    mpz_class e = random.get_z_bits(exponent_bits) | 1;
    mpz_setbit(e.get_mpz_t(), exponent_bits - 1);
    mpz_class power;
    const double powm =
        microseconds(5, 1,
                     [&] { mpz_powm(power.get_mpz_t(), mpz_class(2).get_mpz_t(), e.get_mpz_t(), N.get_mpz_t()); }) /
        exponent_bits;
    const double ours = microseconds(5, 1,
                                     [&] {
                                       if (transform_power_of_two(N, e) != power)
                                         bench::fail("2^e differs from mpz_powm's");
                                     }) /
                        exponent_bits;
    const long q = -1;
    const Modulus modulus(N);
    LucasDoubler doubler(modulus, q);
    mpz_class gu, gn;
    const double gmp = microseconds(5, 1,
                                    [&] {
                                      gu = 1, gn = 1;
                                      for (mp_bitcnt_t bit = exponent_bits - 1; bit-- > 0;)
                                        doubler(gu, gn, mpz_tstbit(e.get_mpz_t(), bit) != 0);
                                    }) /
                       exponent_bits;
    gu = (gu % N + N) % N;
    const LucasStep step = [&](mpz_class& u, mpz_class& u_next, bool odd) { doubler(u, u_next, odd); };
    const double lucas = microseconds(5, 1,
                                      [&] {
                                        const auto got = transform_lucas_u(N, q, e, step);
                                        if (!got || got->first != gu) bench::fail("U_k differs from GMP's");
                                      }) /
                         exponent_bits;
    std::printf("%6lu  %8.2f %6.2f %6.2f | %8.2f %6.2f %6.2f\n", bits, powm, ours, powm / ours, gmp, lucas,
                gmp / lucas);
    std::fflush(stdout);
  }
}

}  // namespace

int main() {
  gmp_randclass random(gmp_randinit_mt);
  random.seed(23);
  per_operation(random);
  crossover(random);
}
