/// @file size_plot.hpp
/// @brief Sizes against part number as SVG: the measured sizes, the run's
/// regression line A_T at each part, the tolerance band (top panel) and the
/// set-up offset the corrections add up to (bottom panel).
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace tk::quality {

struct SizePlotInfo {
  std::string title;
  std::string level_label = "regression A_T at the part";     ///< the legend of the fitted or estimated level
  double nominal = std::numeric_limits<double>::quiet_NaN();  ///< NaN: not drawn
  double lower = std::numeric_limits<double>::quiet_NaN(), upper = std::numeric_limits<double>::quiet_NaN();
};

class SizePlot {
 public:
  /// Parts kept; a longer stream is drawn up to here (truncated() says so).
  static constexpr std::size_t kMaxParts = 1000000;

  /// `fitted` (the line at this part, or a chart's level) and `made` (the true size, in a simulation) may be NaN.
  void add(double part, double measured, double fitted, double offset,
           double made = std::numeric_limits<double>::quiet_NaN());
  bool truncated() const { return truncated_; }
  /// Writes the drawing atomically; throws tk::Error naming the file when it cannot.
  void write(const std::string& path, const SizePlotInfo& info) const;

 private:
  struct Part {
    double part, measured, fitted, offset, made;
  };
  std::vector<Part> parts_;
  bool truncated_ = false;
  bool has_made_ = false;
};

}  // namespace tk::quality
