/// @file right_angle_transform.hpp
/// @brief The acyclic square of a real sequence by one complex transform of
/// half its length: the right-angle convolution of Crandall and Fagin
/// (1994). A real sequence x of length L = 2N taken modulo X^L + 1 is the
/// complex sequence c_j = (x_j + i*x_(j+N)) * theta^j, theta = e^(i*pi/L),
/// taken cyclically modulo Z^N - 1; with x zero from N on (the padding) and
/// the square's 2N - 1 coefficients fitting below L, the negacyclic square
/// is the acyclic one. The transform is our own: split real and imaginary
/// arrays, radix-3, radix-4 and radix-2 passes as SIMD over 8 (AVX-512) or
/// 4 (AVX2) neighbouring butterflies, the last passes and the pointwise
/// square done in registers, the inner passes one L1-sized block at a time;
/// the forward passes leave the spectrum in digit-reversed order and the
/// inverse ones take it so, so no pass reorders.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace tk::primes {

namespace right_angle {
struct Arrays;
}

class RightAngleSquarer {
 public:
  enum class Simd { best, avx2, avx512 };

  /// Nothing where the CPU lacks the SIMD asked for (AVX2 with FMA at
  /// least) or L/2 is not w * 2^a * 3^b, at least 4w (w the SIMD width).
  static std::unique_ptr<RightAngleSquarer> create(std::size_t length, Simd simd = Simd::best);
  /// The shortest transform of at least `minimum` real points (L = 2^a *
  /// 3^b times 8 lanes, b <= 5), or nothing as create().
  static std::unique_ptr<RightAngleSquarer> create_at_least(std::size_t minimum, Simd simd = Simd::best);
  /// Whether `length` (L) has a transform on this CPU.
  static bool supports(std::size_t length);
  /// The widest SIMD this CPU gives it: 8 (AVX-512), 4 (AVX2) or 0.
  static int widest_lanes();

  RightAngleSquarer(const RightAngleSquarer&) = delete;
  RightAngleSquarer& operator=(const RightAngleSquarer&) = delete;
  ~RightAngleSquarer();

  /// output[0..L) = L * the acyclic square of input[0..L/2), the same
  /// scaling as FFTW's unnormalised real transforms give (fft_plans.hpp);
  /// input[L/2..L) is not read. The arrays may be the same.
  void square(const double* input, double* output);

  /// The same square in place, for callers that weight and unweight
  /// themselves: real()/imaginary() hold c_j (theta^j and all) before and
  /// N times the cyclic square after, j < N; the square's coefficient j is
  /// then Re and its coefficient j + N is Im of that times theta^-j / N.
  void square_in_place();
  /// square_in_place() on c_j = digits[j] * (weight_re[j] + i*weight_im[j]),
  /// j < N, read by the first forward pass itself (no pass of its own);
  /// the same result as writing c_j into real()/imaginary() first.
  void square_in_place_from(const std::int64_t* digits, const double* weight_re, const double* weight_im);
  /// The same square split up, for products and for sums of products in
  /// the spectrum (transform_reduction): forward_in_place() turns c_j into
  /// its spectrum (in an order of the transform's own, the same every
  /// time), inverse_in_place() turns a spectrum into N times its cyclic
  /// sequence; a spectrum copied out of real()/imaginary() after
  /// forward_in_place() can be kept and multiplied in: multiply_pointwise
  /// multiplies the spectrum held by it, multiply_in_place() does forward,
  /// product and inverse one L1 block at a time as square_in_place() does.
  /// forward_in_place(), square point by point, inverse_in_place() gives
  /// square_in_place()'s result (up to rounding).
  void forward_in_place();
  void inverse_in_place();
  void multiply_pointwise(const double* spectrum_re, const double* spectrum_im);
  void multiply_in_place(const double* spectrum_re, const double* spectrum_im);
  std::size_t points() const { return half_; }  ///< N, the length of real()/imaginary()

  double* real() { return re_; }
  double* imaginary() { return im_; }
  const double* theta_cos() const { return theta_cos_; }  ///< cos(pi*j/L), j < N
  const double* theta_sin() const { return theta_sin_; }

  std::size_t length() const { return 2 * half_; }
  int lanes() const { return lanes_; }

  /// One pass of the transform: a radix-r butterfly on every r points
  /// `block`/r apart within each block, the twiddles of stage `twiddles`.
  struct Stage {
    int radix;
    std::size_t block;
    std::size_t twiddles;  ///< offset of its (radix - 1) * block / radix twiddles
  };

 private:
  RightAngleSquarer(std::size_t half, int lanes, std::vector<Stage> stages);
  right_angle::Arrays arrays() const;

  std::size_t half_;  ///< N = L/2 complex points
  int lanes_;
  std::vector<Stage> stages_;
  std::size_t inner_from_ = 0;  ///< stages from here on run one block at a time
  std::size_t inner_block_ = 0;
  double* buffer_ = nullptr;  ///< one aligned allocation for all the arrays below
  double* re_ = nullptr;
  double* im_ = nullptr;
  double* twiddle_re_ = nullptr;
  double* twiddle_im_ = nullptr;
  double* theta_cos_ = nullptr;  ///< cos(pi*j/L), j < N
  double* theta_sin_ = nullptr;
  // square_in_place_from()'s input, for the length of that call.
  const std::int64_t* source_digits_ = nullptr;
  const double* source_weight_re_ = nullptr;
  const double* source_weight_im_ = nullptr;

  // ---- One square split over threads (weighted_squaring_split.cpp) ----
 public:
  /// square_in_place() in parts: outer_passes(true, ...) on every part's
  /// columns, then (after all) inner_passes on every part's blocks, then
  /// (after all) outer_passes(false, ...). Points are split by their index
  /// modulo split_period() (Q): the outer passes on columns [from, to) of
  /// every Q touch only those points, so one thread runs them all with no
  /// barrier between; the inner passes work on blocks of Q points.
  std::size_t split_period() const { return inner_block_; }
  std::size_t inner_blocks() const { return half_ / inner_block_; }
  void outer_passes(bool forward, std::size_t from, std::size_t to);
  void inner_passes(std::size_t first_block, std::size_t last_block);
};

}  // namespace tk::primes
