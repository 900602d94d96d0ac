/// @file loops.cpp
/// @brief From loose segments to nested, oriented loops: cluster the ends
/// that lie within the join tolerance, pair the ends at each cluster,
/// follow the pairs into chains, then nest the closed chains by crossing
/// parity and orient them. Everything is ordered by input position, never
/// by hash or address, so the result is deterministic.
#include "cad/loops.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <numeric>
#include <optional>
#include <string>
#include <tuple>
#include <utility>

#include "cad/segment_geometry.hpp"
#include "io/error.hpp"

namespace tk::cad {

namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

using CellKey = std::pair<std::int64_t, std::int64_t>;

CellKey cell_of(Point p, double cell) {
  const auto index = [cell](double x) {
    return static_cast<std::int64_t>(std::clamp(std::floor(x / cell), -4e18, 4e18));
  };
  return {index(p.x), index(p.y)};
}

/// Something (an end, a segment) in a cell.
using CellEntry = std::tuple<CellKey, std::size_t>;
constexpr std::size_t kRadixSortFrom = 4096;  // entries

/// Sorts by cell, then by what is in it. Requires the entries of each cell
/// to come in ascending order of what is in them (both callers add them so):
/// where the cells' rows times columns fit in 64 bits (a part of any
/// sensible size) each cell is one integer and the sort is a stable radix
/// sort of 16-bit digits, a few passes. std::sort of the tuples was most of
/// build_loops' time on a 100,000-element comb.
void sort_cells(std::vector<CellEntry>& entries) {
  if (entries.size() < kRadixSortFrom) {  // not worth its table of counts
    std::sort(entries.begin(), entries.end());
    return;
  }
  std::int64_t min_x = INT64_MAX, min_y = INT64_MAX, max_x = INT64_MIN, max_y = INT64_MIN;
  for (const auto& [key, item] : entries) {
    min_x = std::min(min_x, key.first), max_x = std::max(max_x, key.first);
    min_y = std::min(min_y, key.second), max_y = std::max(max_y, key.second);
  }
  const std::uint64_t rows = std::uint64_t(max_y) - std::uint64_t(min_y) + 1;
  const std::uint64_t columns = std::uint64_t(max_x) - std::uint64_t(min_x) + 1;
  if (rows == 0 || columns == 0 || columns > UINT64_MAX / rows || entries.size() > UINT32_MAX) {
    std::sort(entries.begin(), entries.end());
    return;
  }
  std::vector<std::uint64_t> keys(entries.size());
  std::uint64_t largest = 0;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const CellKey& key = std::get<0>(entries[i]);
    keys[i] =
        (std::uint64_t(key.first) - std::uint64_t(min_x)) * rows + (std::uint64_t(key.second) - std::uint64_t(min_y));
    largest = std::max(largest, keys[i]);
  }
  std::vector<std::uint32_t> order(entries.size()), next(entries.size());
  std::iota(order.begin(), order.end(), 0u);
  std::vector<std::size_t> count(1 << 16);
  for (int shift = 0; shift < 64 && (largest >> shift) != 0; shift += 16) {
    std::fill(count.begin(), count.end(), 0);
    for (const std::uint32_t i : order) ++count[(keys[i] >> shift) & 0xffff];
    std::size_t sum = 0;
    for (std::size_t& c : count) sum += std::exchange(c, sum);
    for (const std::uint32_t i : order) next[count[(keys[i] >> shift) & 0xffff]++] = i;
    order.swap(next);
  }
  std::vector<CellEntry> sorted;
  sorted.reserve(entries.size());
  for (const std::uint32_t i : order) sorted.push_back(entries[i]);
  entries.swap(sorted);
}

class UnionFind {
 public:
  explicit UnionFind(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), std::size_t{0}); }
  std::size_t find(std::size_t i) {
    while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
    return i;
  }
  void unite(std::size_t a, std::size_t b) {
    a = find(a), b = find(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }

 private:
  std::vector<std::size_t> parent_;
};

/// Clusters end points (2k = start of segment k, 2k + 1 = its end) that are
/// within `tolerance` of each other, directly or through a chain of ends.
/// Clusters are numbered by their first end.
std::vector<std::size_t> cluster_ends(const std::vector<Point>& ends, double tolerance, std::size_t& count) {
  const double cell = tolerance > 0 ? tolerance : 1;
  std::vector<CellEntry> sorted;
  sorted.reserve(ends.size());
  for (std::size_t i = 0; i < ends.size(); ++i) sorted.emplace_back(cell_of(ends[i], cell), i);
  sort_cells(sorted);
  UnionFind sets(ends.size());
  const auto key_at = [&](std::size_t k) { return std::get<0>(sorted[k]); };
  const auto unite_near = [&](std::size_t a_begin, std::size_t a_end, std::size_t b_begin, std::size_t b_end) {
    for (std::size_t a = a_begin; a < a_end; ++a)
      for (std::size_t b = std::max(b_begin, a + 1); b < b_end; ++b) {
        const std::size_t i = std::get<1>(sorted[a]), j = std::get<1>(sorted[b]);
        if (distance(ends[i], ends[j]) <= tolerance) sets.unite(i, j);
      }
  };
  // Each pair of neighbouring cells once: a cell with itself, the one above
  // it and the three in the next column. Cells come sorted by column, then
  // row, so the next column's are found by one pointer moving forward.
  std::size_t next_column = 0;
  for (std::size_t begin = 0, end = 0; begin < sorted.size(); begin = end) {
    const CellKey key = key_at(begin);
    while (end < sorted.size() && key_at(end) == key) ++end;
    unite_near(begin, end, begin, end);
    std::size_t above_end = end;
    while (above_end < sorted.size() && key_at(above_end) == CellKey{key.first, key.second + 1}) ++above_end;
    unite_near(begin, end, end, above_end);
    const CellKey low{key.first + 1, key.second - 1}, high{key.first + 1, key.second + 1};
    next_column = std::max(next_column, end);
    while (next_column < sorted.size() && key_at(next_column) < low) ++next_column;
    std::size_t next_column_end = next_column;
    while (next_column_end < sorted.size() && key_at(next_column_end) <= high) ++next_column_end;
    unite_near(begin, end, next_column, next_column_end);
  }
  std::vector<std::size_t> cluster(ends.size()), number(ends.size(), SIZE_MAX);
  count = 0;
  for (std::size_t i = 0; i < ends.size(); ++i) {
    const std::size_t root = sets.find(i);
    if (number[root] == SIZE_MAX) number[root] = count++;
    cluster[i] = number[root];
  }
  return cluster;
}

/// Direction in which the segment leaves the given end.
double leaving_angle(const Segment& segment, bool at_end) {
  const Point t = tangent_at(segment, at_end ? 1 : 0);
  return at_end ? std::atan2(-t.y, -t.x) : std::atan2(t.y, t.x);
}

/// Pairs the ends meeting at one point so that the chains through it do
/// not cross: neighbours in angular order are paired, choosing the phase
/// (and for an odd count the end left over) that avoids pairing two ends
/// leaving in the same direction (a doubled segment) and then minimises the
/// total angle inside the pairs. Ties leave the latest end over; beyond 13
/// ends only the phase is chosen, the last in angular order left over.
void pair_ends(std::vector<std::pair<double, std::size_t>> around, std::vector<std::ptrdiff_t>& partner) {
  std::sort(around.begin(), around.end());
  const std::size_t n = around.size();
  struct Cost {
    int same_direction = 0;
    double angle = 0;
    bool operator<(const Cost& o) const {
      return same_direction != o.same_direction ? same_direction < o.same_direction : angle < o.angle - 1e-12;
    }
  };
  const auto cost_of = [&](std::size_t skip, std::size_t phase) {
    std::vector<std::size_t> kept;
    for (std::size_t i = 0; i < n; ++i)
      if (i != skip) kept.push_back(i);
    Cost cost;
    for (std::size_t i = phase; i + 1 < kept.size() + phase; i += 2) {
      const double from = around[kept[i % kept.size()]].first, to = around[kept[(i + 1) % kept.size()]].first;
      const double gap = std::fmod(to - from + 2 * kTwoPi, kTwoPi);
      cost.same_direction += gap < 1e-9 || gap > kTwoPi - 1e-9;
      cost.angle += gap;
    }
    return std::pair{cost, kept};
  };
  std::vector<std::size_t> skips;
  if (n % 2 == 0) skips.push_back(SIZE_MAX);
  else if (n > 13) skips.push_back(n - 1);
  else
    for (std::size_t i = 0; i < n; ++i) skips.push_back(i);
  bool have = false;
  Cost best;
  std::size_t best_skip = 0, best_phase = 0;
  for (std::size_t skip : skips)
    for (std::size_t phase = 0; phase < 2; ++phase) {
      const Cost cost = cost_of(skip, phase).first;
      const bool later = have && !(best < cost) && skip != SIZE_MAX && around[skip].second > around[best_skip].second;
      if (!have || cost < best || later) {
        have = true, best = cost, best_skip = skip, best_phase = phase;
      }
    }
  const std::vector<std::size_t> kept = cost_of(best_skip, best_phase).second;
  for (std::size_t i = best_phase; i + 1 < kept.size() + best_phase; i += 2) {
    const std::size_t a = around[kept[i % kept.size()]].second, b = around[kept[(i + 1) % kept.size()]].second;
    partner[a] = static_cast<std::ptrdiff_t>(b);
    partner[b] = static_cast<std::ptrdiff_t>(a);
  }
}

Box box_of(const std::vector<Segment>& segments) {
  Box box = bounding_box(segments.front());
  for (const Segment& s : segments) {
    const Box b = bounding_box(s);
    box = {std::min(box.min_x, b.min_x), std::min(box.min_y, b.min_y), std::max(box.max_x, b.max_x),
           std::max(box.max_y, b.max_y)};
  }
  return box;
}

bool box_contains(const Box& box, Point p) {
  return p.x >= box.min_x && p.x <= box.max_x && p.y >= box.min_y && p.y <= box.max_y;
}

/// Even-odd point-in-loop test for one loop, its segments bucketed by
/// their y extent so that a test looks only at the segments near p.y.
class LoopParity {
 public:
  explicit LoopParity(const std::vector<Segment>& segments) : segments_(segments), box_(box_of(segments)) {
    for (const Segment& s : segments) boxes_.push_back(bounding_box(s));
    // As many buckets as segments, fewer when tall segments would fill too many.
    for (buckets_ = std::max<std::size_t>(1, std::min<std::size_t>(segments.size() / 2, 1 << 16));; buckets_ /= 2) {
      height_ = (box_.max_y - box_.min_y) / double(buckets_);
      std::size_t total = 0;
      for (const Box& b : boxes_) total += bucket(b.max_y) - bucket(b.min_y) + 1;
      if (total <= 8 * segments.size() || buckets_ == 1) break;
    }
    start_.assign(buckets_ + 1, 0);
    for (const Box& b : boxes_)
      for (std::size_t k = bucket(b.min_y); k <= bucket(b.max_y); ++k) ++start_[k + 1];
    std::partial_sum(start_.begin(), start_.end(), start_.begin());
    members_.resize(start_.back());
    std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
    for (std::size_t i = 0; i < boxes_.size(); ++i)
      for (std::size_t k = bucket(boxes_[i].min_y); k <= bucket(boxes_[i].max_y); ++k) members_[fill[k]++] = i;
  }

  const Box& box() const { return box_; }

  bool inside(Point p) const {
    if (!box_contains(box_, p)) return false;
    const std::size_t k = bucket(p.y);
    bool odd = false;
    for (std::size_t m = start_[k]; m < start_[k + 1]; ++m) {
      const std::size_t i = members_[m];
      // Outside its box in y, or wholly left of p, a segment cannot cross the ray.
      if (p.y < boxes_[i].min_y || p.y > boxes_[i].max_y || boxes_[i].max_x < p.x) continue;
      odd ^= crosses_ray(segments_[i], p);
    }
    return odd;
  }

 private:
  std::size_t bucket(double y) const {
    const double k = height_ > 0 ? std::floor((y - box_.min_y) / height_) : 0;
    return static_cast<std::size_t>(std::clamp(k, 0.0, double(buckets_ - 1)));
  }

  const std::vector<Segment>& segments_;
  Box box_;
  std::vector<Box> boxes_;
  std::size_t buckets_ = 1;
  double height_ = 0;
  std::vector<std::size_t> start_, members_;
};

/// Ends lying on another segment's interior: segments are cut into pieces
/// of about the mean length and hashed by cell, so long lines cost no more
/// than short ones.
void find_t_junctions(const std::vector<Segment>& kept, const std::vector<bool>& used,
                      const std::vector<std::size_t>& cluster, const std::vector<Point>& cluster_point,
                      double tolerance, std::vector<TJunction>& out) {
  double total = 0;
  std::size_t count = 0;
  for (std::size_t k = 0; k < kept.size(); ++k)
    if (used[k]) total += segment_length(kept[k]), ++count;
  if (count == 0) return;
  const double cell = std::max(2 * tolerance, total / double(count));
  std::vector<CellEntry> grid;
  for (std::size_t k = 0; k < kept.size(); ++k) {
    if (!used[k]) continue;
    const double pieces = std::min(1e6, std::max(1.0, std::ceil(segment_length(kept[k]) / cell)));
    for (double i = 0; i < pieces; ++i) {
      const Box b = bounding_box(sub_segment(kept[k], i / pieces, (i + 1) / pieces));
      const CellKey lo = cell_of({b.min_x - tolerance, b.min_y - tolerance}, cell);
      const CellKey hi = cell_of({b.max_x + tolerance, b.max_y + tolerance}, cell);
      for (std::int64_t x = lo.first; x <= hi.first; ++x)
        for (std::int64_t y = lo.second; y <= hi.second; ++y) grid.emplace_back(CellKey{x, y}, k);
    }
  }
  sort_cells(grid);
  grid.erase(std::unique(grid.begin(), grid.end()), grid.end());
  // Most segments of a cell lie farther than the tolerance from p even by
  // their boxes: they are passed over without the distance (std::hypot's
  // cost was most of this function's). The margin covers the rounding of
  // the box and of the distance, so only segments the distance would pass
  // over are.
  std::vector<Box> boxes(kept.size());
  for (std::size_t k = 0; k < kept.size(); ++k)
    if (used[k]) boxes[k] = bounding_box(kept[k]);
  std::vector<std::size_t> first_end(cluster_point.size(), SIZE_MAX);
  for (std::size_t e = 0; e < cluster.size(); ++e)
    if (used[e / 2] && first_end[cluster[e]] == SIZE_MAX) first_end[cluster[e]] = e;
  for (std::size_t c = 0; c < cluster_point.size(); ++c) {
    if (first_end[c] == SIZE_MAX) continue;
    const Point p = cluster_point[c];
    const CellKey key = cell_of(p, cell);
    const double reach = tolerance * (1 + 1e-9) + 1e-12 * (std::abs(p.x) + std::abs(p.y));
    auto it = std::lower_bound(grid.begin(), grid.end(), CellEntry{key, 0});
    for (; it != grid.end() && std::get<0>(*it) == key; ++it) {
      const std::size_t k = std::get<1>(*it);
      const Segment& s = kept[k];
      if (cluster[2 * k] == c || cluster[2 * k + 1] == c) continue;
      const Box& b = boxes[k];
      if (p.x < b.min_x - reach || p.x > b.max_x + reach || p.y < b.min_y - reach || p.y > b.max_y + reach) continue;
      if (distance(nearest_point(s, p), p) > tolerance || distance(s.start, p) <= tolerance ||
          distance(s.end, p) <= tolerance)
        continue;
      const Segment& own = kept[first_end[c] / 2];
      out.push_back({p, own.entity, own.source_line, s.entity, s.source_line});
    }
  }
}

}  // namespace

void reverse_chain(std::vector<Segment>& chain) {
  std::reverse(chain.begin(), chain.end());
  for (Segment& s : chain) {
    std::swap(s.start, s.end);
    s.bulge = -s.bulge;
  }
}

std::vector<Point> flatten_loop(const Loop& loop, double tolerance) {
  std::vector<Point> points;
  if (loop.segments.empty()) return points;
  points.push_back(loop.segments.front().start);
  for (const Segment& s : loop.segments) flatten(s, tolerance, points);
  return points;
}

double signed_area(const std::vector<Segment>& loop) {
  if (loop.empty()) return 0;
  const Point o = loop.front().start;  // near the loop, for a well-conditioned shoelace
  double twice = 0, arcs = 0;
  for (const Segment& s : loop) {
    twice += (s.start.x - o.x) * (s.end.y - o.y) - (s.end.x - o.x) * (s.start.y - o.y);
    arcs += arc_area(s);
  }
  return twice / 2 + arcs;
}

LoopSet build_loops(const std::vector<Segment>& segments, double join_tolerance) {
  if (!std::isfinite(join_tolerance) || join_tolerance < 0) throw Error("join tolerance must be a finite number >= 0");
  const double tol = join_tolerance;
  LoopSet result;

  // Segments shorter than the tolerance vanish; their ends join neighbours anyway.
  std::vector<Segment> kept;
  std::vector<std::size_t> input_index;
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const Segment& s = segments[i];
    if (!std::isfinite(s.start.x) || !std::isfinite(s.start.y) || !std::isfinite(s.end.x) || !std::isfinite(s.end.y) ||
        !std::isfinite(s.bulge))
      throw Error("entity " + std::to_string(s.entity) + " (line " + std::to_string(s.source_line) +
                  ") has a non-finite coordinate");
    const double length = segment_length(s);
    if (length > 0 && length >= tol) kept.push_back(s), input_index.push_back(i);
  }
  std::vector<Point> ends;
  for (const Segment& s : kept) ends.push_back(s.start), ends.push_back(s.end);
  std::size_t clusters = 0;
  const std::vector<std::size_t> cluster = cluster_ends(ends, tol, clusters);
  std::vector<Point> point(clusters);
  std::vector<std::size_t> size(clusters, 0);
  std::vector<Point> first(clusters), offset(clusters);
  for (std::size_t e = 0; e < ends.size(); ++e) {
    const std::size_t c = cluster[e];
    if (size[c]++ == 0) first[c] = ends[e];
    offset[c].x += ends[e].x - first[c].x;
    offset[c].y += ends[e].y - first[c].y;
  }
  for (std::size_t c = 0; c < clusters; ++c)
    point[c] = {first[c].x + offset[c].x / double(size[c]), first[c].y + offset[c].y / double(size[c])};

  // A segment whose two ends joined each other collapses: a line is gone,
  // an arc cannot be drawn between equal ends and stays open.
  std::vector<bool> used(kept.size(), true);
  for (std::size_t k = 0; k < kept.size(); ++k)
    if (cluster[2 * k] == cluster[2 * k + 1]) {
      used[k] = false;
      if (is_arc(kept[k])) result.open_segments.push_back(kept[k]);
    }

  std::vector<std::vector<std::pair<double, std::size_t>>> around(clusters);
  for (std::size_t e = 0; e < ends.size(); ++e)
    if (used[e / 2]) around[cluster[e]].emplace_back(leaving_angle(kept[e / 2], e % 2 == 1), e);
  std::vector<std::ptrdiff_t> partner(ends.size(), -1);
  for (auto& meeting : around) {
    if (meeting.size() == 2) {
      partner[meeting[0].second] = static_cast<std::ptrdiff_t>(meeting[1].second);
      partner[meeting[1].second] = static_cast<std::ptrdiff_t>(meeting[0].second);
    } else if (meeting.size() > 2) {
      pair_ends(std::move(meeting), partner);
    }
  }

  // Follow the pairs from `enter` (an end id); each segment is oriented
  // along the walk with its ends moved to their cluster's point.
  std::vector<bool> visited(kept.size(), false);
  const auto walk = [&](std::size_t enter, std::vector<Segment>& chain, std::size_t& lowest) {
    lowest = SIZE_MAX;
    while (!visited[enter / 2]) {
      const std::size_t k = enter / 2;
      visited[k] = true;
      lowest = std::min(lowest, input_index[k]);
      Segment s = kept[k];
      if (enter % 2 == 1) s.bulge = -s.bulge;
      s.start = point[cluster[enter]];
      s.end = point[cluster[enter ^ 1]];
      chain.push_back(s);
      const std::ptrdiff_t next = partner[enter ^ 1];
      if (next < 0) break;
      enter = static_cast<std::size_t>(next);
    }
  };
  std::size_t lowest = 0;
  for (std::size_t e = 0; e < ends.size(); ++e) {
    if (!used[e / 2] || partner[e] >= 0) continue;
    const Segment& s = kept[e / 2];
    result.loose_ends.push_back({ends[e], s.entity, s.source_line});
    if (!visited[e / 2]) walk(e, result.open_segments, lowest);
  }
  struct Found {
    Loop loop;
    std::size_t first_input = 0;
    Box box;
    std::vector<Point> samples;
  };
  std::vector<Found> found;
  for (std::size_t k = 0; k < kept.size(); ++k) {
    if (!used[k] || visited[k]) continue;
    Found f;
    walk(2 * k, f.loop.segments, f.first_input);
    f.loop.area = signed_area(f.loop.segments);
    if (std::abs(f.loop.area) <= tol * tol) {
      result.open_segments.insert(result.open_segments.end(), f.loop.segments.begin(), f.loop.segments.end());
      continue;
    }
    f.box = box_of(f.loop.segments);
    const std::size_t n = f.loop.segments.size();
    for (std::size_t i : {std::size_t{0}, n / 3, 2 * n / 3})
      if (i == 0 || n >= 3) f.samples.push_back(point_at(f.loop.segments[i], 0.5));
    f.samples.resize(n >= 3 ? 3 : 1);  // n < 3 pushed the first midpoint more than once
    found.push_back(std::move(f));
  }
  find_t_junctions(kept, used, cluster, point, tol, result.t_junctions);

  // Nesting: a loop lies inside another when most of its sample points do
  // (a sample may sit on a shared edge); the parent is the smallest container.
  // A loop's ray test is built when a smaller loop first asks it (a part of
  // one loop builds none: it cost the 10k-element comb some 1.5 %).
  std::vector<std::optional<LoopParity>> parity(found.size());
  for (std::size_t a = 0; a < found.size(); ++a) {
    double parent_area = 0;
    for (std::size_t b = 0; b < found.size(); ++b) {
      if (a == b || std::abs(found[a].loop.area) >= std::abs(found[b].loop.area)) continue;
      if (!parity[b]) parity[b].emplace(found[b].loop.segments);
      std::size_t votes = 0;
      for (const Point& p : found[a].samples) votes += parity[b]->inside(p);
      if (2 * votes <= found[a].samples.size()) continue;
      ++found[a].loop.depth;
      if (found[a].loop.parent < 0 || std::abs(found[b].loop.area) < parent_area) {
        found[a].loop.parent = static_cast<int>(b);
        parent_area = std::abs(found[b].loop.area);
      }
    }
  }
  for (Found& f : found)
    if ((f.loop.area > 0) == f.loop.is_hole()) {
      reverse_chain(f.loop.segments);
      f.loop.area = -f.loop.area;
    }
  std::vector<std::size_t> order(found.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return std::tie(found[a].loop.depth, found[a].first_input) < std::tie(found[b].loop.depth, found[b].first_input);
  });
  std::vector<int> position(found.size());
  for (std::size_t i = 0; i < order.size(); ++i) position[order[i]] = static_cast<int>(i);
  for (std::size_t i : order) {
    Loop loop = std::move(found[i].loop);
    if (loop.parent >= 0) loop.parent = position[static_cast<std::size_t>(loop.parent)];
    result.loops.push_back(std::move(loop));
  }
  return result;
}

}  // namespace tk::cad

namespace tk::cad {

std::vector<Point> doubled_edges(const std::vector<Loop>& loops) {
  // An edge as its ends in lexicographic order and its bulge seen from the first.
  struct Key {
    double x0, y0, x1, y1, bulge;
    auto operator<=>(const Key&) const = default;
  };
  std::vector<Key> keys;
  for (const Loop& loop : loops)
    for (const Segment& s : loop.segments) {
      const bool forward = std::pair{s.start.x, s.start.y} <= std::pair{s.end.x, s.end.y};
      keys.push_back(forward ? Key{s.start.x, s.start.y, s.end.x, s.end.y, s.bulge}
                             : Key{s.end.x, s.end.y, s.start.x, s.start.y, -s.bulge});
    }
  std::sort(keys.begin(), keys.end());
  std::vector<Point> doubled;
  for (std::size_t i = 1; i < keys.size(); ++i)
    if (keys[i] == keys[i - 1] && (i < 2 || !(keys[i - 1] == keys[i - 2])))  // once per group
      doubled.push_back(point_at(Segment{{keys[i].x0, keys[i].y0}, {keys[i].x1, keys[i].y1}, keys[i].bulge}, 0.5));
  return doubled;
}

}  // namespace tk::cad
