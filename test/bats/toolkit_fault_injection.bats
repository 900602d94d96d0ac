#!/usr/bin/env bats
# Fault injection (issue 21): each tool that writes records or files is
# killed with SIGKILL at a random moment, FAULT_ITERATIONS times (10), and
# what it leaves is checked against an uninterrupted run of the same
# command: records on standard output (a file, or a pipe every other time)
# are whole lines, byte for byte the first lines of the full output; a
# --trace or --svg file is the one there before or the complete new one; a
# --binary stream is refused unless it is complete. The delays are random,
# from 10 ms to a little past the full run's time (printed when a test
# fails); no assertion depends on them.

load test_helper

ITERATIONS=${FAULT_ITERATIONS:-10}

setup() {
  cd "$BATS_TEST_TMPDIR" || exit 1
}

# timed_run OUT CMD...: CMD > OUT to the end; RUN_MS is how long it took.
timed_run() {
  local out=$1 start
  shift
  start=$(date +%s%N)
  "$@" > "$out" 2> /dev/null || { echo "the uninterrupted run failed: $*"; return 1; }
  RUN_MS=$((($(date +%s%N) - start) / 1000000))
}

# random_ms: from 10 ms to 1.1 times RUN_MS.
random_ms() {
  echo $((10 + (RANDOM * 32768 + RANDOM) % (RUN_MS * 11 / 10 + 1)))
}

# kill_after MS OUT CMD...: CMD > OUT (through a pipe to cat when PIPE=1),
# SIGKILL after MS ms. STATUS: 137 when it was killed, 0 when it had ended.
kill_after() {
  local ms=$1 out=$2 pid reader=
  shift 2
  if [ "${PIPE:-0}" = 1 ]; then
    rm -f fifo && mkfifo fifo
    cat fifo > "$out" &
    reader=$!
    "$@" > fifo 2> /dev/null &
    pid=$!
  else
    "$@" > "$out" 2> /dev/null &
    pid=$!
  fi
  sleep "$(printf '%d.%03d' $((ms / 1000)) $((ms % 1000)))"
  kill -9 "$pid" 2> /dev/null || true
  STATUS=0
  wait "$pid" || STATUS=$?
  [ -z "$reader" ] || wait "$reader"
  echo "killed after $ms ms (pipe ${PIPE:-0}): status $STATUS, $(stat -c %s "$out") bytes"
  [ "$STATUS" = 0 ] || [ "$STATUS" = 137 ] || { echo "exit status $STATUS"; return 1; }
}

# whole_prefix OUT FULL: OUT is FULL's beginning and ends at a line's end.
# One exception, on a regular file only (PIPE=0): Linux may cut a write(2)
# at a 4 KiB page boundary when the writer is killed inside it (while the
# kernel throttles a writer of many dirty pages), so there the last line
# may lack its end, at a size that is a multiple of 4096. A pipe takes each
# write of up to PIPE_BUF (4 KiB) bytes whole: no exception.
whole_prefix() {
  local size
  size=$(stat -c %s "$1")
  [ "$size" -le "$(stat -c %s "$2")" ] || { echo "$1 is longer than the full run's output"; return 1; }
  cmp -s -n "$size" "$1" "$2" || { echo "$1 is not the full output's beginning: $(cmp -n "$size" "$1" "$2")"; return 1; }
  [ "$size" -eq 0 ] || [ "$(tail -c 1 "$1" | od -An -tx1 | tr -d ' ')" = 0a ] && return 0
  if [ "${PIPE:-0}" = 0 ] && [ $((size % 4096)) -eq 0 ]; then
    echo "cut by the kernel at a page boundary inside a write"
    sed -i '$ d' "$1"  # the whole lines before it are what the caller checks further
    return 0
  fi
  echo "$1 ends in a torn line: ...$(tail -c 60 "$1")"
  return 1
}

# parse_json_lines FILE: each line of FILE is one JSON object.
parse_json_lines() {
  py 'import json, sys
for n, line in enumerate(open(sys.argv[1]), 1):
    assert isinstance(json.loads(line), dict), (n, line)' "$1"
}

# no_temporaries NAME: no ".NAME.tmp.*" is left in the current directory.
no_temporaries() {
  local left
  left=$(compgen -G ".$1.tmp.*" || true)
  [ -z "$left" ] || { echo "temporaries left: $left"; return 1; }
}

# A program of N straight moves through a 200 mm by 200 mm by 20 mm box (30: 0.3 s of records).
moves_program() {
  py 'import random, sys
random.seed(21)
print("G21 G90 G1 F6000")
for _ in range(int(sys.argv[1])):
    print("X%.3f Y%.3f Z%.3f" % (random.uniform(0, 200), random.uniform(0, 200), random.uniform(0, 20)))' "$1"
}

@test "gcode-pulse records: a killed run leaves whole lines, the first lines of the full run (a file or a pipe)" {
  moves_program 30 > moves.ngc
  timed_run full.jsonl gcode-pulse moves.ngc
  : > last_lines
  for ((i = 0; i < ITERATIONS; i++)); do
    PIPE=$((i % 2))
    kill_after "$(random_ms)" out.jsonl gcode-pulse moves.ngc
    whole_prefix out.jsonl full.jsonl
    tail -n 1 out.jsonl >> last_lines
  done
  parse_json_lines last_lines
}

@test "gcode-pulse --binary: the decoder written from gcode-pulse(1) reads the records' events; every cut stream is refused" {
  moves_program 3 > short.ngc
  gcode-pulse --binary short.ngc > short.bin
  gcode-pulse short.ngc > short.jsonl
  decode-gcode-pulse < short.bin > decoded.csv
  py 'import csv, json, sys
want = [json.loads(l) for l in open("short.jsonl")]
got = list(csv.DictReader(open("decoded.csv")))
assert len(got) == len(want) > 1000, (len(got), len(want))
for g, w in zip(got, want):
    assert int(g["t_ns"]) == round(w["t"] * 1e9), (g, w)
    assert [int(g[k]) for k in ("dx", "dy", "dz")] == [w["dx"], w["dy"], w["dz"]], (g, w)'
  run gcode-pulse --verify-binary short.bin
  assert_success
  py 'import json, sys
r = json.loads(sys.argv[1])
rows = [json.loads(l) for l in open("short.jsonl")]
assert r["events"] == len(rows) and r["last_t"] == round(rows[-1]["t"] * 1e9) / 1e9, r
assert [r["pulses_" + a] for a in "xyz"] == [sum(abs(x["d" + a]) for x in rows) for a in "xyz"], r' "$output"
  # Every cut through the last events and the trailer, and some earlier ones, of a short stream.
  printf 'G21 G90 G1 F600 X1 Y0.3 Z0.2\n' > tiny.ngc
  gcode-pulse --binary tiny.ngc > tiny.bin
  decode-gcode-pulse < tiny.bin > /dev/null 2>&1
  size=$(stat -c %s tiny.bin)
  for cut in $(seq $((size - 24)) $((size - 1))) 0 7 32 33 $((RANDOM % size)) $((RANDOM % size)); do
    head -c "$cut" tiny.bin > cut.bin
    run gcode-pulse --verify-binary cut.bin
    assert_failure 1
    assert_output --regexp "^gcode-pulse: cut.bin: byte [0-9]+: .*truncated"
  done
  for cut in 0 33 $((size - 19)) $((size - 18)) $((size - 1)) $((RANDOM % size)); do
    head -c "$cut" tiny.bin > cut.bin
    run decode-gcode-pulse < cut.bin
    assert_failure 1
  done
  { cat tiny.bin; printf x; } > long.bin
  run gcode-pulse --verify-binary long.bin
  assert_failure 1
  assert_output --partial "bytes after the trailer"
}

@test "gcode-pulse --binary: a killed run's stream is refused by --verify-binary unless it is whole" {
  moves_program 60 > moves.ngc
  timed_run full.bin gcode-pulse --binary moves.ngc
  gcode-pulse --verify-binary full.bin > /dev/null
  refused=0
  for ((i = 0; i < ITERATIONS; i++)); do
    PIPE=$((i % 2))
    kill_after "$(random_ms)" out.bin gcode-pulse --binary moves.ngc
    cmp -s -n "$(stat -c %s out.bin)" out.bin full.bin || { echo "not the full stream's beginning"; false; }
    if cmp -s out.bin full.bin; then
      gcode-pulse --verify-binary out.bin > /dev/null
    else
      refused=$((refused + 1))
      run gcode-pulse --verify-binary out.bin
      assert_failure 1
      assert_output --partial "truncated"
    fi
  done
  echo "$refused of $ITERATIONS streams cut short"
}

@test "dxf2region --check and --svg: whole records, the first of the full run; the drawing is the old one or the whole new one" {
  py 'out = ["0", "SECTION", "2", "ENTITIES"]
def line(a, b, c, d): out.extend(["0", "LINE", "8", "0", "10", str(a), "20", str(b), "11", str(c), "21", str(d)])
line(0, 0, 1000, 0); line(1000, 0, 1000, 1000); line(1000, 1000, 0, 1000); line(0, 1000, 0, 0)
for i in range(10):
    for j in range(10):
        out.extend(["0", "CIRCLE", "8", "0", "10", str(68 + 96 * i), "20", str(68 + 96 * j), "40", "6"])
out.extend(["0", "ENDSEC", "0", "EOF"])
print("\n".join(out))' > holes.dxf
  py 'import math
print("x,y,t")
for i in range(20000):
    t = i * 1e-3
    print("%.4f,%.4f,%.3f" % (500 + 450 * math.cos(0.7 * t), 500 + 450 * math.sin(1.1 * t), t))' > positions.csv
  tool=(dxf2region --units mm --tool-radius 2 --check positions.csv --svg plot.svg holes.dxf)
  timed_run full.jsonl "${tool[@]}"
  mv plot.svg full.svg
  : > last_lines
  for ((i = 0; i < ITERATIONS; i++)); do
    echo previous > plot.svg
    PIPE=$((i % 2))
    kill_after "$(random_ms)" out.jsonl "${tool[@]}"
    whole_prefix out.jsonl full.jsonl
    tail -n 1 out.jsonl >> last_lines
    cmp -s plot.svg full.svg || [ "$(cat plot.svg)" = previous ] || { echo "plot.svg is neither: $(tail -c 60 plot.svg)"; false; }
  done
  parse_json_lines last_lines
  "${tool[@]}" > /dev/null 2>&1
  cmp plot.svg full.svg
  no_temporaries plot.svg
}

# trace_survives_kills CMD...: CMD writes --trace trace.jsonl and records on
# standard output. Killed, the trace is the previous file or the whole new
# one; the next run removes the temporary a killed one left.
trace_survives_kills() {
  timed_run full.jsonl "$@"
  mv trace.jsonl full_trace.jsonl
  parse_json_lines full_trace.jsonl
  local i kept=0
  for ((i = 0; i < ITERATIONS; i++)); do
    echo '{"previous":true}' > trace.jsonl
    PIPE=$((i % 2))
    kill_after "$(random_ms)" out.jsonl "$@"
    whole_prefix out.jsonl full.jsonl
    if cmp -s trace.jsonl full_trace.jsonl; then
      :
    elif [ "$(cat trace.jsonl)" = '{"previous":true}' ]; then
      kept=$((kept + 1))
    else
      echo "trace.jsonl is neither the previous file nor the whole trace: $(wc -l < trace.jsonl) lines, ...$(tail -c 60 trace.jsonl)"
      false
    fi
  done
  echo "the previous trace stayed $kept times of $ITERATIONS"
  "$@" > /dev/null 2>&1
  cmp trace.jsonl full_trace.jsonl
  no_temporaries trace.jsonl
}

@test "fuzzyfeed --trace: a killed run leaves the previous trace or the whole new one" {
  trace_survives_kills fuzzyfeed --simulate --ipo 0.0005 --trace trace.jsonl
}

@test "subtune --trace: a killed run leaves the previous trace or the whole new one" {
  trace_survives_kills subtune --simulate --parts 4000 --arl-runs 2 --trace trace.jsonl
}

@test "tnorm-bench laps --trace: a killed run leaves the previous trace or the whole new one" {
  trace_survives_kills tnorm-bench laps --tnorm minimum product drastic --trace trace.jsonl
}
