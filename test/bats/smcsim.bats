#!/usr/bin/env bats
# Command-line behaviour of smcsim: the sweep against single runs, a sampled
# reference file against the analytic sine, inputs and errors. The paper's
# findings, per reading of its gains, are in smcsim_paper_oracle.bats.

bats_require_minimum_version 1.5.0

setup() {
  load test_helper
  load smcsim_helpers
  cd "$BATS_TEST_TMPDIR"
  SMC="$FIXTURES/smcsim"
}

@test "--help, --version and the man page" {
  run smcsim --help
  assert_success
  for option in --controller --Lambda --alpha --beta --seed-sign --seed-bracket --reference-file --summary --every --svg --units sweep; do
    assert_output --partial -- "$option"
  done
  run smcsim --version
  assert_success
  assert_output --regexp '^smcsim \(toolkit\) [0-9]+\.[0-9]+\.[0-9]+ \(revision [0-9A-Za-z._-]+\)$'
  [ -s "$TOOLKIT_ROOT/man/smcsim.1" ]
}

@test "time series: the eight fields in order, one record every --every periods of --duration" {
  run --separate-stderr smcsim --duration 0.1
  assert_success
  [ "${#lines[@]}" -eq 100 ]  # 1000 periods of 0.1 ms, every 10th
  run py '
import json, math, sys
rows = [json.loads(l) for l in sys.stdin]
assert all(list(r) == ["t", "x_ref", "x", "e", "e_dot", "S", "F", "F_d"] for r in rows)
assert rows[0]["t"] == 0 and rows[0]["x"] == rows[0]["x_ref"] == 0, rows[0]   # starts on the reference
for i, r in enumerate(rows):
    assert abs(r["t"] - i * 1e-3) < 1e-12, (i, r["t"])
    assert abs(r["x_ref"] - math.sin(3 * r["t"])) < 1e-12, r
    assert abs(r["e"] - (r["x_ref"] - r["x"])) < 1e-12, r
print("ok")' <<< "$output"
  assert_output "ok"
  run smcsim --duration 0.1 --every 7
  [ "${#lines[@]}" -eq 143 ]  # k = 0, 7, ..., 994
  run smcsim --duration 0.5 --period 1e-3 --every 1
  [ "${#lines[@]}" -eq 500 ]
  run smcsim --duration 0.1 --every 5000
  [ "${#lines[@]}" -eq 1 ]
}

@test "--csv: a header row, then the same numbers as JSON Lines" {
  smcsim --duration 0.05 > series.jsonl
  smcsim --duration 0.05 --csv > series.csv
  run head -1 series.csv
  assert_output "t,x_ref,x,e,e_dot,S,F,F_d"
  [ "$(wc -l < series.csv)" -eq $(( $(wc -l < series.jsonl) + 1 )) ]
  run py '
import csv, json
rows = [json.loads(l) for l in open("series.jsonl")]
cells = list(csv.DictReader(open("series.csv")))
assert all(float(c[k]) == r[k] for r, c in zip(rows, cells) for k in r)
print("ok")'
  assert_output "ok"
  run smcsim --summary --csv
  assert_line --index 0 "controller,Lambda,alpha,beta,rms_error_mm,max_error_mm,rms_velocity_error_mm_s,rms_s,chattering,hf_share,effort_rms_n,max_force_n,saturated_share,measured_s,plant_steps,diverged,diverged_at_s"
  assert_line --index 1 --regexp "^smc,40.0,,,"
}

@test "--summary: the fields, per controller, and what --settle and --duration measure" {
  run py '
import json, sys
runs = json.loads(sys.stdin.read())
common = ["rms_error_mm", "max_error_mm", "rms_velocity_error_mm_s", "rms_s", "chattering", "hf_share", "effort_rms_n",
          "max_force_n", "saturated_share", "measured_s", "plant_steps", "diverged"]
assert list(runs["smc"]) == ["controller", "Lambda"] + common, list(runs["smc"])
assert list(runs["sta"]) == ["controller", "alpha", "beta"] + common
assert list(runs["pid"]) == ["controller"] + common and list(runs["ppd"]) == ["controller"] + common
assert runs["smc"]["controller"] == "smc" and runs["smc"]["Lambda"] == 40 and runs["sta"]["alpha"] == runs["sta"]["beta"] == 200
for r in runs.values():
    assert r["diverged"] is False and 0 <= r["hf_share"] <= 1 and 0 <= r["saturated_share"] <= 1
    assert r["max_error_mm"] >= r["rms_error_mm"] > 0
assert runs["smc"]["measured_s"] == 10 and runs["smc"]["plant_steps"] == 1000000   # 10 s, 0.1 ms, 10 substeps
assert runs["short"]["measured_s"] == 2 and runs["short"]["plant_steps"] == 100000 # 2 s, 0.2 ms
assert abs(runs["settled"]["measured_s"] - 9) < 1e-9
assert runs["settled"]["max_error_mm"] <= runs["smc"]["max_error_mm"]
print("ok")' <<< "$(figures "smc" "sta --controller sta" "pid --controller pid" "ppd --controller ppd" \
                           "short --duration 2 --period 2e-4" "settled --settle 1")"
  assert_output "ok"
}

@test "sweep: the same summaries as single runs, in grid order whatever -j" {
  smcsim sweep --Lambda 40:400:360 > sweep.jsonl
  { smcsim --summary --Lambda 40; smcsim --summary --Lambda 400; } > single.jsonl
  cmp sweep.jsonl single.jsonl
  smcsim sweep --controller smc --Lambda 10:50:10 --duration 0.5 -j 3 --csv > lambda.csv
  run cut -d, -f2 lambda.csv
  assert_output "$(printf 'Lambda\n10.0\n20.0\n30.0\n40.0\n50.0')"
  for j in 1 2 4; do
    smcsim sweep --controller sta --alpha 100:300:100 --beta 100:200:100 --duration 0.5 -j $j > "sta$j.jsonl"
  done
  cmp sta1.jsonl sta2.jsonl
  cmp sta1.jsonl sta4.jsonl
  run py '
import json
rows = [json.loads(l) for l in open("sta1.jsonl")]
assert [(r["alpha"], r["beta"]) for r in rows] == [(a, b) for a in (100, 200, 300) for b in (100, 200)], rows
print(len(rows))'
  assert_output "6"
  # the default thread count (every core) gives the same too
  smcsim sweep --controller sta --alpha 100:300:100 --beta 100:200:100 --duration 0.5 | cmp - sta1.jsonl
}

@test "a reference file (the sine sampled at 1 kHz, t and x only) tracks like --reference sine" {
  # The fixture is what its generator writes: 1 mm sin(3 t), t from 0 to 2.1 s every 1 ms.
  python3 "$SMC/sine_1khz.py" | cmp - "$SMC/sine_1khz.csv"
  # From samples rounded to 1 nm, with v and a by central differences (relative
  # error (ωh)²/6 = 1.5e-6) and a cubic Hermite curve between them (1e-13 mm),
  # the controllers see the same reference to about a millionth; the
  # switching decisions near S = 0 then differ now and then, which moves the
  # figures of the µm-level runs by up to about 2 % (measured: 1.3 % for
  # Lambda 400), so 5 % is the tolerance. The first 10 ms are left out and the
  # axis starts at the sine's 3 mm/s because the file reference's first
  # sample holds velocity 0 (t <= first t).
  run py '
import json, sys
r = json.loads(sys.stdin.read())
bad = []
for c in ("smc40", "smc400", "sta", "ppd"):
    a, b = r[c], r[c + "_file"]
    for k in ("rms_error_mm", "rms_velocity_error_mm_s", "chattering", "effort_rms_n"):
        if abs(b[k] - a[k]) > 0.05 * a[k]:
            bad.append((c, k, a[k], b[k]))
print(bad or "ok")' <<< "$(
    common="--duration 2 --settle 0.01"
    file="--reference-file $SMC/sine_1khz.csv --initial-velocity 3"
    figures "smc40 $common" "smc40_file $common $file" "smc400 $common --Lambda 400" "smc400_file $common --Lambda 400 $file" \
            "sta $common --controller sta" "sta_file $common --controller sta $file" \
            "ppd $common --controller ppd" "ppd_file $common --controller ppd $file")"
  assert_output "ok"
  # a reference on stdin, as JSON Lines with v given
  py 'import json, math
for i in range(2101):
    t = i / 1000
    print(json.dumps({"t": t, "x": math.sin(3 * t), "v": 3 * math.cos(3 * t)}))' |
    smcsim --reference-file - --summary --duration 2 > stdin.jsonl
  run json-field diverged < stdin.jsonl
  assert_output "False"
}

@test "step and ramp references: the shapes asked for, followed" {
  smcsim --reference step --amplitude 0.5 --start 0.015 --duration 0.05 > step.jsonl
  smcsim --reference ramp --slope 2 --start 0.01 --duration 0.05 > ramp.jsonl
  run py '
import json
step = [json.loads(l) for l in open("step.jsonl")]
ramp = [json.loads(l) for l in open("ramp.jsonl")]
assert len(step) == len(ramp) == 50
assert all(r["x_ref"] == (0.5 if r["t"] >= 0.015 else 0) for r in step)
assert all(abs(r["x_ref"] - 2 * max(0, r["t"] - 0.01)) < 1e-12 for r in ramp)
print("ok")'
  assert_output "ok"
  run py '
import json, sys
r = json.loads(sys.stdin.read())
assert not r["step"]["diverged"] and not r["ramp"]["diverged"]
# The surface (mu 2, lambda 1) puts a double pole at -1/s: the
# axis closes a 1 mm step over seconds, never overshooting the step itself.
assert 0.99 < r["step"]["max_error_mm"] < 1.01, r["step"]
# Lambda 400 follows a 1 mm/s ramp to micrometres once settled.
assert r["ramp"]["rms_error_mm"] < 0.01, r["ramp"]
print("ok")' <<< "$(figures "step --reference step --start 0.1 --duration 3 --Lambda 400" \
                           "ramp --reference ramp --duration 3 --settle 1 --Lambda 400")"
  assert_output "ok"
}

@test "--mass-end and --damping-end are accepted and change the run" {
  run py '
import json, sys
r = json.loads(sys.stdin.read())
base = r["base"]["rms_error_mm"]
for k in ("mass", "damping", "both"):
    assert not r[k]["diverged"] and r[k]["rms_error_mm"] != base, (k, r[k]["rms_error_mm"], base)
assert r["same"]["rms_error_mm"] == base   # drifting to the same value is no drift
print("ok")' <<< "$(figures "base --duration 3" "mass --duration 3 --mass-end 8" "damping --duration 3 --damping-end 300" \
                           "both --duration 3 --mass-end 12 --damping-end 200" "same --duration 3 --mass-end 10 --damping-end 250")"
  assert_output "ok"
}

@test "--svg writes the drawing; an unwritable one is named, after the records" {
  run smcsim --summary --duration 0.5 --svg run.svg
  assert_success
  py 'import xml.dom.minidom; assert xml.dom.minidom.parse("run.svg").documentElement.tagName == "svg"'
  run --separate-stderr smcsim --duration 0.1 --svg no/such/dir/run.svg
  assert_failure 1
  [ "${#lines[@]}" -eq 100 ]
  [[ "$stderr" == "smcsim: no/such/dir/run.svg: "* ]]
  # The title names the law drawn: the printed bracket and sign when asked for.
  for law in "" "--seed-bracket" "--seed-sign" "--seed-bracket --seed-sign"; do
    # shellcheck disable=SC2086
    run smcsim --summary --duration 0.1 --Lambda 400 $law --svg law.svg
    assert_success
    py 'import sys, xml.dom.minidom
title = xml.dom.minidom.parse("law.svg").getElementsByTagName("title")[0].firstChild.data
want = "smcsim --controller smc --Lambda 400" + "".join(" " + w for w in sys.argv[1].split()) + ":"
assert title.startswith(want), (title, want)' "$law"
  done
}

@test "usage errors exit 2 and name the option" {
  check() {  # check MESSAGE ARGS...: exit 2, "smcsim: MESSAGE" and the hint, nothing on stdout
    local message="$1"
    shift
    run --separate-stderr smcsim "$@"
    [ "$status" -eq 2 ] || { echo "status $status for $*: $stderr"; return 1; }
    [ -z "$output" ] || { echo "stdout for $*: $output"; return 1; }
    [ "${stderr%%$'\n'*}" = "smcsim: $message" ] || { echo "for $*: $stderr"; return 1; }
    [[ "$stderr" == *"Try 'smcsim --help' for more information." ]]
  }
  mass="must be a number from 0.001 to 10000"  # a micro stage to a gantry
  check "--mass: $mass, not -1" --mass -1
  check "--mass: $mass, not 0" --mass 0
  check "--mass: $mass, not nan" --mass nan
  check "--mass: $mass, not 1e308" --mass 1e308
  check "--mass: $mass, not 1e-320" --mass 1e-320
  check "--mass: 'ten' is not a number" --mass ten
  check "--mass-end: $mass, not -5" --mass-end -5
  check "--mass-estimate: $mass, not inf" --mass-estimate inf
  check "--damping: must be 0 or a number from 1e-12 to 1e12, not -250" --damping -250
  check "--damping-end: must be 0 or a number from 1e-12 to 1e12, not -2" --damping-end -2
  check "--period: must be a number from 1e-07 to 1, not 0" --period 0
  check "--period: must be a number from 1e-07 to 1, not -1e-4" --period -1e-4
  check "--duration: must be a number from 1e-06 to 100000, not -1" --duration -1
  check "--duration: must be a number from 1e-06 to 100000, not 1e400" --duration 1e400
  check "--Lambda 'nan' is not a number or FROM:TO:STEP" --Lambda nan
  check "--Lambda: must be 0 or a number from 1e-12 to 1e12, not -5" --Lambda -5
  check "--Lambda: must be 0 or a number from 1e-12 to 1e12, not 1e+300" --Lambda 1e300
  check "--alpha 'inf' is not a number or FROM:TO:STEP" --controller sta --alpha inf
  check "--beta: must be 0 or a number from 1e-12 to 1e12, not -1" --controller sta --beta -1
  check "--kp: must be 0 or a number from 1e-12 to 1e12, not -5" --controller pid --kp -5
  check "--pid-ff: must be a number from 0 to 1, not 1.5" --controller pid --pid-ff 1.5
  check "--amplitude: must be a number from -10000 to 10000, not 1e308" --amplitude 1e308
  check "--initial-position: must be a number from -1e12 to 1e12, not nan" --initial-position nan
  check "--substeps: must be a whole number from 1 to 100000, not 0" --substeps 0
  check "--substeps: must be a whole number from 1 to 100000, not -3" --substeps -3
  check "--every: must be a whole number from 1 to 1000000000000, not 0" --every 0
  check "--every: must be a whole number from 1 to 1000000000000, not -1" --every -1
  check "--teeth: must be a whole number from 1 to 64, not 0" --teeth 0
  check "--period 0.5 s is longer than --duration 0.1 s" --period 0.5 --duration 0.1
  check "--duration 10000 s at --period 0.0001 s is 1e+08 control periods; at most 1e+07" --duration 1e4
  check "--duration 10 s at --period 1e-07 s is 1e+08 control periods; at most 1e+07" --period 1e-7
  check "--substeps 100000 over 1e+05 control periods is 1e+10 plant steps; at most 1e+08" --substeps 100000
  check "--settle 10 s leaves nothing of --duration 10 s" --settle 10
  check "--radial-depth 2 mm is more than --tool-diameter 0.9 mm" --radial-depth 2
  check "--reference-file excludes --omega" --reference-file x.csv --omega 2
  check "--reference excludes --reference-file" --reference-file x.csv --reference step
  check "--Lambda takes one value here; ranges are for 'smcsim sweep'" --Lambda 10:100:10
  check "--controller: ded not in {smc,sta,pid,ppd}" --controller ded
  check "--seed-sign and --seed-bracket change the sliding-mode laws (smc, sta), not pid" --controller pid --seed-bracket
  check "--seed-sign and --seed-bracket change the sliding-mode laws (smc, sta), not ppd" --controller ppd --seed-sign
  # sweeps
  check "--Lambda '10:1' is not a number or FROM:TO:STEP" sweep --Lambda 10:1
  check "--Lambda '1:2:0' needs FROM <= TO and a positive STEP" sweep --Lambda 1:2:0
  check "--Lambda '10:1:1' needs FROM <= TO and a positive STEP" sweep --Lambda 10:1:1
  check "--Lambda 'a:b:c' is not a number or FROM:TO:STEP" sweep --Lambda a:b:c
  check "--Lambda '1:1e9:1' has more than 100000 values" sweep --Lambda 1:1e9:1
  check "--Lambda: must be 0 or a number from 1e-12 to 1e12, not -10" sweep --Lambda -10:10:10
  check "--alpha and --beta make 1000 × 1000 settings; a sweep takes at most 100000" \
    sweep --controller sta --alpha 1:1000:1 --beta 1:1000:1
  check "a sweep varies --Lambda (smc) or --alpha and --beta (sta), not pid gains" sweep --controller pid
  check "a sweep varies --Lambda (smc) or --alpha and --beta (sta), not ppd gains" sweep --controller ppd
  check "--alpha and --beta are sta gains; a sweep of smc varies --Lambda" sweep --alpha 100:200:100
  check "--Lambda is an smc gain; a sweep of sta varies --alpha and --beta" sweep --controller sta --Lambda 40
  check "--svg draws one run, not a sweep" sweep --Lambda 40:400:360 --svg sweep.svg
  check "--threads: Value 0 not in range 1 to 1024" sweep -j 0
  [ ! -e sweep.svg ]
}

@test "bad reference files: file:line message, exit 1, nothing run" {
  check() {  # check CONTENT LINE MESSAGE (LINE empty: no line)
    printf "$1" > ref.txt
    run --separate-stderr smcsim --reference-file ref.txt --duration 0.01
    [ "$status" -eq 1 ] || { echo "status $status: $stderr"; return 1; }
    [ -z "$output" ] || { echo "records: $output"; return 1; }
    local where="ref.txt:$2: "
    [ -n "$2" ] || where="ref.txt: "
    [ "$stderr" = "smcsim: $where$3" ] || { echo "stderr: $stderr"; return 1; }
  }
  check '' '' "a reference needs at least two samples, found 0"
  check '\n\n' '' "a reference needs at least two samples, found 0"
  check 't,x\n' '' "a reference needs at least two samples, found 0"
  check 't,x\n0,0\n' '' "a reference needs at least two samples, found 1"
  check 't,x\n0,0\n0.1,1\n0.2' 4 "expected 2 csv fields, found 1"
  check 't,x\n0,0\n0.1,1\n0.2,' 4 "missing field 'x'"
  check 't,x\n0,0\n0.1,1\n0.1,2\n' 4 "t must increase strictly: 0.1 after 0.1"
  check 't,x\n0,0\n0.2,1\n0.1,2\n' 4 "t must increase strictly: 0.1 after 0.2"
  # A header that does not name t and x is refused where it stands.
  check 't,y\n0,0\n0.1,1\n' 1 "'t,y' is not a csv header naming 't' and 'x', nor a json object"
  check 'x\n0\n1\n' 1 "'x' is not a csv header naming 't' and 'x', nor a json object"
  check 't,x\n0,0\n0.1,nan\n' 3 "field 'x' is not finite"
  check 't,x\n0,0\nnan,1\n' 3 "field 't' is not finite"
  check 't,x\n0,0\n0.1,1e400\n' 3 "field 'x' is out of range: '1e400'"
  check 't,x\n0,0\n0.1,abc\n' 3 "field 'x' is not a number: 'abc'"
  check 't,x,v\n0,0,1\n0.1,1,nan\n' 3 "field 'v' is not finite"
  check 't,x\n0,0,5\n0.1,1\n' 2 "expected 2 csv fields, found 3"
  check 't,x\n"0,0\n0.1,1\n' 2 "unterminated quoted field at end of input"
  check '{"t":0,"x":0}\n{"t":0.1}\n' 2 "missing field 'x'"
  check '{"t":0,"x":0}\n{"t":0.1,"x":1\n' 2 \
    "invalid json: parse error column 15: syntax error while parsing object - unexpected end of input; expected '}'"
  printf 't,x\n0,0\n\x00\x01\xff\n' > ref.txt
  run --separate-stderr smcsim --reference-file ref.txt
  assert_failure 1
  [[ "$stderr" == "smcsim: ref.txt:3: "* ]]
  head -c 4096 /dev/urandom > garbage.bin
  run --separate-stderr smcsim --reference-file garbage.bin --summary
  assert_failure 1
  [ -z "$output" ]
  [[ "$stderr" == "smcsim: garbage.bin:"* ]]
  run --separate-stderr smcsim --reference-file no-such-file.csv
  assert_failure 1
  assert_equal "$stderr" "smcsim: no-such-file.csv: cannot open: No such file or directory"
  run --separate-stderr smcsim --reference-file "$BATS_TEST_TMPDIR" --summary
  assert_failure 1
  [[ "$stderr" == *"is a directory" ]]
}

@test "a run that diverges: the time series up to it then exit 1; a summary says so" {
  # a reference that jumps 1e6 mm between two samples
  printf 't,x\n0,0\n0.01,1e6\n' > jump.csv
  run --separate-stderr smcsim --reference-file jump.csv --every 1
  assert_failure 1
  [ "${#lines[@]}" -ge 1 ]
  [[ "$stderr" == "smcsim: the loop diverged at t = "*" s (error beyond 1000 mm)" ]]
  run --separate-stderr smcsim --reference-file jump.csv --summary
  assert_success
  run json-field diverged <<< "$output"
  assert_output "True"
}

@test "the example runs" {
  run bash "$TOOLKIT_ROOT/examples/smcsim.sh" "$BATS_TEST_TMPDIR/example"
  assert_success
  assert_output --regexp "smc --Lambda 400 +0\.00"
  assert_output --regexp "Lambda [0-9]+: rms 0\.0[0-9]+ mm, chattering [0-9]+ N/s, hf_share 0\.(0[0-9]+|100) "
  [ -s "$BATS_TEST_TMPDIR/example/best.svg" ]
  [ "$(wc -l < "$BATS_TEST_TMPDIR/example/sweep.csv")" -eq 101 ]
}

@test "a run that diverges before --settle has no tracking error (null), not 0.0, and a sweep writes it last" {
  # PID gains of 1e12 against a 1e8 N amplifier: the error passes 1000 mm
  # within a few periods, long before the 1 s --settle.
  run --separate-stderr smcsim --summary --controller pid --kp 1e12 --kd 1e12 --voltage-limit 1000 --kt 1000 --ka 1e4 --settle 1
  assert_success
  echo "$output" | check 'r = rows[0]
assert r["diverged"] is True and r["diverged_at_s"] < 0.01, r
for f in ("rms_error_mm", "max_error_mm", "rms_velocity_error_mm_s", "rms_s"):
    assert r[f] is None, (f, r[f])'
  # --seed-sign's wrong sign pushes away from the surface: Lambda 0 tracks,
  # 5e8 and 1e9 (swept first and last) diverge at once.
  run --separate-stderr smcsim sweep --seed-sign --Lambda 0:1e9:5e8 --voltage-limit 1000 --kt 1000 --ka 1e4 --settle 1 --duration 2 -j 2
  assert_success
  echo "$output" | check 'assert [r["Lambda"] for r in rows] == [0, 5e8, 1e9], rows
assert [r["diverged"] for r in rows] == [False, True, True]
assert rows[0]["rms_error_mm"] > 0 and rows[1]["rms_error_mm"] is None and rows[2]["rms_error_mm"] is None'
}

@test "a sweep's plant steps are capped before it starts" {
  load bounded_run
  # 10^4 settings x 10^5 periods x 10 substeps = 10^10 plant steps (~30 min of two cores).
  bounded smcsim sweep --Lambda 0:9999:1 --duration 10
  assert_failure 2
  assert_output --partial "the sweep's settings, --duration, --period and --substeps imply 1e+10 plant steps, more than the 1e+09 this tool allows"
  bounded smcsim --summary --voltage-limit 1e9
  assert_failure 2
  assert_output --partial "--voltage-limit: must be a number from 0.01 to 1000, not 1e9"
}
