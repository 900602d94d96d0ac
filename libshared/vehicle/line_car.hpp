/// @file line_car.hpp
/// @brief A differential-drive line follower with three reflective sensors,
/// driven round a Track by a controller under a sampling latency: the lap
/// simulation behind `tnorm-bench laps`. Nothing here knows the controller;
/// whatever it does (following, oscillating, stopping) comes out of the
/// physics: finite sensor spots, motor lag and deadband, latency.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "vehicle/line_track.hpp"

namespace tk::vehicle {

/// ADC counts, 0 .. 2^adc_bits - 1; high means dark (on the line).
struct SensorReadings {
  double left = 0, mid = 0, right = 0;
};

/// Controller units (PWM-like); the car clamps each to ±255.
struct MotorCommand {
  double left = 0, right = 0;
};

using Controller = std::function<MotorCommand(const SensorReadings&)>;

/// Defaults: the paper's car as far as it describes it (four DC motors on
/// an L298N at 9 V, three MH-Sensor-Series reflective modules, a 10-bit ADC)
/// with the usual parts of such kits where it does not: TT-class 1:48 gear
/// motors (90-200 rpm unloaded at 6 V, stall torque about 0.4 kg cm) on
/// 65 mm wheels, a car of about 0.7 kg. The man page's LAPS section derives
/// each value.
struct CarParameters {
  double wheel_base_mm = 130;   ///< distance between the wheels' contact points
  double sensor_ahead_mm = 90;  ///< sensor bar ahead of the axle centre
  double sensor_spacing_mm =
      20;                    ///< mid to left and mid to right; outer spots 3.5 sigma clear of a 19 mm line when centred
  double spot_sigma_mm = 3;  ///< Gaussian spot of the sensor on the floor (0: a point)
  int adc_bits = 10;         ///< 10 (Uno) or 12 (ESP32); any of 8..16 is accepted
  double floor_counts = 40;  ///< reading over bare floor
  double line_counts = 950;  ///< reading over the tape
  double noise_counts = 3;   ///< Gaussian reading noise, standard deviation
  /// Wheel speed per command unit above the start threshold: 200 rpm at 6 V
  /// is 33 rpm/V; a duty unit is 8.4/255 V at the motor; 65 mm wheels.
  double mm_per_s_per_unit = 3.7;
  double motor_tau_s = 0.06;  ///< first-order lag of wheel speed behind the command
  /// |command| a wheel needs to turn (static friction): the paper's 55 did
  /// not start the motors on ~5 V and did at 12 V (11.4 V at the motors), so
  /// 1.1-2.5 V; at the ~8.4 V the 9 V supply leaves, 33-75 units; near the
  /// middle.
  double deadband_units = 53;

  /// The defaults with the readings scaled from 10 bits to `bits`.
  static CarParameters with_adc_bits(int bits);
  double full_scale() const { return static_cast<double>((1L << adc_bits) - 1); }
};

struct Pose {
  double x = 0, y = 0;  ///< axle centre, mm
  double heading = 0;   ///< radians, counter-clockwise from +x
};

/// Fraction of a Gaussian spot (sigma `sigma_mm`, centre `delta_mm` from the
/// line's centre line) that falls on a line `width_mm` wide:
/// Φ((δ + w/2)/σ) − Φ((δ − w/2)/σ). sigma 0 gives a point sensor.
double spot_coverage(double delta_mm, double width_mm, double sigma_mm);

/// Where the three spots are for a car at `pose`: left, mid, right.
std::array<Point, 3> sensor_positions(const CarParameters& car, const Pose& pose);

/// The wheels and the body: command -> start threshold -> first-order lag ->
/// exact differential-drive kinematics (constant wheel speeds over a step are
/// an arc). A wheel's target speed is k (|u| - u0) in u's direction for
/// |u| > u0 (a DC motor's steady speed against friction), 0 below.
class DriveBody {
 public:
  DriveBody(const CarParameters& car, Pose start);
  /// Clamps to ±255 (a non-finite part counts as 0) and sets the wheels' targets.
  void set_command(MotorCommand command);
  /// Moves the car by dt seconds; returns the distance the axle centre travelled.
  double advance(double dt);
  const Pose& pose() const { return pose_; }
  double left_speed() const { return v_left_; }    ///< mm/s
  double right_speed() const { return v_right_; }  ///< mm/s

 private:
  double target(double command) const;
  CarParameters car_;
  Pose pose_;
  double v_left_ = 0, v_right_ = 0, target_left_ = 0, target_right_ = 0;
};

struct LapOptions {
  int laps = 3;
  /// Sampling to command taking effect. tnorm-bench sets it per board and
  /// t-norm from the paper's Tables 3-4 (one loop: Uno 3.6-11.4 ms, ESP32
  /// 0.31-1.16 ms); this default is one inference of the Uno's minimum.
  double latency_s = 0.0018;
  double control_period_s =
      0;  ///< controller runs every period; 0: = latency (back to back), or the physics step if that is 0
  double time_limit_s = 120;
  double physics_step_s = 0.0002;  ///< longest step; steps are also cut at sampling and command instants
  std::uint64_t seed = 1;          ///< reading noise
  double stop_after_s = 1.0;       ///< "stopped": the axle moved < 1 mm and turned < 0.02 rad for this long
  double leave_track_mm = 150;     ///< "left the track": axle centre this far from the centre line
  double excursion_mm = 50;        ///< an excursion also begins when the axle centre strays this far
  double trace_interval_s = 0.01;  ///< a trace point at most this often
};

struct LapResult {
  bool completed = false;
  std::vector<double> lap_times_s;
  double total_s = 0;
  /// Episodes where the car lost the line: all three spots cover less than
  /// 10% line at a sample, or the axle centre is farther than excursion_mm
  /// from it; an episode ends when a spot covers 50% or more again and the
  /// axle is back within excursion_mm.
  int excursions = 0;
  double max_deviation_mm = 0;       ///< mid sensor's largest distance from the centre line, over samples
  double rms_deviation_mm = 0;       ///< its root mean square over samples
  double max_axle_deviation_mm = 0;  ///< axle centre's (it cuts inside on curves by design)
  std::string stop_reason;           ///< "" (completed), "stopped", "time limit", "left the track"
  SensorReadings readings_at_end;    ///< the last readings the controller saw
  MotorCommand command_at_end;       ///< the command in effect at the end
  double distance_mm = 0;            ///< path length of the axle centre
  long samples = 0;                  ///< controller calls
};

struct TracePoint {
  double t = 0, x = 0, y = 0, heading = 0;  ///< s, axle centre mm, radians
  SensorReadings readings;                  ///< the last sampled
  MotorCommand command;                     ///< in effect
};

/// Starts the car at rest with its axle centre on the track's start point,
/// heading along the first segment, and runs until `laps` laps (progress of
/// the axle's nearest point along the centre line, unwrapped, so going
/// backwards undoes progress), a stop, the time limit or leaving the track.
/// Deterministic for a given seed. Throws tk::UsageError for bad parameters.
LapResult run_laps(const Track& track, const CarParameters& car, const LapOptions& options,
                   const Controller& controller, std::vector<TracePoint>* trace = nullptr);

}  // namespace tk::vehicle
