/// @file tnorm.hpp
/// @brief The six t-norms of Könczöl & Gál's line follower as n-ary
/// operations (their paper writes the three-input forms): minimum,
/// algebraic product, drastic, Łukasiewicz, trigonometric and Hamacher
/// product. Each n-ary form equals folding its binary form, which the
/// tests check.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace tk::fuzzy {

enum class TNorm { minimum, product, drastic, lukasiewicz, trigonometric, hamacher };

/// "minimum", "product", "drastic", "lukasiewicz", "trigonometric", "hamacher".
std::string_view tnorm_name(TNorm t);
std::optional<TNorm> tnorm_from_name(std::string_view name);

/// T(a, b) for a, b in [0, 1].
double tnorm(TNorm t, double a, double b);

/// T(mu_1, ..., mu_n), n >= 1 (T of one value is that value):
///   minimum        min mu_i
///   product        prod mu_i
///   drastic        the smallest mu_i when all the others are 1, else 0
///   lukasiewicz    max(0, sum mu_i - (n - 1))
///   trigonometric  2/pi asin(prod sin(pi/2 mu_i))
///   hamacher       1 / (1 + sum (1/mu_i - 1)), 0 when a mu_i is 0; for
///                  three inputs the paper's mu1 mu2 mu3 / (mu1 mu2 +
///                  mu1 mu3 + mu2 mu3 - 2 mu1 mu2 mu3)
double tnorm(TNorm t, std::span<const double> mu);

}  // namespace tk::fuzzy
