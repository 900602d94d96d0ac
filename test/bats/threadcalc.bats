#!/usr/bin/env bats
# Command-line behaviour of threadcalc: designations as arguments and as
# records (JSON Lines, CSV order lists, bare lines), the errors, the usage
# errors, and the threading programs run through gcode-pulse. The limits are
# checked against ISO 965-2's published tables in threadcalc_oracle.bats.

bats_require_minimum_version 1.5.0

setup() {
  load test_helper
  cd "$BATS_TEST_TMPDIR"
}

@test "--help and --version" {
  run threadcalc --help
  assert_success
  for option in --input --field --kind --decimals --passes --min-last-pass --spring-passes --infeed --flank-angle \
    --stock --chamfer-margin --run-out --gcode --length --rpm --vc --max-rpm --clearance --run-in --csv; do
    assert_output --partial -- "$option"
  done
  run threadcalc --version
  assert_success
  assert_output --regexp '^threadcalc \(toolkit\) [0-9]+\.[0-9]+\.[0-9]+ \(revision [0-9A-Za-z._-]+\)$'
}

@test "the issue's published values: M30x2-6g, M30x2-6H, M6x1-6g, M10x1.5-6g" {
  run -0 bash -c 'threadcalc --decimals 6 M30x2-6g M30x2-6H M6x1-6g M10x1.5-6g > out.jsonl'
  run -0 check '
e, i, m6, m10 = rows
# The tables print 3 decimals: within half a micrometre.
t = 5e-4
assert near(e["d2_max"], 28.663, t) and near(e["d2_min"], 28.493, t), e
assert near(e["d_max"], 29.962, t) and near(e["d_min"], 29.682, t), e
assert near(i["D2_min"], 28.701, t) and near(i["D2_max"], 28.925, t), i
assert near(i["D1_min"], 27.835, t) and near(i["D1_max"], 28.210, t), i
assert near(m6["d2_max"], 5.324, t) and near(m6["d2_min"], 5.212, t) and near(m6["d_max"], 5.974, t) and near(m6["d_min"], 5.794, t)
assert near(m10["d2_max"], 8.994, t) and near(m10["d2_min"], 8.862, t) and near(m10["d_max"], 9.968, t) and near(m10["d_min"], 9.732, t)
assert e["Td2"] == 0.17 and e["es"] == -0.038, e
assert "D2_min" not in e and "d2_max" not in i
assert e["kind"] == "external" and i["kind"] == "internal"
assert e["pitch_series"] == "fine" and m6["pitch_series"] == "coarse"
' < out.jsonl
}

@test "no class: both members in ISO 965-1's medium class; M1 takes 6h/5H" {
  run -0 bash -c 'threadcalc M10 M1 > out.jsonl'
  run -0 check '
assert [r["class"] for r in rows] == ["6g", "6H", "6h", "5H"], rows
assert rows[0]["P"] == 1.5 and rows[2]["P"] == 0.25
assert rows[2]["es"] == 0
' < out.jsonl
  run -0 bash -c 'threadcalc --kind internal M10 | json-field class'
  assert_output "6H"
  run -1 threadcalc --kind internal M10-6g
  assert_output --partial "argument 1: M10x1.5-6g is an external thread's designation"
}

@test "a fit, split classes, left hand, spaces, the multiplication sign" {
  run -0 bash -c 'threadcalc "M10x1.5-6H/6g" "M30x2-5g6g" "M20 × 1.5 - 6H - LH" > out.jsonl'
  run -0 check '
fit_e, fit_i, split, lh = rows[0], rows[1], rows[2], rows[3]
assert (fit_e["kind"], fit_e["class"], fit_e["thread"]) == ("external", "6g", "M10x1.5-6g"), fit_e
assert (fit_i["kind"], fit_i["class"], fit_i["thread"]) == ("internal", "6H", "M10x1.5-6H"), fit_i
assert split["class"] == "5g6g" and split["Td"] == 0.28
assert lh["hand"] == "left" and lh["thread"] == "M20x1.5-6H-LH" and lh["kind"] == "internal"
' < out.jsonl
}

@test "a customer's CSV order list goes through in one command, its columns kept" {
  printf 'order,qty,designation\n1001,50,M8-6g\n1002,20,"M10x1,25-6H"\n1003,5,M30x2-6g\n' > orders.csv
  run -0 threadcalc --csv -i orders.csv
  assert_line --index 0 --regexp '^order,qty,designation,thread,kind,class,'
  assert_line --index 1 --regexp '^1001,50,M8-6g,M8x1.25-6g,external,6g,'
  assert_line --index 2 --regexp '^1002,20,"M10x1,25-6H",M10x1.25-6H,internal,6H,'
  [ "${#lines[@]}" -eq 4 ]
  run -0 bash -c 'threadcalc < orders.csv | json-field order'
  assert_output $'1001\n1002\n1003'
}

@test "the designation column stays where the order list has it" {
  printf 'id,designation,qty\n7,M8-6g,100\n' > mid.csv
  run -0 threadcalc --csv -i mid.csv
  assert_line --index 0 --regexp '^id,designation,qty,thread,kind,class,'
  assert_line --index 1 --regexp '^7,M8-6g,100,M8x1.25-6g,external,6g,'
}

@test "a bare list of designations and JSON Lines with another field name" {
  printf '# from the drawing\nM6\n\n# a comment\nM8x1-6H\n' | threadcalc > out.jsonl
  run -0 json-field thread < out.jsonl
  assert_output $'M6x1-6g\nM6x1-6H\nM8x1-6H'
  printf '{"part":"A","thread":"M12-6g"}\n' | threadcalc --field thread > out.jsonl
  run -0 check 'assert rows[0]["part"] == "A" and rows[0]["P"] == 1.75 and rows[0]["thread"] == "M12x1.75-6g", rows' < out.jsonl
}

@test "the issue's bad designations: one-line errors with the place, exit 1" {
  for bad in M0 Mx2 M30x0 M30x2-6q M30x2-3g; do
    run -1 threadcalc "$bad"
    [ "${#lines[@]}" -eq 1 ]
    assert_output --regexp "^threadcalc: argument 1: "
  done
  run -1 threadcalc M30x2-3g
  assert_output --partial "no major diameter tolerance Td for 3g (d has grades 4, 6 and 8)"
  run -1 threadcalc M30x2-6q
  assert_output --partial "'q' is not a tolerance position"
  run -1 threadcalc M6 M0
  assert_line --index 0 --regexp '^\{"designation":"M6"'
  assert_line --index 2 "threadcalc: argument 2: designation 'M0': diameter 0 mm is outside [0.001, 1000]"
}

@test "bad records: the file and line, records before kept" {
  printf 'designation\nM6\nM8\nM30x2-6q\nM10\n' > orders.csv
  run -1 threadcalc -i orders.csv
  [ "$(grep -c '^{' <<< "$output")" -eq 4 ]
  assert_output --partial "threadcalc: orders.csv:4: designation 'M30x2-6q'"
  # A first line that names no 'designation' column is no header: data.
  printf 'part\nA\n' > nofield.csv
  run -1 threadcalc -i nofield.csv
  assert_output --partial "threadcalc: nofield.csv:1: designation 'part'"
  printf 'part,designation\nA,\n' > nofield.csv
  run -1 threadcalc -i nofield.csv
  assert_output "threadcalc: nofield.csv:2: no 'designation' field with a designation"
  printf '{"designation":"M6"}\n{"designation":"M8","qty":3}\n' > growing.jsonl
  run -1 threadcalc --csv -i growing.jsonl
  assert_output --regexp "threadcalc: growing.jsonl:2: .*qty"
  printf '{"designation": 30}\n' > number.jsonl
  run -1 threadcalc -i number.jsonl
  assert_output --partial "number.jsonl:1: no 'designation' field"
  printf '\x89PNG\r\n\x1a\n\x00\x00\x00\rIHDR\x00\xff\n' > image.png  # a PNG's first bytes
  run -1 threadcalc -i image.png
  assert_output --regexp '^threadcalc: image.png:[0-9]+: '
  [ "${#lines[@]}" -eq 1 ]
  printf 'designation\nM6\n\x00\xff\xfeM\x01\n' > binary.csv
  run -1 threadcalc -i binary.csv
  assert_line --index 0 --partial '"thread":"M6x1-6g"'
  assert_output --regexp 'threadcalc: binary.csv:3: '
  : > empty.csv
  run -0 threadcalc -i empty.csv
  assert_output ""
  run -1 threadcalc M1e999
  run -1 threadcalc M99999999999999999999
  assert_output --partial "outside [0.001, 1000]"
  run -1 threadcalc "M$(printf '9%.0s' {1..400})"
  assert_output --partial "the diameter is out of range"
  [ "${#lines[@]}" -eq 1 ]
  run -1 threadcalc M30xnan
  run -1 threadcalc M30x2-6g-6g
  assert_output --partial "two external tolerance classes"
}

@test "a non-standard pitch and a size outside the tables are warned about, and computed" {
  run -0 --separate-stderr threadcalc M30x2.2-6g
  [[ "$stderr" == *"ISO 261 lists no 2.2 mm pitch for M30"* ]]
  [[ "$stderr" == *"Td2 is not in ISO 965-1's tables; computed by"* ]]
  run -0 check 'assert rows[0]["pitch_series"] == "non-standard" and rows[0]["computed"] == "es Td Td2", rows' <<< "$output"
  run -0 --separate-stderr threadcalc -q M30x2.2-6g
  [ -z "$stderr" ]
}

@test "usage errors exit 2" {
  run -2 threadcalc --kind sideways M10
  run -2 threadcalc --passes 1 M10
  run -2 threadcalc --flank-angle 20 M10
  run -2 threadcalc --length 20 M10
  run -2 threadcalc --gcode g76 M10-6g
  assert_output --partial "--gcode needs the thread's --length"
  run -2 threadcalc --gcode g76 --length 20 M10-6g M12-6g
  run -2 threadcalc --gcode g76 --length 20 M10x1.5-6H/6g
  run -2 threadcalc --gcode g77 --length 20 M10
  run -2 threadcalc -i x.csv M10
  run -2 threadcalc --length -1 --gcode g76 M10
  run -2 threadcalc --decimals 12 M10
  run -2 threadcalc --decimals 2 M10  # tolerances are whole micrometres
  run -2 threadcalc --gcode g76 --length 20000 M10
  assert_output --partial "--length: must be a number from 0.1 to 10000, not 20000"
  run -2 threadcalc --gcode passes --length 20 --rpm 1e9 M10
  run -2 threadcalc --gcode passes --length 20 --accel nan M10
}

@test "--gcode g76 writes LinuxCNC's cycle with the plan's words" {
  run -0 threadcalc --gcode g76 --length 40 --rpm 400 M30x2-6g
  assert_line --regexp '^G18 G21 G90 G94 G7'
  assert_line "S400 M3"
  assert_line --index 7 "G0 Z6"
  assert_line --index 8 "G0 X32.027"
  # The drive line 1 mm (radially) over the blank 30.027; I = peak 30 - drive line 32.027; K = 2 ap (diameters in G7); J = K/sqrt(8) rounded up.
  assert_line "G76 P2 Z-40 I-2.027 J0.9111 K2.5767 R2 Q0 H1 E0 L0"
  assert_line "M30"
  run -0 threadcalc --gcode g76 --length 12 --infeed flank --spring-passes 2 M16x1.5-6H
  assert_line --regexp '^G76 P1.5 Z-12 I[0-9.]+ J[0-9.]+ K[0-9.]+ R2 Q27 H2 E0 L0$'
}

@test "--gcode passes runs through gcode-pulse: every pass at its diameter, the pitch and the spindle speed" {
  threadcalc --gcode passes --length 40 --rpm 300 M30x2-6g > thread.ngc
  [ "$(grep -c '^G33 Z-40 K2$' thread.ngc)" -eq 9 ]  # 8 passes and a spring pass
  # Default machine: 5000 mm/min, 500 mm/s^2 (gcode-pulse(1)); each G33 runs
  # 46 mm at K S = 600 mm/min = 10 mm/s: 4.6 s of cruise plus 10/500 s of
  # ramps, so the nine passes take at least 9 x 4.62 s.
  gcode-pulse --summary thread.ngc > summary.json
  run -0 check '
r = rows[0]
assert r["duration_s"] > 9 * 4.62, r["duration_s"]
# The tool ends where it started: the drive line X32.027 (a radius of 16.0135), Z6.
assert near(r["final_x"], 32.027 / 2, 0.01) and near(r["final_z"], 6, 0.01), r
' < summary.json
  # Each pass's X (a diameter under G7) is 30 - 2 x its depth in the plan.
  threadcalc --decimals 6 M30x2-6g > plan.jsonl
  run -0 py '
import json, re, sys
plan = json.loads(open("plan.jsonl").readline())
depths = [float(x) for x in plan["pass_depths"].split()] + [plan["ap"]]
xs = [float(m) for m in re.findall(r"^G0 X([0-9.]+) \(", open("thread.ngc").read(), re.M)]
assert len(xs) == len(depths) and all(abs(x - (30 - 2 * d)) < 2e-4 for x, d in zip(xs, depths)), (xs, depths)
print("ok")'
  # The default speed, 100 m/min at 30 mm, is 1061 rpm; at 6 mm it stops at --max-rpm.
  run -0 threadcalc --gcode passes --length 10 M30x2-6g
  assert_line "S1061 M3"
  run -0 threadcalc --gcode passes --length 10 M6-6g
  assert_line "S3000 M3"
  run -0 bash -c 'threadcalc --gcode passes --length 10 M6-6g | gcode-pulse --summary > /dev/null'
}

@test "spellings: spaces as separators, dashes, LH on the class; S and L choose ISO 965-1's classes" {
  threadcalc "M8x1.25 6g" "M20x1.5–6gLH" "M10-S" "M10-L" > out.jsonl
  # ISO 965-1's first choices, medium quality: S 5g6g / 5H, L 7g6g / 7H.
  run -0 check '
got = [(r["thread"], r["class"]) for r in rows]
assert got == [("M8x1.25-6g", "6g"), ("M20x1.5-6g-LH", "6g"), ("M10x1.5-5g6g-S", "5g6g"), ("M10x1.5-5H-S", "5H"),
               ("M10x1.5-7g6g-L", "7g6g"), ("M10x1.5-7H-L", "7H")], got
' < out.jsonl
  run -0 --separate-stderr threadcalc M14x1.25-6H
  [[ "$stderr" == *"M14x1.25-6H: ISO 261: only for spark plugs"* ]]
}

@test "internal and left-hand programs run through gcode-pulse and end back on the drive line ahead of the face" {
  for d in M30x2-6H M30x2-6H-LH M30x2-6g-LH M3-6H; do
    threadcalc --gcode g76 --length 20 --infeed flank "$d" > g76.ngc
    run -0 bash -c "grep '^G0' g76.ngc | tail -1"
    assert_output --regexp '^G0 Z[0-9.]+$'
    threadcalc --gcode passes --length 20 --infeed flank "$d" > prog.ngc
    drive=$(grep -m1 '^G0 X' prog.ngc | cut -c5-)
    gcode-pulse --summary prog.ngc > summary.json
    run -0 check "
r = rows[0]
assert r['final_z'] > 0, r
assert near(r['final_x'], $drive / 2, 0.005), (r['final_x'], $drive)  # G7: X words are diameters
" < summary.json
  done
  # The left-hand passes start 3 P beyond the 20 mm thread, in the groove, and cut out past the face.
  threadcalc --gcode passes --length 20 M30x2-6g-LH > lh.ngc
  run -0 grep -c '^G33 Z6 K2$' lh.ngc
  assert_output 9
  run -0 grep -c '^G0 Z-26$' lh.ngc
  assert_output 9
}

@test "the run-in brings Z up to the thread's speed by the face: the step interval at Z0 is 1/(400 K S)" {
  # M10: 3000 rpm (100 m/min capped), K1.5: 75 mm/s, 400 steps/mm: 33.3 us per
  # step. gcode-pulse's 500 mm/s^2 needs 75^2/1000 = 5.625 mm to get there.
  rate='import json, sys
z, xs, last, gap = 0, 0, None, None
for line in sys.stdin:
    r = json.loads(line)
    xs += r["dx"]
    if r["dz"]:
        if r["dz"] < 0 and z > 0 >= z + r["dz"] and xs and gap is None:
            gap = r["t"] - last
        z += r["dz"]
        last = r["t"]
print(gap)'
  threadcalc --gcode passes --length 20 M10 > m10.ngc
  grep -q '^G0 Z5.625$' m10.ngc
  run -0 bash -c "gcode-pulse m10.ngc | /usr/bin/python3 -c '$rate'"
  run -0 py "assert abs($output - 1 / (400 * 75)) < 0.02 / (400 * 75), $output"
  # With too short a run-in the axis is still accelerating at the face.
  threadcalc --gcode passes --length 20 --run-in 1 M10 > short.ngc
  run -0 bash -c "gcode-pulse short.ngc | /usr/bin/python3 -c '$rate'"
  run -0 py "assert $output > 1.5 / (400 * 75), $output"
}
