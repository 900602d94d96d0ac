/// @file test_dxf_reader.cpp
/// @brief Unit tests for the DXF reader on small hand-written files: each
/// entity type, OCS mirroring, header variables, skipped entities, errors
/// and their lines, binary DXF. (Real files against ezdxf: test_dxf_corpus.cpp.)
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <vector>

#include "cad/drawing.hpp"
#include "cad/dxf_reader.hpp"
#include "io/error.hpp"

using namespace tk::cad;

namespace {

/// A DXF with `body` as its ENTITIES section; the body starts on line 5.
std::string entities(const std::string& body) { return "0\nSECTION\n2\nENTITIES\n" + body + "0\nENDSEC\n0\nEOF\n"; }

Drawing read(const std::string& text, DxfReadOptions options = {}) { return read_dxf(text, "t.dxf", options); }

/// "file:line: message" of the error reading `text` gives, "" for none.
std::string dxf_error_of(const std::string& text, DxfReadOptions options = {}) {
  try {
    read_dxf(text, "t.dxf", options);
  } catch (const tk::Error& error) {
    return error.located_message();
  }
  return {};
}

void expect_point(Point actual, double x, double y, double tolerance = 1e-12) {
  EXPECT_NEAR(actual.x, x, tolerance);
  EXPECT_NEAR(actual.y, y, tolerance);
}

double sweep(const Segment& s) { return 4 * std::atan(s.bulge); }

/// Centre of an arc segment, from its chord and bulge.
Point centre(const Segment& s) {
  const double cx = s.end.x - s.start.x, cy = s.end.y - s.start.y, k = (1 - s.bulge * s.bulge) / (4 * s.bulge);
  return {(s.start.x + s.end.x) / 2 - cy * k, (s.start.y + s.end.y) / 2 + cx * k};
}

/// Binary DXF (R13 and later: two-byte group codes) built tag by tag.
struct BinaryDxf {
  std::string bytes{"AutoCAD Binary DXF\r\n\x1a\0", 22};
  BinaryDxf& code(int c) {
    bytes += static_cast<char>(c & 0xff);
    bytes += static_cast<char>(c >> 8);
    return *this;
  }
  BinaryDxf& text(int c, const std::string& value) {
    code(c);
    bytes += value;
    bytes += '\0';
    return *this;
  }
  BinaryDxf& real(int c, double value) {
    code(c);
    const auto bits = std::bit_cast<std::uint64_t>(value);
    for (int i = 0; i < 8; ++i) bytes += static_cast<char>((bits >> (8 * i)) & 0xff);
    return *this;
  }
  BinaryDxf& int16(int c, int value) {
    code(c);
    bytes += static_cast<char>(value & 0xff);
    bytes += static_cast<char>((value >> 8) & 0xff);
    return *this;
  }
};

}  // namespace

// ---- entities ------------------------------------------------------------

TEST(DxfReader, LinesWithLayersEntityIndexAndSourceLine) {
  const Drawing d =
      read(entities("0\nLINE\n8\nwalls\n10\n1.5\n20\n-2\n30\n0\n11\n4\n21\n2\n31\n0\n"  // lines 5-20
                    "0\nTEXT\n8\nnotes\n1\nhello\n"                                     // lines 21-26
                    "0\nLINE\n10\n0\n20\n0\n11\n1e3\n21\n.5\n"                          // lines 27-36
                    "0\nLINE\n8\nwalls\n10\n0\n20\n0\n11\n0\n21\n1\n"));                // lines 37-48
  ASSERT_EQ(d.segments.size(), 3u);
  expect_point(d.segments[0].start, 1.5, -2);
  expect_point(d.segments[0].end, 4, 2);
  EXPECT_EQ(d.segments[0].bulge, 0);
  EXPECT_EQ(d.segments[0].entity, 0u);
  EXPECT_EQ(d.segments[0].source_line, 5u);
  EXPECT_FALSE(d.segments[0].flattened);
  EXPECT_EQ(d.segments[1].entity, 2u);  // the TEXT counts as an entity
  EXPECT_EQ(d.segments[1].source_line, 27u);
  expect_point(d.segments[1].end, 1000, 0.5);
  EXPECT_EQ(d.segments[2].source_line, 37u);
  ASSERT_EQ(d.layers, (std::vector<std::string>{"walls", "0"}));  // "0" when group code 8 is missing
  EXPECT_EQ(d.segments[0].layer, 0u);
  EXPECT_EQ(d.segments[1].layer, 1u);
  EXPECT_EQ(d.segments[2].layer, 0u);
  EXPECT_EQ(d.entities_read.at("LINE"), 3u);
  EXPECT_EQ(d.entities_skipped.at("TEXT"), 1u);
  EXPECT_FALSE(d.binary);
  EXPECT_TRUE(d.version.empty());
  EXPECT_EQ(d.insunits, 0);
}

TEST(DxfReader, ZeroLengthLineIsReadButMakesNoSegment) {
  const Drawing d = read(entities("0\nLINE\n10\n3\n20\n4\n11\n3\n21\n4\n"));
  EXPECT_TRUE(d.segments.empty());
  EXPECT_EQ(d.entities_read.at("LINE"), 1u);
}

TEST(DxfReader, CoordinatesInAnyOrderAsOldWritersPutThem) {
  const Drawing d = read(entities("0\nLINE\n10\n1\n11\n2\n20\n3\n21\n4\n30\n0\n31\n0\n"));
  ASSERT_EQ(d.segments.size(), 1u);
  expect_point(d.segments[0].start, 1, 3);
  expect_point(d.segments[0].end, 2, 4);
}

TEST(DxfReader, ArcFromStartToEndAngleCounterClockwise) {
  const Drawing d = read(entities("0\nARC\n10\n1\n20\n2\n30\n0\n40\n3\n50\n0\n51\n90\n"));
  ASSERT_EQ(d.segments.size(), 1u);
  expect_point(d.segments[0].start, 4, 2);
  expect_point(d.segments[0].end, 1, 5);
  EXPECT_NEAR(d.segments[0].bulge, std::tan(std::numbers::pi / 8), 1e-15);
  expect_point(centre(d.segments[0]), 1, 2);
  EXPECT_EQ(d.entities_read.at("ARC"), 1u);
}

TEST(DxfReader, ArcOverHalfATurnIsTwoArcs) {
  const Drawing d = read(entities("0\nARC\n10\n1\n20\n2\n40\n3\n50\n30\n51\n290\n"));
  ASSERT_EQ(d.segments.size(), 2u);
  expect_point(d.segments[0].start, 1 + 3 * std::cos(std::numbers::pi / 6), 2 + 3 * std::sin(std::numbers::pi / 6));
  expect_point(d.segments[1].end, 1 + 3 * std::cos(290 * std::numbers::pi / 180),
               2 + 3 * std::sin(290 * std::numbers::pi / 180));
  expect_point(d.segments[0].end, d.segments[1].start.x, d.segments[1].start.y, 0);
  EXPECT_NEAR(sweep(d.segments[0]) + sweep(d.segments[1]), 260 * std::numbers::pi / 180, 1e-12);
  EXPECT_LE(d.segments[0].bulge, 1);
  EXPECT_EQ(d.segments[0].entity, d.segments[1].entity);
}

TEST(DxfReader, ArcAnglesFollowEzdxf) {
  // Across 0 degrees.
  Drawing d = read(entities("0\nARC\n40\n1\n50\n350\n51\n10\n"));
  ASSERT_EQ(d.segments.size(), 1u);
  EXPECT_NEAR(sweep(d.segments[0]), 20 * std::numbers::pi / 180, 1e-12);
  // Equal angles: nothing (but read); equal modulo 360: a full circle.
  d = read(entities("0\nARC\n40\n1\n50\n45\n51\n45\n"));
  EXPECT_TRUE(d.segments.empty());
  EXPECT_EQ(d.entities_read.at("ARC"), 1u);
  d = read(entities("0\nARC\n40\n1\n50\n0\n51\n360\n"));
  ASSERT_EQ(d.segments.size(), 2u);
  EXPECT_EQ(d.segments[1].end.x, d.segments[0].start.x);
  EXPECT_EQ(d.segments[1].end.y, d.segments[0].start.y);
  // No radius: nothing.
  d = read(entities("0\nARC\n40\n0\n50\n0\n51\n90\n"));
  EXPECT_TRUE(d.segments.empty());
}

TEST(DxfReader, CircleIsTwoHalfArcs) {
  const Drawing d = read(entities("0\nCIRCLE\n8\nholes\n10\n5\n20\n-1\n40\n2\n"));
  ASSERT_EQ(d.segments.size(), 2u);
  expect_point(d.segments[0].start, 7, -1, 0);
  expect_point(d.segments[0].end, 3, -1, 0);
  expect_point(d.segments[1].start, 3, -1, 0);
  expect_point(d.segments[1].end, 7, -1, 0);
  EXPECT_EQ(d.segments[0].bulge, 1);
  EXPECT_EQ(d.segments[1].bulge, 1);
  EXPECT_EQ(d.layers, std::vector<std::string>{"holes"});
  EXPECT_EQ(d.entities_read.at("CIRCLE"), 1u);
}

TEST(DxfReader, ExtrusionMinusZMirrorsArcCircleAndLwpolyline) {
  const Drawing d =
      read(entities("0\nARC\n10\n1\n20\n2\n40\n1\n50\n0\n51\n90\n210\n0\n220\n0\n230\n-1\n"
                    "0\nCIRCLE\n10\n4\n20\n0\n40\n1\n210\n0.0\n220\n-0.0\n230\n-1.0\n"
                    "0\nLWPOLYLINE\n90\n2\n70\n0\n10\n1\n20\n1\n42\n0.5\n10\n3\n20\n1\n210\n0\n220\n0\n230\n-1\n"));
  ASSERT_EQ(d.segments.size(), 4u);
  // ARC: OCS centre (1,2) is WCS (-1,2); OCS 0..90 ccw is WCS 180..90 clockwise.
  expect_point(d.segments[0].start, -2, 2);
  expect_point(d.segments[0].end, -1, 3);
  EXPECT_NEAR(d.segments[0].bulge, -std::tan(std::numbers::pi / 8), 1e-15);
  expect_point(centre(d.segments[0]), -1, 2);
  // CIRCLE: centre (-4,0), clockwise halves.
  expect_point(d.segments[1].start, -5, 0);
  expect_point(d.segments[1].end, -3, 0);
  EXPECT_EQ(d.segments[1].bulge, -1);
  expect_point(d.segments[2].end, -5, 0);
  // LWPOLYLINE: x negated, bulge negated.
  expect_point(d.segments[3].start, -1, 1);
  expect_point(d.segments[3].end, -3, 1);
  EXPECT_EQ(d.segments[3].bulge, -0.5);
}

TEST(DxfReader, ExtrusionOutOfTheXyPlaneIsSkipped) {
  const Drawing d =
      read(entities("0\nARC\n40\n1\n50\n0\n51\n90\n210\n0\n220\n1\n230\n0\n"
                    "0\nCIRCLE\n40\n1\n210\n0.6\n220\n0\n230\n0.8\n"
                    "0\nLWPOLYLINE\n10\n0\n20\n0\n10\n1\n20\n0\n210\n1\n220\n0\n230\n0\n"
                    "0\nLINE\n11\n1\n210\n1\n220\n0\n230\n0\n"));  // LINE is in world coordinates anyway
  ASSERT_EQ(d.segments.size(), 1u);
  EXPECT_EQ(d.segments[0].entity, 3u);
  EXPECT_EQ(d.entities_skipped.at("ARC (not in XY plane)"), 1u);
  EXPECT_EQ(d.entities_skipped.at("CIRCLE (not in XY plane)"), 1u);
  EXPECT_EQ(d.entities_skipped.at("LWPOLYLINE (not in XY plane)"), 1u);
  EXPECT_EQ(d.entities_read.count("ARC"), 0u);
}

TEST(DxfReader, LwpolylineBulgesClosedFlagAndLyingCount) {
  const Drawing d =
      read(entities("0\nLWPOLYLINE\n8\np\n90\n1000000000000\n70\n1\n38\n5\n43\n0.1\n"
                    "10\n0\n20\n0\n42\n1\n10\n2\n20\n0\n40\n0.2\n41\n0.3\n10\n2\n20\n2\n42\n-0.25\n10\n0\n20\n2\n"
                    "0\nLWPOLYLINE\n10\n5\n20\n5\n10\n5\n20\n5\n10\n6\n20\n5\n"));  // open, a repeated vertex
  ASSERT_EQ(d.segments.size(), 5u);
  expect_point(d.segments[0].start, 0, 0, 0);
  expect_point(d.segments[0].end, 2, 0, 0);
  EXPECT_EQ(d.segments[0].bulge, 1);
  EXPECT_EQ(d.segments[1].bulge, 0);
  EXPECT_EQ(d.segments[2].bulge, -0.25);
  expect_point(d.segments[3].start, 0, 2, 0);  // the closing segment
  expect_point(d.segments[3].end, 0, 0, 0);
  EXPECT_EQ(d.segments[3].entity, 0u);
  expect_point(d.segments[4].start, 5, 5, 0);
  expect_point(d.segments[4].end, 6, 5, 0);
  EXPECT_EQ(d.segments[4].entity, 1u);
  EXPECT_EQ(d.entities_read.at("LWPOLYLINE"), 2u);
}

TEST(DxfReader, PolylineWithVerticesIsOneEntity) {
  const Drawing d =
      read(entities("0\nPOLYLINE\n8\nq\n66\n1\n10\n0\n20\n0\n30\n0\n70\n1\n"  // lines 5-18
                    "0\nVERTEX\n8\nq\n10\n0\n20\n0\n42\n0.5\n"                // 19-28
                    "0\nVERTEX\n8\nq\n10\n4\n20\n0\n"                         // 29-36
                    "0\nVERTEX\n8\nq\n10\n9\n20\n9\n70\n16\n"                 // a frame control point: left out
                    "0\nVERTEX\n8\nq\n10\n4\n20\n3\n"
                    "0\nSEQEND\n"
                    "0\nLINE\n11\n1\n"));
  ASSERT_EQ(d.segments.size(), 4u);
  EXPECT_EQ(d.segments[0].bulge, 0.5);
  expect_point(d.segments[1].end, 4, 3, 0);
  expect_point(d.segments[2].start, 4, 3, 0);  // closed
  expect_point(d.segments[2].end, 0, 0, 0);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(d.segments[i].entity, 0u);
    EXPECT_EQ(d.segments[i].source_line, 5u);
  }
  EXPECT_EQ(d.segments[3].entity, 1u);
  EXPECT_EQ(d.entities_read.at("POLYLINE"), 1u);
  EXPECT_EQ(d.entities_read.at("LINE"), 1u);
  EXPECT_TRUE(d.entities_skipped.empty());
}

TEST(DxfReader, PolylineEndsAtTheNextEntityWithoutSeqendAndMirrors) {
  const Drawing d =
      read(entities("0\nPOLYLINE\n70\n0\n210\n0\n220\n0\n230\n-1\n"
                    "0\nVERTEX\n10\n1\n20\n0\n42\n0.5\n0\nVERTEX\n10\n2\n20\n0\n"
                    "0\nCIRCLE\n40\n1\n"));
  ASSERT_EQ(d.segments.size(), 3u);
  expect_point(d.segments[0].start, -1, 0, 0);
  expect_point(d.segments[0].end, -2, 0, 0);
  EXPECT_EQ(d.segments[0].bulge, -0.5);
  EXPECT_EQ(d.segments[1].entity, 1u);
}

TEST(DxfReader, ThreeDimensionalPolylinesAndMeshesAreSkipped) {
  const Drawing d =
      read(entities("0\nPOLYLINE\n70\n8\n0\nVERTEX\n10\n1\n0\nVERTEX\n10\n2\n0\nSEQEND\n"
                    "0\nPOLYLINE\n70\n16\n0\nVERTEX\n10\n1\n0\nSEQEND\n"
                    "0\nPOLYLINE\n70\n64\n0\nVERTEX\n10\n1\n0\nSEQEND\n"
                    "0\nLINE\n11\n1\n"));
  ASSERT_EQ(d.segments.size(), 1u);
  EXPECT_EQ(d.segments[0].entity, 3u);
  EXPECT_EQ(d.entities_skipped.at("POLYLINE (3D)"), 1u);
  EXPECT_EQ(d.entities_skipped.at("POLYLINE (polygon mesh)"), 1u);
  EXPECT_EQ(d.entities_skipped.at("POLYLINE (polyface mesh)"), 1u);
}

TEST(DxfReader, FullEllipseIsFlattenedWithinTheTolerance) {
  DxfReadOptions options;
  options.chord_tolerance = 0.01;
  const Drawing d =
      read(entities("0\nELLIPSE\n10\n1\n20\n1\n11\n2\n21\n0\n40\n0.5\n41\n0\n42\n6.283185307179586\n"), options);
  ASSERT_GT(d.segments.size(), 8u);
  EXPECT_LT(d.segments.size(), 100u);
  EXPECT_EQ(d.segments.front().start.x, d.segments.back().end.x);
  EXPECT_EQ(d.segments.front().start.y, d.segments.back().end.y);
  expect_point(d.segments.front().start, 3, 1);
  const double n = static_cast<double>(d.segments.size());
  for (std::size_t i = 0; i < d.segments.size(); ++i) {
    const Segment& s = d.segments[i];
    EXPECT_TRUE(s.flattened);
    EXPECT_EQ(s.bulge, 0);
    const double x = (s.end.x - 1) / 2, y = s.end.y - 1;
    EXPECT_NEAR(x * x + y * y, 1, 1e-12);  // semi-axes 2 and 0.5 * 2
    // The curve halfway (in the parameter) strays from the chord by at most the tolerance.
    const double t = 2 * std::numbers::pi * (static_cast<double>(i) + 0.5) / n;
    const Point mid{1 + 2 * std::cos(t), 1 + std::sin(t)};
    const double dx = s.end.x - s.start.x, dy = s.end.y - s.start.y;
    EXPECT_LE(std::abs((mid.x - s.start.x) * dy - (mid.y - s.start.y) * dx) / std::hypot(dx, dy), 0.01);
  }
  EXPECT_EQ(d.entities_read.at("ELLIPSE"), 1u);
}

TEST(DxfReader, EllipticArcAndMirroredEllipse) {
  const Drawing d = read(entities(
      "0\nELLIPSE\n10\n0\n20\n0\n11\n2\n21\n0\n40\n0.5\n41\n0\n42\n1.5707963267948966\n"
      "0\nELLIPSE\n10\n0\n20\n0\n11\n2\n21\n0\n40\n0.5\n41\n0\n42\n1.5707963267948966\n210\n0\n220\n0\n230\n-1\n"));
  std::vector<const Segment*> first, second;
  for (const Segment& s : d.segments) (s.entity == 0 ? first : second).push_back(&s);
  ASSERT_FALSE(first.empty());
  ASSERT_FALSE(second.empty());
  expect_point(first.front()->start, 2, 0);
  expect_point(first.back()->end, 0, 1);
  // Counter-clockwise about (0,0,-1) is clockwise seen from +Z.
  expect_point(second.front()->start, 2, 0);
  expect_point(second.back()->end, 0, -1);
  for (const Segment* s : second) EXPECT_LE(s->end.y, 1e-15);
}

TEST(DxfReader, RationalSplineQuarterCircle) {
  const Drawing d =
      read(entities("0\nSPLINE\n8\ncurves\n70\n12\n71\n2\n72\n6\n73\n3\n74\n0\n"
                    "40\n0\n40\n0\n40\n0\n40\n1\n40\n1\n40\n1\n41\n1\n41\n0.7071067811865476\n41\n1\n"
                    "10\n1\n20\n0\n30\n0\n10\n1\n20\n1\n30\n0\n10\n0\n20\n1\n30\n0\n"));
  ASSERT_GT(d.segments.size(), 4u);
  expect_point(d.segments.front().start, 1, 0);
  expect_point(d.segments.back().end, 0, 1);
  for (const Segment& s : d.segments) {
    EXPECT_TRUE(s.flattened);
    EXPECT_NEAR(std::hypot(s.end.x, s.end.y), 1, 1e-12);
    // Sagitta of the chord of a unit circle.
    EXPECT_LE(1 - std::sqrt(1 - std::pow(std::hypot(s.end.x - s.start.x, s.end.y - s.start.y) / 2, 2)), 0.001);
  }
  EXPECT_EQ(d.entities_read.at("SPLINE"), 1u);
}

TEST(DxfReader, SplineKindsAndInvalidOnes) {
  // Degree 1 through its control points; a clamped cubic without knots
  // (open uniform, as ezdxf assumes) ends on its end control points; fit
  // points only: straight chords through them.
  const Drawing d =
      read(entities("0\nSPLINE\n71\n1\n40\n0\n40\n0\n40\n1\n40\n2\n40\n2\n10\n0\n20\n0\n10\n1\n20\n1\n10\n2\n20\n0\n"
                    "0\nSPLINE\n71\n3\n10\n0\n20\n0\n10\n1\n20\n2\n10\n3\n20\n2\n10\n4\n20\n0\n10\n5\n20\n1\n"
                    "0\nSPLINE\n71\n3\n11\n0\n21\n0\n11\n1\n21\n1\n11\n3\n21\n1\n"
                    "0\nSPLINE\n71\n2\n40\n0\n40\n1\n10\n0\n20\n0\n10\n1\n20\n1\n10\n2\n20\n0\n"  // too few knots
                    "0\nSPLINE\n71\n11\n10\n0\n20\n0\n10\n1\n20\n1\n"                             // degree 11
                    "0\nSPLINE\n71\n1\n41\n1\n10\n0\n20\n0\n10\n1\n20\n1\n"  // one weight for two points
                    "0\nSPLINE\n71\n1\n40\n0\n40\n0\n40\n2\n40\n1\n10\n0\n20\n0\n10\n1\n20\n1\n"));  // decreasing knots
  std::vector<std::vector<Segment>> by(3);
  for (const Segment& s : d.segments) {
    ASSERT_LT(s.entity, 3u);
    by[s.entity].push_back(s);
  }
  ASSERT_EQ(by[0].size(), 2u);
  expect_point(by[0][0].end, 1, 1);
  expect_point(by[0][1].end, 2, 0);
  ASSERT_FALSE(by[1].empty());
  expect_point(by[1].front().start, 0, 0);
  expect_point(by[1].back().end, 5, 1);
  ASSERT_EQ(by[2].size(), 2u);
  expect_point(by[2][1].start, 1, 1);
  expect_point(by[2][1].end, 3, 1);
  EXPECT_EQ(d.entities_read.at("SPLINE"), 3u);
  EXPECT_EQ(d.entities_skipped.at("SPLINE (invalid)"), 4u);
}

TEST(DxfReader, CurvesStopAtTheirPointBudget) {
  DxfReadOptions options;
  options.chord_tolerance = 1e-300;
  const Drawing d = read(entities("0\nELLIPSE\n11\n1\n40\n1\n"
                                  "0\nSPLINE\n71\n2\n10\n0\n20\n0\n10\n1\n20\n1\n10\n2\n20\n0\n"),
                         options);
  std::size_t counts[2] = {0, 0};
  for (const Segment& s : d.segments) ++counts[s.entity];
  EXPECT_EQ(counts[0], 99999u);
  EXPECT_LE(counts[1], 99999u);
  EXPECT_GT(counts[1], 1000u);
}

TEST(DxfReader, HeaderVariablesAndUnits) {
  const Drawing d = read(
      "999\ncomment\n0\nSECTION\n2\nHEADER\n9\n$ACADVER\n1\nAC1015\n9\n$EXTMIN\n10\n0\n20\n0\n"
      "9\n$INSUNITS\n70\n4\n0\nENDSEC\n" +
      entities(""));
  EXPECT_EQ(d.version, "AC1015");
  EXPECT_EQ(d.insunits, 4);
  EXPECT_TRUE(d.segments.empty());
  EXPECT_EQ(millimetres_per_unit(0), 0);
  EXPECT_EQ(millimetres_per_unit(1), 25.4);
  EXPECT_EQ(millimetres_per_unit(2), 304.8);
  EXPECT_EQ(millimetres_per_unit(4), 1);
  EXPECT_EQ(millimetres_per_unit(5), 10);
  EXPECT_EQ(millimetres_per_unit(6), 1000);
  EXPECT_DOUBLE_EQ(millimetres_per_unit(3), 1609344);
  EXPECT_DOUBLE_EQ(millimetres_per_unit(10), 914.4);
  EXPECT_DOUBLE_EQ(millimetres_per_unit(13), 1e-3);
  EXPECT_DOUBLE_EQ(millimetres_per_unit(21), 1200.0 / 3937 * 1000);
  EXPECT_EQ(millimetres_per_unit(-1), 0);
  EXPECT_EQ(millimetres_per_unit(25), 0);
  EXPECT_EQ(millimetres_per_unit(1000), 0);
}

TEST(DxfReader, SkippedEntitiesBlocksAndPaperSpace) {
  const Drawing d =
      read("0\nSECTION\n2\nBLOCKS\n0\nBLOCK\n2\nB\n0\nLINE\n11\n5\n0\nENDBLK\n0\nENDSEC\n" +
           entities("0\nINSERT\n2\nB\n66\n1\n0\nATTRIB\n10\n1\n0\nATTRIB\n10\n2\n0\nSEQEND\n"
                    "0\nMTEXT\n1\nx\n0\nHATCH\n10\n0\n0\nDIMENSION\n0\nPOINT\n10\n1\n0\nSOLID\n0\n3DFACE\n0\nTEXT\n"
                    "0\nLINE\n67\n1\n11\n1\n0\nTEXT\n67\n1\n"
                    "0\nLINE\n11\n2\n"));
  ASSERT_EQ(d.segments.size(), 1u);      // nothing from the block
  EXPECT_EQ(d.segments[0].entity, 10u);  // INSERT with its ATTRIBs and SEQEND is one entity
  EXPECT_EQ(d.entities_skipped.at("INSERT"), 1u);
  EXPECT_EQ(d.entities_skipped.at("MTEXT"), 1u);
  EXPECT_EQ(d.entities_skipped.at("HATCH"), 1u);
  EXPECT_EQ(d.entities_skipped.at("DIMENSION"), 1u);
  EXPECT_EQ(d.entities_skipped.at("POINT"), 1u);
  EXPECT_EQ(d.entities_skipped.at("SOLID"), 1u);
  EXPECT_EQ(d.entities_skipped.at("3DFACE"), 1u);
  EXPECT_EQ(d.entities_skipped.at("TEXT"), 1u);
  EXPECT_EQ(d.entities_skipped.at("LINE (paper space)"), 1u);
  EXPECT_EQ(d.entities_skipped.at("TEXT (paper space)"), 1u);
  EXPECT_EQ(d.entities_skipped.count("ATTRIB"), 0u);
  EXPECT_EQ(d.entities_read.at("LINE"), 1u);
}

TEST(DxfReader, TolerantLayout) {
  // CRLF, spaces and tabs around codes and values, comments, a UTF-8 BOM,
  // application data groups with codes that mean something elsewhere, tags
  // between sections, a stray ENDSEC, no EOF, trailing blank lines.
  const std::string text =
      "\xEF\xBB\xBF  0\r\nSECTION\r\n  2\r\nHEADER\r\n  9\r\n$INSUNITS\r\n 70\r\n\t1 \r\n  0\r\nENDSEC\r\n"
      "  0\r\nENDSEC\r\n  9\r\n$ACADVER\r\n"
      "  0\r\nSECTION\r\n  2\r\nENTITIES\r\n"
      "  0\r\nLINE\r\n102\r\n{ACAD_REACTORS\r\n 10\r\n99\r\n102\r\n}\r\n999\r\nhi\r\n"
      " 10 \r\n  +1.5 \r\n 20\r\n-2E1\r\n 11\r\n  3.\r\n 21\r\n.25\r\n"
      "  0\r\nENDSEC\r\n\r\n\r\n";
  const Drawing d = read(text);
  EXPECT_EQ(d.insunits, 1);
  ASSERT_EQ(d.segments.size(), 1u);
  expect_point(d.segments[0].start, 1.5, -20);
  expect_point(d.segments[0].end, 3, 0.25);
  EXPECT_EQ(d.segments[0].source_line, 19u);
  // Tiny numbers are zero, not errors.
  EXPECT_EQ(read(entities("0\nLINE\n10\n1e-400\n11\n1\n")).segments.at(0).start.x, 0);
}

TEST(DxfReader, TwoEntitiesSectionsCarryOn) {
  const Drawing d =
      read("0\nSECTION\n2\nENTITIES\n0\nLINE\n8\nA\n11\n1\n0\nENDSEC\n" + entities("0\nTEXT\n0\nLINE\n8\nA\n11\n2\n"));
  ASSERT_EQ(d.segments.size(), 2u);
  EXPECT_EQ(d.segments[1].entity, 2u);
  EXPECT_EQ(d.layers, std::vector<std::string>{"A"});
  EXPECT_EQ(d.entities_read.at("LINE"), 2u);
}

TEST(DxfReader, DeepApplicationGroupsAndLongInputsStayCheap) {
  std::string body = "0\nLWPOLYLINE\n";
  for (int i = 0; i < 20000; ++i) body += "102\n{X\n";
  body += "10\n5\n102\n}\n10\n0\n20\n0\n10\n1\n20\n0\n";
  const Drawing d = read(entities(body));
  ASSERT_EQ(d.segments.size(), 1u);
  expect_point(d.segments[0].start, 0, 0);
}

// ---- errors ----------------------------------------------------------------

TEST(DxfReader, ErrorsNameTheLineAtFault) {
  EXPECT_EQ(dxf_error_of(entities("0\nLINE\nxyz\n1\n")), "t.dxf:7: bad group code 'xyz'");
  EXPECT_EQ(dxf_error_of(entities("0\nLINE\n10\nabc\n")), "t.dxf:8: bad number 'abc' for group code 10");
  EXPECT_EQ(dxf_error_of(entities("0\nLINE\n10\n1.5x\n")), "t.dxf:8: bad number '1.5x' for group code 10");
  EXPECT_EQ(dxf_error_of(entities("0\nLINE\n10\n\n")), "t.dxf:8: bad number '' for group code 10");
  EXPECT_EQ(dxf_error_of(entities("0\nARC\n40\n1e400\n")), "t.dxf:8: number out of range '1e400' for group code 40");
  EXPECT_EQ(dxf_error_of(entities("0\nLINE\n20\nnan\n")), "t.dxf:8: bad number 'nan' for group code 20");
  EXPECT_EQ(dxf_error_of(entities("0\nLINE\n20\n-inf\n")), "t.dxf:8: bad number '-inf' for group code 20");
  EXPECT_EQ(dxf_error_of(entities("0\nLWPOLYLINE\n70\n1.5\n")), "t.dxf:8: bad integer '1.5' for group code 70");
  EXPECT_EQ(dxf_error_of(entities("0\nLWPOLYLINE\n70\n99999999999999999999\n")),
            "t.dxf:8: number out of range '99999999999999999999' for group code 70");
  EXPECT_EQ(dxf_error_of(entities("0\nLINE\n2000\nx\n")), "t.dxf:7: bad group code '2000'");
  static const char with_nul[] = "0\nSECTION\n2\nENTITIES\n0\nLINE\n10\n1\0\n";
  EXPECT_EQ(dxf_error_of(std::string(with_nul, sizeof with_nul - 1)), "t.dxf:8: nul byte in a text DXF file");
  // Values only read for the entity types that use them.
  EXPECT_EQ(dxf_error_of(entities("0\nTEXT\n10\nabc\n")), "");
}

TEST(DxfReader, TruncatedAndEmptyFiles) {
  EXPECT_EQ(dxf_error_of(""), "t.dxf: no ENTITIES section");
  EXPECT_EQ(dxf_error_of("\n\n"), "t.dxf: no ENTITIES section");
  EXPECT_EQ(dxf_error_of("0\nSECTION\n2\nHEADER\n0\nENDSEC\n0\nEOF\n"), "t.dxf: no ENTITIES section");
  // An odd number of lines: a code without its value.
  EXPECT_EQ(dxf_error_of("0\nSECTION\n2\nENTITIES\n0\nLINE\n10"),
            "t.dxf:7: group code 10 without a value at the end of the file");
  EXPECT_EQ(dxf_error_of("0\nSECTION\n2\nENTITIES\n0\nLINE\n10\n1\n"),
            "t.dxf:1: the ENTITIES section has no end (ENDSEC): the file is truncated");
  EXPECT_EQ(dxf_error_of("0\nSECTION\n0\nENTITIES\n"),
            "t.dxf:4: expected the section name (group code 2) after SECTION, found group code 0");
  // Without EOF, and ended by EOF without ENDSEC: fine.
  EXPECT_EQ(dxf_error_of("0\nSECTION\n2\nENTITIES\n0\nLINE\n11\n1\n0\nENDSEC\n"), "");
  EXPECT_EQ(dxf_error_of("0\nSECTION\n2\nENTITIES\n0\nLINE\n11\n1\n0\nEOF\n"), "");
}

TEST(DxfReader, LimitsAndOverflow) {
  DxfReadOptions options;
  options.max_segments = 3;
  EXPECT_EQ(
      dxf_error_of(entities("0\nLWPOLYLINE\n70\n1\n10\n0\n20\n0\n10\n1\n20\n0\n10\n1\n20\n1\n10\n0\n20\n1\n"), options),
      "t.dxf:5: more than 3 segments");
  EXPECT_EQ(dxf_error_of(entities("0\nCIRCLE\n10\n1e308\n40\n1e308\n")), "t.dxf:5: coordinates out of range");
  EXPECT_EQ(dxf_error_of(entities("0\nELLIPSE\n10\n1e308\n11\n1e308\n")), "t.dxf:5: coordinates out of range");
  // Within the convex hull of its control points a spline cannot overflow, but its weights can.
  EXPECT_EQ(dxf_error_of(entities("0\nSPLINE\n71\n2\n10\n0\n20\n0\n10\n1e308\n20\n1e308\n10\n-1e308\n20\n0\n")), "");
  EXPECT_EQ(dxf_error_of(entities("0\nSPLINE\n71\n2\n41\n1\n41\n1e10\n41\n1\n"
                                  "10\n0\n20\n0\n10\n1e308\n20\n1e308\n10\n-1e308\n20\n0\n")),
            "t.dxf:5: coordinates out of range");
}

TEST(DxfReader, ReadFileErrors) {
  try {
    read_dxf_file("/nonexistent/part.dxf");
    FAIL() << "no error";
  } catch (const tk::Error& error) {
    EXPECT_EQ(error.located_message(), "/nonexistent/part.dxf: cannot open: No such file or directory");
  }
  EXPECT_THROW(read_dxf_file("/"), tk::Error);
}

// ---- binary DXF ---------------------------------------------------------------

TEST(DxfReader, BinaryDxf) {
  BinaryDxf b;
  b.text(0, "SECTION").text(2, "HEADER").text(9, "$ACADVER").text(1, "AC1015").text(9, "$INSUNITS").int16(70, 1);
  b.text(0, "ENDSEC").text(0, "SECTION").text(2, "ENTITIES");
  b.text(0, "LINE").text(5, "2A").text(100, "AcDbEntity").text(8, "L1").real(10, 1.25).real(20, -3).real(30, 0);
  b.real(11, 4).real(21, 5).real(31, 0);
  b.text(0, "LWPOLYLINE").text(8, "L2").code(90).bytes += std::string("\x02\0\0\0", 4);
  b.int16(70, 1).real(10, 0).real(20, 0).real(42, 0.5).real(10, 2).real(20, 0);
  b.code(310).bytes += std::string("\x03\x01\x02\x03", 4);  // a binary chunk, passed over
  b.code(290).bytes += '\x01';                              // a bool
  b.text(0, "ENDSEC").text(0, "EOF");
  const Drawing d = read(b.bytes);
  EXPECT_TRUE(d.binary);
  EXPECT_EQ(d.version, "AC1015");
  EXPECT_EQ(d.insunits, 1);
  ASSERT_EQ(d.segments.size(), 3u);
  expect_point(d.segments[0].start, 1.25, -3, 0);
  expect_point(d.segments[0].end, 4, 5, 0);
  EXPECT_EQ(d.segments[0].source_line, 0u);
  EXPECT_EQ(d.segments[1].bulge, 0.5);
  expect_point(d.segments[2].end, 0, 0, 0);
  EXPECT_EQ(d.layers, (std::vector<std::string>{"L1", "L2"}));
}

TEST(DxfReader, BinaryDxfErrorsGiveTheByteOffset) {
  BinaryDxf b;
  b.text(0, "SECTION").text(2, "ENTITIES").text(0, "LINE");
  const std::size_t at = b.bytes.size();  // 22 + 10 + 11 + 7 = 50
  b.real(10, std::nan(""));
  b.text(0, "ENDSEC");
  EXPECT_EQ(dxf_error_of(b.bytes), "t.dxf: byte " + std::to_string(at) + ": bad number 'nan' for group code 10");
  BinaryDxf truncated;
  truncated.text(0, "SECTION").text(2, "ENTITIES").text(0, "LINE").code(10).bytes += "abc";
  EXPECT_EQ(dxf_error_of(truncated.bytes), "t.dxf: byte 50: truncated value of group code 10");
  BinaryDxf unterminated;
  unterminated.text(0, "SECTION").code(2).bytes += "ENTI";
  EXPECT_EQ(dxf_error_of(unterminated.bytes), "t.dxf: byte 32: unterminated string value of group code 2");
  BinaryDxf bad_code;
  bad_code.text(0, "SECTION").code(40000);
  EXPECT_EQ(dxf_error_of(bad_code.bytes), "t.dxf: byte 32: bad group code 40000");
}

TEST(DxfReader, BinaryDxfR12OneByteCodes) {
  std::string b{"AutoCAD Binary DXF\r\n\x1a\0", 22};
  const auto text = [&b](int code, const std::string& value) {
    b += static_cast<char>(code);
    b += value;
    b += '\0';
  };
  const auto real = [&b](int code, double value) {
    b += static_cast<char>(code);
    const auto bits = std::bit_cast<std::uint64_t>(value);
    for (int i = 0; i < 8; ++i) b += static_cast<char>((bits >> (8 * i)) & 0xff);
  };
  text(0, "SECTION");
  text(2, "ENTITIES");
  text(0, "LINE");
  text(8, "0");
  real(10, 1);
  real(20, 2);
  b += "\xff\xe9\x03";  // 255: group code 1001 in the next two bytes
  b += "APP";
  b += '\0';
  real(11, 3);
  real(21, 4);
  text(0, "ENDSEC");
  text(0, "EOF");
  const Drawing d = read(b);
  ASSERT_EQ(d.segments.size(), 1u);
  expect_point(d.segments[0].start, 1, 2, 0);
  expect_point(d.segments[0].end, 3, 4, 0);
}
