#include "threads/thread_turning.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "io/error.hpp"

namespace tk::threads {
namespace {

struct PassRow {
  double max_pitch_mm;
  int passes;
};

// Widia catalogue 2017, p. 685, "common V-thread forms ISO, UN...": pitch
// ranges 0.50-0.75, 0.80-1, 1.25-1.5, 1.75-2, 2.5-3, 3.5-4, 4.5-6, 8 mm with
// 4-5, 5-6, 6-8, 8-10, 9-12, 12-15, 14-16, 15-25 passes; the lower ends. A
// pitch between two rows takes the coarser row.
constexpr std::array<PassRow, 8> widia_passes{
    {{0.75, 4}, {1.0, 5}, {1.5, 6}, {2.0, 8}, {3.0, 9}, {4.0, 12}, {6.0, 14}, {8.0, 15}}};

void finish_plan(TurningPlan& plan, const TurningSettings& settings, double pitch) {
  plan.root_diameter = plan.peak_diameter + (plan.external ? -2 : 2) * plan.ap;
  plan.chamfer =
      plan.ap + (std::isnan(settings.chamfer_margin_mm) ? std::min(0.25, pitch / 2) : settings.chamfer_margin_mm);
  plan.run_out = std::isnan(settings.run_out_mm) ? 1.25 * pitch : settings.run_out_mm;
  plan.retract_angle_deg = std::atan2(plan.run_out, plan.ap) * 180 / std::numbers::pi;
  if (settings.passes > 0) {
    plan.passes = settings.passes;
    plan.passes_source = "given";
  } else {
    plan.passes = recommended_passes(pitch);
    plan.passes_source = "Widia 2017";
    // The last pass of the degressive schedule is the thinnest; below the
    // makers' minimum it rubs instead of cutting, so fewer, thicker passes.
    while (plan.passes > 2) {
      const std::vector<double> depths = degressive_depths(plan.ap, plan.passes);
      if (depths.back() - depths[depths.size() - 2] >= settings.min_last_pass_mm) break;
      --plan.passes;
      plan.passes_source = "Widia 2017, fewer for the last pass's minimum";
    }
  }
  plan.depths = degressive_depths(plan.ap, plan.passes);
  plan.infeed = settings.infeed;
  plan.infeed_angle_deg = settings.infeed == Infeed::flank ? settings.flank_angle_deg : 0;
  plan.spring_passes = settings.spring_passes;
}

double topping_stock(const TurningSettings& settings, double pitch) {
  if (!std::isnan(settings.topping_stock_mm)) return settings.topping_stock_mm;
  return 0.15 * std::min(1.0, pitch);
}

}  // namespace

void validate(const TurningSettings& s) {
  require(s.passes == 0 || (s.passes >= 2 && s.passes <= 100), fmt::format("passes {} is outside 2-100", s.passes));
  require(std::isfinite(s.min_last_pass_mm) && s.min_last_pass_mm >= 0,
          fmt::format("the last pass's minimum {} mm is negative or not finite", s.min_last_pass_mm));
  require(s.spring_passes >= 0 && s.spring_passes <= 10,
          fmt::format("spring passes {} is outside 0-10", s.spring_passes));
  require(std::isfinite(s.flank_angle_deg) && s.flank_angle_deg >= 0 && s.flank_angle_deg <= 30,
          fmt::format("the flank infeed angle {} is outside 0-30 degrees", s.flank_angle_deg));
  require(std::isnan(s.topping_stock_mm) || (s.topping_stock_mm >= 0 && s.topping_stock_mm <= 5),
          fmt::format("the topping stock {} mm is outside 0-5 mm", s.topping_stock_mm));
  require(std::isnan(s.chamfer_margin_mm) || (s.chamfer_margin_mm >= 0 && s.chamfer_margin_mm <= 10),
          fmt::format("the chamfer margin {} mm is outside 0-10 mm", s.chamfer_margin_mm));
  require(std::isnan(s.run_out_mm) || (s.run_out_mm >= 0 && s.run_out_mm <= 100),
          fmt::format("the run-out {} mm is outside 0-100 mm", s.run_out_mm));
}

int recommended_passes(double pitch_mm) {
  for (const PassRow& row : widia_passes)
    if (pitch_mm <= row.max_pitch_mm + 1e-9) return row.passes;
  // Coarser than Widia's table: keep its last row's chip area per pass, so
  // the passes grow with the depth (∝ P) squared; at most 100.
  const PassRow& last = widia_passes.back();
  const double passes = std::ceil(1 + (last.passes - 1) * std::pow(pitch_mm / last.max_pitch_mm, 2));
  return static_cast<int>(std::min(passes, 100.0));
}

std::vector<double> degressive_depths(double ap, int passes) {
  require(passes >= 2, "the degressive infeed needs at least 2 passes");
  std::vector<double> depths(static_cast<std::size_t>(passes));
  for (int x = 1; x <= passes; ++x) {
    const double phi = x == 1 ? 0.3 : x - 1;
    depths[static_cast<std::size_t>(x - 1)] = ap * std::sqrt(phi / (passes - 1));
  }
  depths.back() = ap;  // exactly, not to rounding
  return depths;
}

TurningPlan plan_external(const BasicProfile& p, const ExternalLimits& l, const TurningSettings& settings) {
  validate(settings);
  TurningPlan plan;
  plan.external = true;
  plan.peak_diameter = p.major;
  plan.target_pitch_diameter = l.d2_mid();
  plan.ap = p.external_depth + (p.pitch_diameter - plan.target_pitch_diameter) / 2;
  // A full-profile insert forms the crest at 3H/4 over the pitch diameter.
  plan.crest_diameter = plan.target_pitch_diameter + 0.75 * p.height;
  plan.crest_in_zone = plan.crest_diameter <= l.d_max + 1e-9 && plan.crest_diameter >= l.d_min - 1e-9;
  plan.blank_diameter = plan.crest_diameter + topping_stock(settings, p.pitch);
  finish_plan(plan, settings, p.pitch);
  return plan;
}

TurningPlan plan_internal(const BasicProfile& p, const InternalLimits& l, const TurningSettings& settings) {
  validate(settings);
  TurningPlan plan;
  plan.external = false;
  plan.peak_diameter = p.minor;
  plan.target_pitch_diameter = l.D2_mid();
  plan.ap = p.internal_depth + (plan.target_pitch_diameter - p.pitch_diameter) / 2;
  // A full-profile internal insert forms the minor diameter H/2 under D2.
  plan.crest_diameter = plan.target_pitch_diameter - 0.5 * p.height;
  plan.crest_in_zone = plan.crest_diameter >= l.D1_min - 1e-9 && plan.crest_diameter <= l.D1_max + 1e-9;
  plan.blank_diameter = plan.crest_diameter - topping_stock(settings, p.pitch);
  require(plan.blank_diameter > 0,
          fmt::format("M{}x{}: the bore before threading would be {:.4f} mm", p.major, p.pitch, plan.blank_diameter));
  finish_plan(plan, settings, p.pitch);
  return plan;
}

}  // namespace tk::threads
