/// @file fll.hpp
/// @brief fuzzylite's FLL text format (fuzzylite 6.0), read and written for
/// the subset our Mamdani engine (engine.hpp) supports.
///
/// An FLL file is `key: value` lines; `#` starts a comment, lines are
/// trimmed, CRLF is accepted. It opens with `Engine: NAME`, then sections
/// `InputVariable: NAME`, `OutputVariable: NAME` and one `RuleBlock: NAME`.
///
/// Supported:
///   terms         `term: NAME Triangle a b c [1]`,
///                 `term: NAME Trapezoid a b c d [1]` (a height other than 1
///                 is rejected)
///   enabled       true; lock-range and lock-previous (lock-valid): false
///   aggregation   Maximum (old alias `accumulation`)
///   defuzzifier   `Centroid [RESOLUTION]` (default 100)
///   default       a finite number or nan
///   conjunction   Minimum, AlgebraicProduct, DrasticProduct,
///                 BoundedDifference (Lukasiewicz), HamacherProduct, or none
///                 when no rule uses `and`
///   disjunction   none or any fuzzylite S-norm name, but no rule may use `or`
///   implication   Minimum or AlgebraicProduct (also as the old-style
///                 `activation: <TNorm>`), required; activation General
///   rules         `if A is X [and B is Y ...] then Z is W [and V is U ...]
///                 [with WEIGHT]`; no hedges, parentheses or `or`
/// A missing conjunction is none, as in fuzzylite. Where fuzzylite's
/// default could not evaluate or differs from ours (range, aggregation,
/// defuzzifier, implication), the key is required, so that whatever we
/// accept fuzzylite evaluates the same way.
/// Names of variables and terms are letters, digits, `_` and `.` (what
/// fuzzylite keeps of a name), and not a rule keyword or hedge.
///
/// Our extensions, which fuzzylite itself cannot read:
///   `conjunction: Trigonometric`      TNorm::trigonometric (Könczöl & Gál)
///   `defuzzifier: ExactCentroid [R]`  Defuzzifier::Kind::exact (R kept
///                                     only so that the engine round-trips)
///
/// Dropped on reading (the engine has no place for them): RuleBlock
/// description, the disjunction. Everything else read is kept.
#pragma once

#include <string>
#include <string_view>

#include "fuzzy/engine.hpp"

namespace tk::fuzzy {

/// Parses FLL text. Throws tk::Error with Location{file_name, line} (the
/// 1-based line at fault) for anything malformed or unsupported, and at
/// line 0 for what no single line is to blame for (empty input, validate()).
Engine read_fll(std::string_view text, const std::string& file_name);

/// read_fll of a file's content; "-" is stdin. An unreadable file or a NUL
/// byte is an Error.
Engine read_fll_file(const std::string& path);

/// fuzzylite 6.0 style FLL (two-space indent, the keys in fuzzylite's
/// order, numbers in shortest round-trip form, `default: nan`, the
/// Centroid resolution always written) that read_fll reads back to an equal
/// engine. Throws Error when the engine fails validate() or holds text FLL
/// cannot carry (a name that is not a valid name, `#`, a line break or
/// untrimmed blanks in a description). A triangle whose b != c is written
/// as a Trapezoid.
std::string write_fll(const Engine& engine);

/// Empty when `a` and `b` hold the same controller field by field (NaN
/// equals NaN), else a short description of the first difference. For the
/// round-trip tests and the fuzz target.
std::string engine_difference(const Engine& a, const Engine& b);

}  // namespace tk::fuzzy
