/// @file fuzz_thread_designation.cpp
/// @brief libFuzzer target: bytes as one thread designation for threadcalc.
///
/// parse_designation, then for every member (external and internal) the
/// limits, the turning plan, the record fields and both threading programs.
/// tk::Error is the expected rejection; any other exception, crash,
/// sanitizer report or hang is a bug.
///
/// Oracles (switch off by name with TK_FUZZ_SKIP=a,b while a finding is open):
///   canonical  the canonical spelling parses back to the same thread
///   limits     every limit is finite and the zones are ordered
///              (d2 min < d2 max < d min < d max, D1 max < D2 min ...)
///   plan       the passes deepen strictly to ap > 0; the blank and the
///              root lie on the right sides of the peak
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "fuzz_common.hpp"
#include "io/error.hpp"
#include "threads/designation.hpp"
#include "threads/thread_gcode.hpp"
#include "threads/thread_report.hpp"

namespace {

using namespace tk::threads;

std::string show(std::string_view text) { return "'" + std::string(text.substr(0, 200)) + "'"; }

void check_canonical(const ThreadDesignation& d, std::string_view text) {
  if (!tk::fuzz::oracle_enabled("canonical")) return;
  const std::string canonical = d.canonical();
  ThreadDesignation again;
  try {
    again = parse_designation(canonical);
  } catch (const tk::Error& e) {
    tk::fuzz::invariant_failed("canonical", canonical + " of " + show(text) + " does not parse: " + e.what());
  }
  const bool same = again.major_mm == d.major_mm && again.pitch_mm == d.pitch_mm && again.left_hand == d.left_hand &&
                    again.engagement == d.engagement && again.external.has_value() == d.external.has_value() &&
                    again.internal.has_value() == d.internal.has_value() &&
                    (!d.external || again.external->text() == d.external->text()) &&
                    (!d.internal || again.internal->text() == d.internal->text());
  if (!same) tk::fuzz::invariant_failed("canonical", canonical + " of " + show(text) + " reads back differently");
}

void check_result(const ThreadResult& r, std::string_view text) {
  const auto fail = [&](const char* oracle, const std::string& what) {
    tk::fuzz::invariant_failed(oracle, show(text) + ": " + what);
  };
  if (tk::fuzz::oracle_enabled("limits")) {
    if (r.external) {
      const ExternalLimits& l = *r.external;
      for (double v : {l.d_max, l.d_min, l.d2_max, l.d2_min, l.d3_max})
        if (!std::isfinite(v)) fail("limits", "a non-finite external limit");
      if (!(l.d3_max < l.d2_min && l.d2_min < l.d2_max && l.d2_max < l.d_min && l.d_min < l.d_max && l.es <= 0))
        fail("limits", "external zones out of order");
    } else {
      const InternalLimits& l = *r.internal;
      for (double v : {l.D_min, l.D1_min, l.D1_max, l.D2_min, l.D2_max})
        if (!std::isfinite(v)) fail("limits", "a non-finite internal limit");
      if (!(l.D1_min < l.D1_max && l.D1_max < l.D2_min && l.D2_min < l.D2_max && l.D2_max < l.D_min && l.EI >= 0))
        fail("limits", "internal zones out of order");
    }
  }
  if (tk::fuzz::oracle_enabled("plan")) {
    const TurningPlan& p = r.plan;
    if (!(p.ap > 0) || p.passes < 2 || p.depths.size() != static_cast<std::size_t>(p.passes) || p.depths.back() != p.ap)
      fail("plan", "passes do not end at ap");
    for (std::size_t i = 1; i < p.depths.size(); ++i)
      if (!(p.depths[i] > p.depths[i - 1])) fail("plan", "a pass no deeper than the one before");
    const bool sides = p.external ? p.root_diameter < p.peak_diameter && p.blank_diameter > p.root_diameter
                                  : p.root_diameter > p.peak_diameter && p.blank_diameter < p.root_diameter;
    if (!sides) fail("plan", "root or blank on the wrong side of the peak");
  }
}

void run(std::string_view text) {
  ThreadDesignation designation;
  try {
    designation = parse_designation(text);
  } catch (const tk::Error&) {
    return;
  }
  check_canonical(designation, text);
  for (const ThreadMember& member : members_of(designation, MemberChoice::both)) {
    ThreadResult result;
    try {
      result = evaluate(designation, member, {});
    } catch (const tk::Error&) {
      continue;
    }
    check_result(result, text);
    tk::Record record;
    add_fields(record, result, 4);
    (void)record.dump();
    ProgramSettings settings;
    settings.pitch_mm = result.profile.pitch;
    settings.length_mm = 10;
    settings.rpm = 500;
    settings.left_hand = designation.left_hand;
    for (ProgramStyle style : {ProgramStyle::g76, ProgramStyle::passes}) {
      try {
        (void)thread_program(style, result.plan, settings);
      } catch (const tk::Error&) {
      }
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  run(std::string_view(reinterpret_cast<const char*>(data), size));
  return 0;
}
