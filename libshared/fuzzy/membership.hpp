/// @file membership.hpp
/// @brief The membership function of fuzzy terms: the trapezoid, and the
/// triangle as a trapezoid with b == c (see Term in engine.hpp). A vertical
/// edge (two equal vertices) is a step: the term is fully true from that
/// vertex on.
#pragma once

#include <cmath>

namespace tk::fuzzy {

/// Rises from a to b, 1 from b to c, falls from c to d; 0 outside [a, d].
struct Trapezoid {
  double a = 0, b = 0, c = 0, d = 0;

  double operator()(double x) const {
    if (std::isnan(x)) return x;
    if (x < a || x > d) return 0;
    if (x < b) return (x - a) / (b - a);  // b > a here, as a <= x < b
    if (x <= c) return 1;
    return x < d ? (d - x) / (d - c) : (c == d ? 1 : 0);  // x == d: 0 unless the edge is vertical
  }
};

}  // namespace tk::fuzzy
