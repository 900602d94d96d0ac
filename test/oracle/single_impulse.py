#!/usr/bin/python3
"""Panayotov & Goranov's "direct calculation of a single impulse", written
from the paper's text (seed 002, "Development of a mathematical model of a
triaxial interpolation for a CNC machine implemented in control software"),
as an independent check of gcode-pulse --method direct.

Usage: single_impulse.py STEPS_X,Y,Z X0,Y0,Z0 X1,Y1,Z1 [X2,Y2,Z2 ...]
       single_impulse.py --summary STEPS_X,Y,Z X0,Y0,Z0 X1,Y1,Z1 ...
       single_impulse.py --geometry

The points (mm) are a polyline of straight moves from the first point. Each
vertex is put on the step lattice (rounded half away from zero, the end
point a stepping control can reach) and each segment walked by the paper's
rule. The default output is one JSON object per event, {"dx", "dy", "dz"};
--summary prints one object: events, max_deviation_mm and rms_deviation_mm
(distance of the lattice points after each event from the programmed line,
the segment between the given points) and max_reorigin_ratio (see below).

The rule, step by step as the paper prints it (all arithmetic in exact
fractions, so that the paper's ties are ties):

1. The current point is the origin O. The line from O to the end point is
   x/x_end = y/y_end = z/z_end (eq. 1-2), or x = x_end t, ... (eq. 4).
2. The box of one step around O has six planes x = +-dX, y = +-dY,
   z = +-dZ (eq. 7-12). Intersect the line with each (t = +-d / end
   component); a plane parallel to the line (a zero component, where the
   paper's formula divides by zero) has no intersection.
3. Of the intersections, those with every coordinate within the box lie on
   its surface; the one with t > 0 is where the line toward the end point
   leaves it (the puncture point).
4. Move to the discrete point (one of the 26: each axis -d, 0 or +d, not
   all 0) nearest the puncture point. "When the puncture hits the middle of
   the quarter of a given plane ... any matching vector can be chosen":
   ties go to the point that steps more axes.
5. "After moving the tool to one of the discrete points, it is necessary to
   translate the coordinate system to the new point. This will change the
   values of x_end, y_end, z_end": repeat from 1 until O is the end point.

The paper states no bound on the distance from the path. What its rule
implies: the new point is within half a step of the puncture point on each
of the two axes other than the face's, so within half the diagonal of a
face of the box from the line through the previous point and the end (the
re-origined line). max_reorigin_ratio is the largest distance from it over
that half diagonal; the oracle fails if it exceeds 1.

--geometry checks the paper's counts of intersection points: a line through
a corner of the box meets its surface in six points, three by three
coinciding; through an edge, in four (two by two), the other two outside;
otherwise in two, the other four outside. Prints "ok".
"""

import itertools
import json
import math
import sys
from fractions import Fraction

NEIGHBOURS = [m for m in itertools.product((-1, 0, 1), repeat=3) if m != (0, 0, 0)]


def fraction_of(text):
    return Fraction(text.strip())


def round_half_away(value):
    whole = math.floor(abs(value) + Fraction(1, 2))
    return whole if value >= 0 else -whole


def intersections(vector, step):
    """(t, point) of the line O + t*vector with the six planes (eq. 7-12)."""
    found = []
    for axis in range(3):
        if vector[axis] == 0:
            continue  # parallel to both planes of this axis
        for side in (1, -1):
            t = side * step[axis] / vector[axis]
            found.append((t, tuple(t * c for c in vector)))
    return found


def on_surface(point, step):
    return all(abs(point[axis]) <= step[axis] for axis in range(3))


def puncture(vector, step):
    on = [(t, p) for t, p in intersections(vector, step) if on_surface(p, step) and t > 0]
    if not on:
        raise AssertionError("no puncture point toward the end")
    # Every surface intersection with t > 0 is the same point (a corner or
    # an edge gives it two or three times).
    assert len(set(p for _, p in on)) == 1
    return on[0][1]


def nearest_neighbour(point, step):
    # Squared distance = the sum over the axes of (coordinate - discrete
    # coordinate)^2: the nine per-axis terms once, then the 26 sums.
    term = [{k: (point[a] - k * step[a]) ** 2 for k in (-1, 0, 1)} for a in range(3)]
    distance_sq = {m: term[0][m[0]] + term[1][m[1]] + term[2][m[2]] for m in NEIGHBOURS}
    best = min(distance_sq.values())
    tied = [m for m in NEIGHBOURS if distance_sq[m] == best]
    return max(tied, key=lambda m: sum(c != 0 for c in m))


def distance_to_line(point, a, b):
    ab = [b[i] - a[i] for i in range(3)]
    ap = [point[i] - a[i] for i in range(3)]
    length_sq = sum(c * c for c in ab)
    if length_sq == 0:
        return math.sqrt(sum(c * c for c in ap))
    along = sum(ab[i] * ap[i] for i in range(3)) / length_sq
    return math.sqrt(sum((ap[i] - along * ab[i]) ** 2 for i in range(3)))


def walk(start, end, step, programmed, stats, on_event):
    """Steps lattice point `start` to `end` (integers); deviations against
    the programmed line (mm)."""
    at = list(start)
    while at != list(end):
        vector = [(end[a] - at[a]) * step[a] for a in range(3)]  # eq. 4 after the translation
        hit = puncture(vector, step)
        move = nearest_neighbour(hit, step)
        face = next(a for a in range(3) if abs(hit[a]) == step[a])
        half_diagonal = math.sqrt(sum(float(step[a]) ** 2 for a in range(3) if a != face)) / 2
        before = [at[a] * step[a] for a in range(3)]
        at = [at[a] + move[a] for a in range(3)]
        here = [at[a] * step[a] for a in range(3)]
        end_mm = [end[a] * step[a] for a in range(3)]
        reorigin = distance_to_line([float(c) for c in here], [float(c) for c in before], [float(c) for c in end_mm])
        stats["max_reorigin_ratio"] = max(stats["max_reorigin_ratio"], reorigin / half_diagonal)
        deviation = distance_to_line([float(c) for c in here], *programmed)
        stats["events"] += 1
        stats["max_deviation_mm"] = max(stats["max_deviation_mm"], deviation)
        stats["sum_sq"] += deviation * deviation
        on_event(move)
    return at


def check_geometry():
    step = (Fraction(1, 200), Fraction(1, 200), Fraction(1, 400))
    def surface_points(vector):
        found = intersections(vector, step)
        on = [p for _, p in found if on_surface(p, step)]
        return len(found), len(on), len(set(on))
    # Through a corner: (dX, dY, dZ) times any factor.
    assert surface_points([3 * s for s in step]) == (6, 6, 2)
    # Through an edge: equal x and y in steps, less z.
    assert surface_points([5 * step[0], -5 * step[1], 2 * step[2]]) == (6, 4, 2)
    # Through a face: two on the surface, four outside.
    assert surface_points([7 * step[0], 3 * step[1], -2 * step[2]]) == (6, 2, 2)
    # The middle of a quarter of a face: four discrete points equally near.
    middle = (step[0], step[1] / 2, step[2] / 2)
    distances = sorted(sum((middle[a] - m[a] * step[a]) ** 2 for a in range(3)) for m in NEIGHBOURS)
    assert distances[0] == distances[3] < distances[4]
    print("ok")


def main(argv):
    args = argv[1:]
    if args == ["--geometry"]:
        check_geometry()
        return 0
    summary = bool(args) and args[0] == "--summary"
    if summary:
        args = args[1:]
    if len(args) < 3:
        sys.stderr.write(__doc__)
        return 2
    steps_per_mm = [fraction_of(v) for v in args[0].split(",")]
    step = [1 / s for s in steps_per_mm]
    points = [[fraction_of(v) for v in p.split(",")] for p in args[1:]]
    stats = {"events": 0, "max_deviation_mm": 0.0, "sum_sq": 0.0, "max_reorigin_ratio": 0.0}
    out = sys.stdout
    def on_event(move):
        if not summary:
            out.write(json.dumps({"dx": move[0], "dy": move[1], "dz": move[2]}) + "\n")
    at = [round_half_away(points[0][a] * steps_per_mm[a]) for a in range(3)]
    for a, b in zip(points, points[1:]):
        end = [round_half_away(b[a_] * steps_per_mm[a_]) for a_ in range(3)]
        at = walk(at, end, step, ([float(c) for c in a], [float(c) for c in b]), stats, on_event)
    if stats["max_reorigin_ratio"] > 1 + 1e-12:
        sys.stderr.write("single_impulse.py: a step left the re-origined line by more than half a face diagonal\n")
        return 1
    if summary:
        events = stats["events"]
        out.write(json.dumps({"events": events, "max_deviation_mm": stats["max_deviation_mm"],
                              "rms_deviation_mm": math.sqrt(stats["sum_sq"] / events) if events else 0.0,
                              "max_reorigin_ratio": stats["max_reorigin_ratio"]}) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
