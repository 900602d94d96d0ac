/// @file right_angle_transform.cpp
/// @brief RightAngleSquarer's plan (which passes, which twiddles) and the
/// choice of SIMD width at run time.
#include "primes/right_angle_transform.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <new>

#include "primes/cpu_features.hpp"
#include "primes/right_angle_kernels.hpp"

namespace tk::primes {

namespace {

// Passes on blocks of up to this many points run one block at a time, so
// a block (16 bytes a point) and its twiddles stay in a 48 KB L1 cache.
constexpr std::size_t kInnerBlockPoints = 1024;

bool cpu_has(RightAngleSquarer::Simd simd) {
  return simd == RightAngleSquarer::Simd::avx512 ? cpu::has_avx512() : cpu::has_avx2();
}

int lanes_of(RightAngleSquarer::Simd simd) {
  if (simd == RightAngleSquarer::Simd::best)
    simd = cpu_has(RightAngleSquarer::Simd::avx512) ? RightAngleSquarer::Simd::avx512 : RightAngleSquarer::Simd::avx2;
  return simd == RightAngleSquarer::Simd::avx512 ? 8 : 4;
}

// Radix-3 passes first (on the largest blocks), then one radix-2 pass if
// the power of two left is an odd power of 4 over the lanes, then radix-4
// passes down to blocks of one vector, which LanePasses finishes.
std::vector<RightAngleSquarer::Stage> plan(std::size_t half, int lanes) {
  std::vector<RightAngleSquarer::Stage> stages;
  if (half % static_cast<std::size_t>(lanes) != 0) return stages;
  std::size_t rest = half / static_cast<std::size_t>(lanes), block = half, twiddles = 0;
  auto add = [&](int radix) {
    stages.push_back({radix, block, twiddles});
    twiddles += static_cast<std::size_t>(radix - 1) * (block / static_cast<std::size_t>(radix));
    block /= static_cast<std::size_t>(radix);
    rest /= static_cast<std::size_t>(radix);
  };
  while (rest % 3 == 0) add(3);
  int twos = 0;
  for (std::size_t r = rest; r % 2 == 0; r /= 2) ++twos;
  if ((std::size_t{1} << twos) != rest) return {};
  if (twos % 2 == 1) add(2);
  while (rest > 1) add(4);
  return stages;
}

std::size_t twiddle_count(const std::vector<RightAngleSquarer::Stage>& stages) {
  std::size_t count = 0;
  for (const auto& s : stages)
    count += static_cast<std::size_t>(s.radix - 1) * (s.block / static_cast<std::size_t>(s.radix));
  return count;
}

// Whether L/2 = lanes * 3^b * 2^c with at least one pass.
bool plannable(std::size_t length, int lanes) {
  return length % 2 == 0 && length / 2 >= 4 * static_cast<std::size_t>(lanes) && !plan(length / 2, lanes).empty();
}

}  // namespace

int RightAngleSquarer::widest_lanes() { return cpu_has(Simd::best) ? lanes_of(Simd::best) : 0; }

bool RightAngleSquarer::supports(std::size_t length) {
  return cpu_has(Simd::best) && plannable(length, lanes_of(Simd::best));
}

std::unique_ptr<RightAngleSquarer> RightAngleSquarer::create(std::size_t length, Simd simd) {
  if (!cpu_has(simd) || !plannable(length, lanes_of(simd))) return nullptr;
  const int lanes = lanes_of(simd);
  return std::unique_ptr<RightAngleSquarer>(new RightAngleSquarer(length / 2, lanes, plan(length / 2, lanes)));
}

std::unique_ptr<RightAngleSquarer> RightAngleSquarer::create_at_least(std::size_t minimum, Simd simd) {
  if (!cpu_has(simd)) return nullptr;
  const auto lanes = static_cast<std::size_t>(lanes_of(simd));
  std::size_t best = 0;
  for (std::size_t threes = 1; threes <= 243; threes *= 3)
    for (std::size_t length = 8 * lanes * threes; length < (std::size_t{1} << 40); length *= 2)
      if (length >= minimum) {
        if (best == 0 || length < best) best = length;
        break;
      }
  return best ? create(best, simd) : nullptr;
}

RightAngleSquarer::RightAngleSquarer(std::size_t half, int lanes, std::vector<Stage> stages)
    : half_(half), lanes_(lanes), stages_(std::move(stages)) {
  inner_from_ = 0;
  while (inner_from_ < stages_.size() && stages_[inner_from_].block > kInnerBlockPoints) ++inner_from_;
  inner_block_ = inner_from_ < stages_.size() ? stages_[inner_from_].block : static_cast<std::size_t>(lanes);
  const std::size_t twiddles = twiddle_count(stages_);
  // The arrays in one allocation, each kSkew doubles (17 cache lines)
  // past the end of the one before: arrays of a power-of-two length
  // would otherwise start at the same offset modulo 4 KB, and a pass
  // reading the same index of each would use one set of the L1 cache
  // (8 % per squaring at n = 171960 on the Intel host).
  constexpr std::size_t kSkew = 136;
  const std::size_t sizes[] = {half, half, half, half, twiddles, twiddles};
  std::size_t offsets[6] = {}, total = 0;
  for (std::size_t a = 0; a < 6; ++a) {
    offsets[a] = total;
    total += sizes[a] + kSkew;
  }
  buffer_ = static_cast<double*>(std::aligned_alloc(64, ((total * sizeof(double) + 63) / 64) * 64));
  if (!buffer_) throw std::bad_alloc();
  re_ = buffer_ + offsets[0];
  im_ = buffer_ + offsets[1];
  theta_cos_ = buffer_ + offsets[2];
  theta_sin_ = buffer_ + offsets[3];
  twiddle_re_ = buffer_ + offsets[4];
  twiddle_im_ = buffer_ + offsets[5];
  std::fill(re_, re_ + half, 0.0);  // a square before any input squares zeros
  std::fill(im_, im_ + half, 0.0);
  const long double pi = 3.141592653589793238462643383279502884L;
  for (std::size_t j = 0; j < half; ++j) {
    const long double angle = pi * static_cast<long double>(j) / static_cast<long double>(2 * half);
    theta_cos_[j] = static_cast<double>(std::cos(angle));
    theta_sin_[j] = static_cast<double>(std::sin(angle));
  }
  for (const Stage& stage : stages_) {
    const std::size_t part = stage.block / static_cast<std::size_t>(stage.radix);
    for (int t = 1; t < stage.radix; ++t)
      for (std::size_t j = 0; j < part; ++j) {
        // e^(-2*pi*i*j*t/B), the angle reduced exactly first
        const std::size_t turn = (j * static_cast<std::size_t>(t)) % stage.block;
        const long double angle = -2 * pi * static_cast<long double>(turn) / static_cast<long double>(stage.block);
        const std::size_t at = stage.twiddles + static_cast<std::size_t>(t - 1) * part + j;
        twiddle_re_[at] = static_cast<double>(std::cos(angle));
        twiddle_im_[at] = static_cast<double>(std::sin(angle));
      }
  }
}

RightAngleSquarer::~RightAngleSquarer() { std::free(buffer_); }

void RightAngleSquarer::square(const double* input, double* output) {
  const right_angle::Arrays arrays = this->arrays();
  if (lanes_ == 8) right_angle::square_avx512(arrays, input, output);
  else right_angle::square_avx2(arrays, input, output);
}

// By the split square's passes over every column and block: the same
// compiled code, so the same roundings, as a square split over threads
// (GCC fuses multiply-adds differently where the passes inline elsewhere).
void RightAngleSquarer::square_in_place() { square_in_place_from(nullptr, nullptr, nullptr); }

// No digits: the first pass reads real()/imaginary().
void RightAngleSquarer::square_in_place_from(const std::int64_t* digits, const double* weight_re,
                                             const double* weight_im) {
  source_digits_ = digits;
  source_weight_re_ = weight_re;
  source_weight_im_ = weight_im;
  outer_passes(true, 0, inner_block_);
  inner_passes(0, half_ / inner_block_);
  source_digits_ = nullptr;
  source_weight_re_ = source_weight_im_ = nullptr;
  outer_passes(false, 0, inner_block_);
}

void RightAngleSquarer::forward_in_place() {
  const right_angle::Arrays arrays = this->arrays();
  if (lanes_ == 8) right_angle::forward_avx512(arrays);
  else right_angle::forward_avx2(arrays);
}

void RightAngleSquarer::inverse_in_place() {
  const right_angle::Arrays arrays = this->arrays();
  if (lanes_ == 8) right_angle::inverse_avx512(arrays);
  else right_angle::inverse_avx2(arrays);
}

void RightAngleSquarer::multiply_pointwise(const double* spectrum_re, const double* spectrum_im) {
  const right_angle::Arrays arrays = this->arrays();
  if (lanes_ == 8) right_angle::pointwise_avx512(arrays, spectrum_re, spectrum_im);
  else right_angle::pointwise_avx2(arrays, spectrum_re, spectrum_im);
}

void RightAngleSquarer::multiply_in_place(const double* spectrum_re, const double* spectrum_im) {
  const right_angle::Arrays arrays = this->arrays();
  if (lanes_ == 8) right_angle::multiply_avx512(arrays, spectrum_re, spectrum_im);
  else right_angle::multiply_avx2(arrays, spectrum_re, spectrum_im);
}

right_angle::Arrays RightAngleSquarer::arrays() const {
  return {re_,
          im_,
          twiddle_re_,
          twiddle_im_,
          theta_cos_,
          theta_sin_,
          half_,
          stages_.data(),
          stages_.size(),
          inner_from_,
          inner_block_,
          source_digits_,
          source_weight_re_,
          source_weight_im_};
}

// ---- One square split over threads ----

void RightAngleSquarer::outer_passes(bool forward, std::size_t from, std::size_t to) {
  const right_angle::Arrays arrays = this->arrays();
  if (lanes_ == 8) right_angle::outer_columns_avx512(arrays, forward, from, to);
  else right_angle::outer_columns_avx2(arrays, forward, from, to);
}

void RightAngleSquarer::inner_passes(std::size_t first_block, std::size_t last_block) {
  const right_angle::Arrays arrays = this->arrays();
  if (lanes_ == 8) right_angle::inner_blocks_avx512(arrays, first_block, last_block);
  else right_angle::inner_blocks_avx2(arrays, first_block, last_block);
}

}  // namespace tk::primes
