/// @file line_car.cpp
/// @brief Sensors, drive and the lap loop of the line-follower simulation.
#include "vehicle/line_car.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <numbers>

#include "io/error.hpp"
#include "sim/gaussian_noise.hpp"

namespace tk::vehicle {

namespace {

constexpr double kCommandLimit = 255;
constexpr double kLostCoverage = 0.1, kFoundCoverage = 0.5;  // excursion hysteresis
constexpr double kStillMm = 1.0, kStillRad = 0.02;

/// A point followed along the track: the running piece index keeps queries
/// cheap and progress continuous; a scan of the whole line settles it when
/// the point has strayed (then a closer leg of the track may take over).
class Follower {
 public:
  explicit Follower(const Track& track) : track_(track) {}
  Nearest update(Point p) {
    const double moved = std::hypot(p.x - last_.x, p.y - last_.y);
    Nearest n = first_ ? track_.nearest(p) : track_.nearest_near(p, hint_, 20.0 + 2 * moved);
    if (!first_ && n.distance > 30.0) {
      const Nearest global = track_.nearest(p);
      if (global.distance < n.distance) n = global;
    }
    first_ = false;
    hint_ = n.piece;
    last_ = p;
    return n;
  }

 private:
  const Track& track_;
  std::size_t hint_ = 0;
  Point last_;
  bool first_ = true;
};

struct Sample {
  SensorReadings readings;
  double max_coverage = 0;
};

Sample sense(const Track& track, const CarParameters& car, const Pose& pose, sim::GaussianNoise& noise) {
  // Beyond 6 sigma past the edge the spot sees no line (coverage < 1e-9).
  const double reach = track.line_width_mm() / 2 + 6 * car.spot_sigma_mm + 1e-9;
  const std::array<Point, 3> spots = sensor_positions(car, pose);
  double counts[3];
  Sample out;
  for (int i = 0; i < 3; ++i) {
    const double d = track.distance_within(spots[i], reach);
    const double coverage = std::isfinite(d) ? spot_coverage(d, track.line_width_mm(), car.spot_sigma_mm) : 0.0;
    out.max_coverage = std::max(out.max_coverage, coverage);
    const double raw = car.floor_counts + (car.line_counts - car.floor_counts) * coverage + noise.next();
    counts[i] = std::round(std::clamp(raw, 0.0, car.full_scale()));  // an ADC gives integers within its range
  }
  out.readings = {counts[0], counts[1], counts[2]};
  return out;
}

void validate(const CarParameters& car, const LapOptions& o) {
  const auto need = [](bool ok, const char* what) {
    if (!ok) throw UsageError(what);
  };
  need(car.wheel_base_mm > 0 && std::isfinite(car.wheel_base_mm), "wheel base must be positive");
  need(car.sensor_ahead_mm >= 0 && std::isfinite(car.sensor_ahead_mm), "sensor distance ahead must be 0 or more");
  need(car.sensor_spacing_mm > 0 && std::isfinite(car.sensor_spacing_mm), "sensor spacing must be positive");
  need(car.spot_sigma_mm >= 0 && std::isfinite(car.spot_sigma_mm), "sensor spot sigma must be 0 or more");
  need(car.adc_bits >= 8 && car.adc_bits <= 16, "adc bits must be 8 to 16");
  need(std::isfinite(car.floor_counts) && std::isfinite(car.line_counts), "floor and line readings must be finite");
  need(car.noise_counts >= 0 && std::isfinite(car.noise_counts), "reading noise must be 0 or more");
  need(car.mm_per_s_per_unit > 0 && std::isfinite(car.mm_per_s_per_unit), "speed per command unit must be positive");
  need(car.motor_tau_s >= 0 && std::isfinite(car.motor_tau_s), "motor time constant must be 0 or more");
  need(car.deadband_units >= 0 && std::isfinite(car.deadband_units), "deadband must be 0 or more");
  need(o.laps >= 1, "laps must be at least 1");
  need(o.latency_s >= 0 && std::isfinite(o.latency_s), "latency must be 0 or more");
  need(o.control_period_s >= 0 && std::isfinite(o.control_period_s), "control period must be 0 or more");
  need(o.time_limit_s > 0 && std::isfinite(o.time_limit_s), "time limit must be positive");
  need(o.physics_step_s > 0 && o.physics_step_s <= 0.01, "physics step must be positive and at most 10 ms");
  need(o.stop_after_s > 0 && o.leave_track_mm > 0 && o.excursion_mm > 0 && o.trace_interval_s >= 0,
       "stop time, track distances and trace interval must be positive");
}

}  // namespace

CarParameters CarParameters::with_adc_bits(int bits) {
  CarParameters car;
  const double scale = static_cast<double>((1L << std::clamp(bits, 8, 16)) - 1) / car.full_scale();
  car.adc_bits = bits;
  car.floor_counts *= scale;
  car.line_counts *= scale;
  car.noise_counts *= scale;
  return car;
}

double spot_coverage(double delta_mm, double width_mm, double sigma_mm) {
  const double half = width_mm / 2;
  if (sigma_mm <= 0) {
    const double d = std::abs(delta_mm);
    return d < half ? 1.0 : d == half ? 0.5 : 0.0;
  }
  const double k = 1 / (std::sqrt(2.0) * sigma_mm);
  return 0.5 * (std::erf((delta_mm + half) * k) - std::erf((delta_mm - half) * k));
}

std::array<Point, 3> sensor_positions(const CarParameters& car, const Pose& pose) {
  const double c = std::cos(pose.heading), s = std::sin(pose.heading);
  const Point mid{pose.x + car.sensor_ahead_mm * c, pose.y + car.sensor_ahead_mm * s};
  const double d = car.sensor_spacing_mm;
  return {Point{mid.x - d * s, mid.y + d * c}, mid, Point{mid.x + d * s, mid.y - d * c}};  // left is +90° from heading
}

DriveBody::DriveBody(const CarParameters& car, Pose start) : car_(car), pose_(start) {}

double DriveBody::target(double command) const {
  if (!std::isfinite(command)) command = 0;  // a motor driver cannot be given NaN; treat it as no drive
  command = std::clamp(command, -kCommandLimit, kCommandLimit);
  const double above = std::abs(command) - car_.deadband_units;
  return above <= 0 ? 0.0 : std::copysign(above * car_.mm_per_s_per_unit, command);
}

void DriveBody::set_command(MotorCommand command) {
  target_left_ = target(command.left);
  target_right_ = target(command.right);
}

double DriveBody::advance(double dt) {
  // Wheel speed relaxes exponentially to its target; the step uses each wheel's
  // exact mean speed, so each wheel covers exactly its distance.
  double mean_left = target_left_, mean_right = target_right_;
  if (car_.motor_tau_s > 0) {
    const double decay = std::exp(-dt / car_.motor_tau_s);
    const double share = dt > 0 ? car_.motor_tau_s * (1 - decay) / dt : 1.0;
    mean_left += (v_left_ - target_left_) * share;
    mean_right += (v_right_ - target_right_) * share;
    v_left_ = target_left_ + (v_left_ - target_left_) * decay;
    v_right_ = target_right_ + (v_right_ - target_right_) * decay;
  } else {
    v_left_ = target_left_;
    v_right_ = target_right_;
  }
  const double v = (mean_left + mean_right) / 2, omega = (mean_right - mean_left) / car_.wheel_base_mm;
  const double turn = omega * dt, h0 = pose_.heading;
  if (std::abs(turn) < 1e-9) {
    pose_.x += v * dt * std::cos(h0 + turn / 2);
    pose_.y += v * dt * std::sin(h0 + turn / 2);
  } else {  // an arc of radius v / omega about the instantaneous centre
    const double r = v / omega;
    pose_.x += r * (std::sin(h0 + turn) - std::sin(h0));
    pose_.y -= r * (std::cos(h0 + turn) - std::cos(h0));
  }
  pose_.heading = h0 + turn;  // kept within (-pi, pi]
  if (pose_.heading > std::numbers::pi) pose_.heading -= 2 * std::numbers::pi;
  if (pose_.heading <= -std::numbers::pi) pose_.heading += 2 * std::numbers::pi;
  return std::abs(v) * dt;
}

LapResult run_laps(const Track& track, const CarParameters& car, const LapOptions& options,
                   const Controller& controller, std::vector<TracePoint>* trace) {
  validate(car, options);
  const double period = options.control_period_s > 0 ? options.control_period_s
                        : options.latency_s > 0      ? options.latency_s
                                                     : options.physics_step_s;
  constexpr double kEps = 1e-12;
  const double length = track.length_mm();

  DriveBody body(car, Pose{track.start().x, track.start().y, track.start_heading()});
  Follower axle(track), bar(track);
  sim::GaussianNoise noise(car.noise_counts, options.seed);
  std::deque<std::pair<double, MotorCommand>> pending;  // commands on their way to the motors
  MotorCommand active;
  SensorReadings last_readings;
  LapResult result;

  double t = 0, progress = 0, last_s = axle.update({body.pose().x, body.pose().y}).s, axle_deviation = 0;
  double lap_start_t = 0, sum_sq = 0, next_trace = 0;
  long k = 0;  // next sample is at k * period (multiplied, not summed, so it does not drift)
  bool in_excursion = false;
  Pose anchor = body.pose();
  double anchor_t = 0;

  const auto record_trace = [&] {
    if (trace) trace->push_back({t, body.pose().x, body.pose().y, body.pose().heading, last_readings, active});
  };
  const auto apply_due = [&] {
    while (!pending.empty() && pending.front().first <= t + kEps) {
      active = pending.front().second;
      body.set_command(active);
      pending.pop_front();
    }
  };

  for (;;) {
    apply_due();
    if (static_cast<double>(k) * period <= t + kEps) {
      const Sample sample = sense(track, car, body.pose(), noise);
      last_readings = sample.readings;
      pending.emplace_back(static_cast<double>(k) * period + options.latency_s, controller(sample.readings));
      ++k;
      ++result.samples;
      apply_due();  // zero latency: the command acts at once
      const std::array<Point, 3> spots = sensor_positions(car, body.pose());
      const double dev = bar.update(spots[1]).distance;
      result.max_deviation_mm = std::max(result.max_deviation_mm, dev);
      sum_sq += dev * dev;
      const bool lost = sample.max_coverage < kLostCoverage || axle_deviation > options.excursion_mm;
      const bool found = sample.max_coverage >= kFoundCoverage && axle_deviation <= options.excursion_mm;
      if (!in_excursion && lost) ++result.excursions;
      in_excursion = in_excursion ? !found : lost;
    }
    if (trace && t >= next_trace - kEps) {
      record_trace();
      next_trace = t + options.trace_interval_s;
    }
    if (t >= options.time_limit_s - kEps) {
      result.stop_reason = "time limit";
      break;
    }

    double next = std::min({t + options.physics_step_s, static_cast<double>(k) * period, options.time_limit_s});
    if (!pending.empty()) next = std::min(next, pending.front().first);
    const double dt = next - t;
    if (dt > 0) result.distance_mm += body.advance(dt);
    t = next;

    const Pose& pose = body.pose();
    const Nearest here = axle.update({pose.x, pose.y});
    axle_deviation = here.distance;
    result.max_axle_deviation_mm = std::max(result.max_axle_deviation_mm, axle_deviation);
    double delta = here.s - last_s;  // unwrapped: the start line is crossed either way
    if (delta > length / 2) delta -= length;
    if (delta < -length / 2) delta += length;
    last_s = here.s;
    const double before = progress;
    progress += delta;
    const double lap_mark = length * static_cast<double>(result.lap_times_s.size() + 1);
    if (progress >= lap_mark && delta > 0) {
      const double crossed = t - dt * (progress - lap_mark) / (progress - before);  // interpolated within the step
      result.lap_times_s.push_back(crossed - lap_start_t);
      lap_start_t = crossed;
      if (static_cast<int>(result.lap_times_s.size()) >= options.laps) {
        result.completed = true;
        break;
      }
    }
    if (axle_deviation > options.leave_track_mm) {
      result.stop_reason = "left the track";
      break;
    }
    if (std::hypot(pose.x - anchor.x, pose.y - anchor.y) > kStillMm ||
        std::abs(std::remainder(pose.heading - anchor.heading, 2 * std::numbers::pi)) > kStillRad) {
      anchor = pose;
      anchor_t = t;
    } else if (t - anchor_t > options.stop_after_s) {
      result.stop_reason = "stopped";
      break;
    }
  }
  result.total_s = t;
  result.readings_at_end = last_readings;
  result.command_at_end = active;
  result.rms_deviation_mm = result.samples > 0 ? std::sqrt(sum_sq / static_cast<double>(result.samples)) : 0;
  record_trace();
  return result;
}

}  // namespace tk::vehicle
