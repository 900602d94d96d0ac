/// @file fll_names.hpp
/// @brief What the FLL reader and writer share: fuzzylite's operator
/// names, the words rules reserve, and which names fuzzylite keeps intact.
#pragma once

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <string>
#include <string_view>
#include <utility>

#include "fuzzy/tnorm.hpp"

namespace tk::fuzzy::fll_names {

constexpr std::array<std::pair<TNorm, std::string_view>, 6> kConjunctions{{{TNorm::minimum, "Minimum"},
                                                                           {TNorm::product, "AlgebraicProduct"},
                                                                           {TNorm::drastic, "DrasticProduct"},
                                                                           {TNorm::lukasiewicz, "BoundedDifference"},
                                                                           {TNorm::hamacher, "HamacherProduct"},
                                                                           {TNorm::trigonometric, "Trigonometric"}}};
constexpr std::array<std::string_view, 9> kSNorms{"Maximum",          "AlgebraicSum",  "BoundedSum",
                                                  "DrasticSum",       "EinsteinSum",   "HamacherSum",
                                                  "NilpotentMaximum", "NormalizedSum", "UnboundedSum"};
// Words a rule gives meaning to: as names they would make rules ambiguous.
constexpr std::array<std::string_view, 6> kKeywords{"if", "is", "and", "or", "then", "with"};
constexpr std::array<std::string_view, 6> kHedges{"not", "any", "very", "somewhat", "extremely", "seldom"};

template <typename List>
inline bool contains(const List& list, std::string_view word) {
  return std::find(list.begin(), list.end(), word) != list.end();
}

inline std::string_view trim(std::string_view s) {
  constexpr std::string_view blank = " \t\r\v\f";
  const auto first = s.find_first_not_of(blank);
  if (first == std::string_view::npos) return {};
  return s.substr(first, s.find_last_not_of(blank) - first + 1);
}

/// What fuzzylite keeps of a name (letters, digits, '_', '.'), so that
/// names pass through fuzzylite unchanged; rule words are excluded.
inline std::string name_problem(std::string_view name) {
  if (name.empty()) return "a name is empty";
  for (const char c : name)
    if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '.'))
      return fmt::format("invalid name '{}' (use letters, digits, '_' and '.')", name);
  if (contains(kKeywords, name) || contains(kHedges, name))
    return fmt::format("'{}' is a rule word and cannot be a name", name);
  return {};
}

}  // namespace tk::fuzzy::fll_names
