/// @file clipper_sweep.cpp
/// @brief Choosing Clipper's sweep direction (see clipper_sweep.hpp).
#include "cad/clipper_sweep.hpp"

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace tk::cad {
namespace {

constexpr std::size_t kWorthTurning = 1000;  // edges crossed at most before a turn is considered
constexpr std::size_t kTurnGain = 8;         // and how many times fewer it must cross after

/// The most edges any line of constant y (by_x: constant x) crosses inside them.
std::size_t most_crossed(const ClipperLib::Paths& paths, bool by_x) {
  std::vector<std::pair<ClipperLib::cInt, int>> events;  // an edge's span opens at its low end, closes at its high end
  for (const ClipperLib::Path& path : paths)
    for (std::size_t i = 0; i < path.size(); ++i) {
      const ClipperLib::IntPoint& a = path[i];
      const ClipperLib::IntPoint& b = path[(i + 1) % path.size()];
      const ClipperLib::cInt lo = by_x ? std::min(a.X, b.X) : std::min(a.Y, b.Y);
      const ClipperLib::cInt hi = by_x ? std::max(a.X, b.X) : std::max(a.Y, b.Y);
      if (lo < hi) events.push_back({lo, 1}), events.push_back({hi, -1});
    }
  std::sort(events.begin(), events.end());  // at one coordinate the closings (-1) come first
  std::size_t open = 0, most = 0;
  for (const auto& [at, change] : events) {
    open = change > 0 ? open + 1 : open - 1;
    most = std::max(most, open);
  }
  return most;
}

}  // namespace

bool sweep_across(const ClipperLib::Paths& paths) {
  std::size_t edges = 0;
  for (const ClipperLib::Path& path : paths) edges += path.size();
  if (edges < kWorthTurning) return false;
  const std::size_t now = most_crossed(paths, false);
  return now >= kWorthTurning && most_crossed(paths, true) * kTurnGain < now;
}

void quarter_turn(ClipperLib::Paths& paths) {
  for (ClipperLib::Path& path : paths)
    for (ClipperLib::IntPoint& p : path) p = {-p.Y, p.X};
}

void quarter_turn_back(ClipperLib::PolyNode& node) {
  for (ClipperLib::IntPoint& p : node.Contour) p = {p.Y, -p.X};
  for (ClipperLib::PolyNode* child : node.Childs) quarter_turn_back(*child);
}

}  // namespace tk::cad
