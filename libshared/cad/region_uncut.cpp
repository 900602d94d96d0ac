/// @file region_uncut.cpp
/// @brief The uncut search (see region_uncut.hpp).
#include "cad/region_uncut.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "cad/segment_geometry.hpp"

namespace tk::cad {

std::vector<UncutSpan> find_uncut(const std::vector<Loop>& drawn, const RegionIndex* contour, double radius,
                                  const OffsetOptions& options) {
  std::vector<UncutSpan> spans;
  if (radius <= 0) return spans;
  const double step = std::max(radius / 8, 10 * options.tolerance);
  std::size_t hint = SIZE_MAX;  // the last nearest element: each point asked is near the last
  auto gap_at = [&](const Segment& s, double t) {
    if (!contour) return radius + 1;
    const RegionQuery q = contour->nearest(point_at(s, t), hint);
    hint = q.element;
    return q.distance - radius;
  };
  // A sample only matters when its gap exceeds the report threshold; the
  // last answer's element bounds the gap from above (the nearest element
  // is no farther), so where that element alone is near enough, the
  // search is not needed. (Its distance is computed here, not by the
  // index: the margin covers the two computations' rounding.)
  // Tried only after a sample within reach: along material left uncut
  // (most of a gear's or comb's flanks) it would fail every time.
  const double near_enough = radius + options.uncut_report_mm - 1e-9 * (1 + radius);
  bool last_within_reach = true;
  auto sample_gap = [&](const Segment& s, double t) {
    if (last_within_reach && contour && hint < contour->elements().size()) {
      const Point p = point_at(s, t);
      const double bound = distance(nearest_point(contour->elements()[hint], p), p);
      if (bound <= near_enough) return bound - radius;
    }
    const double gap = gap_at(s, t);
    last_within_reach = gap <= options.uncut_report_mm;
    return gap;
  };
  for (const Loop& loop : drawn) {
    const std::size_t first_of_loop = spans.size();
    for (const Segment& s : loop.segments) {
      const std::size_t samples = std::min<std::size_t>(10000, 1 + static_cast<std::size_t>(segment_length(s) / step));
      std::vector<double> gaps(samples + 1);
      for (std::size_t i = 0; i <= samples; ++i) gaps[i] = sample_gap(s, static_cast<double>(i) / samples);
      for (std::size_t i = 0; i <= samples;) {
        if (gaps[i] <= options.uncut_report_mm) {
          ++i;
          continue;
        }
        const std::size_t begin = i;
        std::size_t deepest = i;
        for (; i <= samples && gaps[i] > options.uncut_report_mm; ++i)
          if (gaps[i] > gaps[deepest]) deepest = i;
        double lo = static_cast<double>(deepest == 0 ? 0 : deepest - 1) / samples;
        double hi = static_cast<double>(std::min(deepest + 1, samples)) / samples;
        const double golden = (std::sqrt(5.0) - 1) / 2;
        for (int k = 0; k < 40; ++k) {
          const double a = hi - golden * (hi - lo), b = lo + golden * (hi - lo);
          if (gap_at(s, a) > gap_at(s, b)) {
            hi = b;
          } else {
            lo = a;
          }
        }
        const double depth = std::max(gaps[deepest], gap_at(s, 0.5 * (lo + hi)));
        spans.push_back({point_at(s, static_cast<double>(begin) / samples),
                         point_at(s, static_cast<double>(i - 1) / samples), depth, s.entity, s.source_line});
      }
    }
    // A corner shared by two elements shows up at the end of one and the start of the next.
    std::vector<UncutSpan> merged(spans.begin(), spans.begin() + first_of_loop);
    for (std::size_t i = first_of_loop; i < spans.size(); ++i) {
      if (merged.size() > first_of_loop && distance(merged.back().to, spans[i].from) < 1e-9) {
        merged.back().to = spans[i].to;
        merged.back().depth = std::max(merged.back().depth, spans[i].depth);
      } else {
        merged.push_back(spans[i]);
      }
    }
    if (merged.size() > first_of_loop + 1 && distance(merged.back().to, merged[first_of_loop].from) < 1e-9) {
      merged[first_of_loop].from = merged.back().from;  // the loop's first corner
      merged[first_of_loop].depth = std::max(merged[first_of_loop].depth, merged.back().depth);
      merged.pop_back();
    }
    spans = std::move(merged);
  }
  return spans;
}

}  // namespace tk::cad
