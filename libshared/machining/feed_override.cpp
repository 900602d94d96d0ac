/// @file feed_override.cpp
/// @brief Parameter checks and set-up of the fuzzy feed-override law.
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
  if (!(params.mz_pct > 0 && params.mz_pct <= 100))
    throw UsageError(fmt::format("--mz must be in (0, 100] % of the rated load, not {}", params.mz_pct));
  if (!(params.gain_k > 0 && params.gain_k <= 1)) throw UsageError(fmt::format("--k must be in (0, 1], not {}", params.gain_k));
  if (!(params.dead_band_p >= 0 && params.dead_band_p < 1))
    throw UsageError(fmt::format("--p must be in [0, 1), not {}", params.dead_band_p));
  if (params.average_d < 1) throw UsageError("--d must be an integer >= 1");
  if (params.average_d > 1000000) throw UsageError("--d must be at most 1000000 cycles");
  if (!(params.initial_override_pct > 0 && params.initial_override_pct <= kMaxOverridePct))
    throw UsageError(fmt::format("--initial-override must be in (0, 200] %, not {}", params.initial_override_pct));
  if (!(params.min_override_pct > 0 && params.min_override_pct <= kMaxOverridePct))
    throw UsageError(fmt::format("--min-override must be in (0, 200] %, not {}", params.min_override_pct));
  if (params.initial_override_pct < params.min_override_pct)
    throw UsageError("--initial-override must not be below --min-override");
}

namespace {
const FeedOverrideParams& checked(const FeedOverrideParams& params) {
  validate(params);  // before the ring buffer of d loads is allocated
  return params;
}
}  // namespace

FeedOverride::FeedOverride(const FeedOverrideParams& params)
    : params_(checked(params)),
      modified_(params.variant == OverrideVariant::modified),
      mz_(params.mz_pct),
      gain_k_(params.gain_k),
      dead_band_(params.dead_band_p * params.mz_pct),
      min_override_(params.min_override_pct),
      override_(params.initial_override_pct),
      ring_(modified_ ? params.average_d : 1, 0.0) {}

void FeedOverride::resum() {
  double sum = 0;
  for (const double load : ring_) sum += load;
  sum_ = sum;
}

}  // namespace tk::machining
