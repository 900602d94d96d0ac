/// @file region_distance.hpp
/// @brief Signed distance from a point to a region bounded by closed loops
/// of lines and arcs, the nearest boundary element and point, with a
/// spatial index so a query costs about O(log n) in the boundary size.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "cad/loops.hpp"

namespace tk::cad {

struct RegionQuery {
  double distance = 0;      ///< to the boundary: positive outside the region, negative inside
  Point nearest;            ///< the nearest boundary point
  std::size_t element = 0;  ///< index into RegionIndex::elements() of the nearest element
  bool inside() const { return distance < 0; }
};

class RegionIndex {
 public:
  /// grid: the box tree, and a grid of candidate lists for fast queries,
  /// laid out by the first query() and built tile by tile (8 x 8 cells, some
  /// 64 elements' worth, about a millisecond) by the first query() landing
  /// in each, whichever thread asks first; nearest() uses the tiles built,
  /// the tree elsewhere. tree: the box tree alone, built in well under a
  /// microsecond per element, for query-light uses (its queries are
  /// several times slower unless nearest() gets a hint). Both answer the same.
  enum class Layout { grid, tree };
  /// The region is the even-odd union of the loops' interiors.
  explicit RegionIndex(const std::vector<Loop>& loops, Layout layout = Layout::grid);
  ~RegionIndex();
  RegionIndex(RegionIndex&&) noexcept;
  RegionIndex& operator=(RegionIndex&&) noexcept;

  RegionQuery query(Point p) const;
  /// Builds every tile of the grid now rather than as queries arrive (for
  /// an even pace from the first query on, or to time the whole build).
  void prepare() const;
  /// query() without the inside test: the distance is never negative; the
  /// nearest element and point are query()'s. `hint`, an element near p
  /// (the last answer along a path), speeds up the tree's search.
  RegionQuery nearest(Point p, std::size_t hint = SIZE_MAX) const;
  /// nearest() for many points close together (a search closing in on one
  /// spot): the elements that can be nearest anywhere within `spread` of
  /// `centre`, for points at most `reach` from the boundary, listed once
  /// and sorted by their distance from `centre`, so that each answer
  /// looks at the first few. The same answers as nearest(), bit for bit;
  /// a point outside those bounds gets nearest() itself.
  class Nearby {
   public:
    Nearby(const RegionIndex& index, Point centre, double spread, double reach);
    RegionQuery nearest(Point p) const;
    /// The element strictly nearer than every other at each point within
    /// the spread, and within reach of it, if there is one (SIZE_MAX if
    /// not): nearest(p) names it there, and its distance is distance_to(sole(), p).
    std::size_t sole() const { return sole_; }

   private:
    struct Element {
      double from_centre;  // its distance from the centre, less a margin for rounding
      std::uint32_t index;
    };
    const RegionIndex* index_;
    Point centre_;
    double spread_, reach2_;
    std::vector<Element> elements_;
    std::size_t sole_ = SIZE_MAX;
  };
  /// The distance from p to one element, as nearest() computes it (no
  /// trigonometry: the element's frame is prepared).
  double distance_to(std::size_t element, Point p) const;
  /// Every loop's segments, loop after loop.
  const std::vector<Segment>& elements() const;
  /// Which loop an element belongs to.
  std::size_t loop_of(std::size_t element) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// The same answer by examining every element (the oracle for tests and
/// the benchmark's rival).
RegionQuery brute_force_query(const std::vector<Loop>& loops, Point p);

}  // namespace tk::cad
