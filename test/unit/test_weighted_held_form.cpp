/// @file test_weighted_held_form.cpp
/// @brief WeightedSquaring holds t = x/k mod N (the reduction multiplies by
/// k instead of dividing): load and store convert exactly, held_form is
/// GMP's x * k^-1 mod N, the residue carried mod 2^61 - 1 is that of the
/// held value, and chains of x^2 - 2 and x^2 match GMP's at the ends of
/// the range of k (1 and 56 bits), for both signs, on every transform.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <vector>

#include "primes/weighted_squaring.hpp"
#include "squaring_chain.hpp"

namespace {

using namespace tk::primes;
using squaring_test::expect_chain_matches;
using squaring_test::name_of;
using squaring_test::value_of;

constexpr std::uint64_t kP61 = (std::uint64_t{1} << 61) - 1;

const std::uint64_t kLimitKs[] = {1, 3, 16869987339975ull, (1ull << 55) + 1, (1ull << 56) - 1};

// x / k mod N by GMP's inverse, independent of the -c*2^n the squarer uses.
mpz_class divided_by_k(const mpz_class& x, const SpecialForm& form) {
  const mpz_class N = value_of(form), k = static_cast<unsigned long>(form.k);
  mpz_class inverse;
  mpz_invert(inverse.get_mpz_t(), k.get_mpz_t(), N.get_mpz_t());
  mpz_class t = x * inverse;
  mpz_mod(t.get_mpz_t(), t.get_mpz_t(), N.get_mpz_t());
  return t;
}

// Whether the carried residue is that of held_form(x) + j*N for |j| <= 2.
bool residue_is_of(const WeightedSquaring& squarer, const mpz_class& x, const SpecialForm& form) {
  const mpz_class held = divided_by_k(x, form), N = value_of(form);
  for (long j = -2; j <= 2; ++j) {
    const mpz_class shifted = held + j * N;
    if (mpz_fdiv_ui(shifted.get_mpz_t(), kP61) == squarer.held_mod_p61()) return true;
  }
  return false;
}

TEST(WeightedHeldForm, LoadStoreRoundTripAndHeldFormIsXOverK) {
  gmp_randclass random(gmp_randinit_default);
  random.seed(2311);
  for (std::uint64_t k : kLimitKs)
    for (std::uint64_t n : {64ull, 1001ull, 36627ull})
      for (std::int64_t c : {-1, 1}) {
        const SpecialForm form{k, n, c};
        const mpz_class N = value_of(form);
        auto squarer = WeightedSquaring::create(form);
        ASSERT_NE(squarer, nullptr) << name_of(form);
        for (const mpz_class& x : {mpz_class(0), mpz_class(1), mpz_class(2), mpz_class(N - 1), mpz_class(N),
                                   mpz_class(N + 5), mpz_class(3 * N - 1), mpz_class(random.get_z_range(N))}) {
          EXPECT_EQ(squarer->held_form(x), divided_by_k(x, form)) << name_of(form);
          squarer->load(x);
          mpz_class back;
          squarer->store(back);
          EXPECT_EQ(back, mpz_class(x % N)) << name_of(form) << " x " << x;
          EXPECT_TRUE(squarer->holds_carried_residue()) << name_of(form);
          EXPECT_EQ(squarer->held_mod_p61(), mpz_fdiv_ui(divided_by_k(x, form).get_mpz_t(), kP61)) << name_of(form);
        }
      }
}

// After every square: GMP's value, the digits give the residue carried,
// and that residue is the held form's (what riesel's Watch relies on).
TEST(WeightedHeldForm, ChainsAtTheEndsOfKAgainstGmpWithTheResidueFollowingT) {
  gmp_randclass random(gmp_randinit_default);
  random.seed(2312);
  for (std::uint64_t k : kLimitKs)
    for (std::uint64_t n : {64ull, 127ull, 4503ull, 20000ull})
      for (std::int64_t c : {-1, 1})
        for (unsigned long minus : {0ul, 2ul}) {
          const SpecialForm form{k, n, c};
          const mpz_class N = value_of(form);
          auto squarer = WeightedSquaring::create(form);
          ASSERT_NE(squarer, nullptr) << name_of(form);
          mpz_class x = random.get_z_range(N);
          squarer->load(x);
          for (int round = 0; round < 8; ++round) {
            squarer->square_minus(minus);
            x = x * x - minus;
            mpz_mod(x.get_mpz_t(), x.get_mpz_t(), N.get_mpz_t());
            mpz_class got;
            squarer->store(got);
            ASSERT_EQ(got, x) << name_of(form) << " minus " << minus << " round " << round;
            ASSERT_TRUE(squarer->holds_carried_residue()) << name_of(form) << " round " << round;
            ASSERT_TRUE(residue_is_of(*squarer, x, form)) << name_of(form) << " round " << round;
          }
          EXPECT_EQ(squarer->fallbacks(), 0u) << name_of(form) << " minus " << minus;
        }
}

// The scalar and AVX2 passes (AVX2 width, FFTW's transform) as well as the
// AVX-512 ones, with k at 56 bits: a digit times k's halves near 2^62.
TEST(WeightedHeldForm, EveryTransformWithKAtFiftySixBits) {
  gmp_randclass random(gmp_randinit_default);
  random.seed(2313);
  using Transform = WeightedSquaring::Transform;
  for (Transform transform : {Transform::widest, Transform::avx2, Transform::fftw})
    for (std::uint64_t k : {(1ull << 56) - 1, 1ull})
      for (std::int64_t c : {-1, 1}) {
        const SpecialForm form{k, 30011, c};
        auto squarer = WeightedSquaring::create_with(form, 4096, 20, transform);
        ASSERT_NE(squarer, nullptr) << name_of(form);
        expect_chain_matches(*squarer, form, random.get_z_range(value_of(form)), c < 0 ? 2 : 0, 8);
        expect_chain_matches(*squarer, form, value_of(form) - 1, 0, 3);
        EXPECT_EQ(squarer->fallbacks(), 0u) << name_of(form) << " by " << squarer->transform_name();
      }
}

}  // namespace
