/// @file pseudoprimes.cpp
/// @brief Test oracle: lists every base-2 Fermat pseudoprime (psp(2)), base-2
///        strong pseudoprime (spsp(2)) and Carmichael number below a limit X
///        (default 10^10), independently of the project's primality code.
///
/// Usage:
///   pseudoprimes [--limit X] [--threads N] [--gp PATH] [--verbose] OUTDIR
///       writes OUTDIR/psp2.txt, OUTDIR/spsp2.txt, OUTDIR/carmichael.txt
///       (one decimal number per line, ascending) and prints the three counts.
///       For X = 10^k (k <= 10) the counts are also compared with the published
///       tables; a mismatch makes the exit status 1.
///   pseudoprimes --self-check [--limit X] [--threads N] [--gp PATH] [--verbose]
///       compares the fast method with a brute-force reference below X
///       (default 10^7; 10^8 takes about 10 CPU seconds) and at many smaller
///       limits; exit status 0 iff all agree.
///
/// Method (n < X, N = X - 1, S = isqrt(N), l_p = multiplicative order of 2 mod p):
///  - A psp(2) n is odd (2 is invertible mod n).  If p | n then l_p | n - 1.
///  - If p^2 | n then 2^(n-1) = 1 (mod p^2); the order of 2 mod p^2 is l_p or
///    p*l_p, and p*l_p cannot divide n - 1, so it is l_p, i.e. 2^(p-1) = 1
///    (mod p^2): p is a Wieferich prime.  The Wieferich primes <= S are found
///    by direct test and all multiples of their squares are tested.
///  - Otherwise n = M*P is squarefree with largest prime factor P, M >= 3, and
///    since P = 1 (mod l_P): n - 1 = M - 1 (mod l_P), so M = 1 (mod l_P).
///    Case A, P <= S: walk M = 1 + t*l_P (odd M only), or, when that walk
///    has more than 30000 steps (small P*l_P), enumerate odd squarefree M with
///    all prime factors < P by depth-first search and keep M = 1 (mod l_P);
///    the DFS skips primes q dividing l_P (q | n and l_P | n - 1 exclude each
///    other).
///    Case B, P > S: then M <= N/P <= S, so 2 <= l_P <= S - 1.  For each order l
///    the primes P in (S, N/(l+1)] with l_P = l divide 2^l - 1 and satisfy
///    P = 1 (mod l) (mod 2l for odd l).  For l <= 128 they come from PARI/GP's
///    factorisation of 2^l - 1; for larger l the progression P = 1 + k*l' is
///    sieved by small primes and tested for 2^l = 1 (mod P), primality and exact
///    order.  Then M = 1 + t*l' is walked as in case A.
///  - Every candidate n is accepted only after a full Fermat test mod n, so extra
///    candidates are harmless; the steps above only have to be complete.
///  - spsp(2) = members of the psp(2) list passing the strong base-2 test.
///  - Carmichael numbers are odd (an even squarefree composite n has an odd
///    prime factor p, and Korselt's p - 1 | n - 1 would make n - 1 even) and
///    satisfy a^(n-1) = 1 (mod n) for every a coprime to n, in particular a = 2,
///    so all of them are psp(2): they are the members of the psp(2) list that
///    satisfy Korselt's criterion (squarefree, p - 1 | n - 1 for all p | n).
///
/// Build: g++ -O2 -std=c++20 -pthread pseudoprimes.cpp -lgmp -o pseudoprimes

#include <gmp.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace {

using u32 = std::uint32_t;
using u64 = std::uint64_t;
__extension__ using u128 = unsigned __int128;

// ---------------------------------------------------------------------------
// Modular arithmetic: Montgomery multiplication for odd moduli below 2^63.
// ---------------------------------------------------------------------------

/// Arithmetic modulo an odd n < 2^63 with residues kept in Montgomery form
/// (x represented by x * 2^64 mod n).
class Montgomery {
public:
    explicit Montgomery(u64 n) : n_(n) {
        u64 inv = n;  // n * n = 1 (mod 8): three correct bits
        for (int i = 0; i < 5; ++i) inv *= 2 - n * inv;  // doubles the bits
        neg_inv_ = 0 - inv;                              // n * neg_inv_ = -1 (mod 2^64)
        one_ = (0 - n) % n;                              // 2^64 mod n
    }

    [[nodiscard]] u64 modulus() const { return n_; }
    [[nodiscard]] u64 one() const { return one_; }
    [[nodiscard]] u64 minus_one() const { return n_ - one_; }

    /// Montgomery product a * b / 2^64 mod n, for a, b < n.
    [[nodiscard]] u64 mul(u64 a, u64 b) const {
        const u128 t = static_cast<u128>(a) * b;
        const u64 m = static_cast<u64>(t) * neg_inv_;
        // t + m*n < n^2 + 2^64 n < 2^128 because n < 2^63; the low word is 0.
        const u64 r = static_cast<u64>((t + static_cast<u128>(m) * n_) >> 64);
        return r >= n_ ? r - n_ : r;
    }

    [[nodiscard]] u64 dbl(u64 a) const {
        a += a;  // a < n < 2^63: no overflow
        return a >= n_ ? a - n_ : a;
    }

    /// 2^e mod n in Montgomery form.
    [[nodiscard]] u64 pow2(u64 e) const {
        if (e == 0) return one_;
        u64 x = dbl(one_);
        for (int bit = 62 - __builtin_clzll(e); bit >= 0; --bit) {
            x = mul(x, x);
            if ((e >> bit) & 1) x = dbl(x);
        }
        return x;
    }

    /// Converts out of Montgomery form.
    [[nodiscard]] u64 to_plain(u64 x) const { return mul(x, 1); }

private:
    u64 n_;
    u64 neg_inv_;
    u64 one_;
};

/// 2^(n-1) = 1 (mod n), for odd n >= 3.
bool fermat2(u64 n) {
    const Montgomery m(n);
    return m.pow2(n - 1) == m.one();
}

struct Base2Verdict {
    bool fermat;
    bool strong;
};

/// Fermat and strong (Miller-Rabin) base-2 tests with one exponentiation, odd n >= 3.
Base2Verdict base2_tests(u64 n) {
    const Montgomery m(n);
    const int s = __builtin_ctzll(n - 1);
    u64 x = m.pow2((n - 1) >> s);
    bool strong = (x == m.one() || x == m.minus_one());
    for (int i = 1; i < s; ++i) {
        x = m.mul(x, x);
        if (x == m.minus_one()) strong = true;
    }
    // x = 2^((n-1)/2) now when s >= 1; one more squaring gives 2^(n-1).
    const bool fermat = m.mul(x, x) == m.one();
    return {fermat, strong && fermat};
}

bool strong2(u64 n) { return base2_tests(n).strong; }

// ---------------------------------------------------------------------------
// Small helpers
// ---------------------------------------------------------------------------

u64 isqrt(u64 n) {
    u64 r = static_cast<u64>(__builtin_sqrtl(static_cast<long double>(n)));
    while (r > 0 && r * r > n) --r;
    while ((r + 1) * (r + 1) <= n) ++r;
    return r;
}

/// Odd primes <= n (sieve of Eratosthenes).
std::vector<u32> odd_primes_upto(u64 n) {
    std::vector<u32> primes;
    if (n < 3) return primes;
    std::vector<char> composite(n + 1, 0);
    for (u64 i = 3; i <= n; i += 2) {
        if (composite[i]) continue;
        primes.push_back(static_cast<u32>(i));
        for (u64 j = i * i; j <= n; j += 2 * i) composite[j] = 1;
    }
    return primes;
}

/// Distinct prime factors of m (m <= max(odd_primes)^2, any parity).
std::vector<u64> prime_factors(u64 m, const std::vector<u32>& odd_primes) {
    std::vector<u64> factors;
    if (m % 2 == 0) {
        factors.push_back(2);
        while (m % 2 == 0) m /= 2;
    }
    for (const u32 p : odd_primes) {
        if (static_cast<u64>(p) * p > m) break;
        if (m % p != 0) continue;
        factors.push_back(p);
        while (m % p == 0) m /= p;
    }
    if (m > 1) factors.push_back(m);
    return factors;
}

/// Trial-division primality test for odd n <= max(odd_primes)^2.
bool is_odd_prime(u64 n, const std::vector<u32>& odd_primes) {
    if (n < 3) return false;
    for (const u32 p : odd_primes) {
        if (static_cast<u64>(p) * p > n) return true;
        if (n % p == 0) return false;
    }
    return true;
}

/// Multiplicative order of 2 modulo the odd prime p.
u64 order_of_two(u64 p, const std::vector<u32>& odd_primes) {
    const Montgomery m(p);
    u64 order = p - 1;
    for (const u64 q : prime_factors(p - 1, odd_primes)) {
        while (order % q == 0 && m.pow2(order / q) == m.one()) order /= q;
    }
    return order;
}

/// 2 has order exactly l modulo p (l_factors = distinct primes of l).
bool has_order(u64 p, u64 l, const std::vector<u64>& l_factors) {
    const Montgomery m(p);
    if (m.pow2(l) != m.one()) return false;
    for (const u64 q : l_factors) {
        if (m.pow2(l / q) == m.one()) return false;
    }
    return true;
}

/// Korselt's criterion for odd n >= 3 with max(odd_primes)^2 >= n: n is
/// squarefree, has at least two prime factors and p - 1 | n - 1 for each p | n.
bool is_carmichael(u64 n, const std::vector<u32>& odd_primes) {
    u64 m = n;
    int factors = 0;
    for (const u32 p : odd_primes) {
        if (static_cast<u64>(p) * p > m) break;
        if (m % p != 0) continue;
        m /= p;
        if (m % p == 0 || (n - 1) % (p - 1) != 0) return false;
        ++factors;
    }
    if (m > 1) {
        if ((n - 1) % (m - 1) != 0) return false;
        ++factors;
    }
    return factors >= 2;
}

/// Inverse of a modulo the odd prime q, for a not divisible by q.
u64 inverse_mod(u64 a, u64 q) {
    long long r0 = static_cast<long long>(q), r1 = static_cast<long long>(a % q);
    long long s0 = 0, s1 = 1;
    while (r1 != 0) {
        const long long k = r0 / r1;
        std::swap(r0, r1);
        r1 -= k * r0;
        std::swap(s0, s1);
        s1 -= k * s0;
    }
    const long long inv = s0 % static_cast<long long>(q);
    return static_cast<u64>(inv < 0 ? inv + static_cast<long long>(q) : inv);
}

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// ---------------------------------------------------------------------------
// PARI/GP: prime factors of 2^l - 1 for small l
// ---------------------------------------------------------------------------

/// For l in [2, lmax]: the prime factors of 2^l - 1 below 2^64, as reported
/// by `gp`.  Every factorisation is checked by multiplying it back.
std::vector<std::vector<u64>> mersenne_factors_from_gp(const std::string& gp, u64 lmax) {
    std::vector<std::vector<u64>> result(lmax + 1);
    if (lmax < 2) return result;
    const std::string script = "default(factor_proven,1); for(l=2," + std::to_string(lmax) +
                               ", f=factor(2^l-1); for(i=1,#f~, print(l,\" \",f[i,1],\" \",f[i,2]))); "
                               "print(\"done\")";
    const std::string command = "echo '" + script + "' | '" + gp + "' -q -f";
    FILE* pipe = popen(command.c_str(), "r");
    if (pipe == nullptr) throw std::runtime_error("cannot run gp");

    std::vector<std::string> lines;
    std::string line;
    for (int c; (c = std::fgetc(pipe)) != EOF;) {
        if (c == '\n') {
            lines.push_back(line);
            line.clear();
        } else {
            line.push_back(static_cast<char>(c));
        }
    }
    const int status = pclose(pipe);
    if (status != 0 || lines.empty() || lines.back() != "done") {
        throw std::runtime_error("gp failed (is PARI/GP installed? use --gp PATH)");
    }
    lines.pop_back();

    // Lines are "l p e"; multiply the factors of each l back together.
    std::vector<std::vector<std::pair<std::string, unsigned long>>> factors(lmax + 1);
    for (const std::string& text : lines) {
        std::istringstream in(text);
        u64 l = 0;
        std::string prime;
        unsigned long e = 0;
        if (!(in >> l >> prime >> e) || l < 2 || l > lmax || e == 0) {
            throw std::runtime_error("unexpected gp output: " + text);
        }
        factors[l].emplace_back(prime, e);
    }
    mpz_t p, power, product, mersenne;
    mpz_inits(p, power, product, mersenne, nullptr);
    bool complete = true;
    for (u64 l = 2; l <= lmax && complete; ++l) {
        mpz_set_ui(product, 1);
        for (const auto& [prime, e] : factors[l]) {
            if (mpz_set_str(p, prime.c_str(), 10) != 0) complete = false;
            mpz_pow_ui(power, p, e);
            mpz_mul(product, product, power);
            if (mpz_fits_ulong_p(p) != 0) result[l].push_back(mpz_get_ui(p));
        }
        mpz_ui_pow_ui(mersenne, 2, l);
        mpz_sub_ui(mersenne, mersenne, 1);
        if (mpz_cmp(mersenne, product) != 0) complete = false;
    }
    mpz_clears(p, power, product, mersenne, nullptr);
    if (!complete) throw std::runtime_error("gp output does not multiply back to 2^l - 1");
    return result;
}

/// mersenne_factors_from_gp() with the answer kept for later calls (the
/// self-check runs the generator many times).
const std::vector<std::vector<u64>>& cached_mersenne_factors(const std::string& gp, u64 lmax) {
    static std::string cached_gp;
    static std::vector<std::vector<u64>> cached;
    if (cached.size() < lmax + 1 || cached_gp != gp) {
        cached = mersenne_factors_from_gp(gp, lmax);
        cached_gp = gp;
    }
    return cached;
}

// ---------------------------------------------------------------------------
// Fast generation of psp(2) below the limit
// ---------------------------------------------------------------------------

struct Config {
    u64 limit = 10'000'000'000ULL;  ///< list numbers n < limit
    unsigned threads = 2;
    std::string gp = "gp";
    u64 gp_max_order = 128;          ///< orders l <= this use gp; larger ones walk P = 1 + k*l'
    u64 dfs_min_walk = 30'000;       ///< case A uses the DFS when the M walk is longer than this
    bool verbose = false;
};

struct Counters {
    u64 tests = 0;        ///< Fermat tests of candidates n
    u64 dfs_nodes = 0;    ///< squarefree M enumerated by the DFS
    u64 p_candidates = 0; ///< case B: P = 1 + k*l' tested for 2^l = 1 (mod P)
    void add(const Counters& o) {
        tests += o.tests;
        dfs_nodes += o.dfs_nodes;
        p_candidates += o.p_candidates;
    }
};

class PspGenerator {
public:
    explicit PspGenerator(const Config& cfg) : cfg_(cfg) {}

    std::vector<u64> run() {
        std::vector<u64> all;
        if (cfg_.limit <= 3) return all;
        n_max_ = cfg_.limit - 1;
        root_ = isqrt(n_max_);
        primes_ = odd_primes_upto(root_);
        orders_.resize(primes_.size());
        for (std::size_t i = 0; i < primes_.size(); ++i) orders_[i] = order_of_two(primes_[i], primes_);

        // Case B orders: M <= N/P <= N/(S+1) and l <= M - 1.
        const u64 l_max = n_max_ / (root_ + 1) >= 1 ? n_max_ / (root_ + 1) - 1 : 0;
        const u64 gp_orders = std::min(cfg_.gp_max_order, l_max);
        if (gp_orders >= 2) gp_factors_ = &cached_mersenne_factors(cfg_.gp, cfg_.gp_max_order);

        const std::size_t tasks_a = primes_.size();
        const std::size_t tasks_b = l_max >= 2 ? l_max - 1 : 0;
        std::atomic<std::size_t> next{0};
        const unsigned nthreads = std::max(1u, cfg_.threads);
        std::vector<std::vector<u64>> found(nthreads);
        std::vector<Counters> counters(nthreads);
        auto worker = [&](unsigned id) {
            for (;;) {
                const std::size_t task = next.fetch_add(1);
                if (task < tasks_a) {
                    case_a(task, found[id], counters[id]);
                } else if (task < tasks_a + tasks_b) {
                    case_b(2 + (task - tasks_a), found[id], counters[id]);
                } else {
                    break;
                }
            }
        };
        std::vector<std::thread> pool;
        for (unsigned id = 1; id < nthreads; ++id) pool.emplace_back(worker, id);
        worker(0);
        for (auto& t : pool) t.join();

        Counters total;
        for (unsigned id = 0; id < nthreads; ++id) {
            all.insert(all.end(), found[id].begin(), found[id].end());
            total.add(counters[id]);
        }
        const std::size_t wieferich_tests = add_wieferich_multiples(all);
        std::sort(all.begin(), all.end());
        all.erase(std::unique(all.begin(), all.end()), all.end());
        if (cfg_.verbose) {
            std::cerr << "  limit " << cfg_.limit << ": case A primes " << tasks_a << ", case B orders "
                      << tasks_b << ", Fermat tests " << total.tests + wieferich_tests << ", DFS nodes "
                      << total.dfs_nodes << ", case B P candidates " << total.p_candidates << "\n";
        }
        return all;
    }

    [[nodiscard]] const std::vector<u32>& odd_primes() const { return primes_; }

private:
    void test(u64 n, std::vector<u64>& out, Counters& c) const {
        ++c.tests;
        if (fermat2(n)) out.push_back(n);
    }

    /// Walks n = M*P for M = 1 + t*step, t >= 1, M*P <= N.
    void walk_multipliers(u64 p, u64 step, std::vector<u64>& out, Counters& c) const {
        const u64 m_max = n_max_ / p;
        for (u64 m = 1 + step; m <= m_max; m += step) test(m * p, out, c);
    }

    /// Case A: largest prime factor P = primes_[index] <= S.
    void case_a(std::size_t index, std::vector<u64>& out, Counters& c) const {
        const u64 p = primes_[index];
        const u64 l = orders_[index];
        const u64 m_max = n_max_ / p;
        if (m_max < 3) return;
        const u64 step = (l % 2 == 1) ? 2 * l : l;  // keeps M odd
        if ((m_max - 1) / step <= cfg_.dfs_min_walk) {
            walk_multipliers(p, step, out, c);
        } else {
            dfs(index, p, l, m_max, 0, 1, out, c);
        }
    }

    /// Odd squarefree M (prime factors primes_[start..end)), M <= m_max; tests
    /// n = M*P when M = 1 (mod l).
    void dfs(std::size_t end, u64 p, u64 l, u64 m_max, std::size_t start, u64 m, std::vector<u64>& out,
             Counters& c) const {
        for (std::size_t i = start; i < end; ++i) {
            const u64 q = primes_[i];
            if (m * q > m_max) break;
            if (l % q == 0) continue;  // q | n and l | n - 1 cannot both hold
            const u64 mq = m * q;
            ++c.dfs_nodes;
            if (mq % l == 1) test(mq * p, out, c);
            dfs(end, p, l, m_max, i + 1, mq, out, c);
        }
    }

    /// Case B: largest prime factor P > S with order l.
    void case_b(u64 l, std::vector<u64>& out, Counters& c) const {
        const u64 p_max = n_max_ / (l + 1);
        if (p_max <= root_) return;
        const u64 step = (l % 2 == 1) ? 2 * l : l;  // P = 1 (mod l) and P odd
        const std::vector<u64> l_factors = prime_factors(l, primes_);
        std::vector<u64> big_primes;
        if (l <= cfg_.gp_max_order) {
            for (const u64 p : gp_factors_->at(l)) {
                if (p > root_ && p <= p_max && is_odd_prime(p, primes_) && has_order(p, l, l_factors)) {
                    big_primes.push_back(p);
                }
            }
        } else {
            find_primes_of_order(l, step, p_max, l_factors, big_primes, c);
        }
        for (const u64 p : big_primes) walk_multipliers(p, step, out, c);
    }

    /// Primes P = 1 + k*step in (S, p_max] with order l: the progression is
    /// sieved by small primes, survivors tested for 2^l = 1 (mod P).
    void find_primes_of_order(u64 l, u64 step, u64 p_max, const std::vector<u64>& l_factors,
                              std::vector<u64>& big_primes, Counters& c) const {
        const u64 k0 = (root_ - 1) / step + 1;  // first k with 1 + k*step > S
        const u64 k1 = (p_max - 1) / step;
        if (k0 > k1) return;
        const u64 count = k1 - k0 + 1;
        std::vector<char> candidate(count, 1);
        if (count >= 4096) {
            for (const u32 q : primes_) {
                if (q > 2000) break;  // q <= S < P, so P = q is never sieved out
                if (step % q == 0) continue;
                // q | 1 + k*step  <=>  k = -step^(-1) (mod q)
                const u64 residue = (q - inverse_mod(step % q, q)) % q;
                for (u64 j = (residue + q - k0 % q) % q; j < count; j += q) candidate[j] = 0;
            }
        }
        for (u64 j = 0; j < count; ++j) {
            if (!candidate[j]) continue;
            const u64 p = 1 + (k0 + j) * step;
            ++c.p_candidates;
            const Montgomery m(p);
            if (m.pow2(l) != m.one()) continue;
            if (is_odd_prime(p, primes_) && has_order(p, l, l_factors)) big_primes.push_back(p);
        }
    }

    /// Non-squarefree psp(2): multiples of w^2 for Wieferich primes w <= S.
    std::size_t add_wieferich_multiples(std::vector<u64>& out) const {
        std::size_t tests = 0;
        for (const u32 w : primes_) {
            const u64 w2 = static_cast<u64>(w) * w;
            const Montgomery m(w2);
            if (m.pow2(w - 1) != m.one()) continue;
            if (cfg_.verbose) std::cerr << "  Wieferich prime " << w << "\n";
            for (u64 n = w2; n <= n_max_; n += 2 * w2) {
                ++tests;
                if (fermat2(n)) out.push_back(n);
            }
        }
        return tests;
    }

    Config cfg_;
    u64 n_max_ = 0;
    u64 root_ = 0;
    std::vector<u32> primes_;  ///< odd primes <= S
    std::vector<u64> orders_;  ///< order of 2 modulo primes_[i]
    const std::vector<std::vector<u64>>* gp_factors_ = nullptr;  ///< prime factors of 2^l - 1
};

struct Lists {
    std::vector<u64> psp;
    std::vector<u64> spsp;
    std::vector<u64> carmichael;
};

Lists fast_lists(const Config& cfg) {
    PspGenerator generator(cfg);
    Lists lists;
    lists.psp = generator.run();
    for (const u64 n : lists.psp) {
        if (strong2(n)) lists.spsp.push_back(n);
        if (is_carmichael(n, generator.odd_primes())) lists.carmichael.push_back(n);
    }
    return lists;
}

// ---------------------------------------------------------------------------
// Published counts below 10^k: psp(2) OEIS A055550, Carmichael numbers OEIS
// A055553 (Pinch), spsp(2) the table in R. K. Guy, Unsolved Problems in Number
// Theory, A12 (reproduced in MathWorld's "Pseudoprime" entry), which also lists
// the psp(2) and Carmichael counts.  (A055551 counts Euler-Jacobi pseudoprimes.)
// ---------------------------------------------------------------------------

struct Published {
    u64 limit;
    std::size_t psp, spsp, carmichael;
};

constexpr Published kPublished[] = {
    {10ULL, 0, 0, 0},
    {100ULL, 0, 0, 0},
    {1'000ULL, 3, 0, 1},
    {10'000ULL, 22, 5, 7},
    {100'000ULL, 78, 16, 16},
    {1'000'000ULL, 245, 46, 43},
    {10'000'000ULL, 750, 162, 105},
    {100'000'000ULL, 2057, 488, 255},
    {1'000'000'000ULL, 5597, 1282, 646},
    {10'000'000'000ULL, 14884, 3291, 1547},
};

/// Returns false on a mismatch; true if they match or no published value exists.
bool check_published(u64 limit, const Lists& lists, const char* what) {
    for (const Published& p : kPublished) {
        if (p.limit != limit) continue;
        const bool ok = lists.psp.size() == p.psp && lists.spsp.size() == p.spsp &&
                        lists.carmichael.size() == p.carmichael;
        std::cout << what << " counts below " << limit << (ok ? " match" : " DO NOT match")
                  << " the published counts (" << p.psp << ", " << p.spsp << ", " << p.carmichael << ")\n";
        return ok;
    }
    return true;
}

// ---------------------------------------------------------------------------
// Brute-force reference for --self-check
// ---------------------------------------------------------------------------

/// Tests every odd composite n < limit; Carmichael numbers independently by a
/// Korselt sieve (every prime p marks its odd multiples n = p*k that are not
/// squarefree in p or have p - 1 not dividing n - 1, i.e. k != 1 mod p - 1).
Lists brute_force(u64 limit, unsigned threads) {
    Lists lists;
    if (limit <= 3) return lists;
    const u64 n_max = limit - 1;
    const u64 slots = (n_max + 1) / 2;  // slot i <-> odd n = 2i + 1
    std::vector<bool> composite(slots, false);
    for (u64 p = 3; p * p <= n_max; p += 2) {
        if (composite[p / 2]) continue;
        for (u64 n = p * p; n <= n_max; n += 2 * p) composite[n / 2] = true;
    }

    const unsigned nthreads = std::max(1u, threads);
    const u64 chunk = 1 << 20;
    std::atomic<u64> next{0};
    std::vector<std::vector<std::pair<u64, bool>>> found(nthreads);  // (n, strong)
    auto worker = [&](unsigned id) {
        for (;;) {
            const u64 begin = next.fetch_add(chunk);
            if (begin >= slots) break;
            const u64 end = std::min(slots, begin + chunk);
            for (u64 i = std::max<u64>(begin, 1); i < end; ++i) {
                if (!composite[i]) continue;
                const u64 n = 2 * i + 1;
                const Base2Verdict v = base2_tests(n);
                if (v.fermat) found[id].emplace_back(n, v.strong);
            }
        }
    };
    std::vector<std::thread> pool;
    for (unsigned id = 1; id < nthreads; ++id) pool.emplace_back(worker, id);

    // Korselt sieve, on this thread while the others test.
    std::vector<bool> not_korselt(slots, false);
    for (u64 p = 3; p <= n_max / 3; p += 2) {
        if (composite[p / 2]) continue;
        u64 k_mod_p = 3 % p, k_minus_1_mod = 2 % (p - 1);
        for (u64 k = 3; k <= n_max / p; k += 2) {
            if (k_mod_p == 0 || k_minus_1_mod != 0) not_korselt[(p * k) / 2] = true;
            k_mod_p += 2;
            if (k_mod_p >= p) k_mod_p -= p;
            k_minus_1_mod += 2;
            if (k_minus_1_mod >= p - 1) k_minus_1_mod -= p - 1;
        }
    }
    for (u64 i = 1; i < slots; ++i) {
        if (composite[i] && !not_korselt[i]) lists.carmichael.push_back(2 * i + 1);
    }

    worker(0);
    for (auto& t : pool) t.join();
    std::vector<std::pair<u64, bool>> all;
    for (const auto& f : found) all.insert(all.end(), f.begin(), f.end());
    std::sort(all.begin(), all.end());
    for (const auto& [n, strong] : all) {
        lists.psp.push_back(n);
        if (strong) lists.spsp.push_back(n);
    }
    return lists;
}

/// Strong base-2 test with GMP, as an independent check of base2_tests().
bool strong2_gmp(u64 n) {
    mpz_t nn, d, x, nm1, two;
    mpz_inits(nn, d, x, nm1, two, nullptr);
    mpz_set_ui(nn, n);
    mpz_set_ui(two, 2);
    mpz_sub_ui(nm1, nn, 1);
    const unsigned long s = mpz_scan1(nm1, 0);
    mpz_tdiv_q_2exp(d, nm1, s);
    mpz_powm(x, two, d, nn);
    bool result = mpz_cmp_ui(x, 1) == 0 || mpz_cmp(x, nm1) == 0;
    for (unsigned long i = 1; i < s && !result; ++i) {
        mpz_powm_ui(x, x, 2, nn);
        result = mpz_cmp(x, nm1) == 0;
    }
    mpz_clears(nn, d, x, nm1, two, nullptr);
    return result;
}

/// Montgomery exponentiation against GMP for random odd moduli and exponents.
bool check_montgomery_against_gmp() {
    std::mt19937_64 rng(20240601);
    mpz_t base, e, n, r;
    mpz_inits(base, e, n, r, nullptr);
    mpz_set_ui(base, 2);
    bool ok = true;
    for (int i = 0; i < 200000 && ok; ++i) {
        const int bits = 2 + static_cast<int>(rng() % 62);  // moduli 3 .. 2^63 - 1
        u64 modulus = (rng() >> (64 - bits)) | 1;
        if (modulus < 3) modulus = 3;
        const u64 exponent = rng() >> (rng() % 64);
        const Montgomery m(modulus);
        mpz_set_ui(n, modulus);
        mpz_set_ui(e, exponent);
        mpz_powm(r, base, e, n);
        ok = m.to_plain(m.pow2(exponent)) == mpz_get_ui(r);
    }
    mpz_clears(base, e, n, r, nullptr);
    return ok;
}

std::vector<u64> below(const std::vector<u64>& v, u64 limit) {
    return {v.begin(), std::lower_bound(v.begin(), v.end(), limit)};
}

/// Reports the first difference between two sorted lists.
bool same_list(const std::vector<u64>& expected, const std::vector<u64>& got, const std::string& what) {
    if (expected == got) return true;
    std::vector<u64> missing, extra;
    std::set_difference(expected.begin(), expected.end(), got.begin(), got.end(), std::back_inserter(missing));
    std::set_difference(got.begin(), got.end(), expected.begin(), expected.end(), std::back_inserter(extra));
    std::cout << "MISMATCH " << what << ": " << missing.size() << " missing" << (missing.empty() ? "" : " (first ")
              << (missing.empty() ? "" : std::to_string(missing.front()) + ")") << ", " << extra.size() << " extra"
              << (extra.empty() ? "" : " (first " + std::to_string(extra.front()) + ")") << "\n";
    return false;
}

bool compare_lists(const Lists& reference, u64 limit, const Lists& got, const std::string& label) {
    bool ok = same_list(below(reference.psp, limit), got.psp, label + " psp2");
    ok &= same_list(below(reference.spsp, limit), got.spsp, label + " spsp2");
    ok &= same_list(below(reference.carmichael, limit), got.carmichael, label + " carmichael");
    return ok;
}

int self_check(const Config& base) {
    const auto start = std::chrono::steady_clock::now();
    const u64 limit = base.limit;
    bool ok = true;

    const bool mont_ok = check_montgomery_against_gmp();
    std::cout << "Montgomery 2^e mod n vs GMP (200000 random cases): " << (mont_ok ? "ok" : "FAILED") << "\n";
    ok &= mont_ok;

    auto t = std::chrono::steady_clock::now();
    const Lists reference = brute_force(limit, base.threads);
    std::cout << "brute force below " << limit << ": psp2 " << reference.psp.size() << ", spsp2 "
              << reference.spsp.size() << ", carmichael " << reference.carmichael.size() << " ("
              << seconds_since(t) << " s)\n";

    // Independent checks of the reference itself.
    std::size_t strong_mismatch = 0, korselt_mismatch = 0;
    std::vector<u64> carmichael_from_psp;
    const std::vector<u32> primes = odd_primes_upto(isqrt(limit) + 1);
    for (const u64 n : reference.psp) {
        const bool in_spsp = std::binary_search(reference.spsp.begin(), reference.spsp.end(), n);
        if (strong2_gmp(n) != in_spsp) ++strong_mismatch;
        if (is_carmichael(n, primes)) carmichael_from_psp.push_back(n);
    }
    for (const u64 n : reference.spsp) {
        if (!std::binary_search(reference.psp.begin(), reference.psp.end(), n)) ++strong_mismatch;
    }
    for (const u64 n : reference.carmichael) {
        if (!is_carmichael(n, primes)) ++korselt_mismatch;
    }
    std::cout << "reference spsp2 vs GMP strong test: " << (strong_mismatch == 0 ? "ok" : "FAILED") << "\n";
    std::cout << "reference Carmichael sieve vs Korselt on psp2 list (every Carmichael number is a psp2): "
              << (korselt_mismatch == 0 && carmichael_from_psp == reference.carmichael ? "ok" : "FAILED") << "\n";
    ok &= strong_mismatch == 0 && korselt_mismatch == 0 && carmichael_from_psp == reference.carmichael;

    for (u64 p = 10; p <= limit; p *= 10) {
        const Lists prefix{below(reference.psp, p), below(reference.spsp, p), below(reference.carmichael, p)};
        ok &= check_published(p, prefix, "brute-force");
    }

    // The fast method at many limits (edge cases around 341 = 11*31 and 561,
    // powers of ten, non-round limits), with the default configuration.
    std::vector<u64> limits = {0, 1, 2, 3, 4, 5, 10, 100, 341, 342, 561, 562, 1000, 1105, 1106, 2047, 2048,
                               12345, 100000, 314159, 1000000, 2718281, 10000000, 31415926, 99999999};
    limits.push_back(limit);
    t = std::chrono::steady_clock::now();
    std::size_t runs = 0;
    bool all_limits_ok = true;
    for (const u64 x : limits) {
        if (x > limit) continue;
        Config cfg = base;
        cfg.limit = x;
        all_limits_ok &= compare_lists(reference, x, fast_lists(cfg), "fast(limit " + std::to_string(x) + ")");
        ++runs;
    }
    std::cout << "fast method, default settings, " << runs << " limits up to " << limit << ": "
              << (all_limits_ok ? "ok" : "FAILED") << " (" << seconds_since(t) << " s)\n";
    ok &= all_limits_ok;

    // The other code paths: no gp (every order walked), walk only (no DFS;
    // slow for P = 3, 5, 7, so at most 10^7), DFS for every case-A prime.
    struct Variant {
        const char* name;
        u64 limit;
        u64 gp_max_order;
        u64 dfs_min_walk;
    };
    const Variant variants[] = {{"without gp", limit, 0, base.dfs_min_walk},
                                {"case A walk only", std::min<u64>(limit, 10'000'000), base.gp_max_order, ~0ULL},
                                {"case A DFS only", limit, base.gp_max_order, 0}};
    for (const Variant& v : variants) {
        t = std::chrono::steady_clock::now();
        Config cfg = base;
        cfg.limit = v.limit;
        cfg.gp_max_order = v.gp_max_order;
        cfg.dfs_min_walk = v.dfs_min_walk;
        const bool same = compare_lists(reference, v.limit, fast_lists(cfg), std::string("fast ") + v.name);
        std::cout << "fast method " << v.name << " below " << v.limit << ": " << (same ? "ok" : "FAILED") << " ("
                  << seconds_since(t) << " s)\n";
        ok &= same;
    }

    std::cout << (ok ? "SELF-CHECK PASSED" : "SELF-CHECK FAILED") << " (" << seconds_since(start) << " s)\n";
    return ok ? 0 : 1;
}

// ---------------------------------------------------------------------------
// Command line
// ---------------------------------------------------------------------------

/// Parses "12345", "1e10" or "10^10".
u64 parse_limit(const std::string& text) {
    auto digits = [](const std::string& s) {
        if (s.empty() || s.size() > 19 || s.find_first_not_of("0123456789") != std::string::npos) {
            throw std::invalid_argument("bad number: " + s);
        }
        return std::stoull(s);
    };
    std::size_t pos;
    if ((pos = text.find('e')) != std::string::npos || (pos = text.find("10^")) != std::string::npos) {
        const bool caret = text.compare(0, 3, "10^") == 0;
        const u64 mantissa = caret ? 1 : digits(text.substr(0, pos));
        const u64 exponent = digits(text.substr(caret ? 3 : pos + 1));
        u64 value = mantissa;
        for (u64 i = 0; i < exponent; ++i) {
            if (value > 10'000'000'000'000ULL) throw std::invalid_argument("limit too large: " + text);
            value *= 10;
        }
        return value;
    }
    return digits(text);
}

void usage() {
    std::cerr << "usage: pseudoprimes [--limit X] [--threads N] [--gp PATH] [--verbose] OUTDIR\n"
                 "       pseudoprimes --self-check [--limit X] [--threads N] [--gp PATH] [--verbose]\n"
                 "X defaults to 10^10 (10^7 for --self-check); numbers below X are listed.\n"
                 "Tuning (results do not depend on them): --gp-max-order L (default 128; 0 = no gp),\n"
                 "--dfs-min-walk W (default 30000; 0 = DFS for every small prime).\n";
}

bool write_list(const std::filesystem::path& path, const std::vector<u64>& numbers) {
    std::ofstream out(path);
    for (const u64 n : numbers) out << n << '\n';
    out.close();
    return static_cast<bool>(out);
}

}  // namespace

int main(int argc, char** argv) {
    Config cfg;
    cfg.threads = std::clamp(std::thread::hardware_concurrency(), 1u, 2u);
    bool run_self_check = false;
    bool limit_given = false;
    std::string outdir;
    try {
        for (int i = 1; i < argc; ++i) {
            const std::string arg = argv[i];
            auto value = [&]() -> std::string {
                if (i + 1 >= argc) throw std::invalid_argument(arg + " needs a value");
                return argv[++i];
            };
            if (arg == "--limit") {
                cfg.limit = parse_limit(value());
                limit_given = true;
            } else if (arg == "--threads") {
                cfg.threads = static_cast<unsigned>(std::clamp<u64>(parse_limit(value()), 1, 64));
            } else if (arg == "--gp") {
                cfg.gp = value();
            } else if (arg == "--gp-max-order") {
                cfg.gp_max_order = parse_limit(value());
            } else if (arg == "--dfs-min-walk") {
                cfg.dfs_min_walk = parse_limit(value());
            } else if (arg == "--verbose") {
                cfg.verbose = true;
            } else if (arg == "--self-check") {
                run_self_check = true;
            } else if (arg == "--help" || arg == "-h") {
                usage();
                return 0;
            } else if (!arg.empty() && arg[0] != '-' && outdir.empty()) {
                outdir = arg;
            } else {
                throw std::invalid_argument("unexpected argument: " + arg);
            }
        }
        if (cfg.gp.find('\'') != std::string::npos) throw std::invalid_argument("--gp path must not contain '");
        if (cfg.limit > 1'000'000'000'000ULL) throw std::invalid_argument("limit above 10^12 is not supported");

        if (run_self_check) {
            if (!limit_given) cfg.limit = 10'000'000ULL;
            return self_check(cfg);
        }
        if (outdir.empty()) {
            usage();
            return 2;
        }

        const auto start = std::chrono::steady_clock::now();
        const Lists lists = fast_lists(cfg);
        const double elapsed = seconds_since(start);
        std::filesystem::create_directories(outdir);
        const std::filesystem::path dir(outdir);
        if (!write_list(dir / "psp2.txt", lists.psp) || !write_list(dir / "spsp2.txt", lists.spsp) ||
            !write_list(dir / "carmichael.txt", lists.carmichael)) {
            std::cerr << "pseudoprimes: cannot write to " << outdir << "\n";
            return 1;
        }
        std::cout << "psp2 " << lists.psp.size() << "\n"
                  << "spsp2 " << lists.spsp.size() << "\n"
                  << "carmichael " << lists.carmichael.size() << "\n";
        std::cerr << "pseudoprimes below " << cfg.limit << " computed in " << elapsed << " s with " << cfg.threads
                  << " thread(s)\n";
        return check_published(cfg.limit, lists, "computed") ? 0 : 1;
    } catch (const std::exception& e) {
        std::cerr << "pseudoprimes: " << e.what() << "\n";
        return 2;
    }
}
