/// @file line_track.cpp
/// @brief The track: pieces, grid, nearest-point queries, the oval and the
/// track file reader.
#include "vehicle/line_track.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "cad/segment_geometry.hpp"
#include "io/error.hpp"
#include "io/record_fields.hpp"
#include "io/record_reader.hpp"

namespace tk::vehicle {

namespace {

bool within_box(Point a, Point b, Point p) {
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y);
}

/// Segments ab and cd touch or cross (end points included).
bool segments_meet(Point a, Point b, Point c, Point d) {
  const double d1 = cad::orient(c, d, a), d2 = cad::orient(c, d, b), d3 = cad::orient(a, b, c),
               d4 = cad::orient(a, b, d);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return true;
  return (d1 == 0 && within_box(c, d, a)) || (d2 == 0 && within_box(c, d, b)) || (d3 == 0 && within_box(a, b, c)) ||
         (d4 == 0 && within_box(a, b, d));
}

bool same_point(Point a, Point b) { return a.x == b.x && a.y == b.y; }

}  // namespace

Track::Track(std::vector<Point> vertices, double line_width_mm)
    : vertices_(std::move(vertices)), line_width_(line_width_mm) {
  if (!(line_width_ > 0) || !std::isfinite(line_width_)) throw Error("line width must be a positive number of mm");
  if (vertices_.size() < 3) throw Error("a track needs at least 3 points");
  for (std::size_t i = 0; i < vertices_.size(); ++i) {
    if (!std::isfinite(vertices_[i].x) || !std::isfinite(vertices_[i].y)) throw Error("track point is not finite");
    if (same_point(vertices_[i], vertices_[(i + 1) % vertices_.size()]))
      throw Error(fmt::format("track points {} and {} are equal", i + 1, (i + 1) % vertices_.size() + 1));
  }
  build_pieces();
  build_grid();
}

double Track::start_heading() const {
  return std::atan2(vertices_[1].y - vertices_[0].y, vertices_[1].x - vertices_[0].x);
}

void Track::build_pieces() {
  const std::size_t n = vertices_.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point a = vertices_[i], b = vertices_[(i + 1) % n];
    const double length = std::hypot(b.x - a.x, b.y - a.y);
    const auto count = static_cast<std::size_t>(std::max(1.0, std::ceil(length / kMaxPieceMm)));
    for (std::size_t k = 0; k < count; ++k) {
      // Ends of pieces computed from the segment's ends, so consecutive pieces share them exactly.
      const double f0 = static_cast<double>(k) / count, f1 = static_cast<double>(k + 1) / count;
      const Point p0{a.x + f0 * (b.x - a.x), a.y + f0 * (b.y - a.y)};
      const Point p1 = k + 1 == count ? b : Point{a.x + f1 * (b.x - a.x), a.y + f1 * (b.y - a.y)};
      pieces_.push_back(Piece{p0, p1, length_ + f0 * length, length / count, i});
    }
    length_ += length;
  }
}

void Track::build_grid() {
  Point lo = vertices_.front(), hi = lo;
  for (const Point& v : vertices_) {
    lo = {std::min(lo.x, v.x), std::min(lo.y, v.y)};
    hi = {std::max(hi.x, v.x), std::max(hi.y, v.y)};
  }
  grid_origin_ = lo;
  grid_nx_ = static_cast<long>((hi.x - lo.x) / kCellMm) + 1;
  grid_ny_ = static_cast<long>((hi.y - lo.y) / kCellMm) + 1;
  // Two passes (count, then fill) give the compressed rows without a vector per cell.
  std::vector<std::size_t> count(static_cast<std::size_t>(grid_nx_ * grid_ny_) + 1, 0);
  for (int pass = 0; pass < 2; ++pass) {
    for (std::size_t i = 0; i < pieces_.size(); ++i) {
      const Piece& piece = pieces_[i];
      long cx0, cy0, cx1, cy1;
      cells({std::min(piece.a.x, piece.b.x), std::min(piece.a.y, piece.b.y)},
            {std::max(piece.a.x, piece.b.x), std::max(piece.a.y, piece.b.y)}, cx0, cy0, cx1, cy1);
      for (long cy = cy0; cy <= cy1; ++cy)
        for (long cx = cx0; cx <= cx1; ++cx) {
          const auto c = static_cast<std::size_t>(cy * grid_nx_ + cx);
          if (pass == 0) ++count[c + 1];
          else cell_items_[count[c]++] = i;
        }
    }
    if (pass == 0) {
      for (std::size_t c = 1; c < count.size(); ++c) count[c] += count[c - 1];
      cell_start_ = count;
      cell_items_.resize(count.back());
    }
  }
}

bool Track::cells(Point lo, Point hi, long& cx0, long& cy0, long& cx1, long& cy1) const {
  const double fx0 = std::floor((lo.x - grid_origin_.x) / kCellMm), fy0 = std::floor((lo.y - grid_origin_.y) / kCellMm);
  const double fx1 = std::floor((hi.x - grid_origin_.x) / kCellMm), fy1 = std::floor((hi.y - grid_origin_.y) / kCellMm);
  if (fx1 < 0 || fy1 < 0 || fx0 >= static_cast<double>(grid_nx_) || fy0 >= static_cast<double>(grid_ny_)) return false;
  cx0 = std::max(0L, static_cast<long>(fx0));
  cy0 = std::max(0L, static_cast<long>(fy0));
  cx1 = std::min(grid_nx_ - 1, static_cast<long>(fx1));
  cy1 = std::min(grid_ny_ - 1, static_cast<long>(fy1));
  return true;
}

Nearest Track::to_piece(Point p, std::size_t i) const {
  const Piece& piece = pieces_[i];
  const double dx = piece.b.x - piece.a.x, dy = piece.b.y - piece.a.y;
  const double t = std::clamp(((p.x - piece.a.x) * dx + (p.y - piece.a.y) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
  const double ex = p.x - (piece.a.x + t * dx), ey = p.y - (piece.a.y + t * dy);
  double s = piece.s0 + t * piece.length;
  if (s >= length_) s -= length_;
  return Nearest{ex * ex + ey * ey, s, i};  // squared: the callers take one root for the best
}

Nearest Track::nearest(Point p) const {
  Nearest best;
  for (std::size_t i = 0; i < pieces_.size(); ++i) {
    const Nearest n = to_piece(p, i);
    if (n.distance < best.distance) best = n;
  }
  best.distance = std::sqrt(best.distance);
  return best;
}

Nearest Track::nearest_near(Point p, std::size_t hint, double window_mm) const {
  const std::size_t n = pieces_.size();
  hint %= n;
  Nearest best = to_piece(p, hint);
  double walked = pieces_[hint].length;
  for (std::size_t k = 1; k < n && walked <= window_mm; ++k) {  // forward
    const Nearest c = to_piece(p, (hint + k) % n);
    if (c.distance < best.distance) best = c;
    walked += pieces_[(hint + k) % n].length;
  }
  walked = 0;
  for (std::size_t k = 1; k < n && walked <= window_mm; ++k) {  // backward
    const std::size_t i = (hint + n - k) % n;
    const Nearest c = to_piece(p, i);
    if (c.distance < best.distance) best = c;
    walked += pieces_[i].length;
  }
  best.distance = std::sqrt(best.distance);
  return best;
}

double Track::distance_within(Point p, double radius_mm) const {
  long cx0, cy0, cx1, cy1;
  if (!cells({p.x - radius_mm, p.y - radius_mm}, {p.x + radius_mm, p.y + radius_mm}, cx0, cy0, cx1, cy1))
    return std::numeric_limits<double>::infinity();
  double best = radius_mm * radius_mm;
  const auto search = [&](long cx, long cy) {
    const auto c = static_cast<std::size_t>(cy * grid_nx_ + cx);
    for (std::size_t k = cell_start_[c]; k < cell_start_[c + 1]; ++k)
      best = std::min(best, to_piece(p, cell_items_[k]).distance);
  };
  // The cell holding p first: a near piece found there lets the box test skip most others.
  const long hx = static_cast<long>(std::floor((p.x - grid_origin_.x) / kCellMm));
  const long hy = static_cast<long>(std::floor((p.y - grid_origin_.y) / kCellMm));
  const bool home = hx >= cx0 && hx <= cx1 && hy >= cy0 && hy <= cy1;
  if (home) search(hx, hy);
  for (long cy = cy0; cy <= cy1; ++cy)
    for (long cx = cx0; cx <= cx1; ++cx) {
      if (home && cx == hx && cy == hy) continue;
      const double x0 = grid_origin_.x + static_cast<double>(cx) * kCellMm,
                   y0 = grid_origin_.y + static_cast<double>(cy) * kCellMm;
      const double gx = std::max({x0 - p.x, 0.0, p.x - x0 - kCellMm}),
                   gy = std::max({y0 - p.y, 0.0, p.y - y0 - kCellMm});
      if (gx * gx + gy * gy <= best) search(cx, cy);
    }
  return best < radius_mm * radius_mm ? std::sqrt(best) : std::numeric_limits<double>::infinity();
}

Point Track::point_at(double s) const {
  s = std::fmod(s, length_);
  if (s < 0) s += length_;
  const auto after =
      std::upper_bound(pieces_.begin(), pieces_.end(), s, [](double v, const Piece& piece) { return v < piece.s0; });
  const Piece& piece = *std::prev(after);
  const double t = std::clamp((s - piece.s0) / piece.length, 0.0, 1.0);
  return {piece.a.x + t * (piece.b.x - piece.a.x), piece.a.y + t * (piece.b.y - piece.a.y)};
}

std::optional<std::pair<std::size_t, std::size_t>> Track::self_intersection() const {
  const std::size_t n = pieces_.size();
  std::optional<std::pair<std::size_t, std::size_t>> first;
  for (std::size_t c = 0; c + 1 < cell_start_.size(); ++c)
    for (std::size_t u = cell_start_[c]; u < cell_start_[c + 1]; ++u)
      for (std::size_t w = u + 1; w < cell_start_[c + 1]; ++w) {
        const std::size_t i = std::min(cell_items_[u], cell_items_[w]), j = std::max(cell_items_[u], cell_items_[w]);
        // Neighbours share an end; pieces of one segment are collinear and apart.
        if (j == i + 1 || (i == 0 && j == n - 1) || pieces_[i].vertex == pieces_[j].vertex) continue;
        if (!segments_meet(pieces_[i].a, pieces_[i].b, pieces_[j].a, pieces_[j].b)) continue;
        const std::pair<std::size_t, std::size_t> found{pieces_[i].vertex, pieces_[j].vertex};
        if (!first || std::make_pair(found.second, found.first) < std::make_pair(first->second, first->first))
          first = found;
      }
  return first;
}

Track oval_track(double straight_mm, double radius_mm, double line_width_mm) {
  if (!(straight_mm >= 0) || !(radius_mm > 0) || !std::isfinite(straight_mm) || !std::isfinite(radius_mm))
    throw Error("an oval needs straights of at least 0 mm and a positive radius");
  const double half = straight_mm / 2;
  const int chords = std::max(8, static_cast<int>(std::ceil(std::numbers::pi * radius_mm / 5.0)));
  std::vector<Point> v;
  if (half > 0) v.push_back({0, -radius_mm});  // start: middle of the lower straight
  // Right half circle around (half, 0) from -90° to +90°, then the left one around (-half, 0).
  for (int side = 0; side < 2; ++side) {
    const double cx = side == 0 ? half : -half, a0 = side == 0 ? -std::numbers::pi / 2 : std::numbers::pi / 2;
    for (int k = 0; k <= chords; ++k) {
      if (half == 0 && k == chords) continue;  // a circle: the arcs meet, do not repeat the point
      const double a = a0 + std::numbers::pi * k / chords;
      v.push_back({cx + radius_mm * std::cos(a), radius_mm * std::sin(a)});
    }
  }
  return Track(std::move(v), line_width_mm);
}

Track read_track(const std::string& path, double line_width_mm) {
  io::RecordReader reader({path});
  reader.expect_columns({{"x", "y"}});
  std::vector<Point> points;
  std::vector<Location> where;
  Record record;
  while (reader.next(record)) {
    const Location at = reader.where();
    const Point p{io::number_field(record, "x", at), io::number_field(record, "y", at)};
    if (!points.empty() && same_point(p, points.back())) throw Error("track point equals the one before", at);
    points.push_back(p);
    where.push_back(at);
  }
  if (points.size() > 1 && same_point(points.front(), points.back())) {  // closed explicitly
    points.pop_back();
    where.pop_back();
  }
  if (points.size() < 3)
    throw Error(fmt::format("a track needs at least 3 points, found {}", points.size()),
                where.empty() ? Location{path == "-" ? "<stdin>" : path, 0} : where.back());
  Track track(std::move(points), line_width_mm);
  if (const auto crossing = track.self_intersection())
    throw Error(fmt::format("track crosses itself: the segment from line {} meets the one from line {}",
                            where[crossing->first].line, where[crossing->second].line),
                where[crossing->second]);
  return track;
}

}  // namespace tk::vehicle
