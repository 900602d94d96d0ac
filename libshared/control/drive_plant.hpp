/// @file drive_plant.hpp
/// @brief The linear-motor feed drive m·ẍ + b·ẋ = F − F_d, stepped exactly.
/// The drive force is held between controller samples and the disturbance
/// is linear across each plant step (first-order hold), so one step is a
/// 2×2 update with coefficients that depend only on m, b and the step.
#pragma once

namespace tk::control {

/// Mass and damping, each optionally drifting linearly over the run
/// (material removal lightens the table; warming lubricant thins).
struct DriveMechanics {
  double mass_kg = 10;
  double damping_kg_s = 250;
  double mass_end_kg = -1;       ///< < 0: constant mass
  double damping_end_kg_s = -1;  ///< < 0: constant damping

  double mass_at(double fraction) const {
    return mass_end_kg < 0 ? mass_kg : mass_kg + fraction * (mass_end_kg - mass_kg);
  }
  double damping_at(double fraction) const {
    return damping_end_kg_s < 0 ? damping_kg_s : damping_kg_s + fraction * (damping_end_kg_s - damping_kg_s);
  }
  bool varies() const { return mass_end_kg >= 0 || damping_end_kg_s >= 0; }
};

/// φ_k(z) = Σ_j (−z)^j / (j+k)!, the weights of the exact step with a = b/m
/// and z = a·h; a series near 0 where the closed forms cancel.
struct HoldWeights {
  double decay;  ///< e^{−z}
  double phi1, phi2, phi3;
  static HoldWeights at(double z);
};

/// Position and velocity of the axis (any consistent length unit).
struct AxisState {
  double x = 0, v = 0;
};

class DrivePlant {
 public:
  /// Sets m and b for the following steps of length `step_s`.
  void configure(double mass, double damping, double step_s);

  /// One step of `step_s`: drive force `force` held, disturbance going
  /// linearly from `disturbance_start` to `disturbance_end`.
  void step(AxisState& s, double force, double disturbance_start, double disturbance_end) const {
    const double w0 = force - disturbance_start, dw = disturbance_start - disturbance_end;
    const double x = s.x + x_from_v_ * s.v + x_from_w_ * w0 + x_from_dw_ * dw;
    s.v = v_from_v_ * s.v + v_from_w_ * w0 + v_from_dw_ * dw;
    s.x = x;
  }

 private:
  double x_from_v_ = 0, x_from_w_ = 0, x_from_dw_ = 0;
  double v_from_v_ = 1, v_from_w_ = 0, v_from_dw_ = 0;
};

}  // namespace tk::control
