/// @file subtuning.hpp
/// @brief Active control by dimensional sub-tuning (Georgiev, Chetrokov &
/// Salapateva, eq. 3-6): after each finished part, a straight line fitted to
/// the run's sizes decides whether the difference ΔA = ã − A_TN between its
/// start and its last part is significant; when it is, the set-up is
/// corrected by ΔA and a new run begins. Incremental: O(1) work per part.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string_view>

#include "quality/student_t.hpp"

namespace tk::quality {

/// slope: Student's test of ΔA = ã − A_TN = −N b̃ with the standard error the
/// regression gives it, t = |b̃| √Σ(i − ī)² / s, s² = SSE/(N − 2), against t
/// at N − 2 (the default: its level is α). paper: eq. (6) as printed,
/// t = |ã − A_TN| / S_N · √(N/2), S_N² = SSE/(N − 1) (eq. 3), against t at
/// k = 2(N − 1), whose real level is far above α (0.51 at N = 4, α = 0.05).
enum class TrendStatistic { paper, slope };

/// Which drifts count: either sign (a two-sided test at α), or only growing
/// (greater) or only shrinking (less) sizes, one-sided at α.
enum class Alternative { two_sided, greater, less };

struct SubTuneSettings {
  double alpha = 0.05;
  Alternative alternative = Alternative::two_sided;
  TrendStatistic statistic = TrendStatistic::slope;
  std::size_t min_parts =
      4;  ///< no decision before the run has this many parts (the paper: "after the fourth piece and on")
  /// The gauge's resolution, mm: s (or S_N) is at least its rounding noise
  /// r/√12. 0 takes the spread as computed, so identical sizes give 0.
  double resolution = 0;
  /// Where a sub-tune moves the size: NaN (the paper) back to the run's
  /// starting level ã, correction ã − A_T(N) = −N b̃; a number (the nominal)
  /// to it, correction target − A_T(N), so errors of earlier corrections do
  /// not accumulate.
  double target = std::numeric_limits<double>::quiet_NaN();
};

enum class Decision : std::uint8_t { insufficient, none, subtune };
std::string_view decision_name(Decision d);

/// What the control says after one part. Fields the run cannot yet give
/// (a line from one part, a spread from two, any test before min_parts) are NaN.
struct SubTuneStep {
  std::uint64_t run = 1;  ///< runs since the start, from 1
  std::uint64_t n = 0;    ///< parts in the current run, this one included
  double a = 0, b = 0;    ///< the line A_T(i) = a + i b over i = 1..n
  double s = 0;           ///< s (slope) or S_N (paper)
  double t = 0;  ///< ≥ 0, |ã − A_TN| over its standard error; +inf when the spread is 0 and the line is not flat
  double t_crit = 0;
  std::uint64_t df = 0;
  Decision decision = Decision::insufficient;
  double correction = 0;  ///< mm to add to the set-up when sub-tuning (see SubTuneSettings::target), else 0
  double offset = 0;      ///< the sum of corrections so far, this one included
};

class SubTuner {
 public:
  explicit SubTuner(const SubTuneSettings& settings);

  /// The decision after part `size` (finite, mm). A sub-tune ends the run:
  /// the next part is the first of a new one.
  SubTuneStep observe(double size);
  /// Starts a new run without a correction (a tool change, a new set-up).
  void start_run();
  /// As a new tuner (run 1, no offset), keeping the critical values computed so far.
  void reset();

  double offset() const { return offset_; }

 private:
  SubTuneSettings settings_;
  StudentCriticalValues critical_;
  double spread_floor_sq_;
  std::uint64_t run_ = 1;
  // Welford-style co-moments of (i, size) over the run and the residual sum
  // of squares by recursive least squares: stable over runs of any length,
  // where raw sums of squares would cancel.
  std::uint64_t n_ = 0;
  double origin_ = 0;  ///< the run's first size; the moments are of size − origin_
  double mean_size_ = 0, co_moment_ = 0, sse_ = 0;
  double offset_ = 0;
};

}  // namespace tk::quality
