#!/usr/bin/env bats
# Command-line behaviour of tnorm-bench. Expected values come from closed
# forms (the centroid of a full trapezoid), the fuzzylite 6.0 command-line
# program (Debian package fuzzylite) evaluating the same controller from
# the FLL we write, dense sampling, and the paper's qualitative findings as
# inequalities, never from the tool's own output captured once.

bats_require_minimum_version 1.5.0

setup() {
  load test_helper
  cd "$BATS_TEST_TMPDIR"
  FLL="$FIXTURES/fll"
}

# random_triples N SEED: CSV left,mid,right of N random 10-bit readings.
random_triples() {
  py "
import random
random.seed($2)
print('left,mid,right')
for _ in range($1):
    print(','.join(str(random.randint(0, 1023)) for _ in range(3)))"
}

# compare_with_fuzzylite ENGINE.fll OURS.csv INPUTS.csv [N_INPUTS]: fuzzylite
# evaluates the engine on the inputs; every output must agree with ours
# within 1e-9 (a nan of fuzzylite's is an empty cell of ours).
compare_with_fuzzylite() {
  local n="${4:-3}"
  tail -n +2 "$3" | tr ',' ' ' > inputs.fld
  fuzzylite -i "$1" -of fld -d inputs.fld -decimals 12 -dheader false > theirs.fld
  py '
import csv, math, sys
n = int(sys.argv[3])
ours = list(csv.DictReader(open(sys.argv[1])))
def numeric(line):  # fuzzylite also prints warnings about old FLL keys on stdout
    try:
        float(line.split()[0])
        return True
    except (IndexError, ValueError):
        return False
theirs = [line.split() for line in open(sys.argv[2]) if numeric(line)]
assert len(ours) == len(theirs) > 0, (len(ours), len(theirs))
worst, compared = 0, 0
for o, t in zip(ours, theirs):
    outs = [float(o[k]) if o[k] != "" else math.nan for k in list(o.keys())[n:]]
    ref = [float(x) for x in t[n:]]
    assert len(outs) == len(ref) > 0
    for a, b in zip(outs, ref):
        if math.isnan(a) or math.isnan(b):
            assert math.isnan(a) and math.isnan(b), (a, b)
            continue
        worst = max(worst, abs(a - b))
        compared += 1
assert compared > 0 and worst <= 1e-9, (compared, worst)
print("compared", compared, "worst", worst)' "$2" theirs.fld "$n"
}

@test "--help, --version and the man page" {
  run tnorm-bench --help
  assert_success
  assert_output --partial "eval"
  assert_output --partial "laps"
  run tnorm-bench laps --help
  assert_success
  assert_output --partial "--latency-ms"
  run tnorm-bench --version
  assert_success
  assert_output --regexp '^tnorm-bench \(toolkit\) [0-9]+\.[0-9]+\.[0-9]+ \(revision [0-9A-Za-z._-]+\)$'
  run grep -c "^\.SH" "$TOOLKIT_ROOT/man/tnorm-bench.1"
  [ "$output" -ge 8 ]
}

@test "usage errors exit 2" {
  run tnorm-bench
  assert_failure 2
  run tnorm-bench eval --tnorm maximum
  assert_failure 2
  assert_output --partial "unknown t-norm 'maximum'"
  run tnorm-bench eval --centroid middle
  assert_failure 2
  run tnorm-bench eval --centroid discrete:0
  assert_failure 2
  run tnorm-bench eval --adc 11
  assert_failure 2
  run tnorm-bench eval --backward-slowly -10,-30,-20,-5
  assert_failure 2
  assert_output --partial "in order"
  run tnorm-bench eval --speed-factor nan
  assert_failure 2
  run tnorm-bench laps --laps 0
  assert_failure 2
  run tnorm-bench laps --board pcb
  assert_failure 2
  run tnorm-bench laps --board esp32 --adc 10
  assert_failure 2
  assert_output --partial "contradicts --board esp32"
  run tnorm-bench laps --latency-ms -1
  assert_failure 2
  for bad in "--motor-tau-ms -1" "--wheel-base 0" "--speed-per-unit nan" "--sensor-spacing 0" "--noise -2" "--no-rule keep"; do
    run tnorm-bench laps --tnorm minimum $bad
    assert_failure 2
  done
  # An empty value is not 0 (CLI11 alone reads it so), and a loop under
  # 0.01 ms would run for ever rather than fail.
  for option in --deadband --motor-tau-ms --sensor-ahead --spot-sigma --latency-ms --period-ms --noise; do
    run tnorm-bench laps --tnorm minimum "$option" ""
    assert_failure 2
    assert_output --partial "$option: '' is not a number"
  done
  run timeout 20 tnorm-bench laps --tnorm minimum --latency-ms 1e-12
  assert_failure 2
  run timeout 20 tnorm-bench laps --tnorm minimum --period-ms 0.005
  assert_failure 2
  run tnorm-bench bench --seconds -1
  assert_failure 2
}

@test "a centred line drives both motors at FORWARD's centroid (closed form)" {
  run tnorm-bench eval --centroid exact <<< '{"id":"a","left":40,"mid":950,"right":40}'
  assert_success
  # Only R4 (L D L) fires, fully: FORWARD {45,55,65,75} x 2.0, a full trapezoid.
  py '
import json, sys
r = json.loads(sys.argv[1])
a, b, c, d = (v * 2.0 for v in (45, 55, 65, 75))
g = (c*c + c*d + d*d - a*a - a*b - b*b) / (3 * (c + d - a - b))
assert r["id"] == "a" and list(r)[:4] == ["id", "left", "mid", "right"]
assert abs(r["left_motor"] - g) < 1e-9 and abs(r["right_motor"] - g) < 1e-9, (r, g)' "$output"
}

@test "the right motor mirrors the left" {
  run tnorm-bench eval --tnorm hamacher --csv <<< $'left,mid,right\n900,300,60\n60,300,900'
  assert_success
  py '
import csv, io, sys
rows = list(csv.DictReader(io.StringIO(sys.argv[1])))
assert abs(float(rows[0]["left_motor"]) - float(rows[1]["right_motor"])) < 1e-12
assert abs(float(rows[0]["right_motor"]) - float(rows[1]["left_motor"])) < 1e-12
assert float(rows[0]["left_motor"]) < float(rows[0]["right_motor"])  # line on the left: turn left' "$output"
}

@test "eval agrees with fuzzylite on the paper's controller for every t-norm fuzzylite has" {
  command -v fuzzylite || skip "fuzzylite (Debian package fuzzylite) not installed"
  random_triples 300 7 > in.csv
  printf '40,950,40\n950,950,950\n20,20,20\n400,400,400\n0,1023,0\n' >> in.csv
  for t in minimum product drastic lukasiewicz hamacher; do
    for imp in minimum product; do
      tnorm-bench fll --tnorm "$t" --implication "$imp" > engine.fll
      # fuzzylite fires rules from an activation of 1e-6.
      tnorm-bench eval --tnorm "$t" --implication "$imp" --fire-threshold 1e-6 --csv in.csv > ours.csv
      run compare_with_fuzzylite engine.fll ours.csv in.csv
      assert_success
    done
  done
}

@test "the 12-bit controller and another resolution agree with fuzzylite" {
  command -v fuzzylite || skip "fuzzylite not installed"
  py '
import random
random.seed(3)
print("left,mid,right")
for _ in range(200):
    print(",".join(str(random.randint(0, 4095)) for _ in range(3)))' > in.csv
  tnorm-bench fll --tnorm product --adc 12 --centroid discrete:37 --speed-factor 2 > engine.fll
  grep -q "Centroid 37" engine.fll
  tnorm-bench eval --tnorm product --adc 12 --centroid discrete:37 --speed-factor 2 --fire-threshold 1e-6 --csv in.csv > ours.csv
  run compare_with_fuzzylite engine.fll ours.csv in.csv
  assert_success
}

@test "a user's FLL controller: evaluated as fuzzylite evaluates it" {
  command -v fuzzylite || skip "fuzzylite not installed"
  checked=0
  for f in "$FLL"/*.fll; do
    grep -q "Trigonometric" "$f" && continue
    inputs=$(awk '/^InputVariable:/ { print $2 }' "$f" | paste -sd, -)
    n=$(echo "$inputs" | tr ',' '\n' | wc -l)
    ranges=$(awk '/^InputVariable:/ { v = 1 } v && /range:/ { print $2, $3; v = 0 }' "$f")
    py "
import random
random.seed(5)
ranges = [tuple(map(float, l.split())) for l in '''$ranges'''.strip().splitlines()]
print('$inputs')
for _ in range(100):
    print(','.join('%.6g' % random.uniform(lo, hi) for lo, hi in ranges))" > in.csv
    tnorm-bench eval --fll "$f" --fire-threshold 1e-6 --csv in.csv > ours.csv
    run compare_with_fuzzylite "$f" ours.csv in.csv "$n"
    assert_success
    checked=$((checked + 1))
  done
  [ "$checked" -ge 3 ]
}

@test "fll writes what eval reads back: the same motor commands" {
  tnorm-bench fll --tnorm trigonometric > trig.fll
  grep -q "conjunction: Trigonometric" trig.fll
  random_triples 50 1 > in.csv
  diff <(tnorm-bench eval --tnorm trigonometric --csv in.csv) <(tnorm-bench eval --fll trig.fll --csv in.csv)
}

@test "the exact centroid is the limit of the discrete one" {
  random_triples 40 9 > in.csv
  tnorm-bench eval --centroid exact --csv in.csv > exact.csv
  tnorm-bench eval --centroid discrete:2000000 --csv in.csv > fine.csv
  py '
import csv, sys
a = list(csv.DictReader(open(sys.argv[1]))); b = list(csv.DictReader(open(sys.argv[2])))
for x, y in zip(a, b):
    for k in ("left_motor", "right_motor"):
        assert abs(float(x[k]) - float(y[k])) < 1e-6, (x, y)' exact.csv fine.csv
}

@test "drastic: two sensors unsure and no rule fires, so both motors stop" {
  run tnorm-bench eval --tnorm drastic <<< '{"left":20,"mid":130,"right":130}'
  assert_success
  assert_output '{"left":20,"mid":130,"right":130,"left_motor":0.0,"right_motor":0.0}'
  run tnorm-bench eval --tnorm minimum <<< '{"left":20,"mid":130,"right":130}'
  py 'import json, sys; r = json.loads(sys.argv[1]); assert r["left_motor"] > r["right_motor"] + 10' "$output"  # toward the line on the right
}

@test "bad records: a clear error with file and line, earlier records kept" {
  printf 'left,mid,right\n40,950,40\n40,abc,40\n' > bad.csv
  run tnorm-bench eval bad.csv
  assert_failure 1
  assert_line --index 0 --partial '"left_motor"'
  assert_output --partial "tnorm-bench: bad.csv:3:"
  printf '{"left":40,"mid":950}\n' > missing.jsonl
  run tnorm-bench eval missing.jsonl
  assert_failure 1
  assert_output --partial "missing.jsonl:1:"
  assert_output --partial "right"
  run tnorm-bench eval <<< '{"left":40,"mid":1024,"right":40}'
  assert_failure 1
  assert_output --partial "outside the 10-bit ADC"
  run tnorm-bench eval <<< '{"left":40,"mid":1e308,"right":40}'
  assert_failure 1
  run tnorm-bench eval <<< $'left,mid,right\nnan,1,1'
  assert_failure 1
  run tnorm-bench eval <<< '{"left":-3,"mid":10,"right":40}'
  assert_failure 1
  head -c 3000 /dev/urandom > garbage.bin
  run tnorm-bench eval garbage.bin
  [ "$status" -le 1 ]
  run tnorm-bench eval /dev/null
  assert_success
  assert_output ""
}

@test "a malformed FLL file: its line, exit 1" {
  tnorm-bench fll > good.fll
  sed '5s/.*/  range: 0 banana/' good.fll > bad.fll
  run tnorm-bench eval --fll bad.fll <<< '{"left":1,"mid":2,"right":3}'
  assert_failure 1
  assert_output --partial "bad.fll:5:"
  sed 's/ and mid is / or mid is /' good.fll > or.fll
  run tnorm-bench eval --fll or.fll <<< '{"left":1,"mid":2,"right":3}'
  assert_failure 1
  assert_output --partial "or.fll:"
  run tnorm-bench eval --fll /nonexistent.fll <<< '{"left":1,"mid":2,"right":3}'
  assert_failure 1
}

@test "bench: one record per t-norm with the paper's protocol figure" {
  run tnorm-bench bench --seconds 0.05
  assert_success
  py '
import json, sys
rows = [json.loads(l) for l in sys.argv[1].splitlines()]
assert [r["tnorm"] for r in rows] == ["minimum", "product", "drastic", "lukasiewicz", "trigonometric", "hamacher"]
for r in rows:
    assert r["ns_per_inference"] > 0 and r["ms_per_2x1024"] > 0 and r["inferences"] >= 9 * 16 * 2048
    assert r["centroid"] == "discrete" and r["resolution"] == 100' "$output"
  run tnorm-bench bench --tnorm hamacher --centroid exact --seconds 0.02 --csv
  assert_success
  assert_line --index 0 "tnorm,ns_per_inference,ms_per_2x1024,inferences,centroid,resolution"
}

@test "laps: on the ESP32 the drastic car stops and does not finish, the others complete" {
  run tnorm-bench laps --tnorm all --board esp32 --svg laps.svg --trace trace.jsonl
  assert_success
  py '
import json, sys
rows = {r["tnorm"]: r for r in map(json.loads, sys.argv[1].splitlines())}
assert len(rows) == 6
d = rows.pop("drastic")
assert d["completed"] is False and d["stop_reason"] == "stopped" and d["lap_times_s"] == [], d
for name, r in rows.items():
    assert r["completed"] is True and len(r["lap_times_s"]) == 3, name
    assert abs(sum(r["lap_times_s"]) - r["total_s"]) < 0.01, name
    # 3 laps of the 1000 mm / 300 mm oval: 3 x (2000 + 600 pi) mm, give or take the corners cut.
    assert 0.9 * 3 * (2000 + 600 * 3.14159) < r["distance_mm"] < 1.1 * 3 * (2000 + 600 * 3.14159), name' "$output"
  grep -q "<svg" laps.svg
  [ "$(grep -c '<path' laps.svg)" -ge 7 ]  # the track and six runs
  [ "$(json-field tnorm < trace.jsonl | sort -u | wc -l)" -eq 6 ]
}

@test "laps --svg: one panel per t-norm, none overlapping, and a stop marker at the end of exactly the runs that did not finish" {
  tnorm-bench laps --tnorm all --board esp32 --svg laps.svg --trace trace.jsonl > laps.jsonl
  run py '
import json, re, sys, xml.etree.ElementTree as E
N = "{http://www.w3.org/2000/svg}"
rows = [json.loads(l) for l in open("laps.jsonl")]
unfinished = {r["tnorm"] for r in rows if not r["completed"]}
trace = {}
for line in open("trace.jsonl"):
    t = json.loads(line)
    trace.setdefault(t["tnorm"], []).append((t["x"], t["y"]))
def numbers(d): return [float(v) for v in re.findall(r"-?[0-9.]+(?:e-?[0-9]+)?", d)]
panels = {}
for g in E.parse("laps.svg").getroot().iter(N + "g"):
    caption = [t.text for t in g.iter(N + "text")]
    names = [r["tnorm"] for r in rows if caption and caption[0].startswith(r["tnorm"] + ":")]
    if len(names) != 1:
        continue
    # The bounding box of everything the panel draws: its frame, paths and marks.
    xs, ys = [], []
    for e in g.iter():
        if e.tag == N + "path":
            v = numbers(e.get("d")); xs += v[0::2]; ys += v[1::2]
        elif e.tag == N + "rect":
            x, y = float(e.get("x")), float(e.get("y")); xs += [x, x + float(e.get("width"))]; ys += [y, y + float(e.get("height"))]
        elif e.tag == N + "circle":
            r = float(e.get("r")); xs += [float(e.get("cx")) - r, float(e.get("cx")) + r]; ys += [float(e.get("cy")) - r, float(e.get("cy")) + r]
    panels[names[0]] = (g, (min(xs), min(ys), max(xs), max(ys)))
assert sorted(panels) == sorted(r["tnorm"] for r in rows), sorted(panels)
boxes = list(panels.values())
for i in range(len(boxes)):
    for j in range(i + 1, len(boxes)):
        a, b = boxes[i][1], boxes[j][1]
        assert a[2] <= b[0] or b[2] <= a[0] or a[3] <= b[1] or b[3] <= a[1], (a, b)
marked = set()
for name, (g, box) in panels.items():
    stops = [c for c in g.iter(N + "circle") if c.get("class") == "stop"]
    if not stops:
        continue
    marked.add(name)
    assert len(stops) == 1, name
    # The path starts at the first trace point: that fixes the panel offset (1 mm a unit, y mirrored); the marker sits on the last.
    path = [p for p in g.iter(N + "path") if p.get("class") == "path"][0]
    v = numbers(path.get("d"))
    (x0, y0), (x1, y1) = trace[name][0], trace[name][-1]
    ox, oy = v[0] - x0, v[1] + y0
    assert abs(float(stops[0].get("cx")) - (x1 + ox)) < 0.05 and abs(float(stops[0].get("cy")) - (oy - y1)) < 0.05, name
    labels = [t.text for t in g.iter(N + "text") if t.get("class") == "stop-label"]
    assert len(labels) == 1 and labels[0].startswith(rows[[r["tnorm"] for r in rows].index(name)]["stop_reason"]), labels
print(sorted(marked) == sorted(unfinished), sorted(unfinished))'
  assert_output "True ['drastic']"
}

@test "laps: --no-rule hold keeps the drastic car's motors going where no rule fires" {
  run tnorm-bench laps --tnorm drastic minimum --board esp32 --no-rule hold --laps 1
  assert_success
  # Table 4's loops; one lap, so no three-lap figure of the paper's beside the minimum's (32.49 s for 3).
  check 'assert rows[0]["completed"] and rows[0]["latency_ms"] == 321 / 1024, rows[0]
assert rows[1]["tnorm"] == "minimum" and rows[1]["completed"] and rows[1]["paper_total_s"] is None, rows[1]' <<< "$output"
}

@test "laps: a slower controller follows the line worse" {
  fast=$(tnorm-bench laps --tnorm minimum --latency-ms 1.8 | json-field rms_deviation_mm)
  slow=$(tnorm-bench laps --tnorm minimum --latency-ms 40 | json-field rms_deviation_mm)
  py "assert $slow > $fast, ($slow, $fast)"
}

@test "laps: a track file, and its errors" {
  run tnorm-bench laps --tnorm minimum --laps 1 --track "$FIXTURES/tracks/rounded_rectangle.csv"
  assert_success
  printf 'x,y\n0,0\n100,0\n' > short.csv
  run tnorm-bench laps --tnorm minimum --track short.csv
  assert_failure 1
  assert_output --partial "short.csv"
}

@test "laps: every option has a range and the steps a run implies are capped before it starts" {
  load bounded_run
  bounded tnorm-bench laps --noise -1
  assert_failure 2
  assert_output --partial "--noise: must be a number from 0 to 4096, not -1"
  bounded tnorm-bench laps --period-ms 1e-9
  assert_failure 2
  assert_output --partial "--period-ms: must be 0 or a number from 0.01 to 1000, not 1e-9"
  bounded tnorm-bench laps --oval 1000,1e12
  assert_failure 2
  assert_output --partial "--oval (radius, mm): must be a number from 10 to 100000"
  bounded tnorm-bench laps --speed-factor 1e9
  assert_failure 2
  assert_output --partial "--speed-factor: must be a number from 0.1 to 10"
  # 1000 laps of 17 s each at a 10 us period: 36000 s x (5000 physics steps
  # + 2 x 10^5 samples and commands) a second for each of the six t-norms.
  py 'n = 6 * 36000 * (1 / 0.0002 + 2 / 1e-5); assert abs(n - 4.428e10) < 1e7, n'
  bounded tnorm-bench laps --tnorm all --laps 1000 --period-ms 0.01 --time-limit 36000
  assert_failure 2
  assert_output --partial "--time-limit, --period-ms, --latency-ms and --tnorm imply 4.43e+10 simulation steps, more than the 1e+08 this tool allows"
  bounded tnorm-bench laps --tnorm all --time-limit 3000 --trace trace.jsonl
  assert_failure 2
  assert_output --partial "imply 1.8e+06 trace points"
  [ ! -e trace.jsonl ]
}
