/// @file centroid.hpp
/// @brief Centre of gravity of a Mamdani output: the maximum over the fired
/// terms, each clipped (minimum implication) or scaled (product) at its
/// activation level. Two ways: sampled at midpoints like fuzzylite's
/// Centroid, and exact, since the aggregate is piecewise linear.
#pragma once

#include <span>

#include "fuzzy/engine.hpp"

namespace tk::fuzzy {

/// A fired consequent term: its trapezoid and the activation level h in (0, 1].
struct ImpliedTerm {
  Trapezoid shape;
  double level = 0;
};

/// Integral of the aggregate over [min, max] and its centroid (NaN when the
/// area is 0, e.g. every fired term lies outside the range).
struct CentroidResult {
  double centroid = 0;
  double area = 0;
};

/// The aggregate's value at x: max over terms of implied(level, mu(x)).
double aggregate_membership(std::span<const ImpliedTerm> terms, Implication implication, double x);

/// fuzzylite's Centroid: dx = (max - min) / resolution, samples at
/// x_i = min + (i + 0.5) dx, centroid = sum x_i y_i / sum y_i. The area
/// returned is sum y_i dx.
CentroidResult discrete_centroid(std::span<const ImpliedTerm> terms, Implication implication, double min, double max,
                                 int resolution);

/// The exact centre of gravity over [min, max]: the aggregate is linear
/// between the terms' corners and the points where two terms cross, so the
/// integrals of y and x y have closed forms piece by piece. Terms given in
/// the order of their first corner (a) are not sorted again.
CentroidResult exact_centroid(std::span<const ImpliedTerm> terms, Implication implication, double min, double max);

}  // namespace tk::fuzzy
