#include "threads/thread_report.hpp"

#include <fmt/format.h>

#include <cmath>

#include "io/error.hpp"
#include "threads/iso261.hpp"

namespace tk::threads {
namespace {

ThreadMember member(bool external, const std::optional<ToleranceClass>& written, const ThreadDesignation& d) {
  if (written) return {external, *written, true};
  return {
      external,
      external ? default_external_class(d.major_mm, d.engagement) : default_internal_class(d.major_mm, d.engagement),
      false};
}

double rounded(double value, int decimals) {
  const double scale = std::pow(10.0, decimals);
  const double r = std::round(value * scale) / scale;
  return r == 0 ? 0.0 : r;  // no "-0"
}

std::string depth_list(const std::vector<double>& depths, int decimals) {
  std::string out;
  for (double depth : depths) out += fmt::format("{}{:.{}f}", out.empty() ? "" : " ", depth, decimals);
  return out;
}

std::string computed_list(const std::vector<ComputedNote>& notes) {
  std::string out;
  for (const ComputedNote& note : notes) {
    if (!out.empty()) out += ' ';
    out += note.value;
  }
  return out;
}

}  // namespace

std::vector<ThreadMember> members_of(const ThreadDesignation& d, MemberChoice choice) {
  const std::string name = d.canonical();
  switch (choice) {
    case MemberChoice::external:
      if (d.internal && !d.external)
        throw Error(fmt::format("{} is an internal thread's designation, not an external one", name));
      return {member(true, d.external, d)};
    case MemberChoice::internal:
      if (d.external && !d.internal)
        throw Error(fmt::format("{} is an external thread's designation, not an internal one", name));
      return {member(false, d.internal, d)};
    case MemberChoice::both: return {member(true, d.external, d), member(false, d.internal, d)};
    case MemberChoice::from_class: break;
  }
  std::vector<ThreadMember> members;
  const bool neither = !d.external && !d.internal;
  if (d.external || neither) members.push_back(member(true, d.external, d));
  if (d.internal || neither) members.push_back(member(false, d.internal, d));
  return members;
}

PitchSeries pitch_series(double major_mm, double pitch_mm) {
  const std::optional<Iso261Size> size = iso261_size(major_mm);
  if (!size) return PitchSeries::no_iso261_size;
  if (!iso261_has_pitch(major_mm, pitch_mm)) return PitchSeries::non_standard;
  return std::abs(size->coarse_pitch_mm - pitch_mm) < 1e-9 ? PitchSeries::coarse : PitchSeries::fine;
}

const char* series_name(PitchSeries series) {
  switch (series) {
    case PitchSeries::coarse: return "coarse";
    case PitchSeries::fine: return "fine";
    case PitchSeries::non_standard: return "non-standard";
    case PitchSeries::no_iso261_size: break;
  }
  return "no ISO 261 size";
}

ThreadResult evaluate(const ThreadDesignation& designation, const ThreadMember& member,
                      const TurningSettings& settings) {
  ThreadResult r;
  r.designation = designation;
  r.member = member;
  r.profile = basic_profile(designation.major_mm, designation.pitch_mm);
  r.series = pitch_series(designation.major_mm, designation.pitch_mm);
  const std::string name = member_designation(r);
  if (r.series == PitchSeries::non_standard)
    r.warnings.push_back(
        fmt::format("{}: ISO 261 lists no {} mm pitch for M{}", name, designation.pitch_mm, designation.major_mm));
  else if (r.series == PitchSeries::no_iso261_size)
    r.warnings.push_back(fmt::format("{}: ISO 261 lists no {} mm diameter", name, designation.major_mm));
  else if (const char* note = iso261_pitch_note(designation.major_mm, designation.pitch_mm))
    r.warnings.push_back(fmt::format("{}: {}", name, note));
  const std::vector<ComputedNote>* computed = nullptr;
  if (member.external) {
    r.external = external_limits(r.profile, member.tolerance);
    r.plan = plan_external(r.profile, *r.external, settings);
    computed = &r.external->computed;
  } else {
    r.internal = internal_limits(r.profile, member.tolerance);
    r.plan = plan_internal(r.profile, *r.internal, settings);
    computed = &r.internal->computed;
  }
  for (const ComputedNote& note : *computed)
    r.warnings.push_back(
        fmt::format("{}: {} is not in ISO 965-1's tables; computed by {}", name, note.value, note.source));
  if (!r.plan.crest_in_zone)
    r.warnings.push_back(fmt::format("{}: a full-profile insert forms the crest at {:.4f} mm, outside its zone", name,
                                     r.plan.crest_diameter));
  return r;
}

std::string member_designation(const ThreadResult& r) {
  ThreadDesignation own = r.designation;
  own.internal.reset();
  own.external.reset();
  (r.member.external ? own.external : own.internal) = r.member.tolerance;
  return own.canonical();
}

std::vector<std::string> report_fields() {
  return {"thread",      "kind",        "class",  "d",       "P",           "pitch_series",  "hand",
          "H",           "d2",          "d1",     "d3",      "root_radius", "flat_major",    "flat_minor",
          "es",          "Td",          "Td2",    "d_max",   "d_min",       "d2_max",        "d2_min",
          "d3_max",      "d_mid",       "d2_mid", "R_min",   "EI",          "TD1",           "TD2",
          "D_min",       "D1_min",      "D1_max", "D2_min",  "D2_max",      "D1_mid",        "D2_mid",
          "ap",          "blank",       "crest",  "chamfer", "run_out",     "retract_angle", "passes",
          "passes_from", "pass_depths", "infeed", "computed"};
}

void add_fields(Record& record, const ThreadResult& r, int decimals) {
  const auto mm = [decimals](double value) { return rounded(value, decimals); };
  const BasicProfile& p = r.profile;
  record["thread"] = member_designation(r);
  record["kind"] = r.member.external ? "external" : "internal";
  record["class"] = r.member.tolerance.text();
  record["d"] = p.major;
  record["P"] = p.pitch;
  record["pitch_series"] = series_name(r.series);
  record["hand"] = r.designation.left_hand ? "left" : "right";
  record["H"] = mm(p.height);
  record["d2"] = mm(p.pitch_diameter);
  record["d1"] = mm(p.minor);
  record["d3"] = mm(p.root_minor);
  record["root_radius"] = mm(p.root_radius);
  record["flat_major"] = mm(p.crest_flat);
  record["flat_minor"] = mm(p.root_flat);
  if (r.external) {
    const ExternalLimits& l = *r.external;
    record["es"] = mm(l.es);
    record["Td"] = mm(l.Td);
    record["Td2"] = mm(l.Td2);
    record["d_max"] = mm(l.d_max);
    record["d_min"] = mm(l.d_min);
    record["d2_max"] = mm(l.d2_max);
    record["d2_min"] = mm(l.d2_min);
    record["d3_max"] = mm(l.d3_max);
    record["d_mid"] = mm(l.d_mid());
    record["d2_mid"] = mm(l.d2_mid());
    record["R_min"] = mm(l.root_radius_min);
  } else {
    const InternalLimits& l = *r.internal;
    record["EI"] = mm(l.EI);
    record["TD1"] = mm(l.TD1);
    record["TD2"] = mm(l.TD2);
    record["D_min"] = mm(l.D_min);
    record["D1_min"] = mm(l.D1_min);
    record["D1_max"] = mm(l.D1_max);
    record["D2_min"] = mm(l.D2_min);
    record["D2_max"] = mm(l.D2_max);
    record["D1_mid"] = mm(l.D1_mid());
    record["D2_mid"] = mm(l.D2_mid());
  }
  const TurningPlan& plan = r.plan;
  record["ap"] = mm(plan.ap);
  record["blank"] = mm(plan.blank_diameter);
  record["crest"] = mm(plan.crest_diameter);
  record["chamfer"] = mm(plan.chamfer);
  record["run_out"] = mm(plan.run_out);
  record["retract_angle"] = rounded(plan.retract_angle_deg, decimals);  // degrees
  record["passes"] = plan.passes;
  record["passes_from"] = plan.passes_source;
  record["pass_depths"] = depth_list(plan.depths, decimals);
  record["infeed"] = plan.infeed == Infeed::flank ? fmt::format("flank {}", plan.infeed_angle_deg) : "radial";
  record["computed"] = computed_list(r.external ? r.external->computed : r.internal->computed);
}

}  // namespace tk::threads
