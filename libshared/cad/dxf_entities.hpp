/// @file dxf_entities.hpp
/// @brief The middle layer of the DXF reader (internal to dxf_*.cpp): takes
/// the tags of the ENTITIES section one at a time and turns each entity into
/// segments of the Drawing, counting what it reads and what it skips.
/// Values are converted only for the group codes an entity type uses, and
/// nothing is buffered beyond the entity at hand (and the vertices of an
/// open POLYLINE).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "cad/drawing.hpp"
#include "cad/dxf_reader.hpp"
#include "cad/dxf_tags.hpp"

namespace tk::cad::dxf {

/// Points made for one ELLIPSE or SPLINE at most (tolerance is not met beyond).
inline constexpr std::size_t kMaxCurvePoints = 100000;

class EntityBuilder {
 public:
  EntityBuilder(Drawing& drawing, const TagReader& tags, const DxfReadOptions& options);

  /// A tag with group code 0: ends the entity before it and starts one.
  void start(const Tag& tag);
  /// Any other tag of the ENTITIES section.
  void add(const Tag& tag);
  /// The end of the section: ends what is still open.
  void finish();

 private:
  enum class Kind : std::uint8_t {
    other,
    line,
    arc,
    circle,
    lwpolyline,
    polyline,
    ellipse,
    spline,
    insert,
    child,
    seqend
  };
  struct Vertex {
    double x = 0, y = 0, bulge = 0;
  };
  /// The entity being read; vectors keep their capacity from one to the next.
  struct Entity {
    Kind kind = Kind::other;
    std::string_view type, layer;
    std::size_t start = 0;  ///< TagReader::start_of its group code 0
    std::uint32_t index = 0;
    Point p10, p11;
    double v40 = 0, v41 = 0, v42 = 0, v50 = 0, v51 = 0;
    double extrusion[3] = {0, 0, 1};
    std::int64_t flags = 0, degree = 0;
    bool paper = false, in_app_group = false, too_large = false;
    std::vector<Vertex> vertices;
    std::vector<double> knots, weights;
    std::vector<Point> control, fit;
  };
  /// A POLYLINE waiting for its VERTEX entities and SEQEND.
  struct Polyline {
    bool open = false;
    std::string_view layer;
    std::size_t start = 0;
    std::uint32_t index = 0;
    std::int64_t flags = 0;
    double extrusion[3] = {0, 0, 1};
    bool paper = false;
    std::vector<Vertex> vertices;
  };
  enum class Plane { xy, mirrored, other };

  void add_point(const Tag& tag, double& coordinate) { coordinate = tags_.real(tag); }
  void end_entity();
  void end_spline(Plane plane);
  void close_parent();
  void end_polyline();
  /// Counts the entity as skipped ("TYPE (paper space)", "TYPE (not in XY
  /// plane)"); false when it is to be read.
  bool skipped(std::string_view type, bool paper, Plane plane);
  /// Counts the entity as read and makes it the one segments belong to.
  void count_read(Kind kind, std::string_view layer, std::uint32_t index, std::size_t start);
  static Plane plane_of(const double extrusion[3]);
  /// Points one ELLIPSE or SPLINE may make: kMaxCurvePoints, or fewer when
  /// max_segments is near.
  std::size_t curve_limit() const;
  [[noreturn]] void too_many_segments(std::size_t start) const;

  void emit_arc(Point centre, double radius, double start_degrees, double span_degrees, bool mirror);
  void emit_vertices(const std::vector<Vertex>& vertices, bool closed, bool mirror);
  void emit_chords(const std::vector<Point>& points);
  /// Appends one segment of the entity last counted as read, unless its ends coincide.
  void segment(Point a, Point b, double bulge, bool flattened);

  Drawing& drawing_;
  const TagReader& tags_;
  DxfReadOptions options_;
  Entity entity_;
  Polyline polyline_;
  bool insert_open_ = false;
  bool started_ = false;
  std::uint64_t next_index_ = 0;
  std::size_t read_counts_[8] = {};  ///< by Kind, line to spline; added to the Drawing at the end
  std::unordered_map<std::string, std::uint32_t> layer_index_;
  std::string_view last_layer_;
  std::uint32_t last_layer_index_ = 0;
  bool have_last_layer_ = false;
  std::vector<Point> points_;
  std::string name_;  ///< scratch for skipped-entity names
  // The entity whose segments are being made.
  std::uint32_t out_layer_ = 0, out_index_ = 0;
  std::size_t out_start_ = 0;
};

}  // namespace tk::cad::dxf
