/// @file milling_force.hpp
/// @brief The feed-direction cutting force of end milling, the disturbance on
/// the drive: the linear edge-force model (Altintas, Manufacturing
/// Automation, ch. 2), straight flutes, per engaged tooth
///   F_t = a (K_tc h + K_te),  F_r = a (K_rc h + K_re),  h = f_z sin φ,
///   F_x = −F_t cos φ − F_r sin φ,
/// with φ the tooth's immersion angle from the +y axis and feed along +x.
/// The drive feels F_d = −Σ F_x (positive when it opposes feed along +x).
#pragma once

#include <numbers>
#include <vector>

namespace tk::control {

/// Defaults: the seed's micro-milling cut (2 teeth, 0.9 mm tool, 11,520 rpm,
/// 0.9 mm axial depth, 1.08 mm/min, a full slot) and Al7075-T6 coefficients
/// for a carbide cutter, dry (K_tc 767.01, K_rc 168.8 N/mm², K_te 27.7,
/// K_re 26.6 N/mm; table 5 of the review "Milling force model for aviation
/// aluminum alloy", Chinese J. Mech. Eng. 2021, its ref. [190]). The edge
/// (ploughing) terms are off by default: calibrated on a macro cutter they
/// give about 25 N per tooth at this depth, which would swamp a cut whose
/// chip is 47 nm thick; --kte/--kre put them back.
struct MillingCut {
  int teeth = 2;
  double diameter_mm = 0.9;
  double spindle_rpm = 11520;
  double axial_depth_mm = 0.9;
  double radial_depth_mm = -1;  ///< < 0: a full slot (= the diameter); less: up-milling
  double feed_mm_min = 1.08;
  double ktc_n_mm2 = 767.01, krc_n_mm2 = 168.8;
  double kte_n_mm = 0, kre_n_mm = 0;  ///< edge terms: off by default (see smcsim(1)); the table gives 27.7, 26.6
  bool enabled = true;

  double feed_per_tooth_mm() const { return feed_mm_min / (spindle_rpm * teeth); }
  double tooth_frequency_hz() const { return spindle_rpm / 60 * teeth; }
  /// Throws tk::Error (no location) for a cut that cannot be.
  void validate() const;
};

inline constexpr double kTwoPi = 2 * std::numbers::pi;

/// F_d(t) for one cut; `at(t)` evaluates from scratch, `Stepper` walks a
/// uniform time grid by rotation (no trigonometry per step).
class MillingForce {
 public:
  explicit MillingForce(const MillingCut& cut);

  /// F_d in newtons at time t (the tool at angle 0 at t = 0).
  double at(double t_s) const;

  /// Walks t0, t0 + h, ... ; re-anchor with start() now and then so the
  /// rotation's rounding cannot drift.
  class Stepper {
   public:
    Stepper(const MillingForce& force, double step_s);
    void start(double t_s);
    double value() const { return force_->from_angle(angle_, cos_, sin_); }
    void advance() {
      angle_ += step_angle_;
      if (angle_ >= kTwoPi) angle_ -= kTwoPi;
      const double c = cos_ * step_cos_ - sin_ * step_sin_;
      sin_ = sin_ * step_cos_ + cos_ * step_sin_;
      cos_ = c;
    }

   private:
    const MillingForce* force_;
    double step_angle_, step_cos_, step_sin_;
    double angle_ = 0, cos_ = 1, sin_ = 0;
  };

 private:
  // Inline (with advance()): a call per plant step kept the axis state in
  // memory and cost about half the loop's time.
  double from_angle(double angle, double c, double s) const {
    if (!enabled_) return 0;
    double fx = 0;
    for (std::size_t j = 0; j < pitch_angle_.size(); ++j) {
      double phi = angle + pitch_angle_[j];
      if (phi >= kTwoPi) phi -= kTwoPi;
      if (phi > exit_angle_) continue;
      const double cj = c * pitch_cos_[j] - s * pitch_sin_[j], sj = s * pitch_cos_[j] + c * pitch_sin_[j];
      const double h_sin = sj > 0 ? sj : 0;  // h = f_z sin φ, f_z folded into shear_*
      const double ft = shear_t_ * h_sin + edge_t_, fr = shear_r_ * h_sin + edge_r_;
      fx += -ft * cj - fr * sj;
    }
    return -fx;
  }

  bool enabled_;
  double omega_rad_s_, exit_angle_;
  double shear_t_, shear_r_, edge_t_, edge_r_;  ///< a·K·f_z and a·K, N
  std::vector<double> pitch_angle_, pitch_cos_, pitch_sin_;
};

}  // namespace tk::control
