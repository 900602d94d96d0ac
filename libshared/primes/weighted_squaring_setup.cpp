/// @file weighted_squaring_setup.cpp
/// @brief WeightedSquaring's choice of length and digits, its tables, and
/// the conversions between GMP integers and its digits.
#include <fftw3.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <string_view>
#include <vector>

#include "primes/fft_plans.hpp"
#include "primes/proof_threads.hpp"
#include "primes/right_angle_transform.hpp"
#include "primes/weighted_squaring.hpp"
#include "primes/weighted_squaring_detail.hpp"

namespace tk::primes {

namespace {

using namespace weighted_detail;

constexpr unsigned kMaxKBits = 56;

// The largest average digit size whose squares round safely at this
// length. Measured here on random balanced digits of one size (44-bit k,
// L from 64 to 2^18): the worst rounding error grows 4x per digit bit and
// about 1.25x per doubled length, and this rule keeps it near 0.05. Mixed
// sizes (the weights) roughly double it: 0.125 at L = 18432 (n = 171960,
// 20.3 bits), 0.156 at L = 3584 (n = 36627); 0.4 is what is checked.
double max_average_bits(std::size_t length) { return 25.0 - 0.31 * std::log2(static_cast<double>(length)); }

// TOOLKIT_RIESEL_TRANSFORM=fftw or avx2 asks for FFTW's transform, or for
// ours at AVX2 width where the CPU has AVX-512 (tests compare them).
WeightedSquaring::Transform transform_wanted() {
  static const char* wanted = std::getenv("TOOLKIT_RIESEL_TRANSFORM");
  const std::string_view name = wanted ? wanted : "";
  if (name == "fftw") return WeightedSquaring::Transform::fftw;
  return name == "avx2" ? WeightedSquaring::Transform::avx2 : WeightedSquaring::Transform::widest;
}

bool fits_weighted_squaring(const SpecialForm& form) {
  return form.n >= 64 && (form.c == 1 || form.c == -1) && form.k % 2 == 1 && std::bit_width(form.k) <= kMaxKBits;
}

// Digits above 2^n: the folded value is below about 2^(n + kbits + 2),
// and its square must fit below digit 2(m + t) - 1, at 2^(2n + e_(2t-1)).
std::size_t top_digits(const SpecialForm& form, std::size_t low_digits) {
  const double average = static_cast<double>(form.n) / static_cast<double>(low_digits);
  const double kbits = std::bit_width(form.k);
  return static_cast<std::size_t>(std::ceil((kbits + 3.0) / average + 0.5));
}

std::size_t low_digits_for(std::uint64_t n, double bits) {
  return static_cast<std::size_t>(std::ceil(static_cast<double>(n) / bits));
}

// Where the rule's digits just miss a length, up to this much more is
// taken to reach it (digits otherwise stay the rule's): measured, n =
// 171960 at L = 16384 with 21.0-bit digits (the rule's 20.66 would need
// 18432) rounds within 0.25 over the whole proof with no square redone,
// 12 % faster. The checks (0.4, and the exact sum mod 2^61 - 1) still
// guard every square.
constexpr double kStretchBits = 0.35;

// The low digits for this length: the rule's where they fit, else the
// stretched rule's; 0 where neither fits.
std::size_t low_digits_at(const SpecialForm& form, std::size_t length) {
  for (double bits : {max_average_bits(length), max_average_bits(length) + kStretchBits}) {
    const std::size_t low = low_digits_for(form.n, bits);
    if (2 * (low + top_digits(form, low)) - 1 <= length) return low;
  }
  return 0;
}

bool fast_fft_lengths_contain(std::size_t length) {
  const auto& lengths = fast_fft_lengths();
  return std::binary_search(lengths.begin(), lengths.end(), length);
}

// Which FFTW length is fastest depends on its factors in ways no simple
// rule captured here (15*2^a and 135*2^a are sometimes faster than the
// shorter 2^a and 9*2^a, sometimes slower). From this length on, the
// first few that fit are timed on a few squarings (a few milliseconds, with
// plans estimated in microseconds), and the fastest is kept.
constexpr std::size_t kTimeFromLength = 8192;
constexpr std::size_t kTimedCandidates = 3;
// Eight turns, not four: at n = 171960 four chose the 10 % slower 18432 in
// 3 of 90 runs, eight in 1 of 90.
constexpr int kTimingTurns = 8, kSquaringsPerTurn = 8;

const std::vector<std::size_t>& candidate_lengths() {
  static const std::vector<std::size_t> lengths = [] {
    std::vector<std::size_t> all = fast_fft_lengths();
    for (std::size_t power = 64; power <= (std::size_t{1} << 22); power *= 2) {
      for (std::size_t odd : {15, 27, 135})
        if (odd * power >= kTimeFromLength) all.push_back(odd * power);
      // Only ours plans these below the timed lengths (FFTW's list has
      // no 27 or 81): 3456 = 27*128 takes the seed's n = 36627 at the
      // rule's digits, 10 to 14 % faster than 4096.
      for (std::size_t odd : {27, 81})
        if (odd * power < kTimeFromLength) all.push_back(odd * power);
    }
    std::sort(all.begin(), all.end());
    all.erase(std::unique(all.begin(), all.end()), all.end());
    return all;
  }();
  return lengths;
}

double thread_cpu_seconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + static_cast<double>(now.tv_nsec) * 1e-9;
}

double seconds_for_squarings(WeightedSquaring& squarer, int count) {
  const double start = thread_cpu_seconds();
  for (int i = 0; i < count; ++i) squarer.square_minus(2);
  return thread_cpu_seconds() - start;
}

// The fastest of the candidates: each is timed in short turns, taken in
// rotation, and judged by its best turn, which other jobs on the machine
// disturb least (one long turn each picked the slower length at times).
std::unique_ptr<WeightedSquaring> fastest(std::vector<std::unique_ptr<WeightedSquaring>> candidates,
                                          const mpz_class& N) {
  if (candidates.size() == 1) return std::move(candidates.front());
  gmp_randclass random(gmp_randinit_default);
  random.seed(23);
  const mpz_class x = random.get_z_range(N);
  std::vector<double> best(candidates.size(), 1e300);
  for (auto& candidate : candidates) {
    candidate->load(x);
    seconds_for_squarings(*candidate, 4);  // caches and pages warm
  }
  for (int turn = 0; turn < kTimingTurns; ++turn)
    for (std::size_t i = 0; i < candidates.size(); ++i)
      best[i] = std::min(best[i], seconds_for_squarings(*candidates[i], kSquaringsPerTurn));
  const auto winner = std::min_element(best.begin(), best.end()) - best.begin();
  return std::move(candidates[static_cast<std::size_t>(winner)]);
}

}  // namespace

std::unique_ptr<WeightedSquaring> WeightedSquaring::create(const SpecialForm& form) {
  if (!fits_weighted_squaring(form)) return nullptr;
  std::vector<std::unique_ptr<WeightedSquaring>> candidates;
  const Transform transform = transform_wanted();
  // Below the timed lengths ours is taken at AVX-512 width only: at AVX2
  // width it is no faster than FFTW's at 4096 (bench_riesel).
  const bool own_transform =
      transform == Transform::avx2 || (transform == Transform::widest && RightAngleSquarer::widest_lanes() == 8);
  for (std::size_t length : candidate_lengths()) {
    const bool short_length = length < kTimeFromLength;
    // Below the timed lengths: the first our transform plans (1.45 times
    // FFTW's speed at 4096 with AVX-512, bench_riesel), else FFTW's first.
    if (short_length && !(own_transform ? RightAngleSquarer::supports(length) : fast_fft_lengths_contain(length)))
      continue;
    const std::size_t low = low_digits_at(form, length);
    if (low == 0) continue;
    // FFTW's below the timed lengths unless ours was taken there (not at AVX2 width by default)
    const Transform used = short_length && !own_transform ? Transform::fftw : transform;
    candidates.emplace_back(new WeightedSquaring(form, length, low, used));
    if (short_length || candidates.size() == kTimedCandidates) break;
  }
  if (candidates.empty()) return nullptr;
  auto chosen = fastest(std::move(candidates), modulus_of(form));
  chosen->load(0);
  return chosen;
}

std::unique_ptr<WeightedSquaring> WeightedSquaring::create_with(const SpecialForm& form, std::size_t length,
                                                                double average_bits, Transform transform) {
  if (!fits_weighted_squaring(form) || !(average_bits >= 4 && average_bits <= 40) || length % 2 != 0) return nullptr;
  const std::size_t low = low_digits_for(form.n, average_bits);
  if (2 * (low + top_digits(form, low)) - 1 > length) return nullptr;
  std::unique_ptr<WeightedSquaring> squarer(new WeightedSquaring(form, length, low, transform));
  squarer->load(0);
  return squarer;
}

std::string WeightedSquaring::transform_name() const {
  return right_angle_ ? "right-angle, " + std::to_string(right_angle_->lanes()) + " lanes" : "FFTW";
}

WeightedSquaring::WeightedSquaring(const SpecialForm& form, std::size_t length, std::size_t low_digits,
                                   Transform transform)
    : form_(form), length_(length), low_digits_(low_digits) {
  digits_ = low_digits + top_digits(form, low_digits);
  coefficients_ = 2 * digits_ - 1;
  const std::uint64_t n = form.n, m = low_digits;
  exponent_.resize(coefficients_ + 1);
  for (std::size_t j = 0; j <= coefficients_; ++j) exponent_[j] = (n * j + m - 1) / m;  // ceil(n*j/m)
  bits_.resize(coefficients_);
  rotation_.resize(coefficients_);
  output_weight_.resize(coefficients_);
  input_weight_.resize(digits_);
  for (std::size_t j = 0; j < coefficients_; ++j) {
    bits_[j] = static_cast<std::uint8_t>(exponent_[j + 1] - exponent_[j]);
    max_digit_bits_ = std::max<int>(max_digit_bits_, bits_[j]);
    rotation_[j] = exponent_[j] % 61;
    // e_j - n*j/m = (e_j*m - n*j)/m, exactly in integers, in [0, 1).
    const auto excess = static_cast<long double>(exponent_[j] * m - n * j) / static_cast<long double>(m);
    output_weight_[j] = static_cast<double>(std::exp2(-excess) / static_cast<long double>(length));
    if (j < digits_) input_weight_[j] = static_cast<double>(std::exp2(excess));
  }
  coefficient_.assign(length, 0);
  rotation_.resize(length, 0);
  bits_.resize(length + 8, 0);   // the fused carries read whole vectors past the last coefficient
  digit_.assign(length / 2, 0);  // zero past digits_: the transform's first pass may read them
  modulus_mod_p_ = mpz_fdiv_ui(modulus_of(form).get_mpz_t(), kP61);
  k_mod_p_ = form.k % kP61;
  two_n_mod_p_ = times_power61(1, static_cast<unsigned>(n % 61));
  inverse_two_n_mod_p_ = times_power61(1, static_cast<unsigned>((61 - n % 61) % 61));
  split_k();
  if (transform != Transform::fftw)
    right_angle_ = RightAngleSquarer::create(
        length_, transform == Transform::avx2 ? RightAngleSquarer::Simd::avx2 : RightAngleSquarer::Simd::best);
  wide_ = right_angle_ ? right_angle_->lanes() == 8 : transform != Transform::avx2;
  if (right_angle_) {
    right_angle_weights();
    weigh_in_transform_ = right_angle_->lanes() == 8;
    product_.assign(digit_.size(), 0);  // the fused square's next digits
    return;
  }
  // FFTW's arrays, only where FFTW squares (ours works in its own).
  input_ = fftw_alloc_real(length_);
  output_ = fftw_alloc_real(length_);
  spectrum_ = fftw_alloc_complex(length_ / 2 + 1);
  std::fill(input_, input_ + length_, 0.0);
  plans_ = real_fft_plans(length_);
}

// k = k_high_*2^S + k_low_ with S the largest digit size. A digit d below
// 2^B multiplies into k_low_*d < 2^(S+B) and, moved one digit up,
// k_high_*d*2^(S - s) < 2^(kbits - s_min + B): B = 60 - the larger exponent
// keeps a product digit (two of those and a digit) below 2^62. Full
// balancing leaves |d| <= 2^(S-1) + 1, so B must exceed S (it does for
// every length create() picks: S <= 25).
void WeightedSquaring::split_k() {
  const int s_max = max_digit_bits_;
  const int s_min = *std::min_element(bits_.begin(), bits_.begin() + static_cast<std::ptrdiff_t>(coefficients_));
  const int kbits = std::bit_width(form_.k);
  k_low_ = static_cast<std::int64_t>(form_.k & ((std::uint64_t{1} << s_max) - 1));
  k_high_ = static_cast<std::int64_t>(form_.k >> s_max);
  digit_bound_bits_ = 60 - std::max(s_max, kbits - s_min);
  multiplies_in_64_bits_ = digit_bound_bits_ > s_max;
}

// The right-angle transform gives N (not L) times the square, times
// theta^j: its weights fold theta^-j and 2 into the digits' weights.
void WeightedSquaring::right_angle_weights() {
  const std::size_t half = length_ / 2;
  const double* cosine = right_angle_->theta_cos();
  const double* sine = right_angle_->theta_sin();
  re_weight_.assign(half, 0.0);  // zero past digits_, read with the zero digits there
  im_weight_.assign(half, 0.0);
  for (std::size_t j = 0; j < digits_; ++j) {
    re_weight_[j] = input_weight_[j] * cosine[j];
    im_weight_[j] = input_weight_[j] * sine[j];
  }
  round_a_.assign(half, 0.0);
  round_b_.assign(half, 0.0);
  round_c_.assign(half, 0.0);
  round_d_.assign(half, 0.0);
  for (std::size_t j = 0; j < half; ++j) {
    if (j < coefficients_) {
      round_a_[j] = 2 * output_weight_[j] * cosine[j];
      round_b_[j] = 2 * output_weight_[j] * sine[j];
    }
    if (j + half < coefficients_) {
      round_c_[j] = 2 * output_weight_[j + half] * cosine[j];
      round_d_[j] = 2 * output_weight_[j + half] * sine[j];
    }
  }
}

WeightedSquaring::~WeightedSquaring() {
  if (!input_) return;
  fftw_free(input_);
  fftw_free(output_);
  fftw_free(spectrum_);
}

}  // namespace tk::primes
