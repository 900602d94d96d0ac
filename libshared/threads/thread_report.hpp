/// @file thread_report.hpp
/// @brief One thread member (external or internal) from designation to
/// limits and turning data, and its fields in a threadcalc record.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "io/record.hpp"
#include "threads/designation.hpp"
#include "threads/thread_limits.hpp"
#include "threads/thread_turning.hpp"

namespace tk::threads {

/// Which members a designation gives: as its class says (lower-case
/// external, upper-case internal, both for a fit or when no class is
/// written), or only one kind (the medium class when the designation has
/// none of that kind).
enum class MemberChoice { from_class, external, internal, both };

struct ThreadMember {
  bool external = true;
  ToleranceClass tolerance;
  bool class_given = false;  ///< false: ISO 965-1's medium class was taken
};

/// Throws tk::Error when the kind asked for contradicts the class written
/// (--kind internal for "M10-6g").
std::vector<ThreadMember> members_of(const ThreadDesignation& designation, MemberChoice choice);

/// Where the pitch stands in ISO 261 for the diameter: non_standard is a
/// pitch ISO 261 does not list for it, no_iso261_size a diameter it does
/// not list.
enum class PitchSeries { coarse, fine, non_standard, no_iso261_size };

PitchSeries pitch_series(double major_mm, double pitch_mm);
/// "coarse", "fine", "non-standard", "no ISO 261 size": the output's words.
const char* series_name(PitchSeries series);

struct ThreadResult {
  ThreadDesignation designation;
  ThreadMember member;
  BasicProfile profile;
  std::optional<ExternalLimits> external;
  std::optional<InternalLimits> internal;
  TurningPlan plan;
  PitchSeries series = PitchSeries::coarse;
  std::vector<std::string> warnings;  ///< a non-standard pitch, values from formulas, a crest outside its zone
};

/// Limits and turning data; tk::Error (no location) for a class the
/// standard does not have at this size or inconsistent zones.
ThreadResult evaluate(const ThreadDesignation& designation, const ThreadMember& member,
                      const TurningSettings& settings);

/// The member's own designation: "M30x2-6g", "M20x1.5-6H-LH".
std::string member_designation(const ThreadResult& result);

/// Every field add_fields may write, in output order (for CSV's header).
std::vector<std::string> report_fields();

/// Writes the result's fields into `record` (after the fields it has), mm
/// rounded to `decimals` places; fields of the other kind are left out.
void add_fields(Record& record, const ThreadResult& result, int decimals);

}  // namespace tk::threads
