/// @file turning_profile.hpp
/// @brief Reading an allowance profile (depth of cut along the part) from
/// records, for fuzzyfeed --simulate --profile.
#pragma once

#include <string>
#include <vector>

#include "machining/turning_sim.hpp"

namespace tk::machining {

/// Reads a profile from a record file (JSON Lines or CSV, "-" for stdin)
/// in one of two shapes, decided by the first record:
///  - segments: `z_from`, `z_to`, `depth` (mm) per record, each starting
///    where the one before ends;
///  - positions: `z`, `depth` per record: the depth holds from this z to the
///    next record's; the last record only ends the cut (its depth, if any,
///    is not used).
/// Errors name the file and line.
std::vector<AllowanceSegment> read_profile(const std::string& path);

}  // namespace tk::machining
