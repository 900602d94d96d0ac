/// @file turning_svg.hpp
/// @brief The plot of a simulated cut, like the seed's figures 5-7: the
/// spindle load (top panel, with M_z) and the feed
/// override (bottom panel, with the allowance under it) against time.
#pragma once

#include <string>
#include <vector>

namespace tk::machining {

struct TurningPlotInfo {
  std::string title;
  double mz_pct = 60;
};

class TurningSvg {
 public:
  /// Samples kept; a longer run is drawn up to here (truncated() says so).
  static constexpr std::size_t kMaxSamples = 2000000;

  void add(double t_s, double load_pct, double load_true_pct, double override_pct, double depth_mm);
  bool truncated() const { return truncated_; }
  /// Writes the drawing atomically; throws tk::Error when it cannot.
  void write(const std::string& path, const TurningPlotInfo& info) const;

 private:
  struct Sample {
    double t, load, load_true, override_pct, depth;
  };
  std::vector<Sample> samples_;
  bool truncated_ = false;
};

}  // namespace tk::machining
