/// @file offset_notches.hpp
/// @brief Notches a round tool cannot enter, filled before offsetting.
///
/// Offsetting by R grows a set A into A + D (D the disc of radius R). Any
/// B with A ⊆ B ⊆ C(A), the closing of A by D, grows into the same set,
/// since C(A) + D = A + D. A gear's spikes stand 0.5 mm apart with R = 1:
/// no tool position reaches into the V between two, yet Clipper sweeps
/// every flank's offset across several of its neighbours' (2.7 s of a
/// 100,000-element gear's 3.8 s). With the V's filled first, the offset's
/// edges lie in a band about one tool radius wide, and its round joins turn
/// only where they bound the grown set.
///
/// A notch is a run of concave corners v1 ... vk (turning toward the free
/// side, as the offset sees them) between two other vertices a and b, its
/// mouth. Let M be the polygon a, v1, ..., vk, b. When M is convex, its
/// angles at a and b are at most 90 degrees, and |ab| = W < 2R:
///  - M lies in the strip across ab, so it is nowhere wider than W and no
///    disc of radius R fits in it;
///  - a disc that avoids A and meets M's inside cannot cross the run, so
///    its part beyond the line ab lies in M, and its chord on that line lies
///    in the mouth; it reaches no further into M than the disc resting on a
///    and b (centre c, R - sqrt(R^2 - W^2 / 4) past the line at most).
/// So M outside that resting disc is in C(A), and in particular M below the
/// tangents to it at a and b, which meet W^2 / (4 sqrt(R^2 - W^2 / 4))
/// under the mouth's middle. The run is replaced by one corner t a little
/// deeper: a -> t -> b.
///
/// How much deeper: the offset of a -> t starts at a + R n (n its unit
/// normal), on a's circle; it should start inside b's circle by a margin e
/// beyond the chords of b's round join (2.5 chord tolerances, for a last
/// chord of up to 1.5 steps, and 2 units), so that it hides under them.
/// Its distance from b is sqrt(W^2 - 2 W R sin g + R^2), where g is the
/// angle a -> t dips below the mouth; so sin g = (W^2 + 2 R e - e^2) /
/// (2 W R), and t is (W / 2) tan g deep, and a unit for rounding. Where
/// that would need sin g >= 1 (a mouth nearly 2R wide) the notch is kept.
///
/// Why there: the offset of a -> t starts on a's circle just past c, where
/// the circles round a and b cross (the valley of the grown set), and runs
/// inside b's; a's round join turns only through the part of its circle
/// that bounds the grown set, not round the whole tip. A flat fill at the
/// resting disc's depth would keep the full joins and draw a spike of
/// length R at both its ends.
#pragma once

#include <polyclipping/clipper.hpp>

#include <vector>

namespace tk::cad {

/// The path with each notch the tool cannot enter filled (see above), and
/// the number filled added to `filled`; `delta` is the offset (Clipper
/// units, negative shrinks), `join_tolerance` the round joins' chord
/// tolerance. Only notches reaching at least `worth` beyond t are filled.
/// The filled path may cross another path where one reaches into a notch:
/// the caller checks (simple_and_disjoint) before using it.
ClipperLib::Path fill_notches(const ClipperLib::Path& path, double delta, double join_tolerance, double worth,
                              std::size_t& filled);

}  // namespace tk::cad
