/// @file test_sieve.cpp
/// @brief Unit tests of the generalized sieve: survivors against trial
/// division and against direct modular arithmetic, roots against their
/// definition, thread and shard invariance, checkpoints, output and merge,
/// option values.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "cli/number_option.hpp"
#include "io/error.hpp"
#include "primes/generalized_sieve.hpp"
#include "primes/prime_range.hpp"
#include "primes/sieve_checkpoint.hpp"
#include "primes/sieve_output.hpp"
#include "primes/sieve_roots.hpp"

namespace {

using namespace tk::primes;
__extension__ typedef unsigned __int128 u128;

SieveSpec plain(SieveForm form, std::uint64_t n, std::uint64_t k_min, std::uint64_t k_max, std::uint64_t p_max,
                unsigned length = 1) {
  SieveSpec spec;
  spec.form = form;
  spec.n = n;
  spec.x_min = k_min;
  spec.x_max = k_max;
  spec.p_max = p_max;
  spec.length = length;
  return spec;
}

std::vector<std::uint64_t> survivors_of(GeneralizedSieve& sieve, const SieveControl& control = {}) {
  SieveControl run = control;
  if (run.threads == 0) run.threads = 1;
  sieve.sieve_large_primes(run);
  std::vector<std::uint64_t> ks;
  sieve.for_each_survivor([&](std::uint64_t offset) { ks.push_back(sieve.spec().k_at(sieve.spec().x_min + offset)); });
  return ks;
}

/// True when N has a prime factor p <= bound with p < N (trial division).
bool has_small_proper_factor(std::uint64_t value, std::uint64_t bound) {
  for (std::uint64_t d = 3; d <= bound && d * d <= value; d += 2)
    if (value % d == 0) return true;
  return false;
}

std::uint64_t pow_mod(std::uint64_t base, std::uint64_t exponent, std::uint64_t modulus) {
  std::uint64_t result = 1 % modulus;
  base %= modulus;
  for (; exponent; exponent >>= 1, base = static_cast<std::uint64_t>(static_cast<u128>(base) * base % modulus))
    if (exponent & 1) result = static_cast<std::uint64_t>(static_cast<u128>(result) * base % modulus);
  return result;
}

std::vector<std::uint64_t> brute_force(const SieveSpec& spec) {
  std::vector<std::uint64_t> ks;
  for (std::uint64_t x = spec.x_min; x <= spec.x_max; ++x) {
    const std::uint64_t k = spec.k_at(x);
    bool removed = false;
    for (const SieveMember& m : spec.members()) {
      const std::uint64_t value = (k << (spec.n + m.exponent_offset)) + m.c;  // small n only
      removed = removed || has_small_proper_factor(value, spec.p_max);
    }
    if (!removed) ks.push_back(k);
  }
  return ks;
}

TEST(GeneralizedSieve, EveryFormMatchesTrialDivision) {
  const struct {
    SieveForm form;
    unsigned length;
  } forms[] = {{SieveForm::twin, 1}, {SieveForm::sg, 1},  {SieveForm::riesel, 1}, {SieveForm::proth, 1},
               {SieveForm::cc1, 2},  {SieveForm::cc1, 3}, {SieveForm::cc2, 2},    {SieveForm::cc2, 4}};
  for (const auto& f : forms)
    for (std::uint64_t n : {1u, 2u, 5u, 12u, 20u})
      for (std::uint64_t p_max : {3u, 50u, 2000u}) {
        const SieveSpec spec = plain(f.form, n, 1, 1500, p_max, f.length);
        GeneralizedSieve sieve(spec);
        EXPECT_EQ(survivors_of(sieve), brute_force(spec)) << spec.identity();
      }
}

TEST(GeneralizedSieve, ParametrisedMatchesTrialDivision) {
  SieveSpec spec = plain(SieveForm::twin, 9, 0, 700, 3000);
  spec.parametrised = true;
  spec.h0 = 9;  // h0*2^9 is 0 mod 3 and 3 mod 5, so neither 3 nor 5 divides a member
  spec.c = 30;  // primes 3 and 5 divide c: their members never depend on x
  GeneralizedSieve sieve(spec);
  EXPECT_EQ(survivors_of(sieve), brute_force(spec));
}

/// Large primes (above the bitmap's small-prime bound) against direct
/// modular arithmetic: removed iff some p <= p_max divides some member.
TEST(GeneralizedSieve, LargePrimesMatchModularArithmetic) {
  const SieveSpec spec = plain(SieveForm::twin, 171960, 1000, 1150, 3000000);
  std::set<std::uint64_t> removed;
  for (std::uint64_t p : primes_between(3, spec.p_max)) {
    const std::uint64_t t = pow_mod(2, spec.n, p);
    for (std::uint64_t k = spec.x_min; k <= spec.x_max; ++k) {
      const std::uint64_t r = static_cast<std::uint64_t>(static_cast<u128>(k) * t % p);
      if (r == 1 || r == p - 1) removed.insert(k);
    }
  }
  std::vector<std::uint64_t> expected;
  for (std::uint64_t k = spec.x_min; k <= spec.x_max; ++k)
    if (!removed.count(k)) expected.push_back(k);
  GeneralizedSieve sieve(spec);
  std::vector<SieveFactor> factors;
  SieveControl control;
  control.on_factor = [&](const SieveFactor& f) { factors.push_back(f); };
  EXPECT_EQ(survivors_of(sieve, control), expected);
  EXPECT_EQ(factors.size(), removed.size());
  for (const SieveFactor& f : factors) {  // each reported factor divides its member
    const std::uint64_t k = spec.x_min + f.offset;
    const SieveMember m = spec.members()[f.member];
    EXPECT_EQ((static_cast<u128>(k) * pow_mod(2, spec.n + m.exponent_offset, f.p) + f.p + m.c) % f.p, 0u);
  }
}

TEST(GeneralizedSieve, ThreadsAndShardsDoNotChangeTheResult) {
  SieveSpec spec = plain(SieveForm::sg, 3001, 1, 200000, 30000000);
  GeneralizedSieve one(spec);
  const auto reference = survivors_of(one);
  GeneralizedSieve two(spec);
  SieveControl threads;
  threads.threads = 2;
  EXPECT_EQ(survivors_of(two, threads), reference);
  std::set<std::uint64_t> intersection;
  for (unsigned shard = 0; shard < 3; ++shard) {
    GeneralizedSieve part(spec);
    SieveControl control;
    control.shard_index = shard;
    control.shard_count = 3;
    const auto ks = survivors_of(part, control);
    EXPECT_GE(ks.size(), reference.size());
    if (shard == 0) intersection.insert(ks.begin(), ks.end());
    else {
      std::set<std::uint64_t> next;
      for (std::uint64_t k : ks)
        if (intersection.count(k)) next.insert(k);
      intersection = next;
    }
  }
  EXPECT_EQ(std::vector<std::uint64_t>(intersection.begin(), intersection.end()), reference);
}

TEST(SieveRoots, RootsSolveTheirMembers) {
  std::mt19937_64 random(7);
  SieveSpec spec = plain(SieveForm::cc2, 0, 5, 10, 0, 5);
  spec.parametrised = true;
  for (int trial = 0; trial < 40; ++trial) {
    spec.n = 1 + random() % 300000;
    spec.h0 = random() % 1000000;
    spec.c = 1 + random() % 1000000;
    spec.x_min = random() % 1000;
    SieveRootFinder finder(spec);
    std::vector<std::uint64_t> primes = primes_between(1000003, 1000003 + 2000);
    for (std::uint64_t p : primes_between((std::uint64_t(1) << 40) + 1, (std::uint64_t(1) << 40) + 400))
      primes.push_back(p);
    std::vector<std::uint64_t> roots(primes.size() * finder.member_count());
    finder.find(primes.data(), primes.size(), roots.data());
    for (std::size_t i = 0; i < primes.size(); ++i) {
      const std::uint64_t p = primes[i];
      for (std::size_t m = 0; m < finder.member_count(); ++m) {
        const std::uint64_t root = roots[i * finder.member_count() + m];
        if (spec.c % p == 0) continue;
        ASSERT_LT(root, p);
        const u128 k = static_cast<u128>(spec.h0) + static_cast<u128>(spec.c) * (spec.x_min + root);
        const SieveMember member = finder.members()[m];
        const u128 value = (k % p) * pow_mod(2, spec.n + member.exponent_offset, p) % p;
        EXPECT_EQ((value + p + member.c) % p, 0u) << "p=" << p << " n=" << spec.n;
      }
    }
  }
}

TEST(SieveRoots, PrimeDividingCAndEveryCandidateIsAnError) {
  SieveSpec spec = plain(SieveForm::riesel, 1, 0, 10, 100);
  spec.parametrised = true;
  spec.h0 = 2;  // 2*2 - 1 = 3, and c = 3: every k*2 - 1 is divisible by 3
  spec.c = 3;
  GeneralizedSieve sieve(spec);
  EXPECT_THROW(sieve.sieve_large_primes({}), tk::Error);
}

TEST(SieveSpec, ValidationNamesTheProblem) {
  auto message = [](SieveSpec spec) {
    try {
      spec.validate();
    } catch (const tk::UsageError& e) {  // every parameter is an option: exit 2
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(message(plain(SieveForm::twin, 0, 1, 10, 100)).find("exponent"), std::string::npos);
  EXPECT_EQ(message(plain(SieveForm::twin, 0, 1, 10, 100)).rfind("--n: ", 0), 0u);
  EXPECT_EQ(message(plain(SieveForm::twin, 5, 1, 10, 2)).rfind("--pmax: ", 0), 0u);
  EXPECT_NE(message(plain(SieveForm::twin, 5, 10, 1, 100)).find("empty"), std::string::npos);
  EXPECT_NE(message(plain(SieveForm::twin, 5, 0, 1, 100)).find("k must start"), std::string::npos);
  EXPECT_NE(message(plain(SieveForm::twin, 5, 1, 10, 2)).find("at least 3"), std::string::npos);
  EXPECT_NE(message(plain(SieveForm::cc1, 5, 1, 10, 100, 1)).find("chain length"), std::string::npos);
  EXPECT_NE(message(plain(SieveForm::cc1, 5, 1, 10, 100, 65)).find("chain length"), std::string::npos);
  SieveSpec seed = plain(SieveForm::twin, 5, 1, 10, 100);
  seed.parametrised = true;
  seed.c = 0;
  EXPECT_NE(message(seed).find("c = 0"), std::string::npos);
  // "Prime Hunting"'s Cc22 parametrisation, h0 = 0 and c = 30030: every k is
  // even, and k*2^n+1 is the same number as (k/2^t)*2^(n+t)+1.
  seed.c = 30030;
  seed.h0 = 0;
  EXPECT_EQ(message(seed), "accepted");
  seed.h0 = 1;
  seed.c = std::uint64_t(1) << 62;
  EXPECT_NE(message(seed).find("64 bits"), std::string::npos);
  EXPECT_EQ(message(plain(SieveForm::cc2, 5, 1, 10, 100, 64)), "accepted");
}

TEST(SieveSpec, RieselConditionOfTheSeed) {
  SieveSpec spec = plain(SieveForm::riesel, 40, 0, 1000, 1000);
  spec.parametrised = true;
  spec.c = 30030;  // 2*3*5*7*11*13
  // N = h0*2^40 - 1 mod 13 for odd h0: find one non-residue and one residue.
  std::uint64_t good = 0, bad = 0;  // the first odd h0 of each kind
  for (std::uint64_t h0 = 1; h0 < 100 && (!good || !bad); h0 += 2) {
    const std::uint64_t residue = (h0 % 13 * pow_mod(2, 40, 13) + 12) % 13;
    const bool non_residue = pow_mod(residue, 6, 13) == 12;  // Euler's criterion
    std::uint64_t& slot = non_residue ? good : bad;
    if (!slot) slot = h0;
  }
  ASSERT_TRUE(good && bad);
  spec.h0 = good;
  EXPECT_NO_THROW(spec.check_riesel_condition());
  spec.h0 = bad;
  EXPECT_THROW(spec.check_riesel_condition(), tk::Error);
  spec.h0 = good;
  spec.c = 2310;  // no 13: (13/N) would depend on x
  EXPECT_THROW(spec.check_riesel_condition(), tk::Error);
  spec.c = 30030;
  spec.x_max = std::uint64_t(1) << 30;  // k reaches past 2^40
  EXPECT_THROW(spec.check_riesel_condition(), tk::Error);
  // An even k is proved as (k/2^t)*2^(40+t) - 1, so k need not be odd: with
  // h0 even, N mod 13 still is the same for every x.
  spec.x_max = 1000;
  for (std::uint64_t h0 = 0; h0 < 26; h0 += 2) {
    spec.h0 = h0;
    const std::uint64_t residue = (h0 % 13 * pow_mod(2, 40, 13) + 12) % 13;
    const bool non_residue = pow_mod(residue, 6, 13) == 12;
    if (non_residue) EXPECT_NO_THROW(spec.check_riesel_condition()) << h0;
    else EXPECT_THROW(spec.check_riesel_condition(), tk::Error) << h0;
  }
  // One candidate k = 5*2^41 is not below 2^40, but as 5*2^81 - 1 its odd k
  // is below 2^81; 5*2^81 - 1 = 11 (mod 13), a non-residue.
  SieveSpec one = plain(SieveForm::riesel, 40, 0, 0, 1000);
  one.parametrised = true;
  one.h0 = 5 * (std::uint64_t(1) << 41);
  one.c = 30030;
  ASSERT_EQ((5 * pow_mod(2, 81, 13) + 12) % 13, 11u);
  EXPECT_NO_THROW(one.check_riesel_condition());
  one.h0 = 5 * (std::uint64_t(1) << 41) + 1;  // odd and above 2^40
  EXPECT_THROW(one.check_riesel_condition(), tk::Error);
}

TEST(NumberOption, PrimeHuntersNotation) {
  using tk::cli::parse_count;
  EXPECT_EQ(parse_count("1000000007", "x"), 1000000007u);
  EXPECT_EQ(parse_count("1e9", "x"), 1000000000u);
  EXPECT_EQ(parse_count("1.1e9", "x"), 1100000000u);
  EXPECT_EQ(parse_count("2.50e1", "x"), 25u);
  EXPECT_EQ(parse_count("2^40", "x"), std::uint64_t(1) << 40);
  EXPECT_EQ(parse_count("2^63", "x"), std::uint64_t(1) << 63);
  EXPECT_EQ(parse_count("0^0", "x"), 1u);
  EXPECT_EQ(parse_count("1e19", "x"), 10000000000000000000u);
  for (const char* bad :
       {"", "-1", "1e20", "2^64", "1.25e1", "1.5", "abc", "1e", "^3", "1:2", "0x10", "1e-3", "99999999999999999999"})
    EXPECT_THROW(parse_count(bad, "x"), tk::UsageError) << bad;
  EXPECT_EQ(tk::cli::parse_range("1:1e3", "x"), std::make_pair(std::uint64_t(1), std::uint64_t(1000)));
  EXPECT_THROW(tk::cli::parse_range("5:4", "x"), tk::UsageError);
  EXPECT_THROW(tk::cli::parse_range("5", "x"), tk::UsageError);
  EXPECT_THROW(tk::cli::parse_shard("4/3", "x"), tk::UsageError);
}

TEST(NumberOption, CommaSeparatedNumbers) {
  using tk::cli::parse_numbers;
  EXPECT_EQ(parse_numbers("200,200,400", "x", 3), (std::vector<double>{200, 200, 400}));
  EXPECT_EQ(parse_numbers("-1.5,+2e3,0", "x", 3), (std::vector<double>{-1.5, 2000, 0}));
  EXPECT_EQ(parse_numbers("7", "x", 1), (std::vector<double>{7}));
  for (const char* bad : {"", "1,2", "1,2,3,4", "1,,3", "1,2,", ",1,2", "a,b,c", "nan,1,1", "inf,1,1", "1e999,1,1",
                          "1 ,2,3", "0x10,1,1", "1,2,3 "})
    EXPECT_THROW(parse_numbers(bad, "--steps-per-mm", 3), tk::UsageError) << bad;
  try {
    parse_numbers("1,2", "--window", 4);
    ADD_FAILURE() << "accepted '1,2'";
  } catch (const tk::UsageError& e) {
    EXPECT_STREQ(e.what(), "--window '1,2' is not 4 finite numbers separated by commas");
  }
}

class SieveFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("toolkit-sieve-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  static std::string slurp(const std::string& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  }
  std::string write(GeneralizedSieve& sieve, SieveOutputFormat format, const std::string& name,
                    unsigned shard_index = 0, unsigned shard_count = 1) const {
    std::FILE* out = std::fopen(path(name).c_str(), "wb");
    write_survivors(sieve, format, sieve.spec().p_max, out, shard_index, shard_count);
    std::fclose(out);
    return path(name);
  }
  std::filesystem::path dir_;
};

TEST_F(SieveFiles, CheckpointRoundTripAndDamage) {
  const SieveSpec spec = plain(SieveForm::twin, 1000, 1, 100000, 20000000);
  GeneralizedSieve sieve(spec);
  SieveControl control;
  int blocks = 0;
  control.should_stop = [&] { return blocks >= 2; };
  control.after_block = [&] { ++blocks; };
  EXPECT_FALSE(sieve.sieve_large_primes(control));
  const std::string identity = checkpoint_identity(spec, 0, 1);
  save_checkpoint(path("state"), sieve, identity, 1234);
  auto loaded = load_checkpoint(path("state"), identity, spec.count());
  ASSERT_TRUE(loaded);
  EXPECT_EQ(loaded->bitmap, sieve.bitmap());
  EXPECT_EQ(loaded->next_block, sieve.next_block());
  EXPECT_EQ(loaded->factors_bytes, 1234u);

  GeneralizedSieve resumed(spec);
  resumed.restore(loaded->bitmap, loaded->next_segment, loaded->next_block);
  GeneralizedSieve straight(spec);
  EXPECT_EQ(survivors_of(resumed), survivors_of(straight));

  EXPECT_FALSE(load_checkpoint(path("missing"), identity, spec.count()));
  EXPECT_THROW(load_checkpoint(path("state"), checkpoint_identity(spec, 0, 2), spec.count()), tk::Error);
  std::string bytes = slurp(path("state"));
  for (std::size_t at : {std::size_t(3), bytes.size() / 2, bytes.size() - 1}) {
    std::string damaged = bytes;
    damaged[at] ^= 0x20;
    std::ofstream(path("damaged"), std::ios::binary) << damaged;
    EXPECT_THROW(load_checkpoint(path("damaged"), identity, spec.count()), tk::Error) << at;
  }
  std::ofstream(path("short"), std::ios::binary) << bytes.substr(0, bytes.size() / 3);
  EXPECT_THROW(load_checkpoint(path("short"), identity, spec.count()), tk::Error);
}

TEST_F(SieveFiles, CheckpointInTheSmallPrimePhase) {
  // Two segments of 2^21 (the second short); stopped after the first, saved, loaded and
  // resumed, the run removes the same candidates in the same order.
  const SieveSpec spec = plain(SieveForm::twin, 1000, 1, GeneralizedSieve::kSegmentBits + 1000, 1100000);
  auto digest = [](std::uint64_t& hash, const SieveFactor& factor) {
    hash = (hash ^ factor.offset) * 0x100000001b3ull;
    hash = (hash ^ factor.p) * 0x100000001b3ull;
  };
  std::uint64_t straight_hash = 0;
  GeneralizedSieve straight(spec);
  SieveControl all;
  all.on_factor = [&](const SieveFactor& factor) { digest(straight_hash, factor); };
  ASSERT_TRUE(straight.sieve_large_primes(all));

  std::uint64_t hash = 0;
  GeneralizedSieve first(spec);
  SieveControl control;
  control.on_factor = [&](const SieveFactor& factor) { digest(hash, factor); };
  control.should_stop = [&] { return first.next_segment() >= 1; };
  EXPECT_FALSE(first.sieve_large_primes(control));
  EXPECT_EQ(first.next_segment(), 1u);
  EXPECT_FALSE(first.small_primes_done());
  const std::string identity = checkpoint_identity(spec, 0, 1);
  save_checkpoint(path("state"), first, identity, 0);
  auto loaded = load_checkpoint(path("state"), identity, spec.count());
  ASSERT_TRUE(loaded);
  EXPECT_EQ(loaded->next_segment, 1u);
  EXPECT_EQ(loaded->next_block, 0u);

  GeneralizedSieve resumed(spec);
  resumed.restore(std::move(loaded->bitmap), loaded->next_segment, loaded->next_block);
  EXPECT_EQ(resumed.survivors(), first.survivors());
  SieveControl rest;
  rest.on_factor = control.on_factor;
  ASSERT_TRUE(resumed.sieve_large_primes(rest));
  EXPECT_EQ(hash, straight_hash);
  EXPECT_EQ(survivors_of(resumed), survivors_of(straight));
  EXPECT_EQ(resumed.survivors(), straight.survivors());
}

TEST_F(SieveFiles, OutputFormats) {
  SieveSpec spec = plain(SieveForm::twin, 5, 1, 40, 1000);
  GeneralizedSieve twin(spec);
  twin.sieve_large_primes({});
  // 6*32 -+ 1 = 191, 193 and 36*32 -+ 1 = 1151, 1153 are the twin primes here.
  EXPECT_EQ(slurp(write(twin, SieveOutputFormat::newpgen, "t.npg")), "1000:T:0:2:3\n6 5\n36 5\n");
  EXPECT_EQ(slurp(write(twin, SieveOutputFormat::abc, "t.abc")), "ABC $a*2^5+1 & $a*2^5-1 // Sieved to 1000\n6\n36\n");
  EXPECT_EQ(slurp(write(twin, SieveOutputFormat::abcd, "t.abcd")),
            "ABCD $a*2^5+1 & $a*2^5-1 [6] // Sieved to 1000\n30\n");
  EXPECT_EQ(slurp(write(twin, SieveOutputFormat::json_lines, "t.jsonl")),
            "{\"k\":6,\"n\":5,\"form\":\"twin\"}\n{\"k\":36,\"n\":5,\"form\":\"twin\"}\n");
  EXPECT_EQ(slurp(write(twin, SieveOutputFormat::csv, "t.csv")), "k,n,form\n6,5,twin\n36,5,twin\n");
  EXPECT_EQ(factor_line(spec, SieveFactor{2, 5, 1}), "5 | 3*2^5+1");

  SieveSpec chain = plain(SieveForm::cc1, 3, 1, 1, 10, 3);
  GeneralizedSieve cc1(chain);
  cc1.sieve_large_primes({});  // 7, 15: 15 = 3*5 removes k = 1
  EXPECT_EQ(slurp(write(cc1, SieveOutputFormat::newpgen, "c.npg")), "10:1:3:2:1066\n");
}

TEST_F(SieveFiles, MergeOfShardsEqualsOneRun) {
  const SieveSpec spec = plain(SieveForm::twin, 4000, 1, 30000, 20000000);
  GeneralizedSieve whole(spec);
  whole.sieve_large_primes({});
  for (auto format : {SieveOutputFormat::json_lines, SieveOutputFormat::csv, SieveOutputFormat::newpgen,
                      SieveOutputFormat::abc, SieveOutputFormat::abcd}) {
    const std::string expected = slurp(write(whole, format, "whole"));
    std::vector<std::string> shards;
    for (unsigned k = 0; k < 3; ++k) {
      GeneralizedSieve part(spec);
      SieveControl control;
      control.shard_index = k;
      control.shard_count = 3;
      part.sieve_large_primes(control);
      shards.push_back(write(part, format, "shard" + std::to_string(k), k, 3));
    }
    std::FILE* out = std::fopen(path("merged").c_str(), "wb");
    merge_sieve_outputs(shards, out);
    std::fclose(out);
    EXPECT_EQ(slurp(path("merged")), expected) << static_cast<int>(format);

    // A shard cut short anywhere (a sieve killed while writing it) is refused;
    // only the final newline may go.
    const std::string whole_shard = slurp(shards[1]);
    std::vector<std::size_t> cuts;  // every byte of the header and of the last lines, and some between
    for (std::size_t size = 0; size + 1 < whole_shard.size(); ++size)
      if (size < 60 || size + 100 > whole_shard.size() || size % 211 == 0) cuts.push_back(size);
    for (std::size_t size : cuts) {
      std::ofstream(shards[1], std::ios::binary | std::ios::trunc) << whole_shard.substr(0, size);
      std::FILE* sink = std::fopen(path("merged").c_str(), "wb");
      EXPECT_THROW(merge_sieve_outputs(shards, sink), tk::Error) << static_cast<int>(format) << " cut at " << size;
      std::fclose(sink);
    }
    std::ofstream(shards[1], std::ios::binary | std::ios::trunc) << whole_shard;
    // Each shard once, none missing.
    for (const auto& files : {std::vector<std::string>{shards[0], shards[1]},
                              std::vector<std::string>{shards[0], shards[1], shards[2], shards[2]},
                              std::vector<std::string>{shards[0], shards[0], shards[1], shards[2]}}) {
      std::FILE* sink = std::fopen(path("merged").c_str(), "wb");
      EXPECT_THROW(merge_sieve_outputs(files, sink), tk::Error) << files.size();
      std::fclose(sink);
    }
  }
  // One run's output (no trailer) and garbage are not shard outputs.
  std::ofstream(path("other")) << "1000:M:1:2:2\n3 5\n";
  std::ofstream(path("hello")) << "hello\n";
  std::FILE* out = std::fopen(path("merged").c_str(), "wb");
  EXPECT_THROW(merge_sieve_outputs({path("other")}, out), tk::Error);
  EXPECT_THROW(merge_sieve_outputs({path("hello")}, out), tk::Error);
  std::fclose(out);
}

TEST(SieveShardTrailer, RoundTripAndCutShort) {
  const ShardTrailer trailer{2, 5, 1225, "form=twin length=1 n=1000 k=1:3000"};
  const std::string line = format_shard_trailer(trailer);
  EXPECT_EQ(line, "// sieve shard 3/5 of form=twin length=1 n=1000 k=1:3000: 1225 candidates, complete");
  const auto parsed = parse_shard_trailer(line);
  ASSERT_TRUE(parsed);
  EXPECT_EQ(parsed->index, 2u);
  EXPECT_EQ(parsed->count, 5u);
  EXPECT_EQ(parsed->candidates, 1225u);
  EXPECT_EQ(parsed->run, trailer.run);
  for (std::size_t size = 0; size < line.size(); ++size)
    EXPECT_FALSE(parse_shard_trailer(line.substr(0, size))) << size;
  EXPECT_FALSE(parse_shard_trailer("// sieve shard 6/5 of x: 1 candidates, complete"));
  EXPECT_FALSE(parse_shard_trailer("// sieve shard 1/1 of x: 1 candidates, complete"));
}

}  // namespace
