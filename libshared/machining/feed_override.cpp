/// @file feed_override.cpp
/// @brief Parameter checks and set-up of the feed-override law.
#include "machining/feed_override.hpp"

#include <fmt/format.h>

#include "io/error.hpp"

namespace tk::machining {

OverrideVariant parse_override_variant(const std::string& name) {
  if (name == "original") return OverrideVariant::original;
  if (name == "modified") return OverrideVariant::modified;
  throw UsageError("--variant must be 'original' or 'modified', not '" + name + "'");
}

const char* variant_name(OverrideVariant variant) {
  return variant == OverrideVariant::original ? "original" : "modified";
}

void validate(const FeedOverrideParams& params) {
  // Written as !(inside) so that NaN fails every check.
  const auto within = [](bool inside, const char* option, const char* range, double value) {
    if (!inside) throw UsageError(fmt::format("{} must be in {}, not {}", option, range, value));
  };
  const FeedOverrideParams& p = params;
  within(p.mz_pct > 0 && p.mz_pct <= 100, "--mz", "(0, 100] % of the rated torque", p.mz_pct);
  // k > 1 or p outside [0, 1] would take W_k out of [0, 1] and O_n out of (0, 200].
  within(p.k > 0 && p.k <= 1, "--k", "(0, 1]", p.k);
  within(p.p >= 0 && p.p <= 1, "--p", "[0, 1]", p.p);
  // (7) pulls an overloaded cut's override towards d: above 100 % it would
  // raise the feed past the programmed one under overload.
  within(p.d_pct >= 0 && p.d_pct <= 100, "--d", "[0, 100] %", p.d_pct);
  within(p.initial_override_pct > 0 && p.initial_override_pct <= kMaxOverridePct, "--initial-override", "(0, 200] %",
         p.initial_override_pct);
  within(p.min_override_pct >= 0 && p.min_override_pct < kMaxOverridePct, "--min-override", "[0, 200) %",
         p.min_override_pct);
  if (p.initial_override_pct < p.min_override_pct)
    throw UsageError("--initial-override must not be below --min-override");
}

namespace {
const FeedOverrideParams& checked(const FeedOverrideParams& params) {
  validate(params);
  return params;
}
}  // namespace

FeedOverride::FeedOverride(const FeedOverrideParams& params)
    : params_(checked(params)), override_(params.initial_override_pct) {}

}  // namespace tk::machining
