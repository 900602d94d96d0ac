#!/usr/bin/python3
"""Independent oracle for the canonical commands LinuxCNC's rs274 prints.

Usage: rs274_canon.py FILE...   (each FILE the output of `rs274 -g PROGRAM`)

Prints one JSON object per FILE:

  {"file": name, "complete": bool (PROGRAM_END() seen),
   "extra_axes": bool (A B C U V W move), "nurbs": bool,
   "final_x": mm, "final_y": mm, "final_z": mm (machine), "path_mm": ...,
   "moves": n, "status": "incomplete" | "extra_axes" | "nurbs" | "ok"}

Written from LinuxCNC's documented canonical interface (emccanon: the
interpreter hands program coordinates in the current length units; motion
adds the G92 offset, rotates by the XY rotation, then adds the G5x and the
tool length offsets), not from the project's C++ code. Path length: lines
are straight; ARC_FEED is a helix about its centre whose radius goes
linearly from the start's to the end's, |rotation| - 1 extra turns, end
equal to start in the plane meaning a full circle. Standard library only.
"""
import json
import math
import re
import sys

LINE = re.compile(r"^\s*(?:\d+\s+N\S*\s+)?([A-Z_0-9]+)\((.*)\)\s*$")
UNITS = {"CANON_UNITS_MM": 1.0, "CANON_UNITS_INCHES": 25.4, "CANON_UNITS_CM": 10.0}
# plane -> indices of (first, second, normal) in x, y, z
PLANES = {"CANON_PLANE_XY": (0, 1, 2), "CANON_PLANE_XZ": (2, 0, 1), "CANON_PLANE_YZ": (1, 2, 0)}


def numbers(args):
    return [float(t) for t in re.split(r"[,\s]+", args.strip()) if t]


def helix_length(start, end, centre, plane, rotation):
    a, b, n = plane
    r0 = math.hypot(start[a] - centre[a], start[b] - centre[b])
    r1 = math.hypot(end[a] - centre[a], end[b] - centre[b])
    t0 = math.atan2(start[b] - centre[b], start[a] - centre[a])
    t1 = math.atan2(end[b] - centre[b], end[a] - centre[a])
    ccw = rotation > 0
    sweep = (t1 - t0) if ccw else (t0 - t1)
    sweep %= 2 * math.pi
    if sweep < 1e-12:
        sweep = 2 * math.pi
    sweep += 2 * math.pi * (abs(rotation) - 1)
    rise = end[n] - start[n]
    # numerically integrate sqrt((r dphi)^2 + (dr)^2 + (dz)^2)
    steps = 2000
    total = 0.0
    for i in range(steps):
        r = r0 + (r1 - r0) * (i + 0.5) / steps
        dphi = sweep / steps
        total += math.sqrt((r * dphi) ** 2 + ((r1 - r0) / steps) ** 2 + (rise / steps) ** 2)
    return total


def run(path):
    unit = 1.0
    g5x = [0.0] * 3
    g92 = [0.0] * 3
    tool = [0.0] * 3
    rotation = 0.0
    plane = PLANES["CANON_PLANE_XY"]
    pos = [0.0, 0.0, 0.0]
    extra = None
    out = {"file": path, "complete": False, "extra_axes": False, "nurbs": False, "path_mm": 0.0, "moves": 0}

    def machine(p):
        x, y, z = (p[i] + g92[i] for i in range(3))
        th = math.radians(rotation)
        x, y = x * math.cos(th) - y * math.sin(th), x * math.sin(th) + y * math.cos(th)
        return [x + g5x[0] + tool[0], y + g5x[1] + tool[1], z + g5x[2] + tool[2]]

    with open(path, errors="replace") as f:
        for text in f:
            m = LINE.match(text)
            if not m:
                continue
            name, args = m.groups()
            if name == "PROGRAM_END":
                out["complete"] = True
                break
            if name == "USE_LENGTH_UNITS":
                unit = UNITS[args.strip()]
            elif name == "SELECT_PLANE":
                plane = PLANES[args.strip()]
            elif name == "SET_G5X_OFFSET":
                g5x = [v * unit for v in numbers(args)[1:4]]
            elif name == "SET_G92_OFFSET":
                g92 = [v * unit for v in numbers(args)[0:3]]
            elif name == "SET_XY_ROTATION":
                rotation = numbers(args)[0]
            elif name == "USE_TOOL_LENGTH_OFFSET":
                tool = [v * unit for v in numbers(args)[0:3]]
            elif name == "NURBS_FEED":
                out["nurbs"] = True
            elif name == "RIGID_TAP":  # G33.1: into the hole and back out to the start
                v = numbers(args)
                end = machine([v[0] * unit, v[1] * unit, v[2] * unit])
                out["path_mm"] += 2 * math.dist(pos, end)
                out["moves"] += 2 if end != pos else 0
            elif name in ("STRAIGHT_TRAVERSE", "STRAIGHT_FEED", "STRAIGHT_PROBE", "ARC_FEED"):
                v = numbers(args)
                rest = v[3:] if name != "ARC_FEED" else v[6:]
                if extra is not None and rest != extra:
                    out["extra_axes"] = True
                if extra is None and any(r != 0 for r in rest):
                    out["extra_axes"] = True
                extra = rest
                if name == "ARC_FEED":
                    a, b, n = plane
                    end_p = [0.0] * 3
                    end_p[a], end_p[b], end_p[n] = v[0] * unit, v[1] * unit, v[5] * unit
                    centre_p = [0.0] * 3
                    centre_p[a], centre_p[b] = v[2] * unit, v[3] * unit
                    end = machine(end_p)
                    centre = machine(centre_p)
                    out["path_mm"] += helix_length(pos, end, centre, plane, int(v[4]))
                else:
                    end = machine([v[0] * unit, v[1] * unit, v[2] * unit])
                    out["path_mm"] += math.dist(pos, end)
                if end != pos:
                    out["moves"] += 1
                pos = end
    out["final_x"], out["final_y"], out["final_z"] = pos
    out["status"] = ("incomplete" if not out["complete"] else "extra_axes" if out["extra_axes"]
                     else "nurbs" if out["nurbs"] else "ok")
    return out


for path in sys.argv[1:]:
    print(json.dumps(run(path)))
