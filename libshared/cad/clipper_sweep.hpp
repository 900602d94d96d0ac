/// @file clipper_sweep.hpp
/// @brief Which way Clipper should sweep a set of paths. Clipper sweeps
/// along y and keeps every edge a horizontal line crosses in one list,
/// inserting each new edge by a linear search: on a part long in x whose
/// features all span one band of y (a comb's teeth) that list holds every
/// edge and its union and offset grow as n squared. A quarter turn, exact
/// on Clipper's integers and undone on the result, makes the sweep cross
/// the part the short way.
#pragma once

#include <polyclipping/clipper.hpp>

namespace tk::cad {

/// Whether a quarter turn would let a horizontal line cross far fewer
/// edges (at most) than it does now; false on parts small enough for it
/// not to matter.
bool sweep_across(const ClipperLib::Paths& paths);

/// (x, y) -> (-y, x), and back: exact, and orientation is kept.
void quarter_turn(ClipperLib::Paths& paths);
void quarter_turn_back(ClipperLib::PolyNode& node);

}  // namespace tk::cad
