/// @file drive_plant.cpp
/// @brief With a = b/m and input w(τ) = w0 + (w1 − w0)·τ/h, the exact step is
///   v' = e^{−z} v + (h/m)(w0 φ1 + (w1 − w0) φ2)
///   x' = x + h φ1 v + (h²/m)(w0 φ2 + (w1 − w0) φ3).
#include "control/drive_plant.hpp"

#include <cmath>

namespace tk::control {

HoldWeights HoldWeights::at(double z) {
  HoldWeights w{};
  w.decay = std::exp(-z);
  if (std::abs(z) < 0.5) {  // the closed forms lose digits to cancellation here
    double term1 = 1, term2 = 0.5, term3 = 1.0 / 6;
    w.phi1 = w.phi2 = w.phi3 = 0;
    for (int j = 0; j < 30; ++j) {
      w.phi1 += term1, w.phi2 += term2, w.phi3 += term3;
      term1 *= -z / (j + 2), term2 *= -z / (j + 3), term3 *= -z / (j + 4);
    }
    return w;
  }
  const double one_minus = -std::expm1(-z);
  w.phi1 = one_minus / z;
  w.phi2 = (1 - w.phi1) / z;
  w.phi3 = (0.5 - w.phi2) / z;
  return w;
}

void DrivePlant::configure(double mass, double damping, double step_s) {
  const double h = step_s;
  const HoldWeights w = HoldWeights::at(damping / mass * h);
  x_from_v_ = h * w.phi1;
  x_from_w_ = h * h / mass * w.phi2;
  x_from_dw_ = h * h / mass * w.phi3;  // dw = w1 − w0 = (start − end) of the disturbance
  v_from_v_ = w.decay;
  v_from_w_ = h / mass * w.phi1;
  v_from_dw_ = h / mass * w.phi2;
}

}  // namespace tk::control
