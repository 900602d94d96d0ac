/// @file region_report.cpp
#include "cad/region_report.hpp"

namespace tk::cad {

Record invasion_sim_record(const InvasionSimResult& r, const std::string& invasion_check,
                           const InvasionSimOptions& options) {
  return Record{{"guard", r.guard},
                {"invasion_check", r.guard == "fixed-tolerance" ? invasion_check : "exact"},
                {"tolerance_mm", r.tolerance_mm},
                {"strokes", r.strokes},
                {"invasions", r.invasions},
                {"success_rate", r.success_rate},
                {"mean_undercut_mm", r.mean_undercut_mm},
                {"max_undercut_mm", r.max_undercut_mm},
                {"mean_invasion_mm", r.mean_invasion_mm},
                {"max_invasion_mm", r.max_invasion_mm},
                {"latency_s", options.latency_s},
                {"period_s", options.period_s},
                {"joystick_speed_mm_s", options.feed_mm_s}};
}

std::vector<std::string> position_check_fields(bool summary) {
  std::vector<std::string> fields{"inside", "distance", "clamped_x",     "clamped_y", "element",
                                  "entity", "dxf_line", "approach_mm_s", "stop"};
  if (summary)  // CSV: the summary's columns too, empty in the positions' rows
    fields.insert(fields.end(), {"summary", "positions", "invasions", "deepest_invasion_mm", "deepest_x", "deepest_y",
                                 "closest_mm", "stops"});
  return fields;
}

void add_position_fields(Record& record, const PositionCheck& c, const std::vector<Segment>& elements) {
  record["inside"] = c.answer.distance < 0;
  record["distance"] = c.answer.distance;
  record["clamped_x"] = c.answer.clamped.x;
  record["clamped_y"] = c.answer.clamped.y;
  record["element"] = c.answer.element;
  record["entity"] = elements[c.answer.element].entity;
  record["dxf_line"] = elements[c.answer.element].source_line;
  if (c.approach_mm_s) record["approach_mm_s"] = *c.approach_mm_s;
  if (c.stop) record["stop"] = *c.stop;
}

Record guard_summary_record(const GuardSummary& s) {
  Record last{
      {"summary", true}, {"positions", s.positions}, {"invasions", s.invasions}, {"deepest_invasion_mm", s.deepest_mm}};
  if (s.invasions > 0) {
    last["deepest_x"] = s.deepest_at.x;
    last["deepest_y"] = s.deepest_at.y;
  }
  if (s.positions > 0) last["closest_mm"] = s.closest_mm;
  last["stops"] = s.stops;
  return last;
}

}  // namespace tk::cad
