/// @file feed_controllers.cpp
#include "control/feed_controllers.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "io/error.hpp"

namespace tk::control {

ControllerKind parse_controller_kind(const std::string& name) {
  if (name == "smc") return ControllerKind::smc;
  if (name == "sta") return ControllerKind::sta;
  if (name == "pid") return ControllerKind::pid;
  if (name == "ppd") return ControllerKind::ppd;
  throw Error(fmt::format("unknown controller '{}' (smc, sta, pid, ppd)", name));
}

const char* controller_name(ControllerKind kind) {
  switch (kind) {
    case ControllerKind::smc: return "smc";
    case ControllerKind::sta: return "sta";
    case ControllerKind::pid: return "pid";
    case ControllerKind::ppd: return "ppd";
  }
  return "?";
}

void ControllerGains::validate() const {
  const auto finite = [](double v, const char* what) {
    if (!std::isfinite(v)) throw Error(fmt::format("{} must be a finite number, not {}", what, v));
  };
  const auto non_negative = [&](double v, const char* what) {
    finite(v, what);
    if (v < 0) throw Error(fmt::format("{} must not be negative, not {}", what, v));
  };
  non_negative(mu, "mu"), non_negative(lambda, "lambda");
  non_negative(switching, "Lambda"), non_negative(boundary_layer, "the boundary layer");
  non_negative(alpha, "alpha"), non_negative(beta, "beta");
  finite(kp, "kp"), finite(ki, "ki"), finite(kd, "kd");
  if (!(pid_bandwidth_hz > 0) || !std::isfinite(pid_bandwidth_hz))
    throw Error("the PID bandwidth must be a positive number");
  non_negative(position_gain, "the position gain"), finite(velocity_p, "the velocity gain");
  non_negative(velocity_d, "the velocity derivative gain");
  if (!(velocity_bandwidth_hz > 0) || !std::isfinite(velocity_bandwidth_hz))
    throw Error("the velocity bandwidth must be a positive number");
  if (!(velocity_feedforward >= 0 && velocity_feedforward <= 1))
    throw Error("the velocity feed-forward must be 0 to 1");
  if (!(pid_feedforward >= 0 && pid_feedforward <= 1)) throw Error("the PID feed-forward must be 0 to 1");
}

FeedController::FeedController(const ControllerGains& gains, double mass_estimate, double damping_estimate,
                               double period_s)
    : g_(gains), m_hat_(mass_estimate), b_hat_(damping_estimate), period_(period_s) {
  g_.validate();
  // PID: place the closed loop m̂ s³ + (b̂ + k_d) s² + k_p s + k_i at (s + ω)³.
  const double w = 2 * std::numbers::pi * g_.pid_bandwidth_hz;
  kp_ = g_.kp >= 0 ? g_.kp : 3 * m_hat_ * w * w;
  ki_ = g_.ki >= 0 ? g_.ki : m_hat_ * w * w * w;
  kd_ = g_.kd >= 0 ? g_.kd : std::max(0.0, 3 * m_hat_ * w - b_hat_);
  kpv_ = g_.velocity_p >= 0 ? g_.velocity_p : m_hat_ * 2 * std::numbers::pi * g_.velocity_bandwidth_hz;
}

double FeedController::force(const ControlInput& in) {
  const double s = in.surface;
  const double sign_s = s > 0 ? 1.0 : s < 0 ? -1.0 : 0.0;
  switch (g_.kind) {
    case ControllerKind::smc:
    case ControllerKind::sta: {
      // The printed bracket feeds the friction forward on ẋ_ref only (eq. 8, 9, b/m read as b̂/m̂).
      const double equivalent =
          g_.printed_bracket ? m_hat_ * (in.a_ref + b_hat_ / m_hat_ * in.v_ref + g_.lambda * in.error)
                             : m_hat_ * (in.a_ref + g_.mu * in.error_rate + g_.lambda * in.error) + b_hat_ * in.v;
      if (g_.kind == ControllerKind::smc) {
        const double switched = g_.boundary_layer > 0 ? std::clamp(s / g_.boundary_layer, -1.0, 1.0) : sign_s;
        return equivalent + g_.switching_sign * g_.switching * switched;
      }
      // Super-twisting: α |S|^½ sign(S) + w, ẇ = β sign(S) (w integrated at the sample rate).
      const double f =
          equivalent + g_.switching_sign * (g_.alpha * std::sqrt(std::abs(s)) * sign_s + twisting_integral_);
      twisting_integral_ += period_ * g_.beta * sign_s;
      return f;
    }
    case ControllerKind::pid:
      // A commercial drive's PID with velocity and acceleration feed-forward.
      return g_.pid_feedforward * (m_hat_ * in.a_ref + b_hat_ * in.v_ref) + kp_ * in.error + ki_ * in.error_integral +
             kd_ * in.error_rate;
    case ControllerKind::ppd: {
      // Cascade: position P gives a velocity command, a PD velocity loop gives the force.
      const double velocity_command = g_.velocity_feedforward * in.v_ref + g_.position_gain * in.error;
      const double velocity_error = velocity_command - in.v;
      const double rate = first_ ? 0 : (velocity_error - previous_velocity_error_) / period_;
      previous_velocity_error_ = velocity_error, first_ = false;
      return kpv_ * velocity_error + g_.velocity_d * rate;
    }
  }
  return 0;
}

}  // namespace tk::control
