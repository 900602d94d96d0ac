#!/usr/bin/python3
"""Independent oracle for DXF files: what ezdxf sees in them.

Usage: dxf_entities.py FILE
       dxf_entities.py --write-sample FILE [--binary] [--r12]

Reads FILE with ezdxf (Debian's python3-ezdxf; ezdxf.readfile, and
ezdxf.recover.readfile when readfile rejects the file) and prints JSON Lines:

  {"file": basename, "loader": "readfile"|"recover", "version": ...,
   "insunits": n, "entities": n, "paper": n}
  then one object per entity of the model space, in file order, and one per
  entity of the active paper space with "paper": true:
  LINE        "start", "end" ([x, y, z])
  ARC         "center", "radius", "start_angle", "end_angle" (degrees), "extrusion",
              and from ezdxf's geometry: "center_wcs", "start_point",
              "end_point" (world coordinates), "angle_span" (degrees)
  CIRCLE      "center", "radius", "extrusion", "center_wcs"
  LWPOLYLINE  "points" ([x, y, bulge] each), "closed", "extrusion",
              "wcs_points" ([x, y, z] each, world coordinates)
  POLYLINE    "mode" (ezdxf's get_mode()), "flags", "closed",
              "vertices" ([x, y, bulge, vertex flags] each), "extrusion",
              "wcs_points"
  ELLIPSE     "center", "major_axis", "ratio", "start_param", "end_param",
              "extrusion", "minor_axis", "start_point", "end_point",
              "param_span" (radians)
  SPLINE      "degree", "flags", "control_points", "knots", "weights",
              "fit_points", "extrusion", and "curve": ezdxf's own flattening
              of the curve (BSpline.flattening(1e-6), control points only)
  anything else: just "type" and "layer"
Every object has "type" and "layer". Numbers are printed by json (repr), so
they round-trip. Nothing here shares code with the C++ reader.

--write-sample writes a small drawing with ezdxf itself, with the entity
kinds the shared corpus lacks (SPLINE, ELLIPSE, 2D and 3D POLYLINE,
extrusion (0,0,-1), paper space, INSERT), as R2018 (default), R12 (--r12,
no LWPOLYLINE/ELLIPSE/SPLINE there) or binary DXF (--binary).
"""

import json
import math
import os
import sys

import ezdxf
from ezdxf import recover
from ezdxf.math import arc_angle_span_deg, ellipse_param_span


def vec(v):
    return [float(c) for c in v]


def describe(e):
    t = e.dxftype()
    out = {"type": t, "layer": e.dxf.layer}
    if t == "LINE":
        out.update(start=vec(e.dxf.start), end=vec(e.dxf.end))
    elif t == "ARC":
        out.update(center=vec(e.dxf.center), radius=e.dxf.radius,
                   start_angle=e.dxf.start_angle, end_angle=e.dxf.end_angle,
                   extrusion=vec(e.dxf.extrusion),
                   center_wcs=vec(e.ocs().to_wcs(e.dxf.center)),
                   start_point=vec(e.start_point), end_point=vec(e.end_point),
                   angle_span=arc_angle_span_deg(e.dxf.start_angle, e.dxf.end_angle))
    elif t == "CIRCLE":
        out.update(center=vec(e.dxf.center), radius=e.dxf.radius,
                   extrusion=vec(e.dxf.extrusion),
                   center_wcs=vec(e.ocs().to_wcs(e.dxf.center)))
    elif t == "LWPOLYLINE":
        out.update(points=[[float(x), float(y), float(b)] for x, y, b in e.get_points("xyb")],
                   closed=bool(e.closed), extrusion=vec(e.dxf.extrusion),
                   wcs_points=[vec(p) for p in e.vertices_in_wcs()])
    elif t == "POLYLINE":
        ocs = e.ocs()
        out.update(mode=e.get_mode(), flags=e.dxf.flags, closed=bool(e.is_closed),
                   vertices=[[float(v.dxf.location[0]), float(v.dxf.location[1]),
                              float(v.dxf.bulge), int(v.dxf.flags)] for v in e.vertices],
                   extrusion=vec(e.dxf.extrusion),
                   wcs_points=[vec(ocs.to_wcs(v.dxf.location)) for v in e.vertices])
    elif t == "ELLIPSE":
        out.update(center=vec(e.dxf.center), major_axis=vec(e.dxf.major_axis),
                   ratio=e.dxf.ratio, start_param=e.dxf.start_param,
                   end_param=e.dxf.end_param, extrusion=vec(e.dxf.extrusion),
                   minor_axis=vec(e.minor_axis), start_point=vec(e.start_point),
                   end_point=vec(e.end_point),
                   param_span=ellipse_param_span(e.dxf.start_param, e.dxf.end_param))
    elif t == "SPLINE":
        out.update(degree=e.dxf.degree, flags=e.dxf.flags,
                   control_points=[vec(p) for p in e.control_points],
                   knots=[float(k) for k in e.knots],
                   weights=[float(w) for w in e.weights],
                   fit_points=[vec(p) for p in e.fit_points],
                   extrusion=vec(e.dxf.extrusion))
        if len(e.control_points):
            try:
                out["curve"] = [vec(p) for p in e.construction_tool().flattening(1e-6)]
            except Exception as error:  # ezdxf refuses the definition
                out["curve_error"] = str(error)
    return out


def read(path):
    try:
        return ezdxf.readfile(path), "readfile"
    except ezdxf.DXFStructureError:
        doc, _auditor = recover.readfile(path)
        return doc, "recover"


def dump(path):
    doc, loader = read(path)
    msp = doc.modelspace()
    psp = doc.active_layout()
    model = [describe(e) for e in msp]
    paper = [dict(describe(e), paper=True) for e in psp]
    head = {"file": os.path.basename(path), "loader": loader,
            "version": doc.header.get("$ACADVER", ""),
            "insunits": doc.header.get("$INSUNITS", 0),
            "entities": len(model), "paper": len(paper)}
    sys.stdout.write(json.dumps(head) + "\n")
    for item in model + paper:
        sys.stdout.write(json.dumps(item) + "\n")


def write_sample(path, binary, r12):
    doc = ezdxf.new("R12" if r12 else "R2018")
    doc.header["$INSUNITS"] = 4
    msp = doc.modelspace()
    msp.add_line((0, 0), (10, 0), dxfattribs={"layer": "outline"})
    msp.add_line((5, 5), (5, 5), dxfattribs={"layer": "outline"})  # zero length
    msp.add_arc((1, 2), 3, 30, 290, dxfattribs={"layer": "arcs"})
    msp.add_arc((1, 2), 3, 30, 120, dxfattribs={"extrusion": (0, 0, -1)})
    msp.add_arc((0, 0), 1, 0, 90, dxfattribs={"extrusion": (0, 1, 0)})  # not in XY
    msp.add_circle((4, -3), 2.5, dxfattribs={"layer": "arcs"})
    msp.add_circle((4, -3), 1.5, dxfattribs={"extrusion": (0, 0, -1)})
    poly = msp.add_polyline2d([(0, 0), (4, 0), (4, 3), (0, 3)], dxfattribs={"layer": "poly"})
    poly.close(True)
    poly.vertices[1].dxf.bulge = 0.5
    msp.add_polyline3d([(0, 0, 0), (1, 1, 1), (2, 0, 3)])
    msp.add_point((1, 1))
    msp.add_text("label", dxfattribs={"layer": "notes"})
    block = doc.blocks.new("PART")
    block.add_line((0, 0), (1, 1))
    msp.add_blockref("PART", (20, 20))
    psp = doc.active_layout()
    psp.add_line((0, 0), (100, 100))
    psp.add_circle((50, 50), 10)
    if not r12:
        lw = msp.add_lwpolyline([(0, 0, 0.25), (5, 0, 0), (5, 5, -1), (0, 5, 0)],
                                format="xyb", dxfattribs={"layer": "poly"})
        lw.closed = True
        msp.add_lwpolyline([(0, 0, 0.5), (2, 1, 0), (3, 3, 0)], format="xyb",
                           dxfattribs={"extrusion": (0, 0, -1)})
        msp.add_ellipse((10, 10), major_axis=(4, 1), ratio=0.5, start_param=0.3,
                        end_param=4.0, dxfattribs={"layer": "curves"})
        msp.add_ellipse((-10, 10), major_axis=(0, 3), ratio=0.25)  # full
        msp.add_ellipse((0, -10), major_axis=(2, 0), ratio=0.5, start_param=0,
                        end_param=math.pi / 2, dxfattribs={"extrusion": (0, 0, -1)})
        msp.add_open_spline([(0, 0), (2, 4), (5, -1), (8, 3), (10, 0)], degree=3,
                            dxfattribs={"layer": "curves"})
        msp.add_rational_spline([(1, 0), (1, 1), (0, 1)], [1, math.sqrt(0.5), 1],
                                degree=2, dxfattribs={"layer": "curves"})
        closed = msp.add_open_spline([(0, 0), (4, 0), (4, 4), (0, 4), (0, 0), (4, 0), (4, 4)],
                                     degree=3, knots=list(range(11)))
        closed.closed = True
        msp.add_spline([(0, 0), (1, 2), (3, 2), (4, 0)])  # fit points only
    if binary:
        doc.saveas(path, fmt="bin")
    else:
        doc.saveas(path)


def main(argv):
    args = argv[1:]
    if len(args) >= 2 and args[0] == "--write-sample":
        write_sample(args[1], "--binary" in args[2:], "--r12" in args[2:])
        return 0
    if len(args) != 1:
        sys.stderr.write("usage: dxf_entities.py FILE | --write-sample FILE [--binary] [--r12]\n")
        return 2
    dump(args[0])
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
