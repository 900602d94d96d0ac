/// @file feed_controllers.hpp
/// @brief The four position controllers of the study. Each maps the tracking
/// errors to a drive force using the controller's estimates m̂ and b̂.
///
/// With e = x_ref − x the error, S = ė + μ e + λ ∫e the PID-type sliding
/// surface (the seed's eq. 3), and the plant m ẍ + b ẋ = F − F_d:
///   m Ṡ = m (ẍ_ref + μ ė + λ e) − F + F_d + b ẋ.
/// The equivalent control F_eq = m̂ (ẍ_ref + μ ė + λ e) + b̂ ẋ makes Ṡ ≈ 0;
/// the switching term must then push Ṡ against S, so it enters with a PLUS
/// sign: F = F_eq + Λ sign(S) gives Ṡ ≈ −(Λ/m) sign(S) + (model error)/m.
/// The seed's −Λ sign(S) with this e would drive S away from 0 (a unit test
/// shows the loop diverging).
///
/// The seed's printed bracket (eq. 7-9), m̂ [ẍ_ref + (b̂/m̂) ẋ_ref + λ e], is
/// the equivalent control only when μ = b/m; with another μ it leaves
///   m Ṡ = (m − m̂)(ẍ_ref + λ e) + (b − b̂) ẋ_ref − (b − m μ) ė + F_d − F_sw,
/// the friction on the error velocity uncancelled (smcsim(1), CONTROLLERS).
#pragma once

#include <string>

namespace tk::control {

enum class ControllerKind { smc, sta, pid, ppd };
ControllerKind parse_controller_kind(const std::string& name);
const char* controller_name(ControllerKind kind);

/// Gains in the simulation's units: lengths in its length unit L, forces in
/// kg·L/s² (mN when L is the millimetre). PID and P-PD gains (kg/s², kg/s,
/// kg/s³, 1/s, kg) mean the same in any unit.
struct ControllerGains {
  ControllerKind kind = ControllerKind::smc;
  double mu = 2, lambda = 1;         ///< the surface S = ė + μ e + λ ∫e
  double switching = 40;             ///< Λ, classical SMC
  double boundary_layer = 0;         ///< > 0: sat(S/φ) instead of sign(S), in L/s
  double alpha = 200, beta = 200;    ///< super-twisting
  double switching_sign = +1;        ///< −1 reproduces the seed's written sign (unstable)
  bool printed_bracket = false;      ///< the seed's m̂ [ẍ_ref + (b̂/m̂) ẋ_ref + λ e] instead of F_eq
  double pid_bandwidth_hz = 20;      ///< PID default gains: a triple pole of m̂ s³ + ... at 2π·this
  double kp = -1, ki = -1, kd = -1;  ///< < 0: from the bandwidth
  double pid_feedforward = 1;        ///< PID: share of m̂ ẍ_ref + b̂ ẋ_ref fed forward, 0-1
  double position_gain = 30;         ///< P-PD: K_v, 1/s (velocity command per unit error)
  double velocity_p = -1;            ///< P-PD: kg/s; < 0: m̂·2π·velocity_bandwidth
  double velocity_d = 0;             ///< P-PD: kg (on the derivative of the velocity error)
  double velocity_bandwidth_hz = 100;
  double velocity_feedforward = 0;  ///< P-PD: share of ẋ_ref fed forward, 0-1

  /// Throws tk::Error (no location) for a gain that cannot be used.
  void validate() const;
};

/// What the controller sees at one sample (measured, filtered state).
struct ControlInput {
  double x_ref, v_ref, a_ref;  ///< reference and its derivatives
  double x, v;                 ///< position and velocity estimates
  double error, error_rate, error_integral, surface;
};

class FeedController {
 public:
  FeedController(const ControllerGains& gains, double mass_estimate, double damping_estimate, double period_s);
  /// The drive force to hold over the next period (before saturation).
  double force(const ControlInput& in);
  double kp() const { return kp_; }
  double ki() const { return ki_; }
  double kd() const { return kd_; }

 private:
  ControllerGains g_;
  double m_hat_, b_hat_, period_;
  double kp_, ki_, kd_, kpv_;
  double twisting_integral_ = 0;        ///< the super-twisting w
  double previous_velocity_error_ = 0;  ///< P-PD's derivative
  bool first_ = true;
};

}  // namespace tk::control
