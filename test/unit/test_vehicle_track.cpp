/// @file test_vehicle_track.cpp
/// @brief Unit tests for the line-follower track: the oval's geometry,
/// nearest-point queries and the track file reader, against closed forms.
#include <gtest/gtest.h>

#include <unistd.h>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "io/error.hpp"
#include "project_paths.hpp"
#include "temp_file.hpp"
#include "vehicle/line_track.hpp"

using namespace tk::vehicle;

namespace {

using tk::test::TempFile;

/// The error read_track throws for `content`, as "file:line: message" with the file name cut off.
std::string track_error(const std::string& content, const std::string& suffix = ".csv") {
  TempFile file(content, suffix);
  try {
    read_track(file.path());
  } catch (const tk::Error& e) {
    EXPECT_EQ(e.where().file, file.path());
    return std::to_string(e.where().line) + ": " + e.what();
  }
  return "no error";
}

}  // namespace

TEST(VehicleTrack, OvalLengthIsTwoStraightsPlusCircle) {
  const double straight = 1000, radius = 300;
  const Track track = oval_track(straight, radius);
  // Chords of angle a fall short of their arc by r (a - 2 sin(a/2)) < r a^3 / 24 each.
  const int chords = static_cast<int>(std::ceil(std::numbers::pi * radius / 5.0));
  const double a = std::numbers::pi / chords, bound = 2 * chords * radius * a * a * a / 24;
  EXPECT_NEAR(track.length_mm(), 2 * straight + 2 * std::numbers::pi * radius, bound + 1e-9);
  EXPECT_LT(bound, 0.05);  // against a line 19 mm wide
  EXPECT_EQ(track.line_width_mm(), kTapeWidthMm);
}

TEST(VehicleTrack, OvalStartsMidStraightHeadingAlongIt) {
  const Track track = oval_track(1000, 300);
  EXPECT_DOUBLE_EQ(track.start().x, 0);
  EXPECT_DOUBLE_EQ(track.start().y, -300);
  EXPECT_DOUBLE_EQ(track.start_heading(), 0);
  // Half a straight on is the start of the right half circle; half a circle more, its end.
  const Point p = track.point_at(500);
  EXPECT_NEAR(p.x, 500, 1e-9);
  EXPECT_NEAR(p.y, -300, 1e-9);
  const Point q = track.point_at(500 + std::numbers::pi * 300);
  EXPECT_NEAR(q.x, 500, 0.05);  // the chords are a little shorter than the arc
  EXPECT_NEAR(q.y, 300, 1e-3);
  EXPECT_FALSE(track.self_intersection());
}

TEST(VehicleTrack, NearestPointOnStraightAndArc) {
  const Track track = oval_track(1000, 300);
  const Nearest n = track.nearest({100, -300 + 7});
  EXPECT_NEAR(n.distance, 7, 1e-9);
  EXPECT_NEAR(n.s, 100, 1e-9);
  // Behind the start: arc length wraps to just under the length.
  EXPECT_NEAR(track.nearest({-10, -310}).s, track.length_mm() - 10, 1e-9);
  // Inside the right half circle, 5 mm from the arc (chords sag by < 0.011 mm).
  const double angle = 0.3;
  const Point p{500 + 295 * std::cos(angle), 295 * std::sin(angle)};
  EXPECT_NEAR(track.nearest(p).distance, 5, 0.011);
  EXPECT_NEAR(track.distance_within(p, 10), track.nearest(p).distance, 1e-12);
  EXPECT_TRUE(std::isinf(track.distance_within(p, 4)));
  EXPECT_TRUE(std::isinf(track.distance_within({0, 0}, 100)));        // the infield's middle
  EXPECT_TRUE(std::isinf(track.distance_within({5000, 5000}, 100)));  // off the grid
  // The windowed query agrees with the scan near its hint.
  const Nearest near = track.nearest_near(p, track.nearest(p).piece + 3, 60);
  EXPECT_NEAR(near.distance, track.nearest(p).distance, 1e-12);
}

TEST(VehicleTrack, CircleWhenStraightsAreZero) {
  const Track track = oval_track(0, 200);
  const int chords = static_cast<int>(std::ceil(std::numbers::pi * 200 / 5.0));
  const double a = std::numbers::pi / chords;
  EXPECT_NEAR(track.length_mm(), 2 * std::numbers::pi * 200, 2 * chords * 200 * a * a * a / 24 + 1e-9);
  EXPECT_NEAR(track.nearest({0, 0}).distance, 200, 25.0 / (8 * 200));  // chords sag inwards
}

TEST(VehicleTrack, ReadsCsvFixtureOfKnownLength) {
  const Track track =
      read_track((tk::test::project_root() / "test" / "fixtures" / "tracks" / "rounded_rectangle.csv").string());
  // 1200 x 800 with 200 mm corners: straights 2 (800 + 400), corners 4 x 30 chords of 3 degrees.
  EXPECT_NEAR(track.length_mm(), 2400 + 120 * 2 * 200 * std::sin(1.5 * std::numbers::pi / 180), 1e-3);
  EXPECT_DOUBLE_EQ(track.start().y, -400);
}

TEST(VehicleTrack, ReadsJsonLinesFixture) {
  const Track track = read_track((tk::test::project_root() / "test" / "fixtures" / "tracks" / "bean.jsonl").string());
  EXPECT_EQ(track.vertices().size(), 180u);
  EXPECT_FALSE(track.self_intersection());
  EXPECT_NEAR(track.nearest({0, 0}).distance, 250, 1.0);  // the dent's deepest point is 400 - 150 from the centre
}

TEST(VehicleTrack, ExplicitClosingPointIsDropped) {
  TempFile file("x,y\n0,0\n100,0\n100,100\n0,0\n", ".csv");
  const Track track = read_track(file.path());
  EXPECT_EQ(track.vertices().size(), 3u);
  EXPECT_NEAR(track.length_mm(), 200 + 100 * std::sqrt(2.0), 1e-9);
}

TEST(VehicleTrack, ReadErrorsNameTheLine) {
  EXPECT_EQ(track_error("x,y\n0,0\n100,0\n100,100\n100,100\n"), "5: track point equals the one before");
  EXPECT_EQ(track_error("x,y\n0,0\n100,\n"), "3: missing field 'y'");
  EXPECT_EQ(track_error("x,y\n0,0\nnan,1\n0,5\n"), "3: field 'x' is not finite");
  EXPECT_EQ(track_error("x,y\n0,0\n100,0\n"), "3: a track needs at least 3 points, found 2");
  EXPECT_EQ(track_error("{\"x\": 0, \"y\": 0}\n{\"x\": 1, \"y\": 0}\n{\"x\": 0, \"y\": 0}\n", ".jsonl"),
            "2: a track needs at least 3 points, found 2");
  // A bow tie: the segment from line 2 (to line 3's point) crosses the one from line 4.
  EXPECT_EQ(track_error("x,y\n0,0\n100,100\n100,0\n0,100\n"),
            "4: track crosses itself: the segment from line 2 meets the one from line 4");
}

TEST(VehicleTrack, ConstructorRefusesBadPolylines) {
  EXPECT_THROW(Track({{0, 0}, {1, 0}}), tk::Error);
  EXPECT_THROW(Track({{0, 0}, {1, 0}, {1, 0}}), tk::Error);
  EXPECT_THROW(Track({{0, 0}, {1, 0}, {1, 1}}, 0), tk::Error);
  EXPECT_THROW(oval_track(1000, 0), tk::Error);
}
