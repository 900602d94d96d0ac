/// @file test_transform_reduction.cpp
/// @brief The 18-bit digits (conversions, carries), TransformModulus'
/// Barrett reduction by transforms, and the base-2 and Lucas loops built on
/// it, all against GMP: mpz arithmetic, mpz_mod, mpz_powm, and a Lucas
/// sequence by GMP's U/V doubling formulas. N of several sizes around the
/// crossover, of the shapes 2^b - 1 and 2^(b-1) + 1 and random; inputs
/// random and worst (N - 1); both SIMD widths where the CPU has them.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "primes/transform_digits.hpp"
#include "primes/transform_reduction.hpp"
#include "primes/transform_tests.hpp"
#include "simd_widths.hpp"

namespace transform_reduction_test {

using namespace tk::primes;
namespace d18 = tk::primes::digits18;
using Simd = RightAngleSquarer::Simd;

using simd_test::widths_here;

mpz_class power_of_two(unsigned long bits) {
  mpz_class x;
  mpz_ui_pow_ui(x.get_mpz_t(), 2, bits);
  return x;
}

// Moduli of b bits: 2^b - 1, 2^(b-1) + 1 and a random odd one.
std::vector<mpz_class> moduli_of(unsigned long bits, gmp_randclass& random) {
  mpz_class r = random.get_z_bits(bits);
  mpz_setbit(r.get_mpz_t(), bits - 1);
  mpz_setbit(r.get_mpz_t(), 0);
  return {power_of_two(bits) - 1, power_of_two(bits - 1) + 1, r};
}

TEST(TransformDigits, RoundTripAndCarriesKeepTheValue) {
  gmp_randclass random(gmp_randinit_mt);
  random.seed(2301);
  for (unsigned long bits : {1ul, 17ul, 18ul, 19ul, 64ul, 1000ul, 9966ul}) {
    for (int sign : {1, -1}) {
      const mpz_class x = sign * mpz_class(random.get_z_bits(bits));
      const std::size_t count = bits / 18 + 2;
      std::vector<double> digits(count);
      ASSERT_TRUE(d18::from_mpz(x, digits.data(), count));
      for (double d : digits) EXPECT_LE(std::fabs(d), 131072.0);
      EXPECT_EQ(d18::to_mpz(digits.data(), count), x);
      const mpz_class check = (mpz_class(1) << 36) - 1;
      EXPECT_EQ(d18::residue(digits.data(), count), mpz_class(((x % check) + check) % check).get_si());
    }
    // Coefficients up to 2^50 carried: same value, digits within 2^17 + 1.
    std::mt19937_64 engine(bits);
    std::uniform_real_distribution<double> size(-1.0, 1.0);
    const std::size_t count = bits / 18 + 5;
    std::vector<double> y(count), out(count + 3), scratch(count + 3), wrapped(count);
    for (double& v : y) v = std::nearbyint(size(engine) * 1125899906842624.0);
    d18::carry_acyclic(y.data(), count, out.data(), scratch.data());
    EXPECT_EQ(d18::to_mpz(out.data(), count + 3), d18::to_mpz(y.data(), count));
    for (double d : out) EXPECT_LE(std::fabs(d), 131073.0);
    d18::carry_negacyclic(y.data(), count, wrapped.data(), scratch.data());
    const mpz_class modulus = power_of_two(18 * count) + 1;
    mpz_class expected = d18::to_mpz(y.data(), count) - d18::to_mpz(wrapped.data(), count);
    EXPECT_EQ(expected % modulus, 0);
    for (double d : wrapped) EXPECT_LE(std::fabs(d), 131073.0);
  }
}

// One product x * y (or x^2 * 2) reduced, against mpz_mod.
void expect_product(TransformModulus& m, const mpz_class& x, const mpz_class& y, double factor) {
  const std::size_t h = m.points();
  std::vector<double> xr(h), xi(h), yr(h), yi(h);
  const auto a = m.load(x), b = m.load(y);
  m.spectrum(a, xr.data(), xi.data());
  m.spectrum(b, yr.data(), yi.data());
  for (std::size_t j = 0; j < h; ++j) {
    m.product_real()[j] = xr[j] * yr[j] - xi[j] * yi[j];
    m.product_imaginary()[j] = xr[j] * yi[j] + xi[j] * yr[j];
  }
  TransformModulus::Residue r;
  ASSERT_TRUE(m.reduce(d18::residue_product(a.check, b.check), factor, r));
  const mpz_class N = m.modulus();
  const mpz_class expected = (x * y * static_cast<long>(factor)) % N;
  ASSERT_EQ(m.value(r), expected) << "bits " << mpz_sizeinbase(N.get_mpz_t(), 2);
  // |r| < 2.2 N: what the next step's sizes rely on.
  const mpz_class raw = d18::to_mpz(r.digits.data(), r.digits.size());
  EXPECT_LT(abs(raw), 22 * N / 10);
}

TEST(TransformModulus, ProductsReducedExactlyAtManySizes) {
  gmp_randclass random(gmp_randinit_mt);
  random.seed(2302);
  int tried = 0;
  for (auto simd : widths_here())
    for (unsigned long bits : {65ul, 500ul, 1999ul, 2000ul, 2001ul, 4096ul, 9966ul, 10368ul, 20000ul})
      for (const mpz_class& N : moduli_of(bits, random)) {
        auto m = TransformModulus::create(N, 2, simd);
        ASSERT_TRUE(m) << bits;
        ++tried;
        const int rounds = bits > 5000 ? 20 : 60;
        for (int i = 0; i < rounds; ++i) {
          const mpz_class x = random.get_z_range(N), y = random.get_z_range(N);
          expect_product(*m, x, y, i % 2 ? 2.0 : 1.0);
        }
        expect_product(*m, N - 1, N - 1, 1.0);  // the worst: (N - 1)^2
        expect_product(*m, N - 1, N - 1, 2.0);
        expect_product(*m, 0, N - 1, 1.0);
        EXPECT_EQ(m->failures(), 0u);
      }
  EXPECT_GE(tried, 27);
}

// Chains of squares from residues of |r| up to 2.2 N, as the loops run.
TEST(TransformModulus, SquaringChainsFollowPowm) {
  gmp_randclass random(gmp_randinit_mt);
  random.seed(2303);
  for (auto simd : widths_here())
    for (unsigned long bits : {2000ul, 9966ul})
      for (const mpz_class& N : moduli_of(bits, random)) {
        auto m = TransformModulus::create(N, 2, simd);
        ASSERT_TRUE(m);
        const mpz_class start = random.get_z_range(N);
        auto x = m->load(start);
        std::vector<double> re(m->points()), im(m->points());
        mpz_class expected = start;
        for (int step = 0; step < 200; ++step) {
          m->spectrum(x, re.data(), im.data());
          for (std::size_t j = 0; j < m->points(); ++j) {
            m->product_real()[j] = re[j] * re[j] - im[j] * im[j];
            m->product_imaginary()[j] = 2 * re[j] * im[j];
          }
          ASSERT_TRUE(m->reduce(d18::residue_product(x.check, x.check), 1.0, x));
          expected = expected * expected % N;
        }
        EXPECT_EQ(m->value(x), expected);
      }
}

// A wrong spectrum (one point off) must fail a check, never pass as a result.
TEST(TransformModulus, CorruptedProductFailsItsChecks) {
  gmp_randclass random(gmp_randinit_mt);
  random.seed(2304);
  const mpz_class N = moduli_of(9966, random)[2];
  auto m = TransformModulus::create(N, 2);
  if (!m) GTEST_SKIP() << "no transform on this CPU";
  std::vector<double> re(m->points()), im(m->points());
  int failed = 0;
  for (std::size_t spot : {0ul, 1ul, 7ul, 100ul, 333ul}) {
    const auto x = m->load(random.get_z_range(N));
    m->spectrum(x, re.data(), im.data());
    for (std::size_t j = 0; j < m->points(); ++j) {
      m->product_real()[j] = re[j] * re[j] - im[j] * im[j];
      m->product_imaginary()[j] = 2 * re[j] * im[j];
    }
    m->product_real()[spot % m->points()] += 1000.0 * static_cast<double>(m->points());
    TransformModulus::Residue r;
    failed += !m->reduce(d18::residue_product(x.check, x.check), 1.0, r);
  }
  EXPECT_EQ(failed, 5);
  EXPECT_EQ(m->failures(), 5u);
}

TEST(TransformLoops, PowerOfTwoIsPowm) {
  gmp_randclass random(gmp_randinit_mt);
  random.seed(2305);
  for (unsigned long bits : {kTransformPowerFromBits - 1, kTransformPowerFromBits, kTransformPowerFromBits + 1, 9966ul})
    for (const mpz_class& N : moduli_of(bits, random)) {
      const mpz_class e = random.get_z_bits(bits > 5000 ? 600 : 3000) + 1;
      EXPECT_EQ(transform_power_pays(N), bits >= kTransformPowerFromBits);
      const auto power = transform_power_of_two(N, e);
      ASSERT_TRUE(power) << bits;
      mpz_class expected;
      mpz_powm(expected.get_mpz_t(), mpz_class(2).get_mpz_t(), e.get_mpz_t(), N.get_mpz_t());
      EXPECT_EQ(*power, expected) << bits;
    }
}

// U_k, U_(k+1) by GMP's doubling formulas: U_2j = U_j V_j, V_2j = V_j^2 -
// 2 Q^j, and U_(j+1), V_(j+1) from (P U + V)/2, (D U + P V)/2 with P = 1.
std::pair<mpz_class, mpz_class> lucas_by_gmp(const mpz_class& N, long q, const mpz_class& k) {
  const long d = 1 - 4 * q;
  const mpz_class half = (N + 1) / 2;  // 1/2 mod N
  mpz_class u = 1, v = 1, qk = q;      // j = 1
  for (mp_bitcnt_t bit = mpz_sizeinbase(k.get_mpz_t(), 2) - 1; bit-- > 0;) {
    u = u * v % N;
    v = (v * v - 2 * qk) % N;
    qk = qk * qk % N;
    if (mpz_tstbit(k.get_mpz_t(), bit)) {
      const mpz_class u1 = (u + v) * half % N, v1 = (d * u + v) * half % N;
      u = u1;
      v = v1;
      qk = qk * q % N;
    }
  }
  const mpz_class u_next = (u + v) * half % N;
  auto positive = [&](mpz_class x) { return mpz_class(((x % N) + N) % N); };
  return {positive(u), positive(u_next)};
}

TEST(TransformLoops, LucasChainIsGmps) {
  gmp_randclass random(gmp_randinit_mt);
  random.seed(2306);
  int steps = 0, chains = 0;
  const LucasStep never = [&](mpz_class&, mpz_class&, bool) { ++steps; };
  for (unsigned long bits : {kTransformLucasFromBits - 1, kTransformLucasFromBits, 4000ul, 9966ul})
    for (const mpz_class& N : moduli_of(bits, random))
      for (long q : {-1L, 2L, -2L, 3L, -7L, 101L}) {
        const mpz_class k = random.get_z_bits(bits > 5000 ? 300 : 1200) + 1;
        const auto got = transform_lucas_u(N, q, k, never);
        if (!got) {  // only where the coefficients' bound is past 2^50 (a large |q|)
          EXPECT_EQ(TransformModulus::create(N, static_cast<std::uint64_t>(1 + 4 * std::labs(q))), nullptr);
          continue;
        }
        ++chains;
        const auto expected = lucas_by_gmp(N, q, k);
        EXPECT_EQ(got->first, expected.first) << bits << " q " << q;
        EXPECT_EQ(got->second, expected.second) << bits << " q " << q;
      }
  EXPECT_GE(chains, 4 * 3 * 5);
  EXPECT_EQ(steps, 0);  // no check failed
}

}  // namespace transform_reduction_test
