/// @file transform_reduction.cpp
/// @brief TransformModulus: the lengths and stored spectra, and the
/// checked Barrett reduction on digits.
#include "primes/transform_reduction.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

#include "primes/transform_digits.hpp"

namespace tk::primes {

namespace {

namespace d18 = digits18;

// A coefficient is an integer give or take this much, or the step fails.
constexpr double kMaxRoundoff = 0.25;

// c_j = (x_j + i x_(j+h)) theta^j into the transform, x zero from `count` on.
TK_DIGIT_CLONES void weight_into(RightAngleSquarer& t, const double* x, std::size_t count) {
  const std::size_t h = t.points();
  double *re = t.real(), *im = t.imaginary();
  const double *c = t.theta_cos(), *s = t.theta_sin();
  const std::size_t low = std::min(count, h), high = count > h ? count - h : 0;
  for (std::size_t j = 0; j < high; ++j) {
    re[j] = x[j] * c[j] - x[j + h] * s[j];
    im[j] = x[j] * s[j] + x[j + h] * c[j];
  }
  for (std::size_t j = high; j < low; ++j) {
    re[j] = x[j] * c[j];
    im[j] = x[j] * s[j];
  }
  for (std::size_t j = low; j < h; ++j) re[j] = im[j] = 0.0;
}

// Coefficients [from, to) of the product the transform holds after its
// inverse, times `scale`, rounded into y[0..to - from); whether each was
// within kMaxRoundoff of its integer.
// (A flag, not the worst error, so the loops vectorise: a max of doubles
// is a serial chain to the compiler without -ffast-math.)
TK_DIGIT_CLONES bool unweight_into(RightAngleSquarer& t, double scale, std::size_t from, std::size_t to, double* y) {
  const std::size_t h = t.points();
  const double *re = t.real(), *im = t.imaginary(), *c = t.theta_cos(), *s = t.theta_sin();
  int bad = 0;
  // coefficient k < h is Re of the point k, k >= h Im of the point k - h
  for (std::size_t k = from; k < std::min(to, h); ++k) {
    const double v = scale * (re[k] * c[k] + im[k] * s[k]), rounded = d18::nearest(v);
    bad |= !(std::fabs(v - rounded) <= kMaxRoundoff);  // NaN too
    y[k - from] = rounded;
  }
  for (std::size_t k = std::max(from, h); k < to; ++k) {
    const std::size_t j = k - h;
    const double v = scale * (im[j] * c[j] - re[j] * s[j]), rounded = d18::nearest(v);
    bad |= !(std::fabs(v - rounded) <= kMaxRoundoff);
    y[k - from] = rounded;
  }
  return bad == 0;
}

// x's digits folded modulo 2^(18 length) + 1 into out[0..length), added to it.
TK_DIGIT_CLONES void fold_into(const double* x, std::size_t count, std::size_t length, double* out) {
  for (std::size_t base = 0, turn = 0; base < count; base += length, ++turn) {
    const std::size_t n = std::min(length, count - base);
    if (turn % 2 == 0)
      for (std::size_t j = 0; j < n; ++j) out[j] += x[base + j];
    else
      for (std::size_t j = 0; j < n; ++j) out[j] -= x[base + j];
  }
}

void keep_spectrum(RightAngleSquarer& t, std::vector<double>& re, std::vector<double>& im) {
  t.forward_in_place();
  re.assign(t.real(), t.real() + t.points());
  im.assign(t.imaginary(), t.imaginary() + t.points());
}

}  // namespace

TransformModulus::~TransformModulus() = default;

std::unique_ptr<TransformModulus> TransformModulus::create(const mpz_class& N, std::uint64_t spread,
                                                           RightAngleSquarer::Simd simd) {
  if (mpz_sizeinbase(N.get_mpz_t(), 2) <= 64 || mpz_even_p(N.get_mpz_t()) || spread == 0) return nullptr;
  std::unique_ptr<TransformModulus> m(new TransformModulus());
  m->n_ = N;
  m->bits_ = mpz_sizeinbase(N.get_mpz_t(), 2);
  const std::size_t nb = m->bits_;
  // |r| < 2.2 N < 2^(nb + 2) has no nearly balanced digit past (nb + 3) / 18.
  m->digits_ = (nb + 4) / d18::kBits + 1;
  const std::size_t M = m->digits_;
  // Each coefficient of a product of residues is at most M (2^17 + 1)^2,
  // times spread in a sum of products: below 2^50, where rounding is exact
  // and an error of 1/2 still shows.
  if (static_cast<double>(M) * static_cast<double>(spread) >= 65000.0) return nullptr;
  // |x y| < 0.27 * 2^(36 M), so |a| < 2^a_bits.
  const std::size_t a_bits = 36 * M + static_cast<std::size_t>(std::bit_width(spread)) - 1;
  m->low_shift_ = (nb - 1) / d18::kBits;  // 2^s1 <= 2^(nb - 1) <= N
  const std::size_t s1 = m->low_shift_ * d18::kBits;
  m->high_shift_ = (a_bits - s1 + d18::kBits - 1) / d18::kBits;  // 2^(s1 + s2) >= 2^a_bits > |a|
  mpz_class mu;
  mpz_ui_pow_ui(mu.get_mpz_t(), 2, s1 + m->high_shift_ * d18::kBits);
  mpz_fdiv_q(mu.get_mpz_t(), mu.get_mpz_t(), N.get_mpz_t());

  m->square_ = RightAngleSquarer::create_at_least(2 * M, simd);
  if (!m->square_) return nullptr;
  const std::size_t product_digits = m->square_->length() + 3;
  const std::size_t mu_digits = mpz_sizeinbase(mu.get_mpz_t(), 2) / d18::kBits + 2;
  const std::size_t quotient_digits = (a_bits + 1) / d18::kBits + 1 - m->low_shift_;
  m->quotient_digits_count_ = quotient_digits;
  m->quotient_ = RightAngleSquarer::create_at_least(mu_digits + quotient_digits, simd);
  // |r| < 2^(nb + 2) is then below 2^K / 8: its residue modulo 2^K + 1 is r.
  m->remainder_ = RightAngleSquarer::create_at_least((nb + 5 + d18::kBits - 1) / d18::kBits, simd);
  if (!m->quotient_ || !m->remainder_ || m->high_shift_ < 3) return nullptr;

  std::vector<double> digits(mu_digits);
  if (!d18::from_mpz(mu, digits.data(), mu_digits)) return nullptr;
  weight_into(*m->quotient_, digits.data(), mu_digits);
  keep_spectrum(*m->quotient_, m->mu_re_, m->mu_im_);
  const std::size_t lr = m->remainder_->length();
  m->n_digits_.assign(lr, 0.0);
  if (!d18::from_mpz(N, m->n_digits_.data(), lr)) return nullptr;
  m->n_check_ = d18::residue(m->n_digits_.data(), lr);
  weight_into(*m->remainder_, m->n_digits_.data(), lr);
  keep_spectrum(*m->remainder_, m->n_re_, m->n_im_);

  const std::size_t most = std::max({product_digits, m->quotient_->length(), lr}) + 8;
  m->coefficients_.assign(most, 0.0);
  m->product_.assign(most, 0.0);
  m->scratch_.assign(most, 0.0);
  m->quotient_digits_.assign(most, 0.0);
  m->folded_.assign(most, 0.0);
  m->remainder_digits_.assign(most, 0.0);
  return m;
}

TransformModulus::Residue TransformModulus::load(const mpz_class& x) const {
  Residue r;
  r.digits.assign(digits_, 0.0);
  if (!d18::from_mpz(x, r.digits.data(), digits_)) {
    mpz_class reduced;
    mpz_mod(reduced.get_mpz_t(), x.get_mpz_t(), n_.get_mpz_t());
    d18::from_mpz(reduced, r.digits.data(), digits_);
  }
  r.check = d18::residue(r.digits.data(), digits_);
  return r;
}

mpz_class TransformModulus::value(const Residue& x) const {
  mpz_class v = d18::to_mpz(x.digits.data(), x.digits.size());
  mpz_mod(v.get_mpz_t(), v.get_mpz_t(), n_.get_mpz_t());
  return v;
}

void TransformModulus::spectrum(const Residue& x, double* re, double* im) {
  weight_into(*square_, x.digits.data(), digits_);
  square_->forward_in_place();
  std::copy(square_->real(), square_->real() + points(), re);
  std::copy(square_->imaginary(), square_->imaginary() + points(), im);
}

bool TransformModulus::reduce(std::int64_t check, double factor, Residue& out) {
  RightAngleSquarer& t = *square_;
  t.inverse_in_place();
  const std::size_t length = t.length();
  const bool rounded = unweight_into(t, factor / static_cast<double>(t.points()), 0, length, coefficients_.data());
  d18::carry_acyclic(coefficients_.data(), length, product_.data(), scratch_.data());
  const std::size_t count = length + 3;
  const bool ok =
      rounded &&
      d18::residue(product_.data(), count) == d18::residue_product(check, static_cast<std::int64_t>(factor)) &&
      reduce_digits(product_.data(), count, out);
  if (!ok) ++failures_;
  return ok;
}

// Barrett's quotient from the digits of a above 2^s1 (within 1/2 of
// floor(a / 2^s1), the digits being nearly balanced) times mu, its digits
// above 2^s2 carried from three places below (the lower places add less
// than 1/2 to them): q within 2.2 of a / N. Then r = a - q N modulo 2^K + 1.
bool TransformModulus::reduce_digits(const double* a, std::size_t count, Residue& out) {
  const std::size_t s1 = low_shift_, s2 = high_shift_;
  RightAngleSquarer& q = *quotient_;
  const std::size_t a_top = std::min(count, s1 + quotient_digits_count_);
  weight_into(q, a + s1, a_top > s1 ? a_top - s1 : 0);
  q.multiply_in_place(mu_re_.data(), mu_im_.data());
  const std::size_t lq = q.length(), from = s2 - 3;
  unweight_into(q, 1.0 / static_cast<double>(q.points()), from, lq, coefficients_.data());
  d18::carry_acyclic(coefficients_.data(), lq - from, quotient_digits_.data(), scratch_.data());
  const double* quotient = quotient_digits_.data() + 3;
  const std::size_t quotient_count = lq - from;  // + 3 carried, less the 3 below 2^s2

  RightAngleSquarer& r = *remainder_;
  const std::size_t lr = r.length();
  std::fill(folded_.begin(), folded_.begin() + static_cast<std::ptrdiff_t>(lr), 0.0);
  fold_into(quotient, quotient_count, lr, folded_.data());
  weight_into(r, folded_.data(), lr);
  r.multiply_in_place(n_re_.data(), n_im_.data());
  if (!unweight_into(r, 1.0 / static_cast<double>(r.points()), 0, lr, coefficients_.data())) return false;
  std::fill(folded_.begin(), folded_.begin() + static_cast<std::ptrdiff_t>(lr), 0.0);
  fold_into(a, count, lr, folded_.data());
  for (std::size_t j = 0; j < lr; ++j) folded_[j] -= coefficients_[j];
  d18::carry_negacyclic(folded_.data(), lr, remainder_digits_.data(), scratch_.data());
  // r = a - q N exactly when its digits past a residue's are zero and its
  // value modulo 2^36 - 1 is a's less q's times N's (2^K + 1 is 2 there,
  // K being a multiple of 36).
  for (std::size_t j = digits_; j < lr; ++j)
    if (remainder_digits_[j] != 0.0) return false;
  const std::int64_t expected = d18::residue_product(
      d18::residue(a, count) - d18::residue_product(d18::residue(quotient, quotient_count), n_check_), 1);
  out.digits.assign(remainder_digits_.begin(), remainder_digits_.begin() + static_cast<std::ptrdiff_t>(digits_));
  out.check = d18::residue(out.digits.data(), digits_);
  return out.check == expected;
}

}  // namespace tk::primes
