/// @file region_uncut.cpp
/// @brief The uncut search (see region_uncut.hpp).
///
/// The answer is defined by every sample's exact gap (distance to the
/// contour less R): runs of samples above the report threshold, each run's
/// first deepest sample, refined by a golden-section search. The gap is
/// 1-Lipschitz along the drawing (|g(p) - g(q)| <= |p - q|), so most
/// samples need no search of the contour: one exactly known a little way
/// back, or the element's far end (asked first on a long element), already
/// puts them above the threshold (or below it), and within a
/// run a branch and bound asks only the samples that could still be the
/// deepest. Where one element of the contour is provably nearest all along
/// a stretch (a slot's floor), gaps there are its distance, no search; and
/// the golden-section search is skipped where it provably cannot end
/// deeper than the deepest sample. A margin covers the rounding of the
/// bounds, so each decision is the one the exact gaps would make.
#include "cad/region_uncut.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <queue>

#include "cad/segment_geometry.hpp"

namespace tk::cad {
namespace {

/// |p - q| for the bounds (the margin covers its rounding): cheaper than
/// std::hypot, which guards against overflow no drawing comes near.
double apart_by(Point p, Point q) {
  const double dx = p.x - q.x, dy = p.y - q.y;
  return std::sqrt(dx * dx + dy * dy);
}

/// How large the numbers in a distance to (or a point on) the segment
/// get: its ends' coordinates, its length and, for an arc, its centre's
/// distance from them (twice the radius at most).
double rounding_scale(const Segment& s) {
  const double chord = apart_by(s.start, s.end), bulge = std::abs(s.bulge);
  const double radius = bulge > 0 ? chord * (1 + bulge * bulge) / (4 * bulge) : 0;
  return std::abs(s.start.x) + std::abs(s.start.y) + std::abs(s.end.x) + std::abs(s.end.y) + chord + 2 * radius;
}

/// Exact gaps through the contour's index, each asked near the last (the
/// hint speeds up the tree's search), and counted.
class ExactGaps {
 public:
  ExactGaps(const RegionIndex* contour, double radius) : contour_(contour), radius_(radius) {}
  /// `nearby`: the contour's elements round p (RegionIndex::Nearby), the same answer sooner.
  double at(Point p, std::size_t& count, const RegionIndex::Nearby* nearby = nullptr) {
    ++count;
    if (!contour_) {  // no contour: all is uncut, and no point of it bounds a gap
      nearest_ = {HUGE_VAL, HUGE_VAL};
      return radius_ + 1;
    }
    const RegionQuery q = nearby ? nearby->nearest(p) : contour_->nearest(p, hint_);
    hint_ = q.element;
    nearest_ = std::isfinite(q.distance) ? q.nearest : Point{HUGE_VAL, HUGE_VAL};  // an empty contour: none
    return q.distance - radius_;
  }
  std::size_t last_element() const { return hint_; }
  /// Whether a contour's element is a line (not an arc).
  bool straight(std::size_t element) const {
    return contour_ && element < contour_->elements().size() && !is_arc(contour_->elements()[element]);
  }
  /// The contour's point nearest to the last point asked.
  Point last_nearest() const { return nearest_; }
  /// The contour's elements that can be nearest within `spread` of
  /// `centre` for points whose gap is at most `largest_gap`; none without a contour.
  std::optional<RegionIndex::Nearby> nearby(Point centre, double spread, double largest_gap) const {
    if (!contour_) return std::nullopt;
    return RegionIndex::Nearby(*contour_, centre, spread, largest_gap + radius_);
  }
  /// The gap to one element of the contour alone: at least the exact gap,
  /// but for rounding (which the caller's margin covers).
  bool gap_to(std::size_t element, Point p, double& bound) const {
    if (!contour_ || element >= contour_->elements().size()) return false;
    bound = contour_->distance_to(element, p) - radius_;
    return true;
  }

 private:
  const RegionIndex* contour_;
  double radius_;
  std::size_t hint_ = SIZE_MAX;
  Point nearest_;
};

/// One element's samples, each point computed when asked (most are
/// settled in runs, by bounds, without one): each gap exact or, where
/// `exact` is 0, not kept (the sample's side of the threshold is certain).
struct Samples {
  const Segment* segment = nullptr;
  std::size_t last = 0;  // the samples are 0 ... last, at t = i / last
  std::vector<double> gaps;
  std::vector<unsigned char> exact, uncut;
  std::vector<std::size_t> elements;  // the contour's nearest, where exact
  std::vector<Point> nearest;         // and its nearest point
  void reset(const Segment& s, std::size_t last_sample) {
    segment = &s, last = last_sample;
    const std::size_t count = last + 1;
    elements.resize(count);
    nearest.resize(count);
    gaps.assign(count, 0);
    exact.assign(count, 0);
    uncut.assign(count, 0);
  }
  Point point(std::size_t i) const { return point_at(*segment, static_cast<double>(i) / last); }
  /// Sample i (at p) asked of the contour: its exact gap, nearest element and point.
  void ask(std::size_t i, Point p, ExactGaps& contour, std::size_t& count) {
    gaps[i] = contour.at(p, count);
    exact[i] = 1;
    elements[i] = contour.last_element();
    nearest[i] = contour.last_nearest();
  }
};

/// The last sample after `from` (up to `last`) whose distance along the
/// element from it, at most (j - from) * spacing, is within `room` (below
/// it when `strict`); `from` when there is none.
std::size_t last_within(std::size_t from, double room, double spacing, bool strict, std::size_t last) {
  const auto within = [&](std::size_t j) {
    const double along = static_cast<double>(j - from) * spacing;
    return strict ? along < room : along <= room;
  };
  if (!(room > 0)) return from;
  const double steps = room / spacing;  // infinite for a zero spacing: all the samples are one point
  std::size_t j = steps < static_cast<double>(last - from) ? from + static_cast<std::size_t>(steps) : last;
  while (j > from && !within(j)) --j;
  return j;
}

/// Samples from which an element's far end is asked first (classify()).
constexpr std::size_t kFarEndFirst = 8;

/// Sorts every sample to its side of the threshold, asking the exact gap
/// only where the bounds leave it open. Runs of samples are settled at
/// once: by the Lipschitz bound from the last exact sample (a sample lies
/// at most `spacing` per step from it along the element), and where the
/// distance to the last answer's element puts a sample within reach, on a
/// `straight` element along a straight one of the contour by convexity
/// (the distance from a point moving along a line to a segment is convex,
/// so it stays below the threshold between two samples that are).
void classify(Samples& at, ExactGaps& gaps, double threshold, double slack, double spacing, bool straight,
              UncutQueryCounts& counts) {
  const auto settle = [&](std::size_t from, std::size_t to, bool uncut) {
    std::fill(at.uncut.begin() + static_cast<std::ptrdiff_t>(from),
              at.uncut.begin() + static_cast<std::ptrdiff_t>(to) + 1, uncut);
  };
  const auto ask = [&](std::size_t i, Point p) {
    at.ask(i, p, gaps, counts.sampling);
    at.uncut[i] = at.gaps[i] > threshold;
  };
  // A long element's far end first: its gap bounds every sample before it
  // (Lipschitz, backward), and deep in material left uncut (a slot's wall
  // running down from the tool's reach) that settles most of the element at
  // once, where the forward bounds only doubled their reach question by
  // question. The answer is carried on to the next element.
  const std::size_t end = at.last;
  if (end >= kFarEndFirst && !at.exact[end]) ask(end, at.point(end));
  // The last answer's element bounds the gap from above; tried only after
  // a sample within reach (along material left uncut it fails every time).
  bool last_within_reach = true;
  std::size_t anchor = SIZE_MAX;  // the last sample whose gap is exact
  for (std::size_t i = 0; i <= at.last;) {
    if (at.exact[i]) {  // known already (the element before ended here)
      last_within_reach = !at.uncut[i];
      anchor = i++;
      continue;
    }
    if (at.exact[end]) {  // from i on to the end, the end's bound only tightens
      const double g = at.gaps[end], along = static_cast<double>(end - i) * spacing;
      if (g - along - slack > threshold || g + along + slack <= threshold) {
        settle(i, end - 1, g > threshold);
        i = end;
        continue;
      }
    }
    if (anchor != SIZE_MAX) {
      const double g = at.gaps[anchor];
      const bool above =
          g > threshold;  // uncut while g - along - slack > threshold; cut while g + along + slack <= threshold
      const std::size_t reach =
          last_within(anchor, above ? g - threshold - slack : threshold - g - slack, spacing, above, at.last);
      if (reach >= i) {
        settle(i, reach, above);
        i = reach + 1;
        continue;
      }
    }
    const Point p = at.point(i);
    const std::size_t element = gaps.last_element();
    double bound = 0;
    if (last_within_reach && gaps.gap_to(element, p, bound) && bound + slack <= threshold) {
      std::size_t reach = last_within(i, threshold - bound - slack, spacing, false, at.last);
      const auto cut_at = [&](std::size_t j) {
        double b = 0;
        return gaps.gap_to(element, at.point(j), b) && b + slack <= threshold;
      };
      if (straight && gaps.straight(element) && reach < at.last) {
        std::size_t beyond = at.last;  // cut_at(reach) holds; beyond: the last, or one where it fails
        if (cut_at(beyond)) {
          reach = beyond;
        } else {
          while (beyond - reach > 1) {
            const std::size_t mid = reach + (beyond - reach) / 2;
            (cut_at(mid) ? reach : beyond) = mid;
          }
        }
      }
      settle(i, reach, false);
      i = reach + 1;
      continue;
    }
    ask(i, p);
    last_within_reach = !at.uncut[i];
    anchor = i++;
  }
}

/// A stretch of an element where one element of the contour is nearest
/// throughout: points within `spread` of `centre`.
struct SoleStretch {
  std::size_t element = SIZE_MAX;
  Point centre;
  double spread = 0;
};

/// Where one element of the contour is nearest at both ends of a straight
/// run (a slot's flat floor, whose gaps are all equal, so that no bound
/// settles any), whether it is nearest all along (RegionIndex::Nearby::sole);
/// if so, every sample's exact gap is its distance, with no search (the
/// nearest point is left unknown), and `sole` says where that holds.
bool settled_by_sole(Samples& at, std::size_t begin, std::size_t last, ExactGaps& gaps, double slack,
                     UncutQueryCounts& counts, SoleStretch& sole) {
  const Point a = at.point(begin), b = at.point(last);
  const Point centre{(a.x + b.x) / 2, (a.y + b.y) / 2};
  const double spread = apart_by(a, b) / 2 * (1 + 1e-9) + slack;  // the samples lie on the chord, but for rounding
  // Tried only on a run short beside its gaps: a longer one (a gear's flank)
  // lists many elements and seldom has one nearest all along (tried on
  // every run, the gear's search took twice the time).
  if (!(4 * spread <= std::min(at.gaps[begin], at.gaps[last]))) return false;
  // No gap in the run exceeds an end's by more than the way from it (Lipschitz).
  const double largest_gap = std::min(at.gaps[begin], at.gaps[last]) + 2 * spread + slack;
  const std::optional<RegionIndex::Nearby> nearby = gaps.nearby(centre, spread, largest_gap);
  if (!nearby || nearby->sole() != at.elements[begin]) return false;
  for (std::size_t i = begin + 1; i < last; ++i) {
    if (at.exact[i]) continue;
    ++counts.deepest;
    gaps.gap_to(at.elements[begin], at.point(i), at.gaps[i]);
    at.exact[i] = 1;
    at.elements[i] = at.elements[begin];
    at.nearest[i] = {HUGE_VAL, HUGE_VAL};  // unknown: bounds nothing
  }
  sole = {at.elements[begin], centre, spread};
  return true;
}

/// The run [begin, last]'s first deepest sample by exact gaps (the first
/// of the greatest, as a scan would choose), by branch and bound: between
/// two exact samples l < r, spaced at most `spacing` apart along the
/// element, no gap exceeds (g_l + g_r + (r - l) * spacing) / 2; a stretch
/// whose bound (plus the margin) is below the best exact gap so far holds
/// neither a deeper sample nor an equal one, so it is left unasked. On a
/// `straight` element a second bound is often much tighter (along a slot's
/// wall the gap grows as fast as the Lipschitz bound allows, and that bound
/// alone asked nearly every sample): a sample's gap is at most its
/// distance to any point of the contour, less R, and the distance to l's
/// or r's nearest point is convex along the line, so largest at the samples
/// next to l and r.
std::size_t first_deepest(Samples& at, std::size_t begin, std::size_t last, ExactGaps& gaps, double spacing,
                          double radius, bool straight, double slack, UncutQueryCounts& counts, SoleStretch& sole) {
  const auto ask = [&](std::size_t i) { at.ask(i, at.point(i), gaps, counts.deepest); };
  for (const std::size_t end : {begin, last})
    if (!at.exact[end]) ask(end);
  std::size_t deepest = begin;
  const auto improve = [&](std::size_t i) {  // the scan's rule: the first of equal gaps
    if (at.gaps[i] > at.gaps[deepest] || (at.gaps[i] == at.gaps[deepest] && i < deepest)) deepest = i;
  };
  if (straight && last - begin >= 2 && at.elements[begin] == at.elements[last] &&
      settled_by_sole(at, begin, last, gaps, slack, counts, sole)) {
    for (std::size_t i = begin; i <= last; ++i) improve(i);
    return deepest;
  }
  struct Stretch {
    double bound;
    std::size_t l, r;
    bool operator<(const Stretch& o) const { return bound < o.bound; }
  };
  std::priority_queue<Stretch> open;
  const auto bound = [&](std::size_t l, std::size_t r) {
    double most = (at.gaps[l] + at.gaps[r] + static_cast<double>(r - l) * spacing) / 2;
    if (straight)  // the samples between are no farther from the contour than from l's or r's nearest point
      for (const std::size_t end : {l, r}) {
        const Point a = at.nearest[end];
        most = std::min(most, std::max(apart_by(at.point(l + 1), a), apart_by(at.point(r - 1), a)) - radius);
      }
    return most + slack;
  };
  const auto consider = [&](std::size_t l, std::size_t r) {
    if (r - l >= 2) open.push({bound(l, r), l, r});
  };
  for (std::size_t i = begin, l = begin; i <= last; ++i) {
    if (!at.exact[i]) continue;
    improve(i);
    consider(l, i);
    l = i;
  }
  while (!open.empty() && open.top().bound >= at.gaps[deepest]) {
    const Stretch t = open.top();
    open.pop();
    const std::size_t m = t.l + (t.r - t.l) / 2;
    ask(m);
    improve(m);
    consider(t.l, m);
    consider(m, t.r);
  }
  return deepest;
}

/// A point whose gap is exact, and the contour's element nearest to it.
struct Known {
  Point p;
  double gap;
  std::size_t element;
};

/// The golden-section search's ratio and steps (the search that defines the
/// depth), and the width of its last bracket as a fraction of its first.
const double kGolden = (std::sqrt(5.0) - 1) / 2;
constexpr int kGoldenSteps = 40;
const double kGoldenLastWidth = std::pow(kGolden, kGoldenSteps);

/// Whether the golden-section search over [lo, hi] on a straight element
/// cannot end deeper than the deepest sample (whose gap is `deepest_gap`,
/// its nearest element `element` and point `nearest`): then the depth is
/// that sample's, and the search need not run. Each step keeps a golden
/// fraction of the bracket, so the point it ends on, the middle of the
/// last, lies at least half the last's width inside [lo, hi]; there no gap
/// exceeds the distance to `nearest`, or to `element` if it is a line (both
/// convex along the element), which are largest at its ends. A deepest
/// sample at the element's end (a gear's root) is so settled: the gap
/// falls away from it, even over that last half width.
bool ends_no_deeper(const Segment& s, double lo, double hi, double deepest_gap, Point nearest, std::size_t element,
                    const ExactGaps& gaps, double radius, double margin) {
  const double last_width = (hi - lo) * kGoldenLastWidth;
  const Point a = point_at(s, lo + 0.45 * last_width), b = point_at(s, hi - 0.45 * last_width);  // 0.45: rounding
  double most = std::max(apart_by(a, nearest), apart_by(b, nearest)) - radius;
  double to_a = 0, to_b = 0;
  if (gaps.straight(element) && gaps.gap_to(element, a, to_a) && gaps.gap_to(element, b, to_b))
    most = std::min(most, std::max(to_a, to_b));
  return most + margin <= deepest_gap;
}

/// The golden-section search between the deepest sample's neighbours, in
/// its usual form (both inner points computed every step), each step's
/// comparison decided as the exact gaps would decide it but mostly from
/// bounds: from points already known exactly, a gap is at least theirs
/// less the distance (Lipschitz) and at most the distance to their nearest
/// elements. Only a comparison the bounds leave open asks the contour;
/// where one element is nearest throughout the bracket (`sole_`), each
/// comparison is of the distances to it.
class GoldenSearch {
 public:
  GoldenSearch(const Segment& s, ExactGaps& gaps, double slack, std::size_t& count)
      : s_(s), gaps_(gaps), slack_(slack), count_(count) {}
  void know(const Known& k) {
    known_[next_] = k;
    next_ = (next_ + 1) % kKept;
    size_ = std::min(size_ + 1, kKept);
  }
  /// `sole`: where one element is known nearest throughout (first_deepest's), if anywhere.
  double depth(double lo, double hi, double sampled_depth, const SoleStretch& sole) {
    // Every point asked lies within the bracket (centre_, spread_).
    centre_ = point_at(s_, 0.5 * (lo + hi));
    spread_ = segment_length(s_) * 0.5 * (hi - lo) * (1 + 1e-9) +
              1e-12 * (std::abs(centre_.x) + std::abs(centre_.y) + segment_length(s_));
    if (sole.element != SIZE_MAX && apart_by(centre_, sole.centre) + spread_ <= sole.spread) sole_ = sole.element;
    for (int k = 0; k < kGoldenSteps; ++k) {
      const double a = hi - kGolden * (hi - lo), b = lo + kGolden * (hi - lo);
      if (deeper(point_at(s_, a), point_at(s_, b))) {
        hi = b;
      } else {
        lo = a;
      }
    }
    const Point last = point_at(s_, 0.5 * (lo + hi));
    return std::max(sampled_depth, sole_ != SIZE_MAX ? sole_gap(last) : exact(last));
  }

 private:
  // The last few points asked: the search closes in on them. Three, not six:
  // on a comb the bounds from six cost more than the questions they saved
  // (find_uncut 11 % fewer instructions, 3 % more questions).
  static constexpr std::size_t kKept = 3;
  // Questions asked of the tree before the elements round the bracket are
  // listed (a gear's searches mostly end within two; a comb's ask dozens).
  static constexpr std::size_t kAskedAlone = 2;
  /// Bounds on p's gap (low, high): from the known points' gaps alone
  /// (Lipschitz); `closest`, the known point nearest to p, whose element
  /// bounds the gap best. True when p was asked before (low = high = its gap).
  /// (Plain doubles, not a struct: copying one stalled on its two stores.)
  bool bounds(Point p, double& low, double& high, std::size_t& closest) const {
    low = -HUGE_VAL, high = HUGE_VAL;
    double closest_apart = HUGE_VAL;
    for (std::size_t i = 0; i < size_; ++i) {
      const Known& k = known_[i];
      if (k.p.x == p.x && k.p.y == p.y) {
        low = high = k.gap;
        return true;
      }
      const double apart = apart_by(p, k.p);
      low = std::max(low, k.gap - apart - slack_);
      high = std::min(high, k.gap + apart + slack_);
      if (apart < closest_apart) closest_apart = apart, closest = i;
    }
    return false;
  }
  /// The bound by the closest known point's element, the tighter one.
  void tighten(double& high, Point p, std::size_t closest) const {
    double by_element = 0;
    if (size_ > 0 && gaps_.gap_to(known_[closest].element, p, by_element)) high = std::min(high, by_element + slack_);
  }
  double exact(Point p) {
    std::size_t closest = 0;
    double low, high;
    if (bounds(p, low, high, closest)) return low;
    if (!nearby_ && ++asked_ > kAskedAlone && size_ > 0) {
      // A search that keeps asking: list the contour's elements that can be
      // nearest within the bracket once (bounded by the gaps known), so
      // that each answer looks at a few of them, not down the tree.
      double largest_gap = HUGE_VAL;  // in the bracket, by the Lipschitz bound from each known point
      for (std::size_t i = 0; i < size_; ++i)
        largest_gap = std::min(largest_gap, known_[i].gap + slack_ + apart_by(known_[i].p, centre_) + spread_);
      nearby_ = gaps_.nearby(centre_, spread_, largest_gap);
      if (nearby_) sole_ = nearby_->sole();
    }
    const double gap = gaps_.at(p, count_, nearby_ ? &*nearby_ : nullptr);
    know({p, gap, gaps_.last_element()});
    return gap;
  }
  /// The exact gap where one element is nearest throughout the bracket:
  /// its distance, as the index would answer (no search, no bounds).
  double sole_gap(Point p) {
    ++count_;
    double gap = 0;
    gaps_.gap_to(sole_, p, gap);
    return gap;
  }
  /// gap(a) > gap(b), the exact gaps' answer.
  bool deeper(Point a, Point b) {
    // Along a slot's flat floor the gap barely changes: the bounds settle
    // nothing and each step asked the contour (a comb's refinement was
    // three quarters of its uncut search).
    if (sole_ != SIZE_MAX) return sole_gap(a) > sole_gap(b);
    for (;;) {
      std::size_t closest_a = 0, closest_b = 0;
      double low_a, high_a, low_b, high_b;
      const bool exact_a = bounds(a, low_a, high_a, closest_a), exact_b = bounds(b, low_b, high_b, closest_b);
      if (exact_a && exact_b) return low_a > low_b;
      if (low_a > high_b) return true;
      if (high_a < low_b) return false;
      if (!exact_a) tighten(high_a, a, closest_a);
      if (!exact_b) tighten(high_b, b, closest_b);
      if (low_a > high_b) return true;
      if (high_a < low_b) return false;
      // Ask the less certain of the two; its answer may settle the other.
      const bool ask_a = !exact_a && (exact_b || high_a - low_a >= high_b - low_b);
      exact(ask_a ? a : b);
    }
  }

  const Segment& s_;
  ExactGaps& gaps_;
  double slack_;
  std::size_t& count_;
  Known known_[kKept];
  std::size_t next_ = 0, size_ = 0;
  std::optional<RegionIndex::Nearby> nearby_;
  std::size_t sole_ = SIZE_MAX;  // nearby_'s sole element: nearest throughout the bracket
  Point centre_;
  double spread_ = 0;
  std::size_t asked_ = 0;
};

/// Joins the spans of one loop (from `first_of_loop` on) that meet at a
/// corner: the end of one element and the start of the next.
void join_at_corners(std::vector<UncutSpan>& spans, std::size_t first_of_loop) {
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

}  // namespace

std::vector<UncutSpan> find_uncut(const std::vector<Loop>& drawn, const RegionIndex* contour, double radius,
                                  const OffsetOptions& options, UncutQueryCounts* counts_out) {
  std::vector<UncutSpan> spans;
  if (radius <= 0) return spans;
  UncutQueryCounts counts;
  const double step = std::max(radius / 8, 10 * options.tolerance);
  const double threshold = options.uncut_report_mm;
  ExactGaps gaps(contour, radius);
  // The bounds' margin: far above the rounding of any distance computed
  // here or by the index (a few dozen ulps of the coordinates', centres'
  // and radii's magnitude), so every decision is the exact gaps' one.
  double magnitude = 0;
  for (const Loop& loop : drawn)
    for (const Segment& s : loop.segments) magnitude = std::max(magnitude, rounding_scale(s));
  if (contour)
    for (const Segment& s : contour->elements()) magnitude = std::max(magnitude, rounding_scale(s));
  const double slack = 1e-12 * (1 + radius) + 3e-14 * magnitude;
  // ends_no_deeper()'s margin: its one bound is two distances (each within
  // some 16 ulps of the coordinates' and radii's size, which the magnitude
  // is at least twice) and a point's rounding. A third of the slack: the
  // last half width it must fit into is 2.7e-10 of a 0.125 mm sample
  // spacing, and a 100k gear's slack (its coordinates in the thousands)
  // left no room.
  const double ends_margin = 1e-12 * (1 + radius) + 1e-14 * magnitude;
  Samples at;
  // The last sample's exact gap, if it was asked: the next element starts
  // at the same point (the same question, the same answer).
  struct Carried {
    Point p, nearest;
    double gap = 0;
    std::size_t element = 0;
    bool known = false;
  } carried;
  for (const Loop& loop : drawn) {
    const std::size_t first_of_loop = spans.size();
    for (const Segment& s : loop.segments) {
      const double length = segment_length(s);
      const std::size_t samples = std::min<std::size_t>(10000, 1 + static_cast<std::size_t>(length / step));
      at.reset(s, samples);
      counts.samples += samples + 1;
      const Point first = at.point(0);
      if (carried.known && first.x == carried.p.x && first.y == carried.p.y) {
        at.gaps[0] = carried.gap, at.exact[0] = 1, at.uncut[0] = carried.gap > threshold;
        at.elements[0] = carried.element, at.nearest[0] = carried.nearest;
      }
      const double spacing = length / static_cast<double>(samples) * (1 + 1e-12);
      classify(at, gaps, threshold, slack, spacing, !is_arc(s), counts);
      for (std::size_t i = 0; i <= samples;) {
        if (!at.uncut[i]) {
          ++i;
          continue;
        }
        const std::size_t begin = i;
        while (i <= samples && at.uncut[i]) ++i;
        SoleStretch sole;
        const std::size_t deepest =
            first_deepest(at, begin, i - 1, gaps, spacing, radius, !is_arc(s), slack, counts, sole);
        const double lo = static_cast<double>(deepest == 0 ? 0 : deepest - 1) / samples;
        const double hi = static_cast<double>(std::min(deepest + 1, samples)) / samples;
        double depth = at.gaps[deepest];
        if (is_arc(s) ||
            !ends_no_deeper(s, lo, hi, depth, at.nearest[deepest], at.elements[deepest], gaps, radius, ends_margin)) {
          GoldenSearch search(s, gaps, slack, counts.refining);
          for (const std::size_t k : {deepest == 0 ? deepest : deepest - 1, std::min(deepest + 1, samples), deepest})
            if (at.exact[k]) search.know({at.point(k), at.gaps[k], at.elements[k]});
          depth = search.depth(lo, hi, at.gaps[deepest], sole);
        }
        spans.push_back({point_at(s, static_cast<double>(begin) / samples),
                         point_at(s, static_cast<double>(i - 1) / samples), depth, s.entity, s.source_line});
      }
      carried = {at.point(samples), at.nearest[samples], at.gaps[samples], at.elements[samples],
                 at.exact[samples] != 0};
    }
    join_at_corners(spans, first_of_loop);
  }
  if (counts_out) *counts_out = counts;
  return spans;
}

}  // namespace tk::cad
