/// @file tnorm.cpp
/// @brief The six t-norms.
#include "fuzzy/tnorm.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace tk::fuzzy {
namespace {

constexpr std::array<std::pair<TNorm, std::string_view>, 6> kNames{{{TNorm::minimum, "minimum"},
                                                                    {TNorm::product, "product"},
                                                                    {TNorm::drastic, "drastic"},
                                                                    {TNorm::lukasiewicz, "lukasiewicz"},
                                                                    {TNorm::trigonometric, "trigonometric"},
                                                                    {TNorm::hamacher, "hamacher"}}};

}  // namespace

std::string_view tnorm_name(TNorm t) {
  for (const auto& [value, name] : kNames)
    if (value == t) return name;
  return "?";
}

std::optional<TNorm> tnorm_from_name(std::string_view name) {
  for (const auto& [value, known] : kNames)
    if (known == name) return value;
  return std::nullopt;
}

double tnorm(TNorm t, double a, double b) {
  const double pair[2] = {a, b};
  return tnorm(t, std::span<const double>(pair, 2));
}

double tnorm(TNorm t, std::span<const double> mu) {
  if (mu.empty()) return 1;  // the t-norms' identity
  switch (t) {
    case TNorm::minimum: return *std::min_element(mu.begin(), mu.end());
    case TNorm::product: {
      double p = 1;
      for (double m : mu) p *= m;
      return p;
    }
    case TNorm::drastic: {
      // T(a, 1) = a, T(1, b) = b, else 0; folded: all but the smallest must be 1.
      std::size_t below_one = 0;
      double smallest = 1;
      for (double m : mu) {
        if (m < 1) ++below_one;
        smallest = std::min(smallest, m);
      }
      return below_one <= 1 ? smallest : 0;
    }
    case TNorm::lukasiewicz: {
      double sum = 0;
      for (double m : mu) sum += m;
      return std::max(0.0, sum - static_cast<double>(mu.size() - 1));
    }
    case TNorm::trigonometric: {
      double p = 1;
      for (double m : mu) p *= std::sin(std::numbers::pi / 2 * m);
      return 2 / std::numbers::pi * std::asin(std::clamp(p, -1.0, 1.0));
    }
    case TNorm::hamacher: {
      // 1/T - 1 adds up over the inputs (Hamacher's product is associative).
      double excess = 0;
      for (double m : mu) {
        if (m <= 0) return 0;
        excess += 1 / m - 1;
      }
      return 1 / (1 + excess);
    }
  }
  return 0;
}

}  // namespace tk::fuzzy
