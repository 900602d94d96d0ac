/// @file lap_svg.hpp
/// @brief An SVG drawing of a track (the tape at its width) and of the paths
/// the car's axle centre took in one or more runs, each in its own colour
/// with a legend: for comparing controllers (t-norms) on one picture.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "vehicle/line_car.hpp"
#include "vehicle/line_track.hpp"

namespace tk::vehicle {

/// One run: its label for the legend and its trace.
using LapRun = std::pair<std::string, std::vector<TracePoint>>;

/// Writes the drawing atomically (temporary file, fsync, rename); a dot marks
/// where each run ended. Throws tk::Error when the file cannot be written.
void write_lap_svg(const std::string& path, const Track& track, const std::vector<LapRun>& runs);

}  // namespace tk::vehicle
