/// @file pulse_estimate.hpp
/// @brief The step pulses a motion implies, known before it is stepped, so
/// that a program whose moves would make more pulses than a run allows is
/// refused at the block that crosses the cap instead of running for hours.
#pragma once

#include <array>

#include "motion/gcode.hpp"

namespace tk::motion {

/// The pulses (steps of all axes) `motion` implies at `steps_per_mm`: for a
/// line the lattice distance between its quantised ends on each axis (what
/// the stepper makes), for an arc the distance each plane axis travels over
/// the sweep (the largest radius times the variation of the cosine or sine,
/// plus the change of radius) and the rise, in steps. 0 for a dwell.
double implied_pulses(const Motion& motion, const std::array<double, 3>& steps_per_mm);

}  // namespace tk::motion
