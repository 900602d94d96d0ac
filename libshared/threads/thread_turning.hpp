/// @file thread_turning.hpp
/// @brief Thread-turning data for a full-profile insert: the infeed depth
/// that puts the pitch diameter in the middle of its tolerance zone, the
/// diameter before threading, the chamfer, and the passes with decreasing
/// infeed (constant chip area).
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "threads/thread_limits.hpp"

namespace tk::threads {

enum class Infeed { radial, flank };

struct TurningSettings {
  /// Passes; 0 takes the lower end of the tool maker's range for the pitch
  /// (recommended_passes), reduced while the last pass would be thinner than
  /// min_last_pass_mm.
  int passes = 0;
  double min_last_pass_mm = 0.05;  ///< Widia: "minimum 0.05 mm infeed on last passes"
  int spring_passes = 1;           ///< passes repeated at full depth
  Infeed infeed = Infeed::radial;
  /// Modified flank infeed: the angle of the infeed from the radial, degrees;
  /// 3 to 5 degrees inside the 30-degree flank is the makers' advice.
  double flank_angle_deg = 27;
  /// Diametral stock the full-profile insert tops off the crest: the blank
  /// is this much over (external) or under (internal) the crest it forms.
  /// NaN: 0.15 mm (what the paper's M30x2 "Prog d" 30.027 implies over its
  /// crest 29.877), 0.15 P below a 1 mm pitch.
  double topping_stock_mm = std::numeric_limits<double>::quiet_NaN();
  /// The 45-degree chamfer reaches this far (radially) below the thread's
  /// root. NaN: 0.25 mm (the paper's), P/2 below a 0.5 mm pitch.
  double chamfer_margin_mm = std::numeric_limits<double>::quiet_NaN();
  /// Axial length over which the tool leaves the root for the peak at the
  /// thread's end. NaN: 1.25 P, the 2.5 mm behind the paper's M30x2
  /// "Retract" 62.737 degrees.
  double run_out_mm = std::numeric_limits<double>::quiet_NaN();
};

/// Throws tk::Error naming the bad setting (negative stock, passes < 2, a
/// flank angle outside [0, 30]...).
void validate(const TurningSettings& settings);

struct TurningPlan {
  bool external = true;
  /// The thread's peak, where infeed depths are measured from: the basic
  /// major diameter d for an external thread, the basic minor D1 for an
  /// internal one (the paper's convention for ap).
  double peak_diameter = 0;
  double target_pitch_diameter = 0;  ///< the middle of the pitch diameter's zone
  /// Radial infeed from the peak to the root that gives target_pitch_diameter
  /// with a full-profile insert: h3 + (d2 − d2 target)/2 external,
  /// H1 + (D2 target − D2)/2 internal.
  double ap = 0;
  double root_diameter = 0;   ///< the peak moved by 2 ap
  double crest_diameter = 0;  ///< the crest the full-profile insert forms (d or D1)
  bool crest_in_zone = true;  ///< that crest lies within the d or D1 tolerance zone
  double blank_diameter = 0;  ///< turned or bored before threading
  double chamfer = 0;         ///< 45-degree chamfer, radial = axial size
  double run_out = 0;         ///< axial length of the pull-out at the thread's end
  /// The pull-out's angle from the radial (X) direction, degrees:
  /// atan(run_out / ap), the paper's "Retract".
  double retract_angle_deg = 0;
  int passes = 0;
  std::string passes_source;
  std::vector<double> depths;  ///< cumulative radial depth after each pass; the last is ap
  Infeed infeed = Infeed::radial;
  double infeed_angle_deg = 0;  ///< 0 radial
  int spring_passes = 0;
};

/// The lower end of Widia's recommended range of passes for ISO 60-degree
/// threads by pitch (Widia catalogue 2017, "Recommendation for threading
/// infeed passes"); pitches below its first row take that row's 4.
int recommended_passes(double pitch_mm);

/// Sandvik's constant-chip-area infeed: the cumulative depth after pass x of
/// n is ap·√φ/√(n − 1), φ = 0.3 for the first pass and x − 1 after.
std::vector<double> degressive_depths(double ap, int passes);

TurningPlan plan_external(const BasicProfile& profile, const ExternalLimits& limits, const TurningSettings& settings);
TurningPlan plan_internal(const BasicProfile& profile, const InternalLimits& limits, const TurningSettings& settings);

}  // namespace tk::threads
