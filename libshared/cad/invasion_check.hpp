/// @file invasion_check.hpp
/// @brief The guard over a stream of tool positions: for each, where it is
/// against the prohibited region (grown by the tool radius), the barrier
/// point, and, when positions carry times, the latency-aware stop: the
/// velocity from the last two positions, and whether the move from here to
/// where a stop ordered now would take effect (latency later, at that
/// velocity) comes closer than the margin to the region.
#pragma once

#include <cstddef>
#include <optional>

#include "cad/region_offset.hpp"

namespace tk::cad {

struct GuardOptions {
  double tool_radius = 0;
  MachiningSide side = MachiningSide::outside;
  double latency_s = 0.09;  ///< from a sample to the stop taking effect
  double margin_mm = 0.02;  ///< distance the stop aims to keep
};

struct PositionCheck {
  GuardAnswer answer;
  std::optional<double> approach_mm_s;  ///< rate the distance falls (needs times)
  std::optional<bool> stop;             ///< the latency-aware guard's order (needs times)
};

struct GuardSummary {
  std::size_t positions = 0, invasions = 0, stops = 0;
  double deepest_mm = 0;  ///< deepest invasion (>= 0)
  Point deepest_at;
  double closest_mm = 0;  ///< smallest distance seen
};

class InvasionGuard {
 public:
  /// `contour`: an index over the region's boundary (RegionOffset::loops)
  /// for exact barrier points, or null (see guard_query).
  InvasionGuard(const RegionIndex& index, GuardOptions options, const RegionIndex* contour = nullptr);
  /// `t` in seconds when the position has one; times must not go backwards
  /// (Error otherwise, for the caller to place).
  PositionCheck check(Point p, std::optional<double> t);
  const GuardSummary& summary() const { return summary_; }

 private:
  const RegionIndex& index_;
  const RegionIndex* contour_;
  GuardOptions options_;
  GuardSummary summary_;
  std::optional<double> last_t_;
  double last_distance_ = 0;
  Point last_at_;
};

}  // namespace tk::cad
