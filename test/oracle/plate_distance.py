#!/usr/bin/python3
"""Independent oracle: the exact signed distance from points to the plate of
test/fixtures/dxf/plate.dxf (as make_fixtures.py states it: a 100 x 60
rectangle with corners rounded by 5, a bore of radius 10 at (30, 30), an
obround slot of width 8 from (60, 30) to (80, 30)), from closed-form
distance functions, not from the DXF and not from any code of this project.

Reads JSON Lines with x, y; writes per line {"x", "y", "d"}: d is the
distance to the plate's boundary, negative in the material. With
--grown R also "inside" (d < R) and "expected" (d - R, the distance to the
plate grown by R).  Standard library only."""
import json
import math
import sys


def box(x, y):
    qx, qy = abs(x - 50) - 45, abs(y - 30) - 25  # half extents minus the corner radius
    return math.hypot(max(qx, 0), max(qy, 0)) + min(max(qx, qy), 0) - 5


def bore(x, y):
    return math.hypot(x - 30, y - 30) - 10


def slot(x, y):
    t = min(max((x - 60) / 20, 0), 1)
    return math.hypot(x - (60 + 20 * t), y - 30) - 4


def plate(x, y):
    d = min(abs(box(x, y)), abs(bore(x, y)), abs(slot(x, y)))
    material = box(x, y) < 0 and bore(x, y) > 0 and slot(x, y) > 0
    return -d if material else d


grown = float(sys.argv[2]) if len(sys.argv) > 2 and sys.argv[1] == "--grown" else None
for line in sys.stdin:
    r = json.loads(line)
    out = {"x": r["x"], "y": r["y"], "d": plate(r["x"], r["y"])}
    if grown is not None:
        out["expected"] = out["d"] - grown
        out["inside"] = out["d"] < grown
    print(json.dumps(out))
