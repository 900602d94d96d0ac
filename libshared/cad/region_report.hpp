/// @file region_report.hpp
/// @brief dxf2region's records of the guards: a simulated experiment's
/// result per guard (--simulate), and a checked position and the check's
/// summary (--check).
#pragma once

#include <string>
#include <vector>

#include "cad/drawing.hpp"
#include "cad/invasion_check.hpp"
#include "cad/invasion_sim.hpp"
#include "io/record.hpp"

namespace tk::cad {

/// One guard's result at one joystick speed; `invasion_check` names what
/// the fixed guard compared ("exact" or "printed"; the latency-aware guard's is exact).
Record invasion_sim_record(const InvasionSimResult& result, const std::string& invasion_check,
                           const InvasionSimOptions& options);

/// The fields a --check writes, and with `summary` those of its final record.
std::vector<std::string> position_check_fields(bool summary);

/// Adds the check's answer to the position's record; `elements` are the
/// drawing's (RegionIndex::elements()), to name the nearest one's entity and DXF line.
void add_position_fields(Record& record, const PositionCheck& check, const std::vector<Segment>& elements);

/// The final record of a --check --summary.
Record guard_summary_record(const GuardSummary& summary);

}  // namespace tk::cad
