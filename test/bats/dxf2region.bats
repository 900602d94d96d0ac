#!/usr/bin/env bats
# Command-line behaviour of dxf2region. Expected values come from the
# fixtures' stated geometry (test/fixtures/dxf/make_fixtures.py), closed
# forms (Steiner's formula: a convex part grown by R has area A + P R +
# pi R^2 and perimeter P + 2 pi R), the independent distance oracle
# test/oracle/plate_distance.py, the G-code oracle test/oracle/gcode_path.py,
# python3-ezdxf, and viaconstructor's contour for the corpus pair, never
# from the tool's own output captured once.

bats_require_minimum_version 1.5.0

setup() {
  load test_helper
  cd "$BATS_TEST_TMPDIR"
  DXF="$FIXTURES/dxf"
  CORPUS="$TOOLKIT_ROOT/../shared/corpus"
}

# py EXPRESSION-SCRIPT: plain python3 for arithmetic checks.
# loops FILE: "hole area length" per loop record.
loops() {
  py '
import json, sys
for line in open(sys.argv[1]):
    r = json.loads(line)
    if r["record"] == "loop":
        print(r["hole"], "%.6f" % r["area_mm2"], "%.6f" % r["length_mm"])' "$1"
}

# near A B [TOL]: |A - B| <= TOL (default 1e-6).
near() {
  py "import sys; a, b = float(sys.argv[1]), float(sys.argv[2]); sys.exit(0 if abs(a - b) <= float(sys.argv[3]) else 1)" \
    "$1" "$2" "${3:-1e-6}" || { echo "$1 is not $2 within ${3:-1e-6}"; return 1; }
}

@test "--help, --version and the man page" {
  run dxf2region --help
  assert_success
  assert_output --partial "--tool-radius"
  assert_output --partial "--check"
  run dxf2region --version
  assert_success
  assert_output --regexp '^dxf2region \(toolkit\) [0-9]+\.[0-9]+\.[0-9]+ \(revision [0-9A-Za-z._-]+\)$'
  [ -s "$TOOLKIT_ROOT/man/dxf2region.1" ]
  run grep -c "^\.SH" "$TOOLKIT_ROOT/man/dxf2region.1"
  [ "$output" -ge 8 ]
}

@test "usage errors exit 2" {
  run dxf2region
  assert_failure 2
  run dxf2region "$DXF/plate.dxf" --tool-radius -1
  assert_failure 2
  assert_output --partial "--tool-radius"
  run dxf2region "$DXF/plate.dxf" --tool-radius nan
  assert_failure 2
  run dxf2region "$DXF/plate.dxf" --toolpath --check
  assert_failure 2
  run dxf2region "$DXF/plate.dxf" --summary
  assert_failure 2
  run dxf2region "$DXF/plate.dxf" --side middle
  assert_failure 2
  run dxf2region "$DXF/plate.dxf" --units furlong
  assert_failure 2
  assert_output --partial "furlong"
  # The experiment's options: delays as time or as travel, not both; only with --simulate; no endless strokes.
  for options in "--simulate --latency 0.1 --latency-mm 1" "--simulate --period 0.1 --period-mm 1" "--latency-mm 1" \
      "--invasion-check printed" "--simulate --invasion-check nearest" "--simulate --joystick-speed 12,0" \
      "--simulate --joystick-speed 1e-300" "--simulate --period-mm 0" "--simulate --latency 1e9"; do
    run dxf2region -q "$DXF/plate.dxf" $options
    [ "$status" -eq 2 ] || { echo "$options: exit $status"; false; }
  done
}

@test "the plate's loops: areas and lengths from its stated geometry; skipped and loose entities reported" {
  run --separate-stderr dxf2region "$DXF/plate.dxf"
  assert_success
  echo "$output" > region.jsonl
  # Outer: 100 x 60 less the four corners' (4 - pi) 5^2; the bore, pi 10^2; the slot, 20 x 8 + pi 4^2.
  run loops region.jsonl
  assert_line --index 0 --regexp "^False 5978\.539816 "
  [ "${#lines[@]}" -eq 3 ]
  run py '
import json, math, sys
loops = [json.loads(l) for l in open("region.jsonl")]
loops = [r for r in loops if r["record"] == "loop"]
outer, holes = loops[0], sorted(loops[1:], key=lambda r: r["area_mm2"])
assert abs(outer["length_mm"] - (2 * (90 + 50) + 10 * math.pi)) < 1e-9, outer["length_mm"]
assert abs(holes[0]["area_mm2"] + 100 * math.pi) < 1e-9, holes[0]["area_mm2"]
assert abs(holes[1]["area_mm2"] + (160 + 16 * math.pi)) < 1e-9, holes[1]["area_mm2"]
assert all(h["hole"] and h["depth"] == 1 for h in holes)
# The polyline stays within 0.01 mm of the bore (chords inside the circle).
bore = holes[0]
for x, y in bore["polyline"]:
    assert abs(math.hypot(x - 30, y - 30) - 10) < 1e-9
print("ok")'
  assert_output "ok"
  # The TEXT is counted and reported; the stray LINE on NOTES leaves two loose ends.
  echo "$stderr" | grep -q "1 TEXT entity not used"
  run py 'import json, sys
rs = [json.loads(l) for l in open("region.jsonl")]
ends = sorted((r["x"], r["y"]) for r in rs if r["record"] == "loose_end")
print(ends)
d = rs[-1]
print(d["record"], d["entities_skipped"], d["units"], d["loops"], d["holes"])'
  assert_line --index 0 "[(-20.0, -20.0), (-10.0, -20.0)]"
  assert_line --index 1 "drawing {'TEXT': 1} \$INSUNITS 3 2"
}

@test "--layer keeps the chosen layers; a missing one is an error naming the layers" {
  run --separate-stderr dxf2region "$DXF/plate.dxf" --layer OUTLINE
  assert_success
  run py 'import json, sys; print(sum(json.loads(l)["record"] == "loose_end" for l in sys.stdin))' <<< "$output"
  assert_output "0"
  run dxf2region "$DXF/plate.dxf" --layer NOTES
  assert_failure 1
  assert_output --partial "no closed loop"
  run dxf2region "$DXF/plate.dxf" --layer HIDDEN
  assert_failure 1
  assert_output --regexp "plate.dxf.*no layer 'HIDDEN'.*OUTLINE"
}

@test "--tool-radius grows the outline (Steiner) and shrinks the holes, in exact lines and arcs" {
  run --separate-stderr dxf2region "$DXF/plate.dxf" --layer OUTLINE --tool-radius 2
  assert_success
  echo "$output" > region.jsonl
  run py '
import json, math
rs = [json.loads(l) for l in open("region.jsonl")]
loops = [r for r in rs if r["record"] == "loop"]
A, P, R = 6000 - 25 * (4 - math.pi), 280 + 10 * math.pi, 2
outer = loops[0]
assert abs(outer["area_mm2"] - (A + P * R + math.pi * R * R)) < 1e-7, outer["area_mm2"]
assert abs(outer["length_mm"] - (P + 2 * math.pi * R)) < 1e-7, outer["length_mm"]
# Four lines and four arcs of radius 7 about the corners centres.
arcs = [e for e in outer["elements"] if e["type"] == "arc"]
assert len(arcs) == 4 and all(abs(e["r"] - 7) < 1e-9 for e in arcs), arcs
holes = sorted(loops[1:], key=lambda r: r["area_mm2"])
assert abs(holes[0]["area_mm2"] + math.pi * 64) < 1e-7, holes[0]
assert abs(holes[1]["area_mm2"] + (20 * 4 + math.pi * 4)) < 1e-7, holes[1]
assert rs[-1]["polygon_loops"] == 0 and rs[-1]["uncut"] == 0
print("ok")'
  assert_output "ok"
}

@test "--side inside: the pocket shrinks, the island grows, the prohibited region lies outside" {
  run --separate-stderr dxf2region "$DXF/pocket.dxf" --tool-radius 2 --side inside
  assert_success
  echo "$output" > region.jsonl
  run py '
import json, math
loops = [json.loads(l) for l in open("region.jsonl")]
loops = [r for r in loops if r["record"] == "loop"]
areas = sorted(abs(r["area_mm2"]) for r in loops)
# The 40 x 30 pocket with corners of radius 6 shrinks to 36 x 26 with corners of 4; the island (r 5) grows to r 7.
assert abs(areas[1] - (36 * 26 - 16 * (4 - math.pi))) < 1e-7, areas
assert abs(areas[0] - 49 * math.pi) < 1e-7, areas
# The pocket boundary runs clockwise: the region (everything outside it) on its left.
big = max(loops, key=lambda r: abs(r["area_mm2"]))
assert big["area_mm2"] < 0
print("ok")'
  assert_output "ok"
  # The pocket's middle is allowed, its wall is not.
  run dxf2region "$DXF/pocket.dxf" --tool-radius 2 --side inside --check <<< '{"x": 5, "y": 5}
{"x": 20, "y": 0.5}'
  assert_success
  assert_line --index 0 --partial '"inside":false'
  assert_line --index 1 --partial '"inside":true'
  assert_line --index 1 --partial '"distance":-1.5'
  assert_line --index 1 --partial '"clamped_x":20.0,"clamped_y":2.0'
}

@test "a slot narrower than the tool closes and is reported uncut" {
  run --separate-stderr dxf2region "$DXF/notch.dxf" --tool-radius 2
  assert_success
  echo "$output" > region.jsonl
  echo "$stderr" | grep -q "out of the tool's reach"
  run py '
import json, math
rs = [json.loads(l) for l in open("region.jsonl")]
loops = [r for r in rs if r["record"] == "loop"]
# The block grown by 2 (Steiner), less the dent over the slot that neither
# corner arc reaches: twice the integral of 2 - sqrt(4 - u^2) for u in 0..1.5.
dent = 2 * (3 - (0.75 * math.sqrt(1.75) + 2 * math.asin(0.75)))
assert len(loops) == 1 and abs(loops[0]["area_mm2"] - (2400 + 400 + 4 * math.pi - dent)) < 1e-6, loops[0]["area_mm2"]
uncut = [r for r in rs if r["record"] == "uncut"]
assert uncut and all(28.5 - 1e-9 <= min(r["x0"], r["x1"]) and max(r["x0"], r["x1"]) <= 31.5 + 1e-9 for r in uncut), uncut
print("ok")'
  assert_output "ok"
}

@test "units: \$INSUNITS inches, --units when it is 0, millimetres assumed with a warning" {
  run --separate-stderr dxf2region "$DXF/square_inch.dxf"
  assert_success
  run loops <(echo "$output")
  assert_output --regexp "^False 2580\.640000 203\.200000$"
  run --separate-stderr dxf2region "$DXF/unitless.dxf" --units in
  assert_success
  run loops <(echo "$output")
  assert_output --regexp "^False 2580\.640000 "
  run --separate-stderr dxf2region "$DXF/unitless.dxf"
  assert_success
  [[ "$stderr" == *"taking millimetres"* ]]
  run loops <(echo "$output")
  assert_output --regexp "^False 4\.000000 "
  run --separate-stderr dxf2region -q "$DXF/unitless.dxf"
  [ -z "$stderr" ]
}

@test "an arc with extrusion (0, 0, -1) is mirrored into world coordinates" {
  run --separate-stderr dxf2region "$DXF/mirrored.dxf"
  assert_success
  # A quarter disc centred at (-5, 0) in the world (at (5, 0) if the extrusion were ignored).
  run py '
import json, math, sys
r = json.loads(sys.stdin.readline())
xs = [p[0] for p in r["polyline"]]
arc = [e for e in r["elements"] if e["type"] == "arc"][0]
assert abs(r["area_mm2"] - 25 * math.pi) < 1e-9 and abs(min(xs) + 15) < 1e-9 and max(xs) < -5 + 1e-9, (r["area_mm2"], xs)
assert abs(arc["cx"] + 5) < 1e-12 and abs(arc["cy"]) < 1e-12 and abs(arc["r"] - 10) < 1e-12, arc
print("ok")' <<< "$output"
  assert_output "ok"
}

@test "ELLIPSE, SPLINE and 2D POLYLINE become loops" {
  run --separate-stderr dxf2region "$DXF/shapes.dxf" --flatten-tol 0.001
  assert_success
  run py '
import json, math, sys
loops = [json.loads(l) for l in sys.stdin]
loops = sorted((r for r in loops if r["record"] == "loop"), key=lambda r: r["area_mm2"])
areas = [r["area_mm2"] for r in loops]
# The triangle: 40 x 30 / 2; the ellipse: pi 20 10 (chords inside: slightly less).
assert len(loops) == 3, areas
assert abs(areas[2] - math.pi * 200) < 0.5 and areas[2] <= math.pi * 200, areas
assert any(abs(a - 600) < 1e-9 for a in areas), areas
print("ok")' <<< "$output"
  assert_output "ok"
}

@test "loose ends and T-junctions are reported with coordinates; --join-tol closes a gap" {
  run --separate-stderr dxf2region "$DXF/open.dxf"
  assert_failure 1
  assert_equal "$(echo "$stderr" | tail -1)" "dxf2region: $DXF/open.dxf: no closed loop in the drawing"
  run py '
import json, sys
rs = [json.loads(l) for l in sys.stdin]
print(sorted((r["x"], r["y"]) for r in rs if r["record"] == "loose_end"))
print([(r["x"], r["y"]) for r in rs if r["record"] == "t_junction"])' <<< "$output"
  assert_line --index 0 "[(25.0, 0.0), (25.0, 10.0), (50.0, 24.75), (50.0, 25.25)]"
  assert_line --index 1 "[(25.0, 0.0)]"
  run --separate-stderr dxf2region "$DXF/open.dxf" --join-tol 0.6
  assert_success
  run loops <(echo "$output")
  assert_output --regexp "^False 2500\.000000 200\.000000$"
}

@test "--check against the closed-form distance oracle on 3000 random positions" {
  py '
import json, random
random.seed(5)
for i in range(3000):
    print(json.dumps({"id": i, "x": random.uniform(-15, 115), "y": random.uniform(-15, 75)}))' > positions.jsonl
  run --separate-stderr dxf2region "$DXF/plate.dxf" --layer OUTLINE --tool-radius 2 --check positions.jsonl --summary
  assert_success
  echo "$output" > got.jsonl
  /usr/bin/python3 "$TOOLKIT_ROOT/test/oracle/plate_distance.py" --grown 2 < positions.jsonl > want.jsonl
  run py '
import json
got = [json.loads(l) for l in open("got.jsonl")]
want = [json.loads(l) for l in open("want.jsonl")]
summary = got.pop()
assert len(got) == len(want) == 3000
for g, w in zip(got, want):
    assert (g["x"], g["y"]) == (w["x"], w["y"]), (g, w)
    assert abs(g["distance"] - w["expected"]) < 1e-9, (g, w)
    assert g["inside"] == w["inside"], (g, w)
invasions = sum(w["inside"] for w in want)
assert summary["positions"] == 3000 and summary["invasions"] == invasions, summary
deepest = max(-w["expected"] for w in want)
assert abs(summary["deepest_invasion_mm"] - deepest) < 1e-9, summary
print("ok", invasions)'
  assert_output --regexp "^ok [0-9]+$"
  # The barrier: every clamped position is on the grown boundary (distance 0 in the oracle).
  py 'import json
for l in open("got.jsonl"):
    r = json.loads(l)
    if "clamped_x" in r: print(json.dumps({"x": r["clamped_x"], "y": r["clamped_y"], "moved": r["inside"]}))' > clamped.jsonl
  run py '
import json, subprocess, sys
out = subprocess.run(["/usr/bin/python3", sys.argv[1], "--grown", "2"], stdin=open("clamped.jsonl"), capture_output=True, text=True).stdout
moved = [json.loads(l)["moved"] for l in open("clamped.jsonl")]
bad = [r for r, m in zip(map(json.loads, out.splitlines()), moved) if (abs(r["expected"]) > 1e-9 if m else r["expected"] < 0)]
print(len(bad), bad[:3])' "$TOOLKIT_ROOT/test/oracle/plate_distance.py"
  assert_output "0 []"
}

@test "--check passes fields through, reads CSV, and names file:line for bad positions" {
  printf 'id,x,y\na,50,-5\nb,50,1\n' > pos.csv
  run --separate-stderr dxf2region "$DXF/plate.dxf" --tool-radius 2 --check pos.csv --csv
  assert_success
  assert_line --index 0 --regexp "^id,x,y,inside,distance,clamped_x,clamped_y"
  assert_line --index 1 --regexp "^a,50,-5,false,3(\.0)?,50(\.0)?,-5(\.0)?,"
  assert_line --index 2 --regexp "^b,50,1,true,-3(\.0)?,(50(\.0*[0-9]?)?|49\.9999+[0-9]*),-(2(\.0*[0-9]?)?|1\.9999+[0-9]*),"
  printf '{"x": 50, "y": -5}\n{"x": 50}\n' > missing.jsonl
  run --separate-stderr dxf2region "$DXF/plate.dxf" --layer OUTLINE --check missing.jsonl
  assert_failure 1
  assert_equal "$(echo "$stderr" | tail -1)" "dxf2region: missing.jsonl:2: missing field 'y'"
  assert_output --partial '"x":50,"y":-5'  # the record before the error stays written
  printf 'x,y\n1,abc\n' > bad.csv
  run dxf2region "$DXF/plate.dxf" --check bad.csv
  assert_failure 1
  assert_output --partial "bad.csv:2: field 'y' is not a number"
  printf 'x,y\nnan,1\n' > nan.csv
  run dxf2region "$DXF/plate.dxf" --check nan.csv
  assert_failure 1
  assert_output --partial "nan.csv:2: field 'x' is not finite"
  printf '{"x": 1, "y": 1, "t": 2}\n{"x": 1, "y": 1, "t": 1}\n' > back.jsonl
  run dxf2region "$DXF/plate.dxf" --check back.jsonl
  assert_failure 1
  assert_output --partial "back.jsonl:2: time goes backwards"
}

@test "--check with times: the latency-aware guard orders the stop before the barrier" {
  # Straight up at the bottom edge at 50 mm/s; latency 0.05 s covers 2.5 mm.
  py '
for i in range(0, 13):
    t = i * 0.02
    print("{\"x\": 50, \"y\": %.3f, \"t\": %.2f}" % (-10 + 50 * t, t))' > pos.jsonl
  run --separate-stderr dxf2region "$DXF/plate.dxf" --tool-radius 2 --check pos.jsonl --latency 0.05 --margin 0
  assert_success
  run json-field stop <<< "$output"
  # Distances 8, 7, 6, ...: from the second record on the approach is 50 mm/s; stop once distance < 2.5.
  assert_equal "$(echo "$output" | tr '\n' ' ')" "False False False False False False True True True True True True True "
}

@test "--toolpath: G-code that gcode-pulse runs; the G-code oracle's feed length is the contours' (Steiner) plus the plunges" {
  run --separate-stderr dxf2region "$DXF/plate.dxf" --layer OUTLINE --tool-radius 2 --toolpath --cut-z -1 --safe-z 5
  assert_success
  echo "$output" > finish.ngc
  grep -q "^G21 G90 G91.1 G17 G94" finish.ngc
  run /usr/bin/python3 "$TOOLKIT_ROOT/test/oracle/gcode_path.py" finish.ngc
  assert_success
  feed=$(json-field feed_length_mm <<< "$output")
  # Outer P + 2 pi R, bore 2 pi 8, slot 2 x 20 + 2 pi 2; three plunges of 6 mm.
  expected=$(py 'import math; print(280 + 10 * math.pi + 4 * math.pi + 16 * math.pi + 40 + 4 * math.pi + 3 * 6)')
  near "$feed" "$expected" 1e-4
  run gcode-pulse --summary finish.ngc
  assert_success
  near "$(json-field final_z <<< "$output")" 5 0.003
  # Every contour point the G-code names is on the grown boundary.
  py '
import re
for line in open("finish.ngc"):
    m = re.match(r"G[123] X(\S+) Y(\S+)", line)
    if m: print("{\"x\": %s, \"y\": %s}" % m.groups())' > points.jsonl
  run --separate-stderr dxf2region "$DXF/plate.dxf" --layer OUTLINE --tool-radius 2 --check points.jsonl
  run py 'import json, sys; print(max(abs(json.loads(l)["distance"]) for l in sys.stdin) < 2e-6)' <<< "$output"
  assert_output "True"
}

@test "corpus: the viaconstructor_simple contour (4 mm tool, pyclipper) is ours, vertex for vertex" {
  [ -f "$CORPUS/dxf/viaconstructor_simple.dxf" ] || skip "no corpus at $CORPUS"
  run --separate-stderr dxf2region "$CORPUS/dxf/viaconstructor_simple.dxf" --tool-radius 2 --toolpath --direction conventional
  assert_success
  echo "$output" > ours.ngc
  run py '
import re, sys
def ends(path):
    # (motion, x, y) of every G1/G2/G3 end, X and Y modal (viaconstructor leaves out unchanged axes).
    pts, x, y = [], None, None
    for line in open(path):
        words = dict((w[0], w[1:]) for w in line.split("(")[0].split())
        x, y = float(words.get("X", x or 0)), float(words.get("Y", y or 0))
        g = words.get("G", "").lstrip("0")
        if g in ("1", "2", "3") and ("X" in words or "Y" in words):
            pts.append((g, round(x, 4), round(y, 4)))
    return sorted(pts)
ours, theirs = ends("ours.ngc"), ends(sys.argv[1])
print(len(ours), len(theirs))
print(ours == theirs or [p for p in theirs if p not in ours])' "$CORPUS/gcode/viaconstructor_simple.ngc"
  assert_line --index 1 "True"
}

@test "corpus: every DXF file reads; loops, loose ends and skipped entities are reported" {
  [ -d "$CORPUS/dxf" ] || skip "no corpus at $CORPUS"
  for f in "$CORPUS"/dxf/*.dxf; do
    run --separate-stderr dxf2region "$f" --join-tol 0.01
    # A file with no closed loop is exit 1 with the diagnostic records written.
    [ "$status" -eq 0 ] || [[ "$stderr" == *"no closed loop"* ]] || { echo "$f: $stderr"; false; }
    echo "$output" | tail -1 | grep -q '"record":"drawing"' || { echo "$f: no drawing record"; false; }
  done
}

@test "--svg writes a well-formed drawing" {
  run dxf2region "$DXF/plate.dxf" --tool-radius 2 --svg plate.svg
  assert_success
  run py 'import xml.etree.ElementTree as E; r = E.parse("plate.svg").getroot(); print(r.tag.endswith("svg"), len(r.iter().__next__()) > 0)'
  assert_output "True True"
  grep -q 'fill-rule="evenodd"' plate.svg
}

@test "--svg: a legend names each layer drawn in its own look, and the scale bar is as long as its label says" {
  run --separate-stderr dxf2region "$DXF/notch.dxf" --tool-radius 2 --svg notch.svg
  assert_success
  # The part's width in mm from the DXF (ezdxf), its drawn width from the black path: the drawing's scale.
  py '
import re, sys, ezdxf, xml.etree.ElementTree as E
N = "{http://www.w3.org/2000/svg}"
xs = [p[0] for e in ezdxf.readfile(sys.argv[1]).modelspace() for p in e.get_points("xy")]
part_mm = max(xs) - min(xs)
root = E.parse("notch.svg").getroot()
def numbers(d): return [float(v) for v in re.findall(r"-?[0-9.]+(?:e-?[0-9]+)?", d)]
part = [p for p in root.iter(N + "path") if p.get("stroke") == "black" and p.get("fill") == "none"]
assert len(part) == 1, part
drawn_x = numbers(part[0].get("d"))[0::2]
scale = (max(drawn_x) - min(drawn_x)) / part_mm  # SVG units per mm
groups = {g.get("class"): g for g in root.iter(N + "g") if g.get("class")}
bar = groups["scale-bar"]
label = bar.find(N + "text").text
m = re.fullmatch(r"([0-9]+(?:\.[0-9]+)?) mm", label)
assert m, label
length_mm = float(m.group(1))
mantissa = length_mm / 10 ** int(f"{length_mm:e}".split("e")[1])
assert round(mantissa, 9) in (1, 2, 5), length_mm
assert part_mm / 10 <= length_mm <= part_mm * 0.4, (length_mm, part_mm)
horizontal = [l for l in bar.iter(N + "line") if l.get("y1") == l.get("y2")]
assert len(horizontal) == 1
drawn = abs(float(horizontal[0].get("x2")) - float(horizontal[0].get("x1")))
assert abs(drawn - length_mm * scale) < 1e-6 * drawn, (drawn, length_mm, scale)
vx, vy, vw, vh = map(float, root.get("viewBox").split())
assert vx <= float(horizontal[0].get("x1")) and float(horizontal[0].get("x2")) <= vx + vw
# The legend: one row per layer drawn (no open segments or loose ends here), each swatch in the colour of its layer.
legend = groups["legend"]
labels = [t.text for t in legend.iter(N + "text")]
assert len(labels) == 4, labels
uncut = [p for p in root.iter(N + "path") if p.get("stroke") == "#f08000"]
region = [p for p in root.iter(N + "path") if p.get("fill-rule") == "evenodd"]
expected = {"part": ("stroke", part[0].get("stroke")), "prohibited region": ("fill", region[0].get("fill")),
            "contour": ("stroke", region[0].get("stroke")), "uncut": ("stroke", uncut[0].get("stroke"))}
swatches = [e for e in legend if e.tag != N + "text"]
for word, (attribute, colour) in expected.items():
    rows = [i for i, text in enumerate(labels) if word in text]
    assert len(rows) == 1, (word, labels)
    assert swatches[rows[0]].get(attribute) == colour, (word, swatches[rows[0]].attrib)
' "$DXF/notch.dxf"
  # With open segments and loose ends, they get rows too.
  run --separate-stderr dxf2region "$DXF/plate.dxf" --tool-radius 2 --svg plate.svg
  assert_success
  run py '
import xml.etree.ElementTree as E
N = "{http://www.w3.org/2000/svg}"
legend = [g for g in E.parse("plate.svg").getroot().iter(N + "g") if g.get("class") == "legend"][0]
print(*[t.text.split()[0] for t in legend.iter(N + "text")])'
  assert_output "part prohibited region open loose"
}

@test "--simulate: the fixed guard invades below speed x latency, the latency-aware guard never, with less under-cut" {
  run --separate-stderr dxf2region "$DXF/plate.dxf" --layer OUTLINE --tool-radius 2 --simulate --strokes 200 --tolerances 2,4,6 --joystick-speed 50
  assert_success
  run py '
import json, sys
rs = {(r["guard"], r["tolerance_mm"]): r for r in map(json.loads, sys.stdin)}
fixed2, fixed6 = rs[("fixed-tolerance", 2)], rs[("fixed-tolerance", 6)]
ours = [r for k, r in rs.items() if k[0] == "latency-aware"][0]
# 50 mm/s x 0.09 s = 4.5 mm travelled after the sample: T = 2 always invades, T = 6 never.
assert fixed2["invasions"] == 200 and fixed6["invasions"] == 0, (fixed2, fixed6)
assert ours["invasions"] == 0 and ours["success_rate"] == 1, ours
assert ours["mean_undercut_mm"] < 0.5 and ours["mean_undercut_mm"] < fixed6["mean_undercut_mm"], (ours, fixed6)
print("ok")' <<< "$output"
  assert_output "ok"
}

@test "bad DXF input: missing, empty, binary garbage, truncated, NaN and huge numbers are one-line errors with exit 1" {
  run dxf2region nonexistent.dxf
  assert_failure 1
  assert_output --regexp "^dxf2region: .*nonexistent.dxf"
  : > empty.dxf
  run dxf2region empty.dxf
  assert_failure 1
  assert_output --regexp "^dxf2region: empty.dxf"
  head -c 4000 /dev/urandom > garbage.dxf
  run dxf2region garbage.dxf
  assert_failure 1
  [ "${#lines[@]}" -eq 1 ]
  head -c 3000 "$DXF/plate.dxf" > truncated.dxf
  run dxf2region truncated.dxf
  assert_failure 1
  assert_output --regexp "^dxf2region: truncated.dxf"
  sed '0,/^AcDbLine/s//AcDbLine/; s/^60\.0$/nan/' "$DXF/plate.dxf" > nan.dxf
  grep -q '^nan$' nan.dxf
  run dxf2region nan.dxf
  assert_failure 1
  assert_output --regexp "^dxf2region: nan.dxf:[0-9]+: "
  sed 's/^60\.0$/1e400/' "$DXF/plate.dxf" > huge.dxf
  run dxf2region huge.dxf
  assert_failure 1
  assert_output --regexp "^dxf2region: huge.dxf:[0-9]+: "
  run dxf2region - < "$DXF/plate.dxf"
  assert_success
  # A square 2 km across (metres taken for millimetres?) is refused with its line.
  printf '0\nSECTION\n2\nENTITIES\n0\nLWPOLYLINE\n8\n0\n90\n4\n70\n1\n10\n0\n20\n0\n10\n2e6\n20\n0\n10\n2e6\n20\n2e6\n10\n0\n20\n2e6\n0\nENDSEC\n0\nEOF\n' > huge_part.dxf
  run dxf2region -q huge_part.dxf --tool-radius 1
  assert_failure 1
  assert_output "dxf2region: huge_part.dxf:5: an element spans more than 1 km (2e+06 mm): too large to machine; are the units right?"
}

@test "the fuzzers' regressions run clean: exit 0, or exit 1 with a one-line error" {
  shopt -s nullglob
  for f in "$TOOLKIT_ROOT"/fuzz/regressions/fuzz_dxf/* "$TOOLKIT_ROOT"/fuzz/regressions/fuzz_region/*; do
    # fuzz_region's inputs start with an option byte: bits 0-1 the radius, bit 2 the side.
    options=(--tool-radius 2)
    if [[ "$f" == */fuzz_region/* ]]; then
      byte=$(od -An -tu1 -N1 "$f" | tr -d ' ')
      radii=(0 0.5 2 7)
      sides=(outside inside)
      options=(--tool-radius "${radii[$((byte & 3))]}" --side "${sides[$(((byte >> 2) & 1))]}")
      tail -c +2 "$f" > part.dxf
    else
      cp "$f" part.dxf
    fi
    run --separate-stderr dxf2region -q part.dxf "${options[@]}"
    [ "$status" -le 1 ] || { echo "$f: exit $status"; false; }
    if [ "$status" -eq 1 ]; then
      [ "$(echo "$stderr" | wc -l)" -eq 1 ] && [[ "$stderr" == "dxf2region: "* ]] || { echo "$f: $stderr"; false; }
    fi
  done
}

@test "option ranges and the offset's size are checked before the offset; far positions and vanishing loops are reported" {
  load bounded_run
  bounded dxf2region --tool-radius 1e10 "$DXF/plate.dxf"
  assert_failure 2
  assert_output --partial "--tool-radius: must be a number from 0 to 1000, not 1e+10"
  bounded dxf2region --tool-radius 1e300 "$DXF/plate.dxf"
  assert_failure 2
  assert_output --partial "--tool-radius: must be a number from 0 to 1000, not 1e+300"
  bounded dxf2region --tool-radius 10 --offset-tol 1e-6 "$DXF/plate.dxf"
  assert_failure 2
  assert_output --partial "--offset-tol: must be a number from 0.0001 to 1, not 1e-06"
  # Two circles 980 m across (each element under the 1 km limit), offset at
  # 0.1 um by a 1 m tool: each half circle needs pi/2 sqrt(491000 / 2e-4)
  # ~ 77,800 chords, 311,000 for the four; the corners 7,000 more.
  py 'import math; n = 4 * math.pi / 2 * math.sqrt(491000 / 2e-4) + 2 * math.pi * math.sqrt(1000 / 2e-4) + 4; assert 3.2e5 < n < 3.3e5, n'
  circle() { printf '0\nLWPOLYLINE\n8\n0\n90\n2\n70\n1\n10\n%s\n20\n0\n42\n1\n10\n%s\n20\n0\n42\n1\n' "$1" "$2"; }
  { printf '0\nSECTION\n2\nENTITIES\n'; circle 0 980000; circle 2000000 2980000; printf '0\nENDSEC\n0\nEOF\n'; } > big_arcs.dxf
  bounded dxf2region -q --tool-radius 1000 big_arcs.dxf
  assert_failure 2
  assert_output --partial "--tool-radius, --offset-tol and the drawing's arcs imply 3.2"
  assert_output --partial "offset polygon vertices, more than the 300000 this tool allows"
  # A tool position 1e300 mm out: bad data with its line, not "distance":null.
  printf 'x,y\n1,1\n1e300,0\n' > far.csv
  bounded dxf2region -q --check far.csv "$DXF/plate.dxf"
  assert_failure 1
  assert_output --partial "dxf2region: far.csv:3: position 1e+300 mm is beyond ±1e+09 mm"
  # A closed polyline 0.1 um square vanishes under --join-tol 0.001: said, with its line.
  printf '0\nSECTION\n2\nENTITIES\n0\nLWPOLYLINE\n5\n2A\n8\n0\n90\n4\n70\n1\n10\n0\n20\n0\n10\n0.0001\n20\n0\n10\n0.0001\n20\n0.0001\n10\n0\n20\n0.0001\n0\nLWPOLYLINE\n8\n0\n90\n4\n70\n1\n10\n10\n20\n10\n10\n20\n20\n10\n10\n20\n20\n20\n10\n10\n20\n20\n0\nENDSEC\n0\nEOF\n' > vanish.dxf
  run --separate-stderr dxf2region --units mm vanish.dxf
  assert_success
  [[ "$stderr" == *"dxf2region: vanish.dxf:5: entity 0 vanishes: every segment of it is shorter than --join-tol 0.001 mm"* ]] || { echo "$stderr"; false; }
}
