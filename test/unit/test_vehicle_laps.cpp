/// @file test_vehicle_laps.cpp
/// @brief Unit tests for the line-follower car: sensor coverage, drive
/// kinematics against closed forms, and lap runs with hand-written controllers.
#include <gtest/gtest.h>

#include <unistd.h>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

#include "io/error.hpp"
#include "vehicle/lap_svg.hpp"
#include "vehicle/line_car.hpp"

using namespace tk::vehicle;

namespace {

/// An ideal drive: no lag, no deadband.
CarParameters ideal_car() {
  CarParameters car;
  car.motor_tau_s = 0;
  car.deadband_units = 0;
  return car;
}

/// Drives `body` for `seconds` in steps of `dt`.
void drive(DriveBody& body, double seconds, double dt) {
  const long steps = std::lround(seconds / dt);
  for (long i = 0; i < steps; ++i) body.advance(dt);
}

/// Turn toward the darker side, else straight on (no memory).
MotorCommand bang_bang(const SensorReadings& r) {
  constexpr double kFast = 144, kSlow = 40, kMargin = 100;
  if (r.left > r.right + kMargin) return {kSlow, kFast};
  if (r.right > r.left + kMargin) return {kFast, kSlow};
  return {kFast, kFast};
}

}  // namespace

TEST(VehicleSensor, CoverageClosedForms) {
  const double w = 19, s = 3;
  EXPECT_NEAR(spot_coverage(0, w, s), std::erf(w / (2 * std::sqrt(2.0) * s)), 1e-15);
  EXPECT_NEAR(spot_coverage(w / 2, w, s), 0.5 * std::erf(w / (std::sqrt(2.0) * s)), 1e-15);  // spot centred on the edge
  EXPECT_DOUBLE_EQ(spot_coverage(7, w, s), spot_coverage(-7, w, s));
  EXPECT_LT(spot_coverage(20, w, s), 1e-3);  // the outer sensors of a centred default car
  EXPECT_EQ(spot_coverage(9, w, 0), 1.0);
  EXPECT_EQ(spot_coverage(10, w, 0), 0.0);
}

TEST(VehicleSensor, PositionsAreAheadAndAcross) {
  const CarParameters car;
  const auto spots = sensor_positions(car, Pose{10, 20, std::numbers::pi / 2});  // heading +y: left is -x
  EXPECT_NEAR(spots[1].x, 10, 1e-12);
  EXPECT_NEAR(spots[1].y, 20 + car.sensor_ahead_mm, 1e-12);
  EXPECT_NEAR(spots[0].x, 10 - car.sensor_spacing_mm, 1e-12);
  EXPECT_NEAR(spots[2].x, 10 + car.sensor_spacing_mm, 1e-12);
}

TEST(VehicleSensor, TwelveBitDefaultsScale) {
  const CarParameters car = CarParameters::with_adc_bits(12);
  EXPECT_EQ(car.full_scale(), 4095);
  EXPECT_NEAR(car.line_counts, 950.0 * 4095 / 1023, 1e-9);
}

TEST(VehicleDrive, StraightRunCoversSpeedTimesTime) {
  const CarParameters car = ideal_car();
  DriveBody body(car, Pose{0, 0, 0});
  body.set_command({100, 100});
  drive(body, 2.0, 0.0002);
  EXPECT_NEAR(body.pose().x, 100 * car.mm_per_s_per_unit * 2.0, 1e-6);
  EXPECT_NEAR(body.pose().y, 0, 1e-9);
}

TEST(VehicleDrive, MotorLagDelaysByTheTimeConstant) {
  CarParameters car = ideal_car();
  car.motor_tau_s = 0.06;
  DriveBody body(car, Pose{0, 0, 0});
  body.set_command({100, 100});
  const double t = 0.3, v = 100 * car.mm_per_s_per_unit;
  drive(body, t, 0.0002);
  // From rest, x(t) = v (t - tau (1 - exp(-t / tau))).
  EXPECT_NEAR(body.pose().x, v * (t - car.motor_tau_s * (1 - std::exp(-t / car.motor_tau_s))), 1e-6);
  EXPECT_NEAR(body.left_speed(), v * (1 - std::exp(-t / car.motor_tau_s)), 1e-6);
}

TEST(VehicleDrive, DifferentialCommandDrivesTheKinematicCircle) {
  const CarParameters car = ideal_car();
  DriveBody body(car, Pose{0, 0, 0});
  body.set_command({60, 120});
  const double vl = 60 * car.mm_per_s_per_unit, vr = 120 * car.mm_per_s_per_unit;
  const double radius = car.wheel_base_mm / 2 * (vr + vl) / (vr - vl), omega = (vr - vl) / car.wheel_base_mm;
  // Centre to the left of the start heading (+x): (0, radius). Half a turn later the car is at (0, 2 radius).
  const double half_turn = std::numbers::pi / omega;
  const int steps = 1000;
  for (int i = 0; i < steps; ++i) {
    body.advance(half_turn / steps);
    EXPECT_NEAR(std::hypot(body.pose().x, body.pose().y - radius), radius, 1e-9);
  }
  EXPECT_NEAR(body.pose().x, 0, 1e-9);
  EXPECT_NEAR(body.pose().y, 2 * radius, 1e-9);
  EXPECT_NEAR(std::abs(body.pose().heading), std::numbers::pi, 1e-9);
}

TEST(VehicleDrive, DeadbandAndClamp) {
  CarParameters car = ideal_car();
  car.deadband_units = 30;
  DriveBody body(car, Pose{0, 0, 0});
  body.set_command({29, -29});
  drive(body, 1.0, 0.001);
  EXPECT_EQ(body.pose().x, 0);
  EXPECT_EQ(body.pose().heading, 0);
  body.set_command({1000, 1000});  // clamped to 255
  drive(body, 1.0, 0.001);
  EXPECT_NEAR(body.pose().x, (255 - 30) * car.mm_per_s_per_unit, 1e-6);  // speed grows from the threshold on
  body.set_command({-100, -100});
  drive(body, 1.0, 0.001);
  EXPECT_NEAR(body.pose().x, (255 - 30 - 70) * car.mm_per_s_per_unit, 1e-6);
  body.set_command({NAN, NAN});                               // no drive
  EXPECT_EQ(body.left_speed(), -70 * car.mm_per_s_per_unit);  // the command acts on the next step
  body.advance(0.001);
  EXPECT_EQ(body.left_speed(), 0);
}

TEST(VehicleLaps, BangBangCompletesThreeLapsOfTheOval) {
  const Track track = oval_track();
  const CarParameters car;
  const LapResult r = run_laps(track, car, LapOptions{}, bang_bang);
  ASSERT_TRUE(r.completed) << r.stop_reason << " after " << r.total_s << " s";
  EXPECT_EQ(r.stop_reason, "");
  ASSERT_EQ(r.lap_times_s.size(), 3u);
  // No lap faster than the whole centre line at full speed (the axle cuts inside
  // the half circles by sqrt(r^2 + ahead^2) - r at most... bounded by 2 pi * 15 mm a lap).
  const double v_max = (144 - car.deadband_units) * car.mm_per_s_per_unit;
  for (double lap : r.lap_times_s) EXPECT_GT(lap, (track.length_mm() - 2 * std::numbers::pi * 15) / v_max);
  EXPECT_NEAR(r.lap_times_s[0] + r.lap_times_s[1] + r.lap_times_s[2], r.total_s, 1e-3);
  EXPECT_GT(r.distance_mm, 3 * (track.length_mm() - 2 * std::numbers::pi * 15));
  EXPECT_EQ(r.excursions, 0);
  EXPECT_LT(r.max_deviation_mm, 20);  // the line never left the sensor bar
  EXPECT_LT(r.max_axle_deviation_mm, 50);
}

TEST(VehicleLaps, StandingStillStopsAfterOneSecond) {
  const CarParameters car;
  const LapOptions options;
  const LapResult r = run_laps(oval_track(), car, options, [](const SensorReadings&) { return MotorCommand{0, 0}; });
  EXPECT_FALSE(r.completed);
  EXPECT_EQ(r.stop_reason, "stopped");
  EXPECT_GT(r.total_s, options.stop_after_s);
  EXPECT_LE(r.total_s, options.stop_after_s + options.physics_step_s + 1e-9);
  EXPECT_EQ(r.distance_mm, 0);
  // Centred on the line: mid dark, outer sensors at the floor reading (within 5 sigma of noise).
  EXPECT_GT(r.readings_at_end.mid,
            car.floor_counts + 0.99 * (car.line_counts - car.floor_counts) - 5 * car.noise_counts);
  EXPECT_NEAR(r.readings_at_end.left, car.floor_counts, 5 * car.noise_counts);
  EXPECT_NEAR(r.readings_at_end.right, car.floor_counts, 5 * car.noise_counts);
}

TEST(VehicleLaps, DrivingStraightLeavesTheTrackWhereGeometrySays) {
  // Straight on from (0, -300) along +x: 150 mm outside the right half circle
  // (centre (500, 0), radius 300) at x = 500 + sqrt(450^2 - 300^2).
  std::vector<TracePoint> trace;
  const LapResult r = run_laps(
      oval_track(1000, 300), CarParameters{}, LapOptions{},
      [](const SensorReadings&) {
        return MotorCommand{144, 144};
      },
      &trace);
  EXPECT_EQ(r.stop_reason, "left the track");
  const double x = 500 + std::sqrt(450.0 * 450 - 300 * 300);
  ASSERT_FALSE(trace.empty());
  EXPECT_NEAR(trace.back().x, x, 0.1);  // one physics step at 346 mm/s is 0.07 mm
  EXPECT_NEAR(r.distance_mm, x, 0.1);
  EXPECT_EQ(r.excursions, 1);
}

TEST(VehicleLaps, GoingBackFirstDelaysTheFirstLapWithoutCountingOne) {
  // Reverse for 1 s across the start line, then follow: crossing the start
  // backwards and again forwards must not count a lap.
  const LapOptions options;
  long calls = 0;
  const Controller reverse_then_follow = [&](const SensorReadings& r) {
    return static_cast<double>(calls++) * options.latency_s < 1.0 ? MotorCommand{-100, -100} : bang_bang(r);
  };
  const LapResult r = run_laps(oval_track(), CarParameters{}, options, reverse_then_follow);
  ASSERT_TRUE(r.completed) << r.stop_reason;
  ASSERT_EQ(r.lap_times_s.size(), 3u);
  EXPECT_GT(r.lap_times_s[0], r.lap_times_s[1] + 1.5);  // 1 s back plus the way back to the start
}

TEST(VehicleLaps, LatencyMakesTheCarWander) {
  const Track track = oval_track();
  LapOptions quick, slow;
  quick.latency_s = 0;
  quick.control_period_s = slow.control_period_s = 0.002;  // only the latency differs
  slow.latency_s = 0.08;
  quick.laps = slow.laps = 1;
  const LapResult a = run_laps(track, CarParameters{}, quick, bang_bang);
  const LapResult b = run_laps(track, CarParameters{}, slow, bang_bang);
  EXPECT_TRUE(a.completed);
  EXPECT_GT(b.max_deviation_mm, a.max_deviation_mm);
  EXPECT_GT(b.rms_deviation_mm, a.rms_deviation_mm);
}

TEST(VehicleLaps, SameSeedSameRun) {
  LapOptions options;
  options.laps = 1;
  const LapResult a = run_laps(oval_track(), CarParameters{}, options, bang_bang);
  const LapResult b = run_laps(oval_track(), CarParameters{}, options, bang_bang);
  EXPECT_EQ(a.total_s, b.total_s);
  EXPECT_EQ(a.distance_mm, b.distance_mm);
  EXPECT_EQ(a.max_deviation_mm, b.max_deviation_mm);
}

TEST(VehicleLaps, TimeLimitAndBadParameters) {
  LapOptions options;
  options.time_limit_s = 2;
  const LapResult r = run_laps(oval_track(), CarParameters{}, options, bang_bang);
  EXPECT_EQ(r.stop_reason, "time limit");
  EXPECT_NEAR(r.total_s, 2, 1e-9);
  CarParameters car;
  car.wheel_base_mm = 0;
  EXPECT_THROW(run_laps(oval_track(), car, options, bang_bang), tk::UsageError);
  options.laps = 0;
  EXPECT_THROW(run_laps(oval_track(), CarParameters{}, options, bang_bang), tk::UsageError);
}

TEST(VehicleLaps, SvgHasAPanelPerRunAndMarksARunCutShort) {
  std::vector<TracePoint> trace;
  LapOptions options;
  options.time_limit_s = 1;
  const LapResult result = run_laps(oval_track(), CarParameters{}, options, bang_bang, &trace);
  ASSERT_EQ(result.stop_reason, "time limit");
  const std::string path =
      (std::filesystem::temp_directory_path() / ("tk_vehicle_laps_" + std::to_string(::getpid()) + ".svg")).string();
  write_lap_svg(path, oval_track(), {{"minimum", trace, result}, {"drastic <&>", {}, {}}});
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  std::filesystem::remove(path);
  const std::string svg = text.str();
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_NE(svg.find(">minimum: did not finish (time limit)</text>"), std::string::npos);
  EXPECT_NE(svg.find(">drastic &lt;&amp;&gt;: did not finish (ended)</text>"), std::string::npos);
  std::size_t panels = 0, stops = 0;
  for (std::size_t at = 0; (at = svg.find("class=\"panel\"", at)) != std::string::npos; ++at) ++panels;
  for (std::size_t at = 0; (at = svg.find("class=\"stop\"", at)) != std::string::npos; ++at) ++stops;
  EXPECT_EQ(panels, 2u);
  EXPECT_EQ(stops, 1u);  // the run without a trace has no end to mark
  EXPECT_NE(svg.find(">time limit after 1.0 s, "), std::string::npos);
  EXPECT_EQ(svg.rfind("</svg>\n"), svg.size() - 7);
  EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
}
