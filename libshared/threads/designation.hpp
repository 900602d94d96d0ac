/// @file designation.hpp
/// @brief ISO metric thread designations as users write them (ISO 965-1
/// clause 9): "M30x2-6g", "M10", "M10x1.25-6H", "M30x2-5g6g",
/// "M10x1.5-6H/6g", "M20x2-6g-LH", "M16 × 1.5 - 6H - L".
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace tk::threads {

/// One diameter's tolerance: grade (3 to 9) and position letter
/// (e f g h for external threads, G H for internal ones).
struct ToleranceZone {
  int grade = 6;
  char position = 'g';
  bool operator==(const ToleranceZone&) const = default;
};

/// A tolerance class of one member: the pitch diameter's zone and the crest
/// diameter's (d for external threads, D1 for internal ones). "6g" gives
/// both 6g; "5g6g" gives pitch 5g, crest 6g.
struct ToleranceClass {
  ToleranceZone pitch;
  ToleranceZone crest;
  bool external() const { return pitch.position >= 'a' && pitch.position <= 'z'; }
  /// "6g", or "5g6g" when the zones differ.
  std::string text() const;
};

/// ISO 965-1's groups of length of engagement; N (normal) unless given.
enum class Engagement { short_s, normal_n, long_l };

struct ThreadDesignation {
  double major_mm = 0;  ///< nominal (basic major) diameter d = D
  double pitch_mm = 0;
  bool left_hand = false;
  std::optional<ToleranceClass> internal;
  std::optional<ToleranceClass> external;
  Engagement engagement = Engagement::normal_n;
  /// "M30x2-6g" in the canonical spelling (pitch always written).
  std::string canonical() const;
};

/// Parses a designation. Accepted: "M" (or "m"), the diameter (a '.' or ','
/// decimal mark), optionally "x" / "X" / "×" / "*" and the pitch, then
/// optionally "-" and a tolerance class or a fit "6H/6g", a length of
/// engagement "-S" / "-N" / "-L", and "-LH" (or "LH" right after the pitch).
/// Spaces anywhere are ignored. With no pitch, the coarse pitch of ISO 261
/// is taken (an error when ISO 261 has none for the diameter). Throws
/// tk::Error (without a location) naming what is wrong: a zero or missing
/// diameter, a zero pitch, an unknown position letter, a grade outside 3-9,
/// a crest position that differs from the pitch diameter's, two classes of
/// one kind, a multi-start "Ph" designation (not supported).
ThreadDesignation parse_designation(std::string_view text);

}  // namespace tk::threads
