/// @file lap_svg.hpp
/// @brief An SVG drawing of the paths the car's axle centre took in one or
/// more runs, one panel per run (each with the track, the tape at its
/// width), so runs of different controllers (t-norms) do not hide one
/// another; a run that did not finish is marked where it ended.
#pragma once

#include <string>
#include <vector>

#include "vehicle/line_car.hpp"
#include "vehicle/line_track.hpp"

namespace tk::vehicle {

/// One run: its name (the panel's caption), its trace, and its result (laps
/// and time in the caption; a run not completed gets a marker at its end).
struct LapRun {
  std::string label = {};
  std::vector<TracePoint> trace = {};
  LapResult result = {};
};

/// Writes the drawing atomically (temporary file, fsync, rename): panels in
/// up to three columns, a legend above them. Throws tk::Error when the file
/// cannot be written.
void write_lap_svg(const std::string& path, const Track& track, const std::vector<LapRun>& runs);

}  // namespace tk::vehicle
