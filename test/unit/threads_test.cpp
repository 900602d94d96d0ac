// Designations, ISO 68-1 profiles, limits of size, turning data and the
// threading programs. Expected values come from ISO 965-2's published
// limits (quoted in the issue), ISO 68-1's formulas worked by hand, and
// LinuxCNC's documented G76 pass rule, not from the code's own output.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <regex>
#include <sstream>

#include "io/error.hpp"
#include "motion/gcode.hpp"
#include "threads/designation.hpp"
#include "threads/thread_gcode.hpp"
#include "threads/thread_limits.hpp"
#include "threads/thread_report.hpp"
#include "threads/thread_turning.hpp"

using namespace tk::threads;

TEST(ThreadDesignation, ReadsTheSpellingsUsersWrite) {
  const ThreadDesignation a = parse_designation("M30x2-6g");
  EXPECT_EQ(a.major_mm, 30);
  EXPECT_EQ(a.pitch_mm, 2);
  ASSERT_TRUE(a.external);
  EXPECT_EQ(a.external->pitch, (ToleranceZone{6, 'g'}));
  EXPECT_EQ(a.external->crest, (ToleranceZone{6, 'g'}));
  EXPECT_FALSE(a.internal);

  const ThreadDesignation coarse = parse_designation("M10");  // ISO 261: M10 coarse 1.5
  EXPECT_EQ(coarse.pitch_mm, 1.5);
  EXPECT_FALSE(coarse.external || coarse.internal);

  const ThreadDesignation split = parse_designation("M30x2-5g6g");
  EXPECT_EQ(split.external->pitch, (ToleranceZone{5, 'g'}));
  EXPECT_EQ(split.external->crest, (ToleranceZone{6, 'g'}));
  EXPECT_EQ(split.external->text(), "5g6g");

  const ThreadDesignation fit = parse_designation("M10x1.5-6H/6g");
  ASSERT_TRUE(fit.internal && fit.external);
  EXPECT_EQ(fit.internal->text(), "6H");
  EXPECT_EQ(fit.external->text(), "6g");
  EXPECT_EQ(fit.canonical(), "M10x1.5-6H/6g");

  const ThreadDesignation spaced = parse_designation(" M 16 \xC3\x97 1,5 - 6H - L - LH ");
  EXPECT_EQ(spaced.major_mm, 16);
  EXPECT_EQ(spaced.pitch_mm, 1.5);
  EXPECT_TRUE(spaced.left_hand);
  EXPECT_EQ(spaced.engagement, Engagement::long_l);
  EXPECT_EQ(spaced.canonical(), "M16x1.5-6H-L-LH");

  EXPECT_TRUE(parse_designation("M20x2LH").left_hand);
  // A space separates parts as '-' does; dashes and the minus sign are '-'.
  EXPECT_EQ(parse_designation("M8x1.25 6g").canonical(), "M8x1.25-6g");
  EXPECT_EQ(parse_designation("M20x1.5-6g LH").canonical(), "M20x1.5-6g-LH");
  EXPECT_EQ(parse_designation("M20x1.5\xE2\x80\x93"
                              "6g")
                .canonical(),
            "M20x1.5-6g");  // en dash
  EXPECT_EQ(parse_designation("M20x1.5\xE2\x88\x92"
                              "6H")
                .canonical(),
            "M20x1.5-6H");  // minus sign
  EXPECT_EQ(parse_designation("M20\xC2\xA0"
                              "x\xC2\xA0"
                              "1.5")
                .canonical(),
            "M20x1.5");  // no-break spaces
  EXPECT_EQ(parse_designation("M20x1.5-6gLH").canonical(), "M20x1.5-6g-LH");
  EXPECT_EQ(parse_designation("M20x1.5-6H-l").engagement, Engagement::long_l);
  EXPECT_EQ(parse_designation("m1,6").pitch_mm, 0.35);  // ISO 261: M1.6 coarse 0.35
  EXPECT_EQ(parse_designation("M8*1").pitch_mm, 1);
}

TEST(ThreadDesignation, RefusesWhatIsNotADesignation) {
  for (const char* bad : {"M0",
                          "Mx2",
                          "M30x0",
                          "M30x2-6q",
                          "",
                          "30x2",
                          "M30x2-",
                          "M30x2-6g-6g",
                          "M30x2-6H/6H",
                          "M30x2-2g",
                          "M30x2-6g5h",
                          "M16xPh3P1.5",
                          "M30x2-6g-LH-LH",
                          "M30x2-S-L",
                          "M30x2 6g 6g",
                          "M30x2-6gLH-LH",
                          "M1e3",
                          "M30x2-6gg",
                          "M30x2-66",
                          "M-30",
                          "M30x2-6g\x01",
                          "M31"})
    EXPECT_THROW(parse_designation(bad), tk::Error) << bad;
}

TEST(ThreadProfile, FollowsIso68) {
  const BasicProfile p = basic_profile(30, 2);
  EXPECT_NEAR(p.height, 0.866025 * 2, 1e-6);
  EXPECT_NEAR(p.pitch_diameter, 30 - 0.649519 * 2, 1e-6);
  EXPECT_NEAR(p.minor, 30 - 1.082532 * 2, 1e-6);
  EXPECT_NEAR(p.root_minor, 30 - 1.226869 * 2, 1e-6);
  EXPECT_NEAR(p.external_depth, 0.613435 * 2, 1e-6);
  EXPECT_NEAR(p.internal_depth, 0.541266 * 2, 1e-6);
  EXPECT_NEAR(p.root_radius, 0.144338 * 2, 1e-6);
  EXPECT_THROW(basic_profile(1, 0.9), tk::Error);  // d3 below zero
}

struct PublishedExternal {
  const char* designation;
  double d_max, d_min, d2_max, d2_min;
};

// ISO 965-2 limits of size, as quoted in the issue.
TEST(ThreadLimits, ExternalMatchIso965Part2) {
  for (const PublishedExternal& row : {PublishedExternal{"M6x1-6g", 5.974, 5.794, 5.324, 5.212},
                                       PublishedExternal{"M10x1.5-6g", 9.968, 9.732, 8.994, 8.862},
                                       PublishedExternal{"M30x2-6g", 29.962, 29.682, 28.663, 28.493}}) {
    const ThreadDesignation d = parse_designation(row.designation);
    const ExternalLimits l = external_limits(basic_profile(d.major_mm, d.pitch_mm), *d.external);
    EXPECT_NEAR(l.d_max, row.d_max, 5e-4) << row.designation;
    EXPECT_NEAR(l.d_min, row.d_min, 5e-4) << row.designation;
    EXPECT_NEAR(l.d2_max, row.d2_max, 5e-4) << row.designation;
    EXPECT_NEAR(l.d2_min, row.d2_min, 5e-4) << row.designation;
    EXPECT_TRUE(l.computed.empty());
  }
}

TEST(ThreadLimits, InternalMatchIso965Part2) {
  const ThreadDesignation d = parse_designation("M30x2-6H");
  const InternalLimits l = internal_limits(basic_profile(30, 2), *d.internal);
  EXPECT_NEAR(l.D2_min, 28.701, 5e-4);
  EXPECT_NEAR(l.D2_max, 28.925, 5e-4);
  EXPECT_NEAR(l.D1_min, 27.835, 5e-4);
  EXPECT_NEAR(l.D1_max, 28.210, 5e-4);
  EXPECT_EQ(l.D_min, 30);
}

TEST(ThreadLimits, RefusesGradesTheDiameterDoesNotHave) {
  const BasicProfile p = basic_profile(30, 2);
  EXPECT_THROW(external_limits(p, parse_designation("M30x2-3g").external.value()), tk::Error);  // d: 4, 6, 8
  EXPECT_NO_THROW(external_limits(p, parse_designation("M30x2-3g6g").external.value()));        // d2 has 3
  EXPECT_THROW(external_limits(p, parse_designation("M30x2-5g").external.value()), tk::Error);
  EXPECT_THROW(internal_limits(p, parse_designation("M30x2-9H").internal.value()), tk::Error);  // D2: 4-8
  // e is not defined below P 0.5 mm.
  EXPECT_THROW(external_limits(basic_profile(2, 0.4), parse_designation("M2x0.4-6e").external.value()), tk::Error);
}

TEST(ThreadLimits, DefaultClassIsIsoMediumQuality) {
  EXPECT_EQ(default_external_class(10).text(), "6g");
  EXPECT_EQ(default_internal_class(10).text(), "6H");
  EXPECT_EQ(default_external_class(10, Engagement::short_s).text(), "5g6g");
  EXPECT_EQ(default_internal_class(10, Engagement::short_s).text(), "5H");
  EXPECT_EQ(default_external_class(10, Engagement::long_l).text(), "7g6g");
  EXPECT_EQ(default_internal_class(10, Engagement::long_l).text(), "7H");
  EXPECT_EQ(members_of(parse_designation("M10-L"), MemberChoice::from_class).front().tolerance.text(), "7g6g");
  EXPECT_EQ(default_external_class(1.4).text(), "6h");
  EXPECT_EQ(default_internal_class(1.2).text(), "5H");
}

TEST(ThreadTurning, DegressiveDepthsAreSandviksFormula) {
  const std::vector<double> depths = degressive_depths(1.2883, 8);
  ASSERT_EQ(depths.size(), 8u);
  EXPECT_NEAR(depths[0], 1.2883 * std::sqrt(0.3 / 7), 1e-12);
  for (int x = 2; x <= 8; ++x) EXPECT_NEAR(depths[x - 1], 1.2883 * std::sqrt((x - 1) / 7.0), 1e-12);
  EXPECT_EQ(depths.back(), 1.2883);
  for (std::size_t i = 1; i < depths.size(); ++i) {
    EXPECT_GT(depths[i], depths[i - 1]);
    if (i >= 2) {
      EXPECT_LT(depths[i] - depths[i - 1], depths[i - 1] - depths[i - 2]);  // decreasing infeed
    }
  }
  EXPECT_THROW(degressive_depths(1, 1), tk::Error);
}

TEST(ThreadTurning, WidiaPassesByPitch) {
  EXPECT_EQ(recommended_passes(0.5), 4);
  EXPECT_EQ(recommended_passes(0.75), 4);
  EXPECT_EQ(recommended_passes(1), 5);
  EXPECT_EQ(recommended_passes(1.25), 6);
  EXPECT_EQ(recommended_passes(2), 8);
  EXPECT_EQ(recommended_passes(3), 9);
  EXPECT_EQ(recommended_passes(4), 12);
  EXPECT_EQ(recommended_passes(6), 14);
  EXPECT_EQ(recommended_passes(8), 15);
  EXPECT_GT(recommended_passes(12), 15);
}

// The paper's screen (Karker et al., Fig. 5) for M30x2-6g: Td2 0.1700, es
// 0.0380, ap 1.2883, chamfer 1.5383 x 45°, Prog d 30.0270, passes 8, Retract
// 62.7370°. Its ap takes h3 as 0.6134 P (rounded); ISO 68-1's 17H/24 =
// 0.613435 P puts ours 0.07 µm deeper.
TEST(ThreadTurning, ReproducesThePapersM30x2) {
  const BasicProfile p = basic_profile(30, 2);
  const ExternalLimits l = external_limits(p, parse_designation("M30x2-6g").external.value());
  EXPECT_NEAR(l.Td2, 0.170, 1e-12);
  EXPECT_NEAR(l.es, -0.038, 1e-12);
  const TurningPlan plan = plan_external(p, l, {});
  EXPECT_NEAR(plan.ap, 0.6134 * 2 + 0.038 / 2 + 0.170 / 4, 1e-4);
  EXPECT_NEAR(plan.ap, 1.2883, 1e-4);
  EXPECT_NEAR(plan.chamfer, 1.5383, 1e-4);
  EXPECT_EQ(plan.passes, 8);
  // By hand: d2 aimed at the middle of ISO 965-2's 28.493-28.663, 28.578; the
  // root 2 ap = 2.57674 under d, 27.42326; the crest 3H/4 = 1.29904 over d2,
  // 29.877 (= d + es − Td2/2), inside d's 29.682-29.962; the blank 0.15 over
  // that, the paper's Prog d 30.0270, over the nominal 30 as its text says.
  EXPECT_NEAR(plan.target_pitch_diameter, 28.578, 5e-4);
  EXPECT_NEAR(plan.root_diameter, 27.42326, 1e-4);
  EXPECT_NEAR(plan.crest_diameter, 30 - 0.038 - 0.170 / 2, 1e-9);
  EXPECT_TRUE(plan.crest_in_zone);
  EXPECT_NEAR(plan.blank_diameter, 30.0270, 5e-5);
  EXPECT_GT(plan.blank_diameter, 30);
  // Retract: the pull-out rises ap over 2.5 mm (1.25 P) along Z, its angle
  // from the radial atan(2.5/ap): the paper's ap 1.2883 gives 62.7370°
  // (tan 1.94054), ours 1.288369 gives 62.7358°.
  EXPECT_NEAR(plan.run_out, 2.5, 1e-12);
  EXPECT_NEAR(std::atan(2.5 / 1.2883) * 180 / std::numbers::pi, 62.7370, 5e-5);
  EXPECT_NEAR(plan.retract_angle_deg, 62.7358, 5e-5);
}

// The retract angle follows the run-out: 0 is a radial pull-out, a run-out
// equal to ap is 45 degrees.
TEST(ThreadTurning, RetractAngleFromTheRunOut) {
  const BasicProfile p = basic_profile(10, 1.5);
  const ExternalLimits l = external_limits(p, default_external_class(10));
  EXPECT_NEAR(plan_external(p, l, {}).run_out, 1.875, 1e-12);
  TurningSettings radial;
  radial.run_out_mm = 0;
  EXPECT_EQ(plan_external(p, l, radial).retract_angle_deg, 0);
  TurningSettings diagonal;
  diagonal.run_out_mm = plan_external(p, l, {}).ap;
  EXPECT_NEAR(plan_external(p, l, diagonal).retract_angle_deg, 45, 1e-9);
  TurningSettings bad;
  bad.run_out_mm = -1;
  EXPECT_THROW(plan_external(p, l, bad), tk::Error);
}

TEST(ThreadTurning, InternalRootPutsD2MidZone) {
  const BasicProfile p = basic_profile(30, 2);
  const InternalLimits l = internal_limits(p, parse_designation("M30x2-6H").internal.value());
  const TurningPlan plan = plan_internal(p, l, {});
  // By hand: D2 aimed at the middle of ISO 965-2's 28.701-28.925, 28.813;
  // ap = H1 + (28.813 − 28.70096)/2 = 1.08253 + 0.05602 = 1.13855 from D1
  // 27.83494; the insert's crest H/2 = 0.86603 under D2, 27.94697, inside
  // D1's 27.835-28.210; the bore 0.15 under that.
  EXPECT_NEAR(plan.target_pitch_diameter, 28.813, 5e-4);
  EXPECT_NEAR(plan.ap, 1.13855, 1e-4);
  EXPECT_NEAR(plan.crest_diameter, 27.94697, 1e-4);
  EXPECT_TRUE(plan.crest_in_zone);
  EXPECT_NEAR(plan.blank_diameter, 27.79697, 1e-4);
}

// M1.6 (P 0.35): Widia's 4 passes would end with a last pass under
// 0.05 mm; the plan takes the most passes whose last one is at least that.
TEST(ThreadTurning, FewerPassesWhenTheLastWouldRub) {
  const BasicProfile p = basic_profile(1.6, 0.35);
  const ExternalLimits l = external_limits(p, default_external_class(1.6));
  const TurningPlan plan = plan_external(p, l, {});
  const auto last_pass = [&](int n) {
    const double a = plan.ap;
    return a * (std::sqrt((n - 1.0) / (n - 1)) - std::sqrt((n - 2.0) / (n - 1)));
  };
  ASSERT_LT(plan.passes, recommended_passes(0.35));
  EXPECT_GE(last_pass(plan.passes), 0.05);
  EXPECT_LT(last_pass(plan.passes + 1), 0.05);
  TurningSettings fixed;
  fixed.passes = 6;
  EXPECT_EQ(plan_external(p, l, fixed).passes, 6);
  TurningSettings bad;
  bad.flank_angle_deg = 31;
  EXPECT_THROW(plan_external(p, l, bad), tk::Error);
}

TEST(ThreadTurning, TopsOffStockScaledWithFinePitches) {
  const BasicProfile p = basic_profile(1, 0.25);
  const TurningPlan plan = plan_external(p, external_limits(p, default_external_class(1)), {});
  EXPECT_NEAR(plan.blank_diameter - plan.crest_diameter, 0.0375, 1e-12);  // 0.15 P
  const BasicProfile m30 = basic_profile(30, 2);
  const TurningPlan coarse = plan_external(m30, external_limits(m30, default_external_class(30)), {});
  EXPECT_NEAR(coarse.blank_diameter - coarse.crest_diameter, 0.15, 1e-12);
}

namespace {

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

double word(const std::string& line, char letter) {
  const std::regex pattern(std::string("(^| )") + letter + "(-?[0-9.]+)");
  std::smatch m;
  if (!std::regex_search(line, m, pattern)) return NAN;
  return std::stod(m[2]);
}

TurningPlan m30_plan(const TurningSettings& settings = {}) {
  const BasicProfile p = basic_profile(30, 2);
  return plan_external(p, external_limits(p, parse_designation("M30x2-6g").external.value()), settings);
}

ProgramSettings m30_program() {
  ProgramSettings s;
  s.title = "M30x2-6g";
  s.pitch_mm = 2;
  s.length_mm = 40;
  s.rpm = 500;
  return s;
}

}  // namespace

// LinuxCNC's G76 cuts pass n at J·n^(1/R) beyond the peak while that is
// under K, then at K: with R2 and J = K/√n, n passes in all.
TEST(ThreadProgram, G76MakesThePlansPassCount) {
  const TurningPlan plan = m30_plan();
  const std::string program = thread_program(ProgramStyle::g76, plan, m30_program());
  std::string g76;
  for (const std::string& line : lines_of(program))
    if (line.rfind("G76", 0) == 0) g76 = line;
  ASSERT_FALSE(g76.empty()) << program;
  const double j = word(g76, 'J'), k = word(g76, 'K'), r = word(g76, 'R');
  EXPECT_NEAR(k, 2 * plan.ap, 1e-4);  // G7: diameters
  EXPECT_EQ(word(g76, 'P'), 2);
  EXPECT_EQ(word(g76, 'Z'), -40);
  EXPECT_EQ(word(g76, 'H'), 1);
  int passes = 0;
  for (int n = 1; j * std::pow(n, 1 / r) < k; ++n) ++passes;
  EXPECT_EQ(passes + 1, plan.passes);
  // I: from the drive line (the X of the G0 before) to the peak, negative outside.
  double drive_x = NAN;
  for (const std::string& line : lines_of(program))
    if (line.rfind("G0 X", 0) == 0) drive_x = word(line, 'X');
  EXPECT_NEAR(drive_x + word(g76, 'I'), 30, 1e-4);
  EXPECT_LT(word(g76, 'I'), 0);
}

TEST(ThreadProgram, PassesCutEachDepthThenSpringPasses) {
  TurningSettings flank;
  flank.infeed = Infeed::flank;
  flank.flank_angle_deg = 27;
  const TurningPlan plan = m30_plan(flank);
  const std::string program = thread_program(ProgramStyle::passes, plan, m30_program());
  std::vector<double> cut_x, start_z, end_z;
  double last_x = NAN, last_z = NAN;
  for (const std::string& line : lines_of(program)) {
    if (line.rfind("G0", 0) == 0) {
      if (!std::isnan(word(line, 'X'))) last_x = word(line, 'X');
      if (!std::isnan(word(line, 'Z'))) last_z = word(line, 'Z');
    }
    if (line.rfind("G33", 0) == 0) {
      EXPECT_EQ(word(line, 'K'), 2);
      cut_x.push_back(last_x);
      start_z.push_back(last_z);
      end_z.push_back(word(line, 'Z'));
    }
  }
  ASSERT_EQ(cut_x.size(), plan.depths.size() + 1u);  // + one spring pass
  for (std::size_t i = 0; i < plan.depths.size(); ++i) {
    EXPECT_NEAR(cut_x[i], 30 - 2 * plan.depths[i], 1e-4);
    // Start and end slide along the cut by depth · tan 27° so one flank stays
    // put; the full-depth pass ends at the thread's end, Z-40.
    const double shift = (plan.ap - plan.depths[i]) * std::tan(27 * M_PI / 180);
    EXPECT_NEAR(start_z[i], 6 + shift, 1e-4);
    EXPECT_NEAR(end_z[i], -40 + shift, 1e-4);
    EXPECT_GE(end_z[i], -40 - 1e-9);  // never past the programmed length
  }
  EXPECT_EQ(end_z.back(), -40);
  EXPECT_NEAR(cut_x.back(), 30 - 2 * plan.ap, 1e-4);
  EXPECT_NE(program.find("M30"), std::string::npos);
}

struct Rapid {
  double x0, z0, x1, z1;
};

/// The rapids of a program, each from where the tool really was (after
/// G33 cuts too), starting at (x, z).
std::vector<Rapid> rapids_of(const std::string& program, double x, double z) {
  std::vector<Rapid> rapids;
  for (const std::string& line : lines_of(program)) {
    const double x0 = x, z0 = z;
    if (!std::isnan(word(line, 'X'))) x = word(line, 'X');
    if (!std::isnan(word(line, 'Z'))) z = word(line, 'Z');
    if (line.rfind("G0 ", 0) == 0) rapids.push_back({x0, z0, x, z});
  }
  return rapids;
}

// An internal left-hand M30x2 (40 mm, run-in 6): every rapid stays ahead of
// the face (Z > 0), inside the bore, or in the groove beyond the thread's
// inner end (Z < -40): never a diagonal through the metal.
TEST(ThreadProgram, InternalLeftHandRapidsStayClear) {
  const BasicProfile p = basic_profile(30, 2);
  const TurningPlan plan = plan_internal(p, internal_limits(p, default_internal_class(30)), {});
  ProgramSettings s = m30_program();
  s.left_hand = true;
  for (ProgramStyle style : {ProgramStyle::g76, ProgramStyle::passes}) {
    const std::string program = thread_program(style, plan, s);
    for (const Rapid& r : rapids_of(program, 100, 100)) {  // from a tool change position outside
      const bool ahead_of_face = r.z0 > 0 && r.z1 > 0;
      const bool inside_bore = r.x0 < plan.blank_diameter && r.x1 < plan.blank_diameter;
      const bool in_groove = r.z0 < -40 && r.z1 < -40;
      EXPECT_TRUE(ahead_of_face || inside_bore || in_groove)
          << program << "rapid " << r.x0 << "," << r.z0 << " -> " << r.x1 << "," << r.z1;
    }
    if (style == ProgramStyle::passes) {
      EXPECT_NE(program.find("G0 Z-46\n"), std::string::npos) << program;
      EXPECT_NE(program.find("G33 Z6 K2"), std::string::npos) << program;
    }
  }
}

TEST(ThreadProgram, SmallBoreKeepsTheDriveLineOffTheAxis) {
  const BasicProfile p = basic_profile(3, 0.5);
  const TurningPlan plan = plan_internal(p, internal_limits(p, default_internal_class(3)), {});
  ProgramSettings s = m30_program();
  s.pitch_mm = 0.5;
  double drive_x = NAN;
  for (const std::string& line : lines_of(thread_program(ProgramStyle::g76, plan, s)))
    if (line.rfind("G0 X", 0) == 0) drive_x = word(line, 'X');
  EXPECT_NEAR(drive_x, plan.blank_diameter * 0.8, 1e-4);  // a tenth of the bore each side
}

// Flank infeed at the flank's own 30°: the tool's trailing flank (the +Z
// side when cutting towards −Z) must lie on the same line in every pass, so
// only the leading edge cuts. At depth a under the peak that flank sits at
// z_tip + (depth_tip − a)·tan 30°.
TEST(ThreadProgram, FlankInfeedKeepsTheTrailingFlankInPlace) {
  TurningSettings flank;
  flank.infeed = Infeed::flank;
  flank.flank_angle_deg = 30;
  const TurningPlan plan = m30_plan(flank);
  const std::string program = thread_program(ProgramStyle::passes, plan, m30_program());
  double z_tip = NAN, x_tip = NAN;
  std::vector<double> flank_at_peak;  // the trailing flank's z at depth 0 (d = 30)
  for (const std::string& line : lines_of(program)) {
    if (line.rfind("G0 Z", 0) == 0) z_tip = word(line, 'Z');
    if (line.rfind("G0 X", 0) == 0) x_tip = word(line, 'X');
    if (line.rfind("G33", 0) == 0) {
      const double depth = (30 - x_tip) / 2;
      flank_at_peak.push_back(z_tip + depth * std::tan(M_PI / 6));
    }
  }
  ASSERT_EQ(flank_at_peak.size(), plan.depths.size() + 1u);
  for (double z : flank_at_peak) EXPECT_NEAR(z, flank_at_peak.front(), 2e-4);
  // Radial infeed moves it by ap·tan 30° = 0.74 mm between the first and the last pass.
  const std::string radial = thread_program(ProgramStyle::passes, m30_plan(), m30_program());
  EXPECT_EQ(radial.find("G0 Z5."), std::string::npos);  // every radial pass starts at Z6
}

TEST(ThreadProgram, RefusesImpossibleSettings) {
  const TurningPlan plan = m30_plan();
  ProgramSettings s = m30_program();
  s.length_mm = 0;
  EXPECT_THROW(thread_program(ProgramStyle::g76, plan, s), tk::Error);
  s = m30_program();
  s.rpm = NAN;
  EXPECT_THROW(thread_program(ProgramStyle::passes, plan, s), tk::Error);
}

TEST(ThreadReport, MembersAndSeries) {
  EXPECT_EQ(members_of(parse_designation("M10"), MemberChoice::from_class).size(), 2u);
  EXPECT_EQ(members_of(parse_designation("M10-6g"), MemberChoice::from_class).size(), 1u);
  EXPECT_THROW(members_of(parse_designation("M10-6g"), MemberChoice::internal), tk::Error);
  EXPECT_EQ(members_of(parse_designation("M10-6g"), MemberChoice::both).size(), 2u);
  EXPECT_EQ(pitch_series(30, 3.5), PitchSeries::coarse);  // ISO 261: M30 coarse 3.5, fine 3, 2, 1.5, 1
  EXPECT_EQ(pitch_series(30, 2), PitchSeries::fine);
  EXPECT_EQ(pitch_series(30, 2.2), PitchSeries::non_standard);
  EXPECT_EQ(pitch_series(31, 2), PitchSeries::no_iso261_size);
  EXPECT_STREQ(series_name(PitchSeries::no_iso261_size), "no ISO 261 size");
}

// Every line of both programs lexes as G-code: no comment inside a comment
// (LinuxCNC and gcode-pulse refused the G76 program's "ap*sqrt(i/n)"), and a
// title with parentheses and a newline stays inside its comment.
TEST(ThreadProgram, EveryLineLexesWithItsCommentsClosed) {
  ProgramSettings s = m30_program();
  for (const std::string& title : {std::string("M30x2-6g"), std::string("M30 (spare)\n(MSG, x")}) {
    s.title = title;
    for (ProgramStyle style : {ProgramStyle::g76, ProgramStyle::passes})
      for (const std::string& line : lines_of(thread_program(style, m30_plan(), s))) {
        EXPECT_NO_THROW(tk::motion::lex_gcode_line(line)) << line;
        EXPECT_TRUE(tk::motion::lex_gcode_line(line).message.empty()) << line;
      }
  }
}
