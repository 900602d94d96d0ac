#!/usr/bin/env bats
# Command-line behaviour of fuzzyfeed. The stream mode is checked against
# hand-computed values and against an independent Python re-implementation
# of the law written from the man page's formulas
# (test/fixtures/fuzzyfeed/override_oracle.py); the simulation against
# closed forms (baseline time L / (f n) with n = v_c / (pi D)) and against
# the seed's observations as inequalities, never against output captured once.

bats_require_minimum_version 1.5.0

setup() {
  load test_helper
  cd "$BATS_TEST_TMPDIR"
  FF="$FIXTURES/fuzzyfeed"
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

# against_oracle OUTPUT ORACLE-OUTPUT: wk and override agree to 1e-9 (relative), and load_avg when given.
against_oracle() {
  py '
import json, sys
ours = [json.loads(l) for l in open(sys.argv[1])]
theirs = [l.split() for l in open(sys.argv[2])]
assert len(ours) == len(theirs), (len(ours), len(theirs))
for i, (r, t) in enumerate(zip(ours, theirs)):
    w, o = float(t[0]), float(t[1])
    assert abs(r["wk"] - w) <= 1e-9, (i, r["wk"], w)
    assert abs(r["override"] - o) <= 1e-9 * o, (i, r["override"], o)
    assert abs(r["feed_out"] - r["feed"] * o / 100) <= 1e-12, i
    if len(t) > 2:
        assert abs(r["load_avg"] - float(t[2])) <= 1e-9, (i, r["load_avg"], t[2])
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
  assert_output --regexp "^fuzzyfeed \(toolkit\) [0-9]+\.[0-9]+"
  [ -s "$TOOLKIT_ROOT/man/fuzzyfeed.1" ]
  run grep -c "^\.SH" "$TOOLKIT_ROOT/man/fuzzyfeed.1"
  [ "$output" -ge 10 ]
  grep -q "reconstruction" "$TOOLKIT_ROOT/man/fuzzyfeed.1"
}

@test "usage errors exit 2 and name the option" {
  for args in "--mz 0" "--mz 100.5" "--mz nan" "--k 0" "--k 1.5" "--p 1" "--p -0.1" "--d 0" "--d 2.5" \
              "--initial-override 0" "--initial-override 201" "--min-override 0" "--variant fuzzy"; do
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
  run fuzzyfeed --no-such-option
  assert_failure 2
}

@test "the original law by hand: W_k 1.5, 0.75, 1, 2 and the 200 % ceiling; fields pass through" {
  printf 't,load,feed,id\n0,30,0.4,a\n0.008,90,0.4,b\n0.016,60,0.4,c\n0.024,0,,d\n0.032,0,0.2,e\n' > loads.csv
  run --separate-stderr fuzzyfeed loads.csv
  assert_success
  assert_line --index 0 '{"t":"0","load":"30","feed":"0.4","id":"a","wk":1.5,"override":150.0,"feed_out":0.6}'
  assert_line --index 1 '{"t":"0.008","load":"90","feed":"0.4","id":"b","wk":0.75,"override":112.5,"feed_out":0.45}'
  assert_line --index 2 '{"t":"0.016","load":"60","feed":"0.4","id":"c","wk":1.0,"override":112.5,"feed_out":0.45}'
  assert_line --index 3 '{"t":"0.024","load":"0","feed":"","id":"d","wk":2.0,"override":200.0}'
  assert_line --index 4 '{"t":"0.032","load":"0","feed":"0.2","id":"e","wk":2.0,"override":200.0,"feed_out":0.4}'
  run fuzzyfeed --csv loads.csv
  assert_success
  assert_line --index 0 "t,load,feed,id,wk,override,feed_out"
  assert_line --index 2 "0.008,90,0.4,b,0.75,112.5,0.45"
  assert_line --index 4 "0.024,0,,d,2.0,200.0,"
}

@test "the modified law by hand: warm-up average, gain k, dead band" {
  printf '{"t":0,"load":30}\n{"t":1,"load":90}\n{"t":2,"load":66}\n{"t":3,"load":0}\n{"t":4,"load":12}\n' > loads.jsonl
  run fuzzyfeed --variant modified --d 4 loads.jsonl
  assert_success
  # 30 -> W_k 1.5, W_k' 1.05: 105; means 60 and 62 are in the band 54..66;
  # 46.5 -> W_k' 1.0225; (90 + 66 + 0 + 12) / 4 = 42 -> W_k' 1.03.
  run py '
import json, sys
rows = [json.loads(l) for l in sys.stdin]
assert [r["load_avg"] for r in rows] == [30, 60, 62, 46.5, 42], rows
expect = [105, 105, 105, 105 * 1.0225, 105 * 1.0225 * 1.03]
for r, e in zip(rows, expect):
    assert abs(r["override"] - e) < 1e-9, (r, e)
print("ok")' <<< "$output"
  assert_output "ok"
}

@test "stream mode agrees with the independent Python law: original and modified, several parameter sets" {
  random_loads 6000 5 > loads.jsonl
  fuzzyfeed loads.jsonl > original.jsonl
  python3 "$FF/override_oracle.py" < loads.jsonl > oracle.txt
  run against_oracle original.jsonl oracle.txt
  assert_success
  assert_output "agree 6000"
  for params in "--d 25" "--k 0.5 --p 0.05 --d 3" "--k 1 --p 0 --d 1 --mz 40" "--mz 75 --initial-override 50 --min-override 10 --d 100"; do
    fuzzyfeed --variant modified $params loads.jsonl > modified.jsonl
    python3 "$FF/override_oracle.py" --variant modified $params < loads.jsonl > oracle.txt
    run against_oracle modified.jsonl oracle.txt
    assert_success
    assert_output "agree 6000"
  done
  fuzzyfeed --mz 45 --min-override 5 loads.jsonl > original.jsonl
  python3 "$FF/override_oracle.py" --mz 45 --min-override 5 < loads.jsonl > oracle.txt
  run against_oracle original.jsonl oracle.txt
  assert_success
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
n = 170000 / (math.pi * 80) / 60                      # rev/s at v_c 170 m/min, D 80 mm
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

@test "simulate: the seed's observations come out of the defaults" {
  for seed in 1 2 3; do
    fuzzyfeed --simulate --seed $seed > original.json
    fuzzyfeed --simulate --seed $seed --variant modified --k 0.1 --p 0.1 --d 25 > modified.json
    run py '
import json
o = json.load(open("original.json")); m = json.load(open("modified.json"))
assert o["override_oscillation_pct"] > 5, o          # seed: about +-10 % at 1 mm allowance
assert 0.7 < o["time_ratio"] < 0.9, o                # seed: about 20 % shorter
assert m["override_oscillation_pct"] < 1, m          # seed: the oscillation is gone
assert m["time_ratio"] < 0.9, m
assert o["time_above_mz_s"] < o["baseline_time_above_mz_s"]
assert abs(o["mean_load_pct"] - 60) < 3
print("ok")'
    assert_output "ok"
  done
  # With no noise the original law settles: the oscillation is noise the loop amplifies.
  run fuzzyfeed --simulate --noise 0
  run py 'import json, sys; r = json.loads(sys.stdin.read()); print(r["override_oscillation_pct"] < 1)' <<< "$output"
  assert_output "True"
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
    python3 "$FF/override_oracle.py" --variant $variant < trace.jsonl > oracle.txt
    run against_oracle again.jsonl oracle.txt
    assert_success
  done
  fuzzyfeed --simulate --csv --trace trace.csv > summary.csv
  run head -1 trace.csv
  assert_output "t,z,depth,load_true,load,wk,override,feed,feed_out"
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
n = 170000 / (math.pi * 80) / 60
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
