/// @file thread_gcode.hpp
/// @brief Threading programs for a lathe (XZ plane, diameter mode G7): a
/// LinuxCNC G76 cycle, or plain G33 passes for controls without a cycle.
#pragma once

#include <string>

#include "threads/thread_turning.hpp"

namespace tk::threads {

enum class ProgramStyle { g76, passes };

struct ProgramSettings {
  std::string title;  ///< the designation, written in the header comment
  double pitch_mm = 0;
  double length_mm = 0;     ///< thread length, from the face at Z0 towards −Z
  double rpm = 0;           ///< spindle speed S
  double clearance_mm = 1;  ///< radial gap between the drive line and the blank (or bore)
  /// Z start ahead of the face; 0 takes 3 pitches, or more when the Z axis
  /// needs more to reach the thread's speed P·S at acceleration_mm_s2.
  double run_in_mm = 0;
  double acceleration_mm_s2 = 500;  ///< the Z axis's (gcode-pulse's default)
  bool left_hand = false;           ///< cut from the thread's inner end out to the face
};

/// Spindle speed, rpm, for a cutting speed (m/min) at a diameter (mm),
/// at most max_rpm.
double spindle_speed(double cutting_speed_m_min, double diameter_mm, double max_rpm);

/// Distance, mm, the Z axis needs to reach (or leave) the thread's speed
/// P·S from rest at the settings' acceleration: v²/2a.
double synchronisation_distance(const ProgramSettings& settings);

/// Throws tk::UsageError naming the option (threadcalc's) for a non-positive length or speed, a clearance outside
/// (0, 100] mm, and so on. An internal drive line keeps at most a tenth of
/// the bore's diameter from it on each side, whatever the clearance.
void validate(const ProgramSettings& settings);

/// The whole program, from the modal set-up to M30, one block per line.
/// g76: one G76 block with P (pitch), I (peak − drive line), J (first depth),
/// K (ap), R2 (constant chip area), Q (the flank infeed angle), H (spring
/// passes), all in diameter mode as LinuxCNC reads them under G7. J is
/// K/√n, rounded up to 0.1 µm, so the cycle makes the plan's n passes.
/// passes: per pass a rapid to the start (shifted along the flank for
/// flank infeed), a rapid in to the pass's diameter, G33 to the end, a rapid
/// out; then the spring passes.
std::string thread_program(ProgramStyle style, const TurningPlan& plan, const ProgramSettings& settings);

}  // namespace tk::threads
