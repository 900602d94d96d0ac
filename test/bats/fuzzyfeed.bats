#!/usr/bin/env bats
# Command-line behaviour of fuzzyfeed. The stream mode is checked against
# values worked by hand from the paper's formulas (1)-(7) and against an
# independent Python re-implementation written from the paper's text
# (test/oracle/fuzzyfeed_law.py); the simulation against closed forms
# (baseline time L / (f n) with n = v_c / (pi D)). The paper's findings and
# the law on a grid are in fuzzyfeed_paper_oracle.bats.

bats_require_minimum_version 1.5.0

setup() {
  load test_helper
  cd "$BATS_TEST_TMPDIR"
  FF="$FIXTURES/fuzzyfeed"
  LAW="$TOOLKIT_ROOT/test/oracle/fuzzyfeed_law.py"
}

# random_loads N SEED: N records {t, load, feed, id} with loads round 60 %,
# bursts of overload and idle stretches.
random_loads() {
  py '
import json, random, sys
n, seed = int(sys.argv[1]), int(sys.argv[2])
r = random.Random(seed)
level = 60.0
for i in range(n):
    if i % 400 == 0:
        level = r.choice([5.0, 35.0, 60.0, 62.0, 90.0, 100.0])
    load = min(100.0, max(0.0, level + r.gauss(0, 4)))
    print(json.dumps({"t": round(i * 0.008, 3), "load": load, "feed": 0.4, "id": i}))' "$1" "$2"
}

# against_oracle OUTPUT ORACLE-OUTPUT: wk and override agree to 1e-12 (relative).
against_oracle() {
  py '
import json, sys
ours = [json.loads(l) for l in open(sys.argv[1])]
theirs = [l.split() for l in open(sys.argv[2])]
assert len(ours) == len(theirs), (len(ours), len(theirs))
for i, (r, t) in enumerate(zip(ours, theirs)):
    w, o = float(t[0]), float(t[1])
    assert abs(r["wk"] - w) <= 1e-12 * max(w, 1e-300), (i, r["wk"], w)
    assert abs(r["override"] - o) <= 1e-12 * o, (i, r["override"], o)
    if "feed_out" in r:
        assert abs(r["feed_out"] - float(r["feed"]) * o / 100) <= 1e-12, i
print("agree", len(ours))' "$1" "$2"
}

@test "--help, --version and the man page" {
  run fuzzyfeed --help
  assert_success
  assert_output --partial "--mz"
  assert_output --partial "--simulate"
  assert_output --partial "--variant"
  run fuzzyfeed --version
  assert_success
  assert_output --regexp '^fuzzyfeed \(toolkit\) [0-9]+\.[0-9]+\.[0-9]+ \(revision [0-9A-Za-z._-]+\)$'
  [ -s "$TOOLKIT_ROOT/man/fuzzyfeed.1" ]
  run grep -c "^\.SH" "$TOOLKIT_ROOT/man/fuzzyfeed.1"
  [ "$output" -ge 10 ]
  grep -q '^\.SH FIDELITY' "$TOOLKIT_ROOT/man/fuzzyfeed.1"
  ! grep -qi "reconstruct" "$TOOLKIT_ROOT/man/fuzzyfeed.1"
}

@test "usage errors exit 2 and name the option" {
  for args in "--mz 0" "--mz 100.5" "--mz nan" "--k 0" "--k 1.5" "--p 1.5" "--p -0.1" "--d -1" "--d 100.5" \
              "--initial-override 0" "--initial-override 201" "--min-override 200" "--variant fuzzy"; do
    run fuzzyfeed $args < /dev/null
    assert_failure 2
    assert_output --partial "${args%% *}"
    assert_output --partial "Try 'fuzzyfeed --help'"
  done
  run fuzzyfeed --trace x.jsonl < /dev/null
  assert_failure 2
  assert_output --partial "--trace goes with --simulate"
  run fuzzyfeed --simulate loads.csv
  assert_failure 2
  run fuzzyfeed --simulate --ipo 0
  assert_failure 2
  run fuzzyfeed --simulate --efficiency 1.2
  assert_failure 2
  run fuzzyfeed --simulate --kv 0
  assert_failure 2
  # 204 mm at 10^-3 mm/rev and a 0.1 ms IPO: 2.2e8 IPO cycles at 100 %, refused at once.
  run fuzzyfeed --simulate --feed 0.001 --ipo 1e-4
  assert_failure 2
  assert_output --partial "IPO cycles"
  run fuzzyfeed --no-such-option
  assert_failure 2
}

@test "the original law by hand: (1)+(3) at 30 %, (2)+(4) at 80 %, the hold at M_z, 200 % when idle; fields pass through" {
  printf 't,load,feed,id\n0,30,0.4,a\n0.008,80,0.4,b\n0.016,60,0.4,c\n0.024,0,,d\n0.032,100,0.2,e\n' > loads.csv
  run --separate-stderr fuzzyfeed loads.csv
  assert_success
  # M_z 60: (1) e^(-5/3600 * 900) = e^-1.25, (3) 100 + 100 e^-1.25;
  # (2) e^(-10/0.4 * 0.2^2) = e^-1, (4) times e^-1; M_a = M_z holds;
  # M_a = 0: W_k 1, (3) gives 200; 100 %: e^(-25 * 0.16) = e^-4.
  check '
o1 = 100 + 100 * math.exp(-1.25); o2 = o1 * math.exp(-1); o5 = 200 * math.exp(-4)
want = [(math.exp(-1.25), o1), (math.exp(-1), o2), (1, o2), (1, 200), (math.exp(-4), o5)]
for r, (w, o) in zip(rows, want):
    assert near(r["wk"], w, 1e-14) and near(r["override"], o, 1e-12), (r, w, o)
assert [r["id"] for r in rows] == list("abcde") and rows[0]["t"] == "0" and rows[3]["feed"] == ""
assert "feed_out" not in rows[3] and near(rows[4]["feed_out"], 0.2 * o5 / 100, 1e-15)
assert near(rows[0]["feed_out"], 0.4 * o1 / 100, 1e-15)' <<< "$output"
  run fuzzyfeed --csv loads.csv
  assert_success
  assert_line --index 0 "t,load,feed,id,wk,override,feed_out"
  run py 'import csv, math, sys
rows = list(csv.DictReader(sys.stdin))
o = (100 + 100 * math.exp(-1.25)) * math.exp(-1)
assert rows[2]["id"] == "c" and rows[2]["wk"] == "1.0" and abs(float(rows[2]["override"]) - o) < 1e-12, rows[2]
print("ok")' <<< "$output"
  assert_output "ok"
  run fuzzyfeed --csv loads.csv
  assert_line --index 4 --partial "0.024,0,,d,1.0,200.0,"
}

@test "the modified law by hand: (5)+(3) below M_z, (6)+(7) above, towards d and not below it" {
  printf '{"t":0,"load":30}\n{"t":1,"load":80}\n{"t":2,"load":60}\n' > loads.jsonl
  run fuzzyfeed --variant modified loads.jsonl
  assert_success
  # k = p = 0.1, d = 25: 100 + 100 * 0.1 e^-1.25; then (0.1 e^-1 + 0.9)(O - 25) + 25; then held.
  check '
o1 = 100 + 10 * math.exp(-1.25); w2 = 0.1 * math.exp(-1) + 0.9; o2 = w2 * (o1 - 25) + 25
assert near(rows[0]["wk"], 0.1 * math.exp(-1.25), 1e-15) and near(rows[0]["override"], o1, 1e-12), rows[0]
assert near(rows[1]["wk"], w2, 1e-15) and near(rows[1]["override"], o2, 1e-12), rows[1]
assert rows[2]["wk"] == 1 and rows[2]["override"] == rows[1]["override"]' <<< "$output"
  # 400 cycles at full load: the override comes down to d = 40, never below.
  py 'import json
for i in range(400): print(json.dumps({"t": i, "load": 100}))' > full.jsonl
  run fuzzyfeed --variant modified --d 40 --initial-override 180 full.jsonl
  check 'o = [r["override"] for r in rows]
assert all(a >= b >= 40 for a, b in zip(o, o[1:])) and o[0] < 180 and near(o[-1], 40, 1e-9), o[-3:]' <<< "$output"
}

@test "stream mode agrees with the Python law written from the paper: both variants, several parameter sets" {
  random_loads 6000 5 > loads.jsonl
  for params in "" "--mz 45 --initial-override 10" "--variant modified" "--variant modified --k 0.5 --p 0.3 --d 10 --mz 80" \
                "--mz 100 --min-override 10"; do
    fuzzyfeed $params loads.jsonl > ours.jsonl
    /usr/bin/python3 "$LAW" stream $params < loads.jsonl > oracle.txt
    run against_oracle ours.jsonl oracle.txt
    assert_success
    assert_output "agree 6000"
  done
}

@test "bad records: file:line message, exit 1, earlier records written" {
  check() {  # check CONTENT LINE MESSAGE
    printf "$1" > bad.txt
    run --separate-stderr fuzzyfeed bad.txt
    assert_failure 1
    [ "${#lines[@]}" -eq 1 ] || { echo "records before the error: ${#lines[@]}"; return 1; }
    [ "$stderr" = "fuzzyfeed: bad.txt:$2: $3" ] || { echo "stderr: $stderr"; return 1; }
  }
  check 't,load\n0,30\n0.1,abc\n' 3 "field 'load' is not a number: 'abc'"
  check 't,load\n0,30\n0.1,nan\n' 3 "field 'load' is not finite"
  check '{"t":0,"load":30}\n{"t":0.1,"load":"inf"}\n' 2 "field 'load' is not finite"
  check '{"t":0,"load":30}\n{"t":0.1}\n' 2 "missing field 'load'"
  check '{"t":0,"load":30}\n{"load":30}\n' 2 "missing field 't'"
  check 't,load\n0,30\n0,40\n' 3 "t must increase strictly: 0 after 0"
  check 't,load\n1,30\n0.5,40\n' 3 "t must increase strictly: 0.5 after 1"
  check 't,load\n0,30\n0.1,-1\n' 3 "load -1 is outside 0-100 % of rated"
  check 't,load\n0,30\n0.1,100.5\n' 3 "load 100.5 is outside 0-100 % of rated"
  check 't,load\n0,30\n0.1,1e400\n' 3 "field 'load' is out of range: '1e400'"
  check '{"t":0,"load":30}\n{"t":1e300,"load":1e300}\n' 2 "load 1e+300 is outside 0-100 % of rated"
  check 't,load,feed\n0,30,0.4\n0.1,30,-1\n' 3 "feed -1 is negative"
  check 't,load,feed\n0,30,0.4\n0.1,30,1e308\n' 3 "feed 1e+308 times the override overflows"
  check '{"t":0,"load":30}\n{"t":0.1,"load":30\n' 2 "invalid json: parse error column 19: syntax error while parsing object - unexpected end of input; expected '}'"
  printf '{"t":0,"load":30}\n\x00\x01\xff\n' > bad.txt
  run --separate-stderr fuzzyfeed bad.txt
  assert_failure 1
  [ "${#lines[@]}" -eq 1 ]
  [[ "$stderr" == "fuzzyfeed: bad.txt:2: "* ]]
  head -c 4096 /dev/urandom > garbage.bin
  run --separate-stderr fuzzyfeed garbage.bin
  assert_failure 1
  [[ "$stderr" == "fuzzyfeed: garbage.bin:"* ]]
}

@test "empty input: no records, exit 0" {
  run --separate-stderr fuzzyfeed < /dev/null
  assert_success
  assert_output ""
  [ -z "$stderr" ]
  printf '\n\n' | fuzzyfeed > out.jsonl
  [ ! -s out.jsonl ]
}

@test "simulate: the baseline time is L / (f n) and the summary is consistent" {
  run --separate-stderr fuzzyfeed --simulate
  assert_success
  run py '
import json, math, sys
r = json.loads(sys.stdin.read())
n = 140000 / (math.pi * 80) / 60                      # rev/s at v_c 140 m/min, D 80 mm
assert abs(r["baseline_time_s"] - 204 / (0.4 * n)) < 1e-9, r
assert abs(r["time_ratio"] - r["machining_time_s"] / r["baseline_time_s"]) < 1e-12
assert abs(r["spindle_rpm"] - 60 * n) < 1e-9
assert r["length_mm"] == 204 and r["variant"] == "original" and r["record"] == "summary"
# at 100 % the three 8 mm collars are above 1.1 M_z: 24 mm at the baseline feed rate
assert abs(r["baseline_time_above_mz_s"] - 24 / (0.4 * n)) < 6 * 0.008, r
for key in ("machining_time_s", "time_above_mz_s", "override_oscillation_pct", "mean_load_pct"):
    assert key in r, key
print("ok")' <<< "$output"
  assert_output "ok"
}

@test "simulate: the trace is one record per IPO cycle, and the stream mode reproduces it" {
  for variant in original modified; do
    fuzzyfeed --simulate --variant $variant --trace trace.jsonl > summary.json
    run py '
import json
s = json.load(open("summary.json"))
rows = [json.loads(l) for l in open("trace.jsonl")]
assert len(rows) == s["cycles"], (len(rows), s["cycles"])
assert all(b["t"] > a["t"] for a, b in zip(rows, rows[1:]))
assert abs(rows[1]["t"] - 0.008) < 1e-15
assert {r["depth"] for r in rows} == {1, 3}
assert all(0 <= r["load"] <= 100 for r in rows)
print("ok")'
    assert_output "ok"
    fuzzyfeed --variant $variant trace.jsonl > again.jsonl
    run py '
import json
a = [json.loads(l) for l in open("trace.jsonl")]
b = [json.loads(l) for l in open("again.jsonl")]
assert len(a) == len(b) and all(x["override"] == y["override"] and x["wk"] == y["wk"] for x, y in zip(a, b))
print("same")'
    assert_output "same"
    /usr/bin/python3 "$LAW" stream --variant $variant < trace.jsonl > oracle.txt
    run against_oracle again.jsonl oracle.txt
    assert_success
  done
  fuzzyfeed --simulate --csv --trace trace.csv > summary.csv
  run head -1 trace.csv
  assert_output "t,z,depth,chip,load_true,load,wk,override,feed,feed_out"
  run head -1 summary.csv
  assert_output --partial "record,variant,mz,machining_time_s"
}

@test "simulate: profiles as segments or positions; bad profiles name file and line" {
  run fuzzyfeed --simulate --noise 0 --profile "$FF/profile_segments.csv"
  assert_success
  seg="$output"
  run fuzzyfeed --simulate --noise 0 --profile "$FF/profile_positions.jsonl"
  assert_success
  [ "$output" = "$seg" ]
  run py '
import json, math, sys
r = json.loads(sys.stdin.read())
n = 140000 / (math.pi * 80) / 60
assert r["length_mm"] == 110 and abs(r["baseline_time_s"] - 110 / (0.4 * n)) < 1e-9, r
print("ok")' <<< "$seg"
  assert_output "ok"
  run --separate-stderr fuzzyfeed --simulate --profile "$FF/profile_gap.csv"
  assert_failure 1
  [ "$stderr" = "fuzzyfeed: $FF/profile_gap.csv:3: z_from must be where the segment before ends" ]
  run --separate-stderr fuzzyfeed --simulate --profile "$FF/profile_missing_depth.jsonl"
  assert_failure 1
  [ "$stderr" = "fuzzyfeed: $FF/profile_missing_depth.jsonl:2: missing field 'depth'" ]
  printf 'z,depth\n0,1\n' > one.csv
  run --separate-stderr fuzzyfeed --simulate --profile one.csv
  assert_failure 1
  assert_equal "$stderr" "fuzzyfeed: one.csv: the profile needs at least two records (z, depth), the last ending the cut"
}

@test "simulate: --segments records and the SVG's two panels" {
  run fuzzyfeed --simulate --segments --svg plot.svg
  assert_success
  [ "${#lines[@]}" -eq 7 ]
  run py '
import json, sys
rows = [json.loads(l) for l in sys.stdin]
segs, s = rows[:-1], rows[-1]
assert [r["depth"] for r in segs] == [1, 3, 1, 3, 1, 3]
assert abs(sum(r["duration_s"] for r in segs) - s["machining_time_s"]) < 1e-9
assert max(r["oscillation_pct"] for r in segs) == s["override_oscillation_pct"]
print("ok")' <<< "$output"
  assert_output "ok"
  run py '
import xml.etree.ElementTree as ET
root = ET.parse("plot.svg").getroot()
ns = "{http://www.w3.org/2000/svg}"
print(len(root.findall(ns + "polyline")), len(root.findall(ns + "rect")) >= 3)'
  assert_output "4 True"
  run fuzzyfeed --simulate --segments --csv
  assert_success
  assert_line --index 0 --partial "record,segment,z_from,z_to,depth"
  [ "${#lines[@]}" -eq 8 ]
}

@test "the example runs" {
  run bash "$TOOLKIT_ROOT/examples/fuzzyfeed.sh" "$BATS_TEST_TMPDIR/example"
  assert_success
  [ -s "$BATS_TEST_TMPDIR/example/original.svg" ]
  [ -s "$BATS_TEST_TMPDIR/example/modified.svg" ]
}

@test "the size of a run is checked before it starts: every process option has a range, a traced run a cap" {
  load bounded_run
  bounded fuzzyfeed --simulate --feed 1e-12
  assert_failure 2
  assert_output --partial "--feed: must be a number from 0.001 to 5, not 1e-12"
  bounded fuzzyfeed --simulate --ipo 1e-9
  assert_failure 2
  assert_output --partial "--ipo: must be a number from 0.0001 to 1"
  bounded fuzzyfeed --simulate --power 1e300
  assert_failure 2
  assert_output --partial "--power: must be a number from 0.1 to 1000"
  # 204 mm at 0.0012 mm/rev and 557 rpm: 18300 s, 2.29e6 IPO cycles of 8 ms
  # at 100 %, above the trace's 2e6 (it wrote ~110 bytes a cycle, 250 MB).
  py 'import math; n = 140e3 / (math.pi * 80) / 60; c = 204 / (0.0012 * n) / 0.008; assert 2e6 < c < 2.4e6, c'
  bounded fuzzyfeed --simulate --feed 0.0012 --trace trace.jsonl
  assert_failure 2
  assert_output --partial "--trace with --feed, --cutting-speed, --diameter, --ipo and the profile's length imply 2.29e+06 trace records"
  assert_output --partial "more than the 2e+06 this tool allows"
  [ ! -e trace.jsonl ]
}
