/// @file line_track.hpp
/// @brief The track of a line follower: a closed centre line (a polyline in
/// mm) of dark tape on a light floor, with the queries the simulation needs:
/// the nearest point and its arc length (lap progress), and the distance to
/// the line within a radius (the sensors), through a uniform grid so a point
/// near a corner or a hairpin sees every piece of line close to it.
#pragma once

#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cad/drawing.hpp"

namespace tk::vehicle {

using cad::Point;

/// Black electrical tape, the usual line of hobby tracks.
inline constexpr double kTapeWidthMm = 19.0;

/// The point of the centre line nearest to a query point.
struct Nearest {
  double distance = std::numeric_limits<double>::infinity();  ///< mm
  double s = 0;           ///< arc length of the nearest point from the start, [0, length)
  std::size_t piece = 0;  ///< internal piece index, a hint for the next query
};

class Track {
 public:
  /// `vertices` is closed implicitly (the last joins the first). Throws
  /// tk::Error for fewer than 3 points, a non-finite coordinate, two equal
  /// consecutive points or a line width that is not positive; read_track
  /// checks the same with file and line first.
  explicit Track(std::vector<Point> vertices, double line_width_mm = kTapeWidthMm);

  const std::vector<Point>& vertices() const { return vertices_; }
  double line_width_mm() const { return line_width_; }
  double length_mm() const { return length_; }
  /// The lap starts and ends at the first vertex, heading along the first segment.
  Point start() const { return vertices_.front(); }
  double start_heading() const;  ///< radians, counter-clockwise from +x

  /// Nearest point over the whole line: a scan, for a first fix or a car that strayed.
  Nearest nearest(Point p) const;
  /// Nearest point among the pieces within `window_mm` of arc length either
  /// side of `hint` (a previous answer's piece): cheap, and continuous along
  /// the line, so progress does not jump to a leg of the track that passes close by.
  Nearest nearest_near(Point p, std::size_t hint, double window_mm) const;
  /// Distance from p to the centre line when it is at most `radius_mm`,
  /// otherwise infinity; every piece of line within the radius counts.
  double distance_within(Point p, double radius_mm) const;
  /// The point of the centre line at arc length s (taken modulo the length).
  Point point_at(double s) const;

  /// The first pair of non-adjacent segments that touch or cross, as the
  /// indices of their first vertices (i < j), or nullopt.
  std::optional<std::pair<std::size_t, std::size_t>> self_intersection() const;

 private:
  /// The line is cut into pieces of at most kMaxPieceMm so the grid cells and
  /// the arc-length windows hold few pieces each.
  struct Piece {
    Point a, b;
    double s0 = 0, length = 0;
    std::size_t vertex = 0;  ///< index of the vertex that starts the segment it belongs to
  };
  static constexpr double kMaxPieceMm = 10.0;
  static constexpr double kCellMm = 25.0;

  void build_pieces();
  void build_grid();
  /// Squared distance and arc length of the point of piece i nearest to p.
  Nearest to_piece(Point p, std::size_t i) const;
  /// Cell ranges covering the box [lo, hi]; false when it misses the grid.
  bool cells(Point lo, Point hi, long& cx0, long& cy0, long& cx1, long& cy1) const;

  std::vector<Point> vertices_;
  double line_width_;
  double length_ = 0;
  std::vector<Piece> pieces_;
  Point grid_origin_;
  long grid_nx_ = 0, grid_ny_ = 0;
  std::vector<std::size_t>
      cell_start_;  ///< compressed rows: cell c holds cell_items_[cell_start_[c] .. cell_start_[c+1])
  std::vector<std::size_t> cell_items_;
};

/// An oval: two straights of `straight_mm` joined by two half circles of
/// `radius_mm`, centred on the origin, driven counter-clockwise, starting at
/// the middle of the lower straight heading +x. Arcs are cut into chords of
/// about 5 mm: they sag by 25/(8 r) mm (0.01 mm at r = 300 mm), nothing
/// against a sensor spot; each falls short of its arc by < 0.1 µm there.
Track oval_track(double straight_mm = 1000, double radius_mm = 300, double line_width_mm = kTapeWidthMm);

/// A track from records with fields `x` and `y` in mm (JSON Lines or CSV with
/// a header, through the shared reader), closed implicitly; a last point
/// equal to the first is taken as an explicit closing and dropped. Errors
/// (tk::Error) name the file and line: a missing or non-finite coordinate,
/// a point equal to the one before, fewer than 3 points, a self-intersection.
Track read_track(const std::string& path, double line_width_mm = kTapeWidthMm);

}  // namespace tk::vehicle
