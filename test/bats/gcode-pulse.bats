#!/usr/bin/env bats
# Command-line behaviour of gcode-pulse: usage, the fixtures and the corpus
# against the independent oracle (test/oracle/gcode_path.py, compared by
# test/bin/compare-gcode-oracle) and against the hand-computed expectations
# in the fixtures' comments, the pulse stream's consistency, the deviation
# of the stepping methods, CNC-style errors, unused words, units and a long
# streamed program. Expected values come from the oracle, the fixtures'
# hand computations or arithmetic done here, never from the tool itself.

bats_require_minimum_version 1.5.0

setup() {
  load test_helper
  cd "$BATS_TEST_TMPDIR"
  GCODE="$FIXTURES/gcode"
  CORPUS="$TOOLKIT_ROOT/../shared/corpus/gcode"
  ORACLE="$TOOLKIT_ROOT/test/oracle/gcode_path.py"
}

METHODS="nearest direct bresenham dda"
# Acceleration, junction limits and the feed cap made to vanish, so that the
# duration is the oracle's: feed moves at their feed, rapids at --rapid.
NO_ACCEL="--accel 1e12 --junction-deviation 1e6 --max-feed 1e12 --rapid 5000"

# oracle FILE...: the oracle's records, one per file.
oracle() {
  /usr/bin/python3 "$ORACLE" "$@"
}

need_corpus() {
  [ -d "$CORPUS" ] || skip "no G-code corpus at $CORPUS"
}

# corpus_files: the corpus' files in the order of corpus_expected.jsonl.
corpus_files() {
  json-field file < "$GCODE/corpus_expected.jsonl" | sed "s|^|$CORPUS/|"
}

# G43 needs the tool's length (cds.ngc asks for tool 1's): tools of no length
# leave the path where the words put it, as the oracle, which knows no tool
# offsets, has it (gcode-pulse_rs274_oracle.bats tests real lengths).
NO_LENGTH_TOOLS="$BATS_TEST_DIRNAME/../fixtures/gcode/linuxcnc/zero_length_tools.tbl"

# summaries OUT METHOD OPTIONS FILE...: one --summary record per file into OUT.
summaries() {
  local out=$1 method=$2 options=$3 file
  shift 3
  : > "$out"
  for file in "$@"; do
    # shellcheck disable=SC2086
    gcode-pulse --summary --method "$method" --tool-table "$NO_LENGTH_TOOLS" $options "$file" >> "$out" ||
      { echo "gcode-pulse failed on $file"; return 1; }
  done
}

# field NAME < summary: one field of a single summary record.
field() {
  json-field "$1"
}

# sums < pulses.jsonl: "SX SY SZ" of the dx, dy, dz of a JSON Lines pulse stream.
sums() {
  python3 -c '
import json, sys
s = [0, 0, 0]
for line in sys.stdin:
    if line.strip():
        r = json.loads(line)
        s = [s[0] + r["dx"], s[1] + r["dy"], s[2] + r["dz"]]
print(*s)'
}

# check_stream SUMMARY PULSES.jsonl PULSES.csv STEPS: the pulse stream against
# its summary and its CSV twin (see the test "pulse streams ..."). Prints the
# problems and fails if any.
check_stream() {
  python3 - "$@" <<'PY'
import csv, json, sys
summary = json.load(open(sys.argv[1]))
steps = [float(v) for v in sys.argv[4].split(",")]
rows = [json.loads(line) for line in open(sys.argv[2])]
table = list(csv.reader(open(sys.argv[3])))
bad = []
if table[0] != ["t", "dx", "dy", "dz"]:
    bad.append("CSV header %r" % table[0])
if len(table) - 1 != len(rows):
    bad.append("%d CSV rows, %d JSON records" % (len(table) - 1, len(rows)))
for i, (r, c) in enumerate(zip(rows, table[1:])):
    if [float(c[0]), int(c[1]), int(c[2]), int(c[3])] != [r["t"], r["dx"], r["dy"], r["dz"]]:
        bad.append("record %d: JSON %r, CSV %r" % (i, r, c))
        break
total, moved, last = [0, 0, 0], [0, 0, 0], 0.0
for i, r in enumerate(rows):
    d = [r["dx"], r["dy"], r["dz"]]
    if any(v not in (-1, 0, 1) for v in d) or d == [0, 0, 0]:
        bad.append("record %d is no unit move: %r" % (i, r))
        break
    if r["t"] < last:
        bad.append("record %d: t %r after %r" % (i, r["t"], last))
        break
    last = r["t"]
    for axis in range(3):
        total[axis] += d[axis]
        moved[axis] += d[axis] != 0
for axis, name in enumerate("xyz"):
    want = summary["final_" + name] * steps[axis]  # the start is 0,0,0
    if abs(want - round(want)) > 1e-6 or total[axis] != round(want):
        bad.append("d%s sums to %d, final_%s %r" % (name, total[axis], name, summary["final_" + name]))
    if moved[axis] != summary["pulses_" + name]:
        bad.append("%d records move %s, pulses_%s %d" % (moved[axis], name, name, summary["pulses_" + name]))
if len(rows) != summary["events"]:
    bad.append("%d records, events %d" % (len(rows), summary["events"]))
if rows and rows[-1]["t"] > summary["duration_s"]:
    bad.append("last t %r after duration_s %r" % (rows[-1]["t"], summary["duration_s"]))
if not rows:
    bad.append("no pulses")
print("\n".join(bad))
sys.exit(1 if bad else 0)
PY
}

# The program every error test starts with: the bad line comes third, after
# a move to X1.5 Y-0.5 = 300 and -100 steps at the default 200 steps/mm.
PREFIX='G21 G90\nG1 X1.5 Y-0.5 F600\n'

# bad_program LINE...: writes $PREFIX and the lines as bad.ngc.
bad_program() {
  { printf '%b' "$PREFIX"; printf '%s\n' "$@"; } > bad.ngc
}

# assert_prefix_ran: after a failed run, the prefix' pulses were written:
# stdout holds pulses and they end at X1.5 Y-0.5 Z0.
assert_prefix_ran() {
  [ -n "$output" ]
  run_sums=$(sums <<< "$output")
  [ "$run_sums" = "300 -100 0" ] || { echo "pulses before the bad line sum to $run_sums"; false; }
}

# assert_cnc_error LINE REGEXP: exit 1, one "gcode-pulse: bad.ngc:LINE: message" line.
assert_cnc_error() {
  assert_failure 1
  [[ "$stderr" =~ ^gcode-pulse:\ bad\.ngc:$1:\ $2 ]] || { echo "stderr: $stderr"; false; }
  [ "$(printf '%s\n' "$stderr" | wc -l)" -eq 1 ]
}

# ------------------------------------------------------------ help, version, usage

@test "--help prints usage on stdout and exits 0" {
  run --separate-stderr gcode-pulse --help
  assert_success
  assert_output --partial "Usage: gcode-pulse"
  for option in --steps-per-mm --method nearest direct bresenham dda --summary --lenient --accel --rapid --max-feed \
    --junction-deviation --lookahead --csv; do
    assert_output --partial -- "$option"
  done
  [ -z "$stderr" ]
}

@test "--version names the tool" {
  run --separate-stderr gcode-pulse --version
  assert_success
  assert_output --regexp '^gcode-pulse \(toolkit\) [0-9]+\.[0-9]+\.[0-9]+ \(revision [0-9A-Za-z._-]+\)$'
  [ -z "$stderr" ]
}

@test "unknown options, bad --method, bad --steps-per-mm and a negative --accel are usage errors with exit 2" {
  printf 'G1 X1 F100\n' > ok.ngc
  for args in "--no-such-option" "--method closest" "--method Direct" "--method" \
    "--steps-per-mm 0,200,400" "--steps-per-mm 1,2" "--steps-per-mm a,b,c" "--steps-per-mm nan,1,1" \
    "--steps-per-mm -5,1,1" "--steps-per-mm inf,1,1" "--steps-per-mm 1,2,3,4" "--steps-per-mm 200,,400" \
    "--accel -1" "--accel 0" "--rapid 0" "--lookahead 0" "--junction-deviation -1" \
    "--axis-max-feed 1,0,1" "--axis-accel 1,1" "--axis-accel 1,-1,1" "--start 1,2" "--start 1e9,0,0" "--start x,0,0"; do
    # shellcheck disable=SC2086
    run --separate-stderr gcode-pulse $args ok.ngc
    [ "$status" -eq 2 ] || { echo "$args: exit $status"; false; }
    [ -z "$output" ] || { echo "$args: stdout $output"; false; }
    [[ "$stderr" == *"Try 'gcode-pulse --help' for more information."* ]] || { echo "$args: $stderr"; false; }
  done
  run --separate-stderr gcode-pulse --steps-per-mm 1,2 ok.ngc
  [[ "$stderr" == *"--steps-per-mm"* ]]
  run --separate-stderr gcode-pulse --accel -1 ok.ngc
  [[ "$stderr" == *"--accel"* ]]
}

# ------------------------------------------------------------ machine description

# The arithmetic: 200 steps/mm and 10 mm make 2000 X pulses; with 100
# steps/mm, 1000. Durations without acceleration are length / speed.
@test "--start puts the machine there: a move to where it stands makes no pulses, the way back does" {
  printf 'G90 G1 X10 Y-5 F600\nG1 X0 Y0\n' > back.ngc
  run --separate-stderr gcode-pulse --summary --start 10,-5,2 back.ngc
  assert_success
  [ "$(field pulses_x <<< "$output")" = 2000 ]
  [ "$(field pulses_y <<< "$output")" = 1000 ]
  [ "$(field pulses_z <<< "$output")" = 0 ]
  [ "$(field final_z <<< "$output")" = 2.0 ]
  [ "$(field final_x <<< "$output")" = 0.0 ]
}

@test "--axis-max-feed caps G0 and G1 by each axis' share; --axis-accel likewise" {
  # G0 Z-10 at Z's 300 mm/min (5 mm/s): 2 s; X at 6000 mm/min is not involved.
  printf 'G0 Z-10\n' > z.ngc
  run --separate-stderr gcode-pulse --summary $NO_ACCEL --axis-max-feed 6000,6000,300 z.ngc
  assert_success
  python3 -c "import sys; d = float(sys.argv[1]); sys.exit(0 if abs(d - 2.0) < 1e-9 else 1)" "$(field duration_s <<< "$output")"
  [ "$(field feed_capped_blocks <<< "$output")" = 0 ]
  # G1 at 45 degrees in XY, F6000 (100 mm/s), X limited to 600 mm/min (10
  # mm/s): the path runs at 10/cos45 = 14.142 mm/s over 100 mm; capped.
  printf 'G1 X70.71067811865476 Y70.71067811865476 F6000\n' > diagonal.ngc
  run --separate-stderr gcode-pulse --summary $NO_ACCEL --axis-max-feed 600,6000,6000 diagonal.ngc
  python3 -c "import sys, math; d = float(sys.argv[1]); sys.exit(0 if abs(d - 100 / (10 * math.sqrt(2))) < 1e-6 else 1)" \
    "$(field duration_s <<< "$output")"
  [ "$(field feed_capped_blocks <<< "$output")" = 1 ]
  # X alone at 10 mm/s, accelerating at X's 100 mm/s^2: 100/10 + 10/100 s.
  printf 'G1 X100 F600\n' > x.ngc
  run --separate-stderr gcode-pulse --summary --accel 1e6 --axis-accel 100,1e6,1e6 x.ngc
  python3 -c "import sys; d = float(sys.argv[1]); sys.exit(0 if abs(d - 10.1) < 1e-9 else 1)" "$(field duration_s <<< "$output")"
}

@test "--machine FILE: its settings apply, options given on the command line win" {
  cat > router.json <<'JSON'
{"name": "router", "# note": "a comment", "steps_per_mm": [100, 100, 50], "start": [5, 0, 0],
 "rapid": 6000, "accel": 1e12, "junction_deviation": 1e6, "max_feed": 1e12, "lookahead": 16}
JSON
  printf 'G0 X15\n' > x.ngc
  run --separate-stderr gcode-pulse --summary --machine router.json x.ngc
  assert_success
  [ "$(field pulses_x <<< "$output")" = 1000 ]
  # 10 mm at 6000 mm/min: 0.1 s.
  python3 -c "import sys; d = float(sys.argv[1]); sys.exit(0 if abs(d - 0.1) < 1e-9 else 1)" "$(field duration_s <<< "$output")"
  run --separate-stderr gcode-pulse --summary --machine router.json --steps-per-mm 200,200,400 --rapid 3000 x.ngc
  [ "$(field pulses_x <<< "$output")" = 2000 ]
  python3 -c "import sys; d = float(sys.argv[1]); sys.exit(0 if abs(d - 0.2) < 1e-9 else 1)" "$(field duration_s <<< "$output")"
}

@test "a bad machine file: its name in a one-line error, exit 1" {
  printf 'G0 X1\n' > x.ngc
  printf '{"steps_per_mm": [100, 100]}' > short.json
  printf '{"acel": 500}' > misspelt.json
  printf '{"accel": -5}' > negative.json
  printf '{"steps_per_mm": [100, 100, 100]' > truncated.json
  printf '[1, 2, 3]' > list.json
  head -c 300 /dev/urandom > garbage.json
  for file in short.json misspelt.json negative.json truncated.json list.json garbage.json missing.json; do
    run --separate-stderr gcode-pulse --machine "$file" x.ngc
    [ "$status" -eq 1 ] || { echo "$file: exit $status"; false; }
    [[ "$stderr" =~ ^gcode-pulse:\ $file:\  ]] || { echo "$file: $stderr"; false; }
    [ "$(wc -l <<< "$stderr")" -eq 1 ]
  done
  run --separate-stderr gcode-pulse --machine misspelt.json x.ngc
  [[ "$stderr" == *"unknown key 'acel'"* ]]
}

@test "--svg draws the ideal and the stepped path inside --window; either alone is a usage error" {
  run --separate-stderr gcode-pulse --summary --svg path.svg --window -1,-1,16,16 "$GCODE/square_g91.ngc"
  assert_success
  # Well-formed SVG; every drawn point inside the window (SVG coordinates
  # start at the window's top left: x_svg = x + 1, y_svg = 16 - y); the
  # square's four corners are on both paths.
  /usr/bin/python3 - path.svg <<'PY'
import re, sys, xml.etree.ElementTree as ET
root = ET.parse(sys.argv[1]).getroot()
paths = [p.get("d") for p in root.iter("{http://www.w3.org/2000/svg}path")]
assert len(paths) >= 2, paths
for d in paths:
    points = [(float(x) - 1, 16 - float(y)) for x, y in re.findall(r"[ML]([-0-9.e]+) ([-0-9.e]+)", d)]
    assert points, d[:80]
    assert all(-1 - 1e-9 <= x <= 16 + 1e-9 and -1 - 1e-9 <= y <= 16 + 1e-9 for x, y in points), "outside the window"
    for corner in ((5, 5), (15, 15), (15, 5), (5, 15)):
        assert min(abs(x - corner[0]) + abs(y - corner[1]) for x, y in points) < 0.02, corner
PY
  run --separate-stderr gcode-pulse --svg path.svg "$GCODE/square_g91.ngc"
  [ "$status" -eq 2 ]
  run --separate-stderr gcode-pulse --window 0,0,1,1 "$GCODE/square_g91.ngc"
  [ "$status" -eq 2 ]
  run --separate-stderr gcode-pulse --svg path.svg --window 0,0,1 "$GCODE/square_g91.ngc"
  [ "$status" -eq 2 ]
  [[ "$stderr" == *"--window needs X0,Y0,X1,Y1"* ]]
}

# ------------------------------------------------------------ fixtures

@test "fixtures: every summary matches the oracle (position, path, duration) for all four methods" {
  skip_volume_when_sanitized
  oracle "$GCODE"/*.ngc > oracle.jsonl
  [ "$(wc -l < oracle.jsonl)" -eq "$(ls "$GCODE"/*.ngc | wc -l)" ]
  for method in $METHODS; do
    summaries "$method.jsonl" "$method" "$NO_ACCEL" "$GCODE"/*.ngc
    run compare-gcode-oracle "$method.jsonl" oracle.jsonl 200,200,400 5000 time
    [ "$status" -eq 0 ] || { echo "--method $method:"; echo "$output"; false; }
  done
  # Other lattices too: the final position within half a step of each axis.
  for steps in 80,80,400 57.3,113,25; do
    summaries odd.jsonl direct "$NO_ACCEL --steps-per-mm $steps" "$GCODE"/*.ngc
    run compare-gcode-oracle odd.jsonl oracle.jsonl "$steps" 5000 time
    [ "$status" -eq 0 ] || { echo "--steps-per-mm $steps:"; echo "$output"; false; }
  done
}

# Each fixture's "; expect final X Y Z feed_length L" and "; expect
# rapid_length R ... duration_s D dwell_s W" lines were computed by hand:
# the final position (within half a step), path_mm = L + R (given to 6
# decimals) and, with acceleration gone, duration_s = D + R / (5000/60) + W.
@test "fixtures: the hand-computed expectations in their comments hold for all four methods" {
  skip_volume_when_sanitized
  for method in $METHODS; do
    summaries "$method.jsonl" "$method" "$NO_ACCEL" "$GCODE"/*.ngc
    run python3 - "$method.jsonl" "$GCODE"/*.ngc <<'PY'
import json, os, re, sys
bad = []
for line, path in zip(open(sys.argv[1]), sys.argv[2:]):
    got = json.loads(line)
    text = open(path).read()
    name = os.path.basename(path)
    first = re.search(r"^; expect final (\S+) (\S+) (\S+) feed_length (\S+)", text, re.M)
    second = re.search(r"^; expect rapid_length (\S+) .*duration_s (\S+) dwell_s (\S+)", text, re.M)
    x, y, z, feed = map(float, first.groups())
    rapid, duration, dwell = map(float, second.groups())
    for axis, want, step in (("x", x, 1 / 200), ("y", y, 1 / 200), ("z", z, 1 / 400)):
        if abs(got["final_" + axis] - want) > step / 2:
            bad.append("%s: final_%s %r, by hand %r" % (name, axis, got["final_" + axis], want))
    if abs(got["path_mm"] - (feed + rapid)) > 2e-6:
        bad.append("%s: path_mm %r, by hand %r + %r" % (name, got["path_mm"], feed, rapid))
    expected = duration + rapid / (5000 / 60) + dwell
    if abs(got["duration_s"] - expected) > 2e-6 * max(1, expected):
        bad.append("%s: duration_s %r, by hand %r" % (name, got["duration_s"], expected))
    if abs(got["dwell_s"] - dwell) > 1e-9:
        bad.append("%s: dwell_s %r, by hand %r" % (name, got["dwell_s"], dwell))
print("\n".join(bad))
sys.exit(1 if bad else 0)
PY
    [ "$status" -eq 0 ] || { echo "--method $method:"; echo "$output"; false; }
  done
}

# ------------------------------------------------------------ corpus

@test "corpus: every file runs without error with default options (and a tool table) for all four methods" {
  skip_volume_when_sanitized  # the summaries test below steps the corpus by all four methods
  need_corpus
  [ "$(corpus_files | wc -l)" -eq "$(ls "$CORPUS" | wc -l)" ]
  for method in $METHODS; do
    for file in $(corpus_files); do
      rc=0
      gcode-pulse --method "$method" --tool-table "$NO_LENGTH_TOOLS" "$file" > pulses.jsonl 2> stderr.txt || rc=$?
      [ "$rc" -eq 0 ] || { echo "$file --method $method: exit $rc: $(cat stderr.txt)"; false; }
      [ -s pulses.jsonl ]
      [ ! -s stderr.txt ] || { echo "$file --method $method: $(cat stderr.txt)"; false; }
    done
  done
}

@test "corpus: summaries match corpus_expected.jsonl and the oracle run live, for all four methods" {
  need_corpus
  # shellcheck disable=SC2046
  oracle $(corpus_files) > live.jsonl
  # The stored expectations are the oracle's output for these very files.
  run python3 -c '
import json, sys
a = [json.loads(l) for l in open(sys.argv[1])]
b = [json.loads(l) for l in open(sys.argv[2])]
sys.exit(0 if a == b else 1)' live.jsonl "$GCODE/corpus_expected.jsonl"
  assert_success
  for method in $METHODS; do
    # shellcheck disable=SC2046
    summaries "$method.jsonl" "$method" "$NO_ACCEL" $(corpus_files)
    for want in "$GCODE/corpus_expected.jsonl" live.jsonl; do
      run compare-gcode-oracle "$method.jsonl" "$want" 200,200,400 5000 time
      [ "$status" -eq 0 ] || { echo "--method $method vs $want:"; echo "$output"; false; }
    done
  done
}

# ------------------------------------------------------------ pulse stream

# Sums of dx, dy, dz = the summary's final position times the steps per mm
# (from 0,0,0); every record one of the 26 unit moves; t never decreasing
# and never after duration_s; the --csv stream the same numbers; as many
# records as events and as moves of each axis as pulses_x/y/z.
@test "pulse streams: sums, unit moves, time order, JSON Lines = CSV, one record per event" {
  skip_volume_when_sanitized
  for name in helix g18_arc g19_arc inch inverse_time dwell square_g91; do
    file="$GCODE/$name.ngc"
    for method in $METHODS; do
      gcode-pulse --summary --method "$method" "$file" > summary.json
      gcode-pulse --method "$method" "$file" > pulses.jsonl
      gcode-pulse --csv --method "$method" "$file" > pulses.csv
      run check_stream summary.json pulses.jsonl pulses.csv 200,200,400
      [ "$status" -eq 0 ] || { echo "$name --method $method:"; echo "$output"; false; }
    done
  done
  # The sums also land on the oracle's final position (helix: -5 0 -7 mm).
  run bash -c "gcode-pulse '$GCODE/helix.ngc' | python3 -c '
import json, sys
s = [0, 0, 0]
for line in sys.stdin:
    r = json.loads(line); s = [s[0] + r[\"dx\"], s[1] + r[\"dy\"], s[2] + r[\"dz\"]]
print(*s)'"
  assert_output "-1000 0 -2800"
  # Another lattice.
  gcode-pulse --summary --steps-per-mm 80,113,25 "$GCODE/helix.ngc" > summary.json
  gcode-pulse --steps-per-mm 80,113,25 "$GCODE/helix.ngc" > pulses.jsonl
  gcode-pulse --csv --steps-per-mm 80,113,25 "$GCODE/helix.ngc" > pulses.csv
  run check_stream summary.json pulses.jsonl pulses.csv 80,113,25
  [ "$status" -eq 0 ] || { echo "$output"; false; }
}

# ------------------------------------------------------------ deviation from the ideal path

# deviations FILE...: "name nearest_max bresenham_max nearest_rms bresenham_rms" per file.
deviations() {
  summaries nearest.jsonl nearest "" "$@"
  summaries bresenham.jsonl bresenham "" "$@"
  python3 -c '
import json, os, sys
names = sys.argv[3:]
for name, d, b in zip(names, map(json.loads, open(sys.argv[1])), map(json.loads, open(sys.argv[2]))):
    print(os.path.basename(name), repr(d["max_deviation_mm"]), repr(b["max_deviation_mm"]),
          repr(d["rms_deviation_mm"]), repr(b["rms_deviation_mm"]))' nearest.jsonl bresenham.jsonl "$@"
}

# The nearest method follows the ideal path at least as closely as
# Bresenham. Measured (mm, default steps 200,200,400):
#   file                             max nearest max bresenham  rms nearest rms bresenham
#   gcoders_estlcam_circle_a.gcode   0.003330    0.004938       0.001475    0.001599
#   gcoders_tweakie_program_3.gcode  0.002824    0.004889       0.001309    0.001557
#   linuxcnc_3dtest.ngc              0.002485    0.002485       0.001005    0.001005
#   linuxcnc_arcspiral.ngc           0.003296    0.003925       0.001304    0.001312
#   linuxcnc_cds.ngc                 0.002838    0.004980       0.001059    0.001125
#   linuxcnc_tort.ngc                0.003643    0.006909       0.001715    0.001857
#   viaconstructor_simple.ngc        0.002495    0.004333       0.001352    0.002005
# On the corpus the claim holds for both measures.
@test "nearest vs bresenham on the corpus: nearest's max and rms deviation are never larger" {
  need_corpus
  # shellcheck disable=SC2046
  deviations $(corpus_files) > dev.txt
  cat dev.txt
  run awk '$2 > $3 || $4 > $5 { print "nearest deviates more on " $0 }' dev.txt
  assert_output ""
  [ "$(wc -l < dev.txt)" -eq "$(corpus_files | wc -l)" ]
}

# On the fixtures the claim does NOT hold everywhere. Measured (mm):
#   fixture          max nearest max bresenham  rms nearest rms bresenham
#   g18_arc.ngc      0.003511    0.003483       0.001218    0.001213
#   g19_arc.ngc      0.003383    0.003414       0.001271    0.001268
#   helix.ngc        0.003114    0.002680       0.001508    0.001462
# all three helices (an arc whose normal axis moves: the nearest method weighs
# the axial error, Bresenham lets the normal axis follow on its own). On
# every other fixture both methods give the same numbers, e.g. half_circle_r
# 0.002438/0.001305, full_circle_ij 0.002489/0.001260, straight lines
# (dwell, program_end, square_g91, mach3_g70_g71) 0 and 0.
# What holds: nearest is never worse on the fixtures without a helix, and on
# the helical ones within 25% (max) and 5% (rms) of Bresenham.
@test "nearest vs bresenham on the fixtures: never worse without a helix, within 25% (max) and 5% (rms) with one" {
  skip_volume_when_sanitized
  deviations "$GCODE"/*.ngc > dev.txt
  cat dev.txt
  helical=" g18_arc.ngc g19_arc.ngc helix.ngc "
  run awk -v helical="$helical" '
    index(helical, " " $1 " ") == 0 && ($2 > $3 || $4 > $5) { print "nearest deviates more on " $0 }
    $2 > 1.25 * $3 || $4 > 1.05 * $5 { print "nearest far worse on " $0 }' dev.txt
  assert_output ""
}

# One step diagonal: sqrt(3)/200 = 0.00866 mm. Measured maxima on the
# fixtures: nearest 0.003511 (g18_arc), bresenham 0.003483 (g18_arc), dda
# 0.003679 (g19_arc); on the corpus 0.003643 (nearest, tort), 0.006909
# (bresenham, tort), 0.006384 (dda, tort). No exception. (Arcs of a radius
# of one or two steps can exceed it: not in the fixtures or the corpus.)
# The paper's direct method is not held to it: on its lines each minor axis
# falls behind by up to an eighth of the major axis' steps
# (gcode-pulse_paper_oracle.bats).
@test "every method but the paper's direct keeps max_deviation_mm below one step diagonal on the fixtures (and the corpus)" {
  skip_volume_when_sanitized
  files=("$GCODE"/*.ngc)
  if [ -d "$CORPUS" ]; then mapfile -t -O "${#files[@]}" files < <(corpus_files); fi
  for method in nearest bresenham dda; do
    summaries "$method.jsonl" "$method" "" "${files[@]}"
    paste <(printf '%s\n' "${files[@]}") <(field max_deviation_mm < "$method.jsonl") > max.txt
    run awk -v m="$method" '$2 >= sqrt(3) / 200 || $2 < 0 { print m ": " $0 }' max.txt
    assert_output ""
  done
}

# ------------------------------------------------------------ errors as a CNC control gives them

@test "two G codes of one modal group: FILE:LINE error, exit 1, the blocks before it ran" {
  for pair in "G0 G1 X5" "G17 G18" "G20 G21" "G90 G91" "G2 G3 X1 Y1 R1"; do
    bad_program "$pair"
    run --separate-stderr gcode-pulse bad.ngc
    assert_cnc_error 3 '.*both in the .* group'
    assert_prefix_ran
  done
}

@test "an arc whose end is not on its circle: FILE:LINE error, exit 1, the blocks before it ran" {
  # From 0,0: centre 3,0, start radius 3, end radius 7.
  bad_program 'G0 X0 Y0' 'G2 X10 Y0 I3 J0 F100'
  run --separate-stderr gcode-pulse bad.ngc
  assert_cnc_error 4 '.*radius'
  [ -n "$output" ]
  [ "$(sums <<< "$output")" = "0 0 0" ]  # out to X1.5 Y-0.5 and back before line 4
  printf 'G2 X10 Y0 I3 J0 F100\n' > bad.ngc
  run --separate-stderr gcode-pulse bad.ngc
  assert_cnc_error 1 '.*radius'
  [ -z "$output" ]
}

@test "a feed of zero on G1 (and G1 with no feed yet): FILE:LINE error, exit 1" {
  bad_program 'G1 X5 F0'
  run --separate-stderr gcode-pulse bad.ngc
  assert_cnc_error 3 '.*feed'
  assert_prefix_ran
  printf 'G21\nG1 X5\n' > bad.ngc
  run --separate-stderr gcode-pulse bad.ngc
  assert_cnc_error 2 '.*feed'
  [ -z "$output" ]
}

@test "a bad number: FILE:LINE error, exit 1, the blocks before it ran" {
  for word in 'G1 X1.2.3' 'G1 X--1' 'G1 X.' 'G1 X' 'G1 Xnan' 'G1 Xinf'; do
    bad_program "$word"
    run --separate-stderr gcode-pulse bad.ngc
    assert_cnc_error 3 '.*(number|without)'
    assert_prefix_ran
  done
}

@test "an unclosed comment: FILE:LINE error, exit 1, the blocks before it ran" {
  bad_program 'G1 X2 (no closing parenthesis'
  run --separate-stderr gcode-pulse bad.ngc
  assert_cnc_error 3 '.*unclosed comment'
  assert_prefix_ran
}

@test "G41 is an error; with --lenient a warning on stderr and success" {
  bad_program 'G41 D1' 'G1 X2.5'
  run --separate-stderr gcode-pulse bad.ngc
  assert_cnc_error 3 'G41'
  assert_prefix_ran
  run --separate-stderr gcode-pulse --lenient bad.ngc
  assert_success
  [[ "$stderr" == *G41* ]]
  [ "$(sums <<< "$output")" = "500 -100 0" ]
  run --separate-stderr gcode-pulse --lenient --quiet bad.ngc
  assert_success
  [ -z "$stderr" ]
}

@test "--lenient warnings say where: FILE:LINE" {
  bad_program 'G41 D1' 'G1 X2.5'
  run --separate-stderr gcode-pulse --lenient bad.ngc
  assert_success
  [[ "$stderr" =~ ^gcode-pulse:\ bad\.ngc:3:\ .*G41 ]]
}

@test "a canned cycle G81 is an error; --lenient skips it and the lines in its mode" {
  bad_program 'G81 X5 Y5 Z-1 R1' 'X6' 'G80' 'G1 X2'
  run --separate-stderr gcode-pulse bad.ngc
  assert_cnc_error 3 'G81'
  assert_prefix_ran
  run --separate-stderr gcode-pulse --lenient bad.ngc
  assert_success
  [[ "$stderr" == *G81* ]]
  [ "$(sums <<< "$output")" = "400 -100 0" ]
}

@test "coordinates beyond the counters: FILE:LINE error, exit 1, the blocks before it ran" {
  # X1e300 would be X1 and an E word: 99999999999 is beyond any counter.
  for word in 'G1 X99999999999' 'G0 Y-99999999999' 'G1 Z99999999999'; do
    bad_program "$word"
    run --separate-stderr gcode-pulse bad.ngc
    assert_cnc_error 3 '.*beyond'
    assert_prefix_ran
  done
  bad_program 'G1 X1e300'
  run --separate-stderr gcode-pulse bad.ngc
  assert_cnc_error 3 '.*E'
  assert_prefix_ran
}

@test "the coordinate limit's message shows the coordinate that broke it" {
  bad_program 'G0 X1000001'
  run --separate-stderr gcode-pulse bad.ngc
  assert_cnc_error 3 '.*(1000001|1\.000001e\+0?6)'
}

@test "--steps-per-mm finer than a step per nanometre is a usage error, before any pulse" {
  # 1e12 steps/mm once put X10000 beyond the step counters' 9e15 at its
  # line; the range (1 to 1e6) keeps 1e6 mm within 1e12 steps.
  printf 'G1 X0.000001 F100\nG0 X10000\n' > bad.ngc
  run --separate-stderr gcode-pulse --steps-per-mm 1e12,1e12,1e12 --summary bad.ngc
  assert_failure 2
  [[ "$stderr" == "gcode-pulse: --steps-per-mm: must be a number from 1 to 1e+06, not 1e+12"* ]]
}

@test "empty input: success and no pulses (file, stdin, CSV, comments only)" {
  : > empty.ngc
  run --separate-stderr gcode-pulse empty.ngc
  assert_success
  [ -z "$output" ]
  [ -z "$stderr" ]
  run --separate-stderr gcode-pulse < /dev/null
  assert_success
  [ -z "$output" ]
  run --separate-stderr gcode-pulse --csv empty.ngc
  assert_success
  [ -z "$output" ]  # the CSV header comes with the first record
  printf '(only a comment)\n\n; and another\n%%\n' > comments.ngc
  for file in empty.ngc comments.ngc; do
    run --separate-stderr gcode-pulse --summary "$file"
    assert_success
    for name in pulses_x pulses_y pulses_z events blocks motions; do
      [ "$(field "$name" <<< "$output")" = 0 ]
    done
    [ "$(field duration_s <<< "$output")" = 0.0 ]
  done
}

@test "binary garbage: an error with FILE:LINE and exit 1, never a crash" {
  for seed in $(seq 1 20); do
    python3 -c 'import random, sys; random.seed(int(sys.argv[1])); sys.stdout.buffer.write(bytes(random.randrange(256) for _ in range(4096)))' "$seed" > garbage.bin
    run --separate-stderr gcode-pulse garbage.bin
    [ "$status" -eq 1 ] || { echo "seed $seed: exit $status"; false; }
    [[ "$stderr" =~ ^gcode-pulse:\ garbage\.bin:[0-9]+:\  ]] || { echo "seed $seed: $stderr"; false; }
  done
  # High and control bytes after good lines (no NUL): the lines before ran.
  { printf '%b' "$PREFIX"; printf '\001\002\377\376G1 X9\n'; } > bad.ngc
  run --separate-stderr gcode-pulse bad.ngc
  assert_cnc_error 3 '.*byte'
  assert_prefix_ran
}

@test "a NUL byte: FILE:LINE error, exit 1" {
  printf 'G1 X1 F100\n\000\n' > bad.ngc
  run --separate-stderr gcode-pulse bad.ngc
  assert_cnc_error 2 '.*NUL'
  printf '\000G1 X1 F100\n' > bad.ngc
  run --separate-stderr gcode-pulse bad.ngc
  assert_cnc_error 1 '.*NUL'
  [ -z "$output" ]
}

@test "a NUL byte: the pulses of the blocks before its line are written" {
  { printf '%b' "$PREFIX"; printf 'G1 X2\000\n'; } > bad.ngc
  run --separate-stderr gcode-pulse bad.ngc
  assert_cnc_error 3 '.*NUL'
  assert_prefix_ran
}

@test "lines after M2 are not read, so a NUL byte there does not matter" {
  printf 'G1 X1 F100\nM2\n\000\001garbage\n' > end.ngc
  run --separate-stderr gcode-pulse --summary end.ngc
  assert_success
  [ "$(field final_x <<< "$output")" = 1.0 ]
}

@test "when a later input file cannot be opened, the earlier file's pulses are all written" {
  # 300 blocks, more than the look-ahead of 256: X30 = 6000 steps.
  awk 'BEGIN { print "G1 F1000"; for (i = 1; i <= 300; i++) print "G1 X" i / 10 }' > first.ngc
  run --separate-stderr gcode-pulse first.ngc missing.ngc
  assert_failure 1
  [[ "$stderr" == *missing.ngc* ]]
  [ "$(sums <<< "$output")" = "6000 0 0" ]
}

@test "a last line without a newline and CRLF line endings run as usual" {
  printf 'G21 G90\nG1 X1 F100\nG1 X2 Y3' > truncated.ngc
  printf 'G21 G90\r\nG1 X1 F100\r\nG1 X2 Y3\r\n' > crlf.ngc
  printf 'G21 G90\nG1 X1 F100\nG1 X2 Y3\n' > lf.ngc
  oracle lf.ngc > want.jsonl
  for file in truncated.ngc crlf.ngc; do
    run --separate-stderr gcode-pulse --summary $NO_ACCEL "$file"
    assert_success
    [ -z "$stderr" ]
    echo "$output" > got.jsonl
    run compare-gcode-oracle got.jsonl want.jsonl 200,200,400 5000 time
    assert_success
    [ "$(gcode-pulse "$file" | sums)" = "400 600 0" ]
  done
  # A CRLF fixture gives exactly the LF one's pulses.
  sed 's/$/\r/' "$GCODE/helix.ngc" > helix_crlf.ngc
  cmp <(gcode-pulse helix_crlf.ngc) <(gcode-pulse "$GCODE/helix.ngc")
  # Errors count CRLF lines right.
  printf 'G21 G90\r\nG1 X1.5 Y-0.5 F600\r\nG1 X1.2.3\r\n' > bad.ngc
  run --separate-stderr gcode-pulse bad.ngc
  assert_cnc_error 3 ".*bad number 'X1\.2\.3'$"
  assert_prefix_ran
}

# ------------------------------------------------------------ unused words, program end

@test "unused words are counted in the summary; M2 and M30 end the program" {
  printf 'G21 G90 G54\nM3 S1000\nT1 M6\nG1 X5 F100 S2000\nM03\nM2\nG1 X100\nM5 T2\n' > unused.ngc
  run --separate-stderr gcode-pulse --summary unused.ngc
  assert_success
  run python3 -c '
import json, sys
r = json.loads(sys.argv[1])
print(sorted(r["unused_words"].items()), r["final_x"], r["pulses_x"], r["blocks"])' "$output"
  # M3 twice (M03 is M3), T and M6 once, G54 once; M5 T2 and the G1 after
  # M2 never read; G21 G90 act, and so does S (G33 follows it): not unused.
  assert_output "[('G54', 1), ('M3', 2), ('M6', 1), ('T', 1)] 5.0 1000 6"
  [ "$(oracle unused.ngc | json-field final_x)" = 5.0 ]
  [ "$(oracle unused.ngc | json-field blocks)" = 6 ]
  sed 's/^M2$/M30/' unused.ngc > m30.ngc
  run --separate-stderr gcode-pulse --summary m30.ngc
  assert_success
  [ "$(field final_x <<< "$output")" = 5.0 ]
  [ "$(field unused_words <<< "$output")" = '{"G54": 1, "M3": 2, "M6": 1, "T": 1}' ]
  # The pulse stream stops at M2 too.
  [ "$(gcode-pulse unused.ngc | sums)" = "1000 0 0" ]
}

# ------------------------------------------------------------ lathe: G33 threading, G7 diameters

# close_to GOT WANT [TOLERANCE]: |GOT - WANT| <= TOLERANCE (default 1e-9), else a message.
close_to() {
  python3 -c '
import sys
got, want = float(sys.argv[1]), float(sys.argv[2])
tolerance = float(sys.argv[3]) if len(sys.argv) > 3 else 1e-9
sys.exit(0 if abs(got - want) <= tolerance else print("%r, not %r" % (got, want)) or 1)' "$@"
}

# G33 Z-20 K2 at S300: K is 2 mm of the line per spindle revolution, so the
# tool moves 2 * 300 = 600 mm/min = 10 mm/s and takes 20/600 min = 2 s. Z:
# 20 mm * 400 steps/mm = 8000 steps, at 10 * 400 = 4000 steps/s in the
# cruise. Accelerating at 500 mm/s^2 from rest and stopping adds 10/500 s.
@test "G33 Z-20 K2 at S300: 8000 Z steps, 2 s of cruise at 4000 steps/s, plus the acceleration" {
  printf 'G21 G90 G18\nS300 M3\nG33 Z-20 K2\nM2\n' > thread.ngc
  run --separate-stderr gcode-pulse --summary $NO_ACCEL thread.ngc
  assert_success
  [ -z "$stderr" ]
  [ "$(field pulses_z <<< "$output")" = 8000 ]
  [ "$(field pulses_x <<< "$output")" = 0 ]
  [ "$(field final_z <<< "$output")" = -20.0 ]
  close_to "$(field duration_s <<< "$output")" 2
  close_to "$(field path_mm <<< "$output")" 20
  [ "$(field feed_capped_blocks <<< "$output")" = 0 ]
  run --separate-stderr gcode-pulse --summary --accel 500 thread.ngc
  assert_success
  close_to "$(field duration_s <<< "$output")" 2.02
  close_to "$(field peak_rate_z <<< "$output")" 4000 1e-6
  # The pulse stream: 8000 steps of -1 in Z, the last when the tool is half
  # a step (1.25 um) from the end, sqrt(2 * 0.00125 / 500) s before 2.02 s.
  gcode-pulse --accel 500 thread.ngc > pulses.jsonl
  [ "$(sums < pulses.jsonl)" = "0 0 -8000" ]
  close_to "$(tail -n 1 pulses.jsonl | json-field t)" "$(python3 -c 'import math; print(2.02 - math.sqrt(2 * 0.00125 / 500))')"
  # The feed rate plays no part: an F before the G33 changes nothing.
  printf 'G21 G90 G18\nG1 F50\nS300 M3\nG33 Z-20 K2\nM2\n' > with_f.ngc
  run --separate-stderr gcode-pulse --summary $NO_ACCEL with_f.ngc
  close_to "$(field duration_s <<< "$output")" 2
}

# K follows the drive line (LinuxCNC): G33 X3 Z-4 K1 at S400 is a line of
# 5 mm at 1 * 400 = 400 mm/min, 0.75 s; X 3 * 200 = 600 steps, Z 4 * 400 = 1600.
@test "G33 on a taper: K is measured along the line, not along Z" {
  printf 'S400 M3\nG33 X3 Z-4 K1\n' > taper.ngc
  run --separate-stderr gcode-pulse --summary $NO_ACCEL taper.ngc
  assert_success
  close_to "$(field duration_s <<< "$output")" 0.75
  [ "$(field pulses_x <<< "$output")" = 600 ]
  [ "$(field pulses_z <<< "$output")" = 1600 ]
  # In inches: K0.0625 (16 TPI) at S600 is 37.5 in/min = 15.875 mm/s; Z-1 in
  # = 25.4 mm takes 25.4/15.875 = 1.6 s.
  printf 'G20 S600 M3\nG33 Z-1 K0.0625\n' > inch.ngc
  run --separate-stderr gcode-pulse --summary $NO_ACCEL inch.ngc
  close_to "$(field duration_s <<< "$output")" 1.6
}

# With 500 mm/s^2 and 10 mm/s a move from rest to rest takes length/10 +
# 10/500 s. G1 Z-0.5 at F600 then G33 Z-20.5 K2 at S300, both 10 mm/s:
# joined as plain moves they take 20.5/10 + 0.02 = 2.07 s; a control waits
# at rest for the spindle's index before a G33, so 0.07 + 2.02 = 2.09 s.
@test "G33 starts from rest after a move that does not follow the spindle, not after a G33" {
  printf 'S300 M3\nG1 Z-0.5 F600\nG33 Z-20.5 K2\n' > into.ngc
  run --separate-stderr gcode-pulse --summary --accel 500 into.ngc
  assert_success
  close_to "$(field duration_s <<< "$output")" 2.09
  printf 'S300 M3\nG1 Z-0.5 F600\nG1 Z-20.5\n' > plain.ngc
  run --separate-stderr gcode-pulse --summary --accel 500 plain.ngc
  close_to "$(field duration_s <<< "$output")" 2.07
  printf 'S300 M3\nG33 Z-0.5 K2\nZ-20.5 K2\n' > locked.ngc
  run --separate-stderr gcode-pulse --summary --accel 500 locked.ngc
  close_to "$(field duration_s <<< "$output")" 2.07
}

@test "G33 without K, with K0, with F, without S or with the spindle stopped: FILE:LINE error, exit 1" {
  bad_program 'S300 M3' 'G33 Z-20'
  run --separate-stderr gcode-pulse bad.ngc
  assert_cnc_error 4 'G33 without a K word'
  assert_prefix_ran
  bad_program 'S300 M3' 'G33 Z-20 K0'
  run --separate-stderr gcode-pulse bad.ngc
  assert_cnc_error 4 'G33 K0: .*must be positive'
  assert_prefix_ran
  bad_program 'S300 M3' 'G33 Z-20 K2 F100'
  run --separate-stderr gcode-pulse bad.ngc
  assert_cnc_error 4 'F100 with G33'
  assert_prefix_ran
  bad_program 'M3' 'G33 Z-20 K2'
  run --separate-stderr gcode-pulse bad.ngc
  assert_cnc_error 4 'G33 without a spindle speed'
  assert_prefix_ran
  bad_program 'S0 M3' 'G33 Z-20 K2'
  run --separate-stderr gcode-pulse bad.ngc
  assert_cnc_error 4 'G33 without a spindle speed'
  bad_program 'S300' 'G33 Z-20 K2'
  run --separate-stderr gcode-pulse bad.ngc
  assert_cnc_error 4 'G33 with the spindle stopped'
  assert_prefix_ran
  # G33 is modal, K is not: the second pass needs its own K.
  bad_program 'S300 M3' 'G33 Z-20 K2' 'G0 Z0' 'G33 Z-20'
  run --separate-stderr gcode-pulse bad.ngc
  assert_cnc_error 6 'G33 without a K word'
  # --lenient does not make these pass: they are no unsupported words.
  bad_program 'S300 M3' 'G33 Z-20'
  run --separate-stderr gcode-pulse --lenient bad.ngc
  assert_cnc_error 4 'G33 without a K word'
}

# K2 at S3000 is 6000 mm/min, above the default --max-feed (the rapid speed,
# 5000 mm/min): a G33 cannot be slowed down, so it is an error, not a cap.
@test "a G33 faster than the machine: FILE:LINE error; --max-feed high enough lets it run" {
  bad_program 'S3000 M3' 'G33 Z-20 K2'
  run --separate-stderr gcode-pulse bad.ngc
  assert_cnc_error 4 'G33 needs 6000 mm/min .*\(5000 mm/min\)'
  assert_prefix_ran
  run --separate-stderr gcode-pulse --summary --max-feed 6000 bad.ngc
  assert_success
  [ "$(field feed_capped_blocks <<< "$output")" = 0 ]
  run --separate-stderr gcode-pulse --max-feed 8000 --axis-max-feed 8000,8000,3000 bad.ngc
  assert_cnc_error 4 'G33 needs 6000 mm/min .*\(3000 mm/min\)'
}

# G7: X20 is a diameter, the machine's X moves to radius 10 mm = 2000 steps
# at 200 steps/mm; G1 at F600 (10 mm/s) takes 10/10 = 1 s, as the tool
# moves 10 mm. G91 X4 in G7 moves 2 mm; G8 X20 goes to 20 mm.
@test "G7: X words are diameters, the X axis moves half; G8 goes back to radius" {
  printf 'G21 G90 G7\nG1 X20 F600\n' > diameter.ngc
  run --separate-stderr gcode-pulse --summary $NO_ACCEL diameter.ngc
  assert_success
  [ "$(field pulses_x <<< "$output")" = 2000 ]
  [ "$(field final_x <<< "$output")" = 10.0 ]
  close_to "$(field duration_s <<< "$output")" 1
  [ "$(gcode-pulse diameter.ngc | sums)" = "2000 0 0" ]
  printf 'G21 G90 G7\nG0 X20\nG91 X4\nG90 G8 X20\n' > modes.ngc
  run --separate-stderr gcode-pulse --summary modes.ngc
  assert_success
  [ "$(field final_x <<< "$output")" = 20.0 ]
  # 10 mm out, 2 mm more, then 8 mm to 20: 20 mm, 4000 steps.
  [ "$(field pulses_x <<< "$output")" = 4000 ]
  printf 'G21 G90 G7\nG0 X20\nG91 X4\n' > half.ngc
  [ "$(gcode-pulse half.ngc | sums)" = "2400 0 0" ]
}

# The fixture's comments hold the hand computation: 3800 X and 74800 Z
# steps, path 92 + 111.708204 mm, duration without acceleration 9.2 s of
# G33 plus 111.708204 mm of rapids at 5000 mm/min. With acceleration and
# --junction-deviation 0 every move runs from rest to rest: each pass has
# 23 * 400 = 9200 Z steps 0.25 ms apart in its cruise (10 mm/s), and from
# its first step (the tool half a step, 1.25 um, in: sqrt(2 * 0.00125 /
# 500) s after the start) to its last it takes 23/10 + 10/500 s less
# twice that.
@test "a multi-pass thread in G7 (fixture lathe/thread_m10x1.5.ngc): steps, path and time by hand" {
  thread="$GCODE/lathe/thread_m10x1.5.ngc"
  run --separate-stderr gcode-pulse --summary $NO_ACCEL "$thread"
  assert_success
  [ -z "$stderr" ]
  [ "$(field pulses_x <<< "$output")" = 3800 ]
  [ "$(field pulses_z <<< "$output")" = 74800 ]
  [ "$(field final_x <<< "$output")" = 6.0 ]
  [ "$(field final_z <<< "$output")" = 3.0 ]
  close_to "$(field path_mm <<< "$output")" "$(python3 -c 'import math; print(92 + math.sqrt(45) + 13 + 92)')" 1e-6
  close_to "$(field duration_s <<< "$output")" "$(python3 -c 'import math; print(9.2 + (math.sqrt(45) + 105) / (5000 / 60))')" 1e-6
  gcode-pulse --junction-deviation 0 "$thread" > pulses.jsonl
  run python3 - pulses.jsonl <<'PY'
import json, math, sys
times = [r["t"] for r in map(json.loads, open(sys.argv[1])) if r["dz"] == -1]  # Z- only in the passes
passes = [[times[0]]]
for t in times[1:]:
    if t - passes[-1][-1] > 0.1:
        passes.append([t])
    else:
        passes[-1].append(t)
bad = []
if [len(p) for p in passes] != [9200] * 4:
    bad.append("Z- steps per pass: %r" % [len(p) for p in passes])
first = math.sqrt(2 * (0.5 / 400) / 500)
for i, p in enumerate(passes):
    gaps = sorted(b - a for a, b in zip(p, p[1:]))
    if abs(gaps[len(gaps) // 2] - 1 / 4000) > 1e-12 or gaps[0] < 1 / 4000 - 1e-12:
        bad.append("pass %d: median gap %r, shortest %r" % (i, gaps[len(gaps) // 2], gaps[0]))
    if abs(p[-1] - p[0] - (2.32 - 2 * first)) > 1e-9:
        bad.append("pass %d: %r s from first to last step" % (i, p[-1] - p[0]))
print("\n".join(bad))
sys.exit(1 if bad else 0)
PY
  [ "$status" -eq 0 ] || { echo "$output"; false; }
}

# ------------------------------------------------------------ units and distance modes

@test "G20: final positions are 25.4 times the inch values; G91 moves are incremental" {
  printf 'G20 G90\nG1 X1.5 Y-0.25 Z0.125 F10\nG91 G1 X0.5 Y0.5\n' > inch.ngc
  run --separate-stderr gcode-pulse --summary inch.ngc
  assert_success
  # X 1.5 + 0.5 = 2 in, Y -0.25 + 0.5 = 0.25 in, Z 0.125 in.
  for pair in "x 2" "y 0.25" "z 0.125"; do
    set -- $pair
    got=$(field "final_$1" <<< "$output")
    awk -v got="$got" -v inch="$2" 'BEGIN { d = got - 25.4 * inch; exit !(d < 1e-9 && d > -1e-9) }' ||
      { echo "final_$1 $got, not 25.4 * $2"; false; }
  done
  # G91 in mm: +1.5,+2 then +1.5,-3,-0.5, a rapid -10 in X, then G90 X7:
  # ends at 7 -1 -0.5; path 2.5 + sqrt(11.5) + 10 + 14 = 29.891165 mm.
  printf 'G21 G91\nG1 X1.5 Y2 F100\nG1 X1.5 Y-3 Z-0.5\nG0 X-10\nG90 G1 X7\n' > inc.ngc
  run --separate-stderr gcode-pulse --summary inc.ngc
  assert_success
  [ "$(field final_x <<< "$output")" = 7.0 ]
  [ "$(field final_y <<< "$output")" = -1.0 ]
  [ "$(field final_z <<< "$output")" = -0.5 ]
  path=$(field path_mm <<< "$output")
  awk -v p="$path" 'BEGIN { d = p - (2.5 + sqrt(11.5) + 24); exit !(d < 1e-6 && d > -1e-6) }' || { echo "path $path"; false; }
  [ "$(gcode-pulse inc.ngc | sums)" = "1400 -200 -200" ]
  oracle inc.ngc > want.jsonl
  echo "$output" > got.jsonl
  run compare-gcode-oracle got.jsonl want.jsonl 200,200,400 5000
  assert_success
}

# ------------------------------------------------------------ streaming

@test "streaming: 200,000 short G1 lines end where the oracle says" {
  skip_volume_when_sanitized  # the fixtures' short programs take the same reading path there
  awk 'BEGIN {
    print "G21 G90 G17"; print "G1 F3000"
    for (i = 1; i <= 200000; i++) printf "G1 X%.3f Y%.3f\n", (i % 1000) * 0.01, int(i / 1000) * 0.01 + (i % 7) * 0.005
  }' > long.ngc
  [ "$(wc -l < long.ngc)" -eq 200002 ]
  run --separate-stderr gcode-pulse --summary $NO_ACCEL long.ngc
  assert_success
  echo "$output" > got.jsonl
  [ "$(field blocks < got.jsonl)" = 200002 ]
  [ "$(field motions < got.jsonl)" = 200000 ]
  oracle long.ngc > want.jsonl
  [ "$(json-field final_y < want.jsonl)" = 2.015 ]
  run compare-gcode-oracle got.jsonl want.jsonl 200,200,400 5000 time
  [ "$status" -eq 0 ] || { echo "$output"; false; }
}
