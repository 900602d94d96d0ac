/// @file test_dxf_corpus.cpp
/// @brief Every DXF file of the shared corpus and of test/fixtures/dxf, and
/// three drawings ezdxf writes itself (R2018, R12, binary) with the entity
/// kinds the corpus lacks, read by our reader and by ezdxf
/// (test/oracle/dxf_entities.py), compared entity by entity: counts of read
/// and skipped entities by type, $INSUNITS, and every segment against
/// ezdxf's coordinates to 1e-9 relative. Skipped when the corpus,
/// /usr/bin/python3 or ezdxf is absent.
#include <gtest/gtest.h>
#include <stdlib.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>
#include <vector>

#include "cad/drawing.hpp"
#include "cad/dxf_reader.hpp"
#include "io/error.hpp"
#include "project_paths.hpp"

using namespace tk::cad;
using json = nlohmann::json;

namespace {

constexpr double kChordTolerance = DxfReadOptions{}.chord_tolerance;

std::vector<std::filesystem::path> dxf_files(const std::filesystem::path& folder) {
  std::vector<std::filesystem::path> files;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(folder, error))
    if (entry.path().extension() == ".dxf") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

bool have_ezdxf() {
  static const bool ok = std::system("/usr/bin/python3 -c 'import ezdxf' >/dev/null 2>&1") == 0;
  return ok;
}

/// The oracle's output lines, parsed; fails the test when it does not run.
std::vector<json> run_oracle(const std::string& arguments) {
  const std::string command = "/usr/bin/python3 '" +
                              (tk::test::project_root() / "test" / "oracle" / "dxf_entities.py").string() + "' " +
                              arguments;
  std::vector<json> lines;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) {
    ADD_FAILURE() << "cannot run " << command;
    return lines;
  }
  std::string line;
  for (int c; (c = std::fgetc(pipe)) != EOF;) {
    if (c != '\n') {
      line += static_cast<char>(c);
      continue;
    }
    lines.push_back(json::parse(line));
    line.clear();
  }
  EXPECT_EQ(pclose(pipe), 0) << command;
  return lines;
}

Point xy(const json& v) { return {v.at(0).get<double>(), v.at(1).get<double>()}; }

bool mirrored(const json& e) { return e.at("extrusion").at(2).get<double>() < 0; }

/// The reader's plane rule: extrusion along +-Z or not.
bool in_xy_plane(const json& e) {
  if (!e.contains("extrusion")) return true;
  const auto& v = e["extrusion"];
  const double x = v[0], y = v[1], z = v[2], length = std::hypot(x, y, z);
  return length > 0 && std::abs(x) <= 1e-12 * length && std::abs(y) <= 1e-12 * length;
}

/// How the reader should count an entity ezdxf found in the model space:
/// "" when read, else the name it is skipped under.
std::string skip_name(const json& e) {
  const std::string type = e.at("type");
  if (type == "POLYLINE") {
    const std::string mode = e.at("mode");
    if (mode == "AcDb3dPolyline") return "POLYLINE (3D)";
    if (mode == "AcDbPolygonMesh") return "POLYLINE (polygon mesh)";
    if (mode == "AcDbPolyFaceMesh") return "POLYLINE (polyface mesh)";
  }
  const bool supported = type == "LINE" || type == "ARC" || type == "CIRCLE" || type == "LWPOLYLINE" ||
                         type == "POLYLINE" || type == "ELLIPSE" || type == "SPLINE";
  if (!supported) return type;
  if (!in_xy_plane(e) && type != "LINE") return type + " (not in XY plane)";
  if (type == "SPLINE" && e.contains("curve_error")) return "SPLINE (invalid)";
  return "";
}

struct Expected {
  Point start, end;
  double bulge;
};

/// The segments a polyline must give: ezdxf's world coordinates, its bulges
/// (turned around for extrusion (0,0,-1)), spline frame points left out.
std::vector<Expected> polyline_segments(const json& e) {
  const bool lw = e.at("type") == "LWPOLYLINE";
  const json& data = lw ? e.at("points") : e.at("vertices");
  const json& wcs = e.at("wcs_points");
  const double sign = mirrored(e) ? -1 : 1;
  std::vector<std::pair<Point, double>> vertices;
  for (std::size_t i = 0; i < data.size(); ++i)
    if (lw || !(data[i][3].get<int>() & 16)) vertices.push_back({xy(wcs[i]), sign * data[i][2].get<double>()});
  std::vector<Expected> out;
  const auto add = [&out](std::pair<Point, double> a, std::pair<Point, double> b) {
    if (a.first.x != b.first.x || a.first.y != b.first.y) out.push_back({a.first, b.first, a.second});
  };
  for (std::size_t i = 0; i + 1 < vertices.size(); ++i) add(vertices[i], vertices[i + 1]);
  if (e.at("closed").get<bool>() && vertices.size() > 1) add(vertices.back(), vertices.front());
  return out;
}

/// Whether ezdxf's entity should give any segment at all.
bool makes_segments(const json& e) {
  const std::string type = e.at("type");
  if (type == "LINE") return xy(e["start"]).x != xy(e["end"]).x || xy(e["start"]).y != xy(e["end"]).y;
  if (type == "ARC") return e["angle_span"].get<double>() > 0 && e["radius"].get<double>() > 0;
  if (type == "CIRCLE") return e["radius"].get<double>() > 0;
  if (type == "LWPOLYLINE" || type == "POLYLINE") return !polyline_segments(e).empty();
  if (type == "ELLIPSE") return e["param_span"].get<double>() > 0;
  if (type == "SPLINE") return e["control_points"].empty() ? e["fit_points"].size() > 1 : true;
  return false;
}

double magnitude(const json& value) {
  if (value.is_number()) return std::abs(value.get<double>());
  double m = 0;
  if (value.is_array() || value.is_object())
    for (const auto& item : value) m = std::max(m, magnitude(item));
  return m;
}

double distance_to_segment(Point q, Point a, Point b) {
  const double dx = b.x - a.x, dy = b.y - a.y, length2 = dx * dx + dy * dy;
  const double t = length2 > 0 ? std::clamp(((q.x - a.x) * dx + (q.y - a.y) * dy) / length2, 0.0, 1.0) : 0;
  return std::hypot(q.x - a.x - t * dx, q.y - a.y - t * dy);
}

double distance_to_polyline(Point q, const std::vector<Point>& line) {
  double best = line.empty() ? HUGE_VAL : std::hypot(q.x - line[0].x, q.y - line[0].y);
  for (std::size_t i = 1; i < line.size(); ++i) best = std::min(best, distance_to_segment(q, line[i - 1], line[i]));
  return best;
}

#define EXPECT_POINT(actual, expected, tolerance)                \
  do {                                                           \
    EXPECT_NEAR((actual).x, (expected).x, tolerance) << #actual; \
    EXPECT_NEAR((actual).y, (expected).y, tolerance) << #actual; \
  } while (0)

/// Our segments of one entity against ezdxf's description of it.
void compare_entity(const json& e, const std::vector<Segment>& ours, const Drawing& drawing) {
  const std::string type = e.at("type");
  SCOPED_TRACE(e.dump().substr(0, 300));
  const double scale = std::max(1.0, magnitude(e));
  const double tolerance = 1e-9 * scale;
  for (const Segment& s : ours) {
    EXPECT_EQ(drawing.layers.at(s.layer), e.at("layer").get<std::string>());
    EXPECT_EQ(s.source_line == 0, drawing.binary);
    EXPECT_EQ(s.flattened, type == "ELLIPSE" || type == "SPLINE");
  }
  for (std::size_t i = 1; i < ours.size(); ++i) {  // a chain
    EXPECT_EQ(ours[i].start.x, ours[i - 1].end.x);
    EXPECT_EQ(ours[i].start.y, ours[i - 1].end.y);
  }
  if (type == "LINE") {
    ASSERT_EQ(ours.size(), 1u);
    EXPECT_POINT(ours[0].start, xy(e["start"]), tolerance);
    EXPECT_POINT(ours[0].end, xy(e["end"]), tolerance);
    EXPECT_EQ(ours[0].bulge, 0);
  } else if (type == "ARC" || type == "CIRCLE") {
    const Point centre = xy(e["center_wcs"]);
    const double radius = e["radius"], sign = mirrored(e) ? -1 : 1;
    double span = 2 * std::numbers::pi;
    if (type == "ARC") {
      span = e["angle_span"].get<double>() * std::numbers::pi / 180;
      EXPECT_POINT(ours.front().start, xy(e["start_point"]), tolerance);
      EXPECT_POINT(ours.back().end, xy(e["end_point"]), tolerance);
    } else {
      EXPECT_POINT(ours.front().start, (Point{centre.x + sign * radius, centre.y}), tolerance);
      EXPECT_POINT(ours.back().end, ours.front().start, 0);
    }
    double total = 0;
    for (const Segment& s : ours) {
      total += 4 * std::atan(s.bulge);
      EXPECT_LE(std::abs(s.bulge), 1.0);
      EXPECT_NEAR(std::hypot(s.end.x - centre.x, s.end.y - centre.y), radius, tolerance);
    }
    EXPECT_NEAR(total, sign * span, 1e-9);
  } else if (type == "LWPOLYLINE" || type == "POLYLINE") {
    const std::vector<Expected> expected = polyline_segments(e);
    ASSERT_EQ(ours.size(), expected.size());
    for (std::size_t i = 0; i < ours.size(); ++i) {
      EXPECT_POINT(ours[i].start, expected[i].start, tolerance);
      EXPECT_POINT(ours[i].end, expected[i].end, tolerance);
      EXPECT_NEAR(ours[i].bulge, expected[i].bulge, 1e-12);
    }
  } else if (type == "ELLIPSE") {
    const Point c = xy(e["center"]), major = xy(e["major_axis"]), minor = xy(e["minor_axis"]);
    EXPECT_POINT(ours.front().start, xy(e["start_point"]), tolerance);
    EXPECT_POINT(ours.back().end, xy(e["end_point"]), tolerance);
    const auto parameter = [&](Point p) {
      const double u = ((p.x - c.x) * major.x + (p.y - c.y) * major.y) / (major.x * major.x + major.y * major.y);
      const double v = ((p.x - c.x) * minor.x + (p.y - c.y) * minor.y) / (minor.x * minor.x + minor.y * minor.y);
      EXPECT_NEAR(u * u + v * v, 1, 1e-9) << "a point off the ellipse";
      return std::atan2(v, u);
    };
    for (const Segment& s : ours) {
      const double t0 = parameter(s.start), t1 = parameter(s.end);
      const double t =
          t0 + std::fmod(t1 - t0 + 4 * std::numbers::pi, 2 * std::numbers::pi) / 2;  // the parameter runs upwards
      const Point mid{c.x + std::cos(t) * major.x + std::sin(t) * minor.x,
                      c.y + std::cos(t) * major.y + std::sin(t) * minor.y};
      EXPECT_LE(distance_to_segment(mid, s.start, s.end), kChordTolerance * (1 + 1e-9));
    }
  } else if (type == "SPLINE") {
    std::vector<Point> mine{ours.front().start};
    for (const Segment& s : ours) mine.push_back(s.end);
    if (e["control_points"].empty()) {  // fit points joined by chords
      std::vector<Point> fit;
      for (const auto& p : e["fit_points"])
        if (fit.empty() || xy(p).x != fit.back().x || xy(p).y != fit.back().y) fit.push_back(xy(p));
      ASSERT_EQ(mine.size(), fit.size());
      for (std::size_t i = 0; i < fit.size(); ++i) EXPECT_POINT(mine[i], fit[i], tolerance);
      return;
    }
    std::vector<Point> curve;  // ezdxf's flattening within 1e-6
    for (const auto& p : e["curve"]) curve.push_back(xy(p));
    ASSERT_GE(curve.size(), 2u);
    EXPECT_POINT(mine.front(), curve.front(), tolerance);
    EXPECT_POINT(mine.back(), curve.back(), tolerance);
    for (Point p : mine) EXPECT_LE(distance_to_polyline(p, curve), 2e-6 + tolerance) << "a point off the curve";
    for (Point p : curve) EXPECT_LE(distance_to_polyline(p, mine), kChordTolerance + 2e-6) << "a chord too far";
  }
}

/// Reads `file` with our reader and with ezdxf and compares the two.
void compare_file(const std::filesystem::path& file) {
  SCOPED_TRACE(file.filename().string());
  Drawing drawing;
  try {
    drawing = read_dxf_file(file.string());
  } catch (const tk::Error& error) {
    FAIL() << error.located_message();
  }
  const std::vector<json> oracle = run_oracle("'" + file.string() + "'");
  ASSERT_FALSE(oracle.empty());
  const json& head = oracle[0];
  EXPECT_EQ(drawing.insunits, head.at("insunits").get<int>());
  if (head.at("loader") == "readfile") {
    EXPECT_EQ(drawing.version, head.at("version").get<std::string>());
  }

  std::vector<json> model;
  std::map<std::string, std::size_t> read, skipped;
  for (std::size_t i = 1; i < oracle.size(); ++i) {
    const json& e = oracle[i];
    if (e.contains("paper")) {
      ++skipped[e.at("type").get<std::string>() + " (paper space)"];
      continue;
    }
    model.push_back(e);
    const std::string name = skip_name(e);
    ++(name.empty() ? read[e.at("type")] : skipped[name]);
  }
  EXPECT_EQ(drawing.entities_read, read);
  EXPECT_EQ(drawing.entities_skipped, skipped);

  // Our segments, entity by entity (each entity's segments are together).
  std::vector<std::vector<Segment>> groups;
  for (const Segment& s : drawing.segments) {
    if (groups.empty() || groups.back().back().entity != s.entity) {
      if (!groups.empty()) {
        EXPECT_GT(s.entity, groups.back().back().entity);
      }
      groups.emplace_back();
    }
    groups.back().push_back(s);
  }
  // The model space in file order; with no paper space entities in the
  // ENTITIES section, ezdxf's position is our entity index.
  const bool same_indices = head.at("paper").get<int>() == 0;
  std::size_t next = 0;
  for (std::size_t i = 0; i < model.size(); ++i) {
    if (!skip_name(model[i]).empty() || !makes_segments(model[i])) continue;
    ASSERT_LT(next, groups.size()) << "no segments for " << model[i].dump().substr(0, 200);
    if (same_indices) {
      EXPECT_EQ(groups[next].front().entity, i);
    }
    compare_entity(model[i], groups[next], drawing);
    ++next;
  }
  EXPECT_EQ(next, groups.size()) << "segments for entities ezdxf does not make any from";
}

}  // namespace

TEST(DxfCorpus, EveryFileReadsAsEzdxfReadsIt) {
  const auto files = dxf_files(tk::test::corpus_folder("dxf"));
  if (files.empty()) GTEST_SKIP() << "no DXF corpus at " << tk::test::corpus_folder("dxf");
  if (!have_ezdxf()) GTEST_SKIP() << "/usr/bin/python3 cannot import ezdxf";
  for (const auto& file : files) compare_file(file);
}

TEST(DxfCorpus, TheToolsFixturesReadAsEzdxfReadsThem) {
  const auto files = dxf_files(tk::test::project_root() / "test" / "fixtures" / "dxf");
  if (files.empty()) GTEST_SKIP() << "no fixtures";
  if (!have_ezdxf()) GTEST_SKIP() << "/usr/bin/python3 cannot import ezdxf";
  for (const auto& file : files) compare_file(file);
}

TEST(DxfCorpus, TheBinaryFile) {
  const auto file = tk::test::corpus_folder("dxf") / "ezdxf_bin_dxf_r2000.dxf";
  if (!std::filesystem::exists(file)) GTEST_SKIP() << "no DXF corpus at " << tk::test::corpus_folder("dxf");
  const Drawing drawing = read_dxf_file(file.string());
  EXPECT_TRUE(drawing.binary);
  EXPECT_EQ(drawing.version, "AC1015");
  EXPECT_EQ(drawing.insunits, 6);
  EXPECT_EQ(drawing.entities_skipped.at("TEXT"), 1u);
}

TEST(DxfCorpus, DrawingsEzdxfWritesReadAsEzdxfReadsThem) {
  if (!have_ezdxf()) GTEST_SKIP() << "/usr/bin/python3 cannot import ezdxf";
  char folder[] = "/tmp/test_dxf_corpus_XXXXXX";
  ASSERT_NE(mkdtemp(folder), nullptr);
  for (const char* kind : {"", "--binary", "--r12"}) {
    const std::filesystem::path file = std::filesystem::path(folder) / (std::string("sample") + kind + ".dxf");
    run_oracle("--write-sample '" + file.string() + "' " + kind);
    compare_file(file);
    if (std::string(kind) == "--binary") {
      EXPECT_TRUE(read_dxf_file(file.string()).binary);
    }
  }
  std::filesystem::remove_all(folder);
}
