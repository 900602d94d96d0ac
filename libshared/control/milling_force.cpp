/// @file milling_force.cpp
#include "control/milling_force.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "io/error.hpp"

namespace tk::control {

namespace {

double wrap_angle(double a) {
  a = std::fmod(a, kTwoPi);
  return a < 0 ? a + kTwoPi : a;
}
}  // namespace

void MillingCut::validate() const {
  const auto positive = [](double v, const char* what) {
    if (!(v > 0 && std::isfinite(v))) throw Error(fmt::format("{} must be a positive number, not {}", what, v));
  };
  if (teeth < 1 || teeth > 64) throw Error(fmt::format("teeth must be 1 to 64, not {}", teeth));
  positive(diameter_mm, "the tool diameter");
  positive(spindle_rpm, "the spindle speed");
  positive(axial_depth_mm, "the axial depth");
  if (!(feed_mm_min >= 0 && std::isfinite(feed_mm_min)))
    throw Error(fmt::format("the feed must be >= 0, not {}", feed_mm_min));
  if ((radial_depth_mm >= 0 || std::isnan(radial_depth_mm)) && !(radial_depth_mm > 0 && radial_depth_mm <= diameter_mm))
    throw Error(fmt::format("the radial depth {} mm must be above 0 and at most the diameter {} mm", radial_depth_mm,
                            diameter_mm));
  for (const double k : {ktc_n_mm2, krc_n_mm2, kte_n_mm, kre_n_mm})
    if (!std::isfinite(k)) throw Error("cutting coefficients must be finite numbers");
}

MillingForce::MillingForce(const MillingCut& cut) : enabled_(cut.enabled) {
  cut.validate();
  omega_rad_s_ = cut.spindle_rpm / 60 * kTwoPi;
  const double immersion = cut.radial_depth_mm < 0 ? cut.diameter_mm : cut.radial_depth_mm;
  exit_angle_ = std::acos(1 - 2 * immersion / cut.diameter_mm);  // up-milling from 0; a slot exits at π
  const double a = cut.axial_depth_mm, fz = cut.feed_per_tooth_mm();
  shear_t_ = a * cut.ktc_n_mm2 * fz, shear_r_ = a * cut.krc_n_mm2 * fz;
  edge_t_ = a * cut.kte_n_mm, edge_r_ = a * cut.kre_n_mm;
  for (int j = 0; j < cut.teeth; ++j) {
    const double pitch = kTwoPi * j / cut.teeth;
    pitch_angle_.push_back(pitch), pitch_cos_.push_back(std::cos(pitch)), pitch_sin_.push_back(std::sin(pitch));
  }
}

double MillingForce::at(double t_s) const {
  const double angle = wrap_angle(omega_rad_s_ * t_s);
  return from_angle(angle, std::cos(angle), std::sin(angle));
}

MillingForce::Stepper::Stepper(const MillingForce& force, double step_s)
    : force_(&force),
      step_angle_(wrap_angle(force.omega_rad_s_ * step_s)),
      step_cos_(std::cos(step_angle_)),
      step_sin_(std::sin(step_angle_)) {}

void MillingForce::Stepper::start(double t_s) {
  angle_ = wrap_angle(force_->omega_rad_s_ * t_s);
  cos_ = std::cos(angle_), sin_ = std::sin(angle_);
}

}  // namespace tk::control
