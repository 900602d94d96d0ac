#!/usr/bin/env bats
# Every reader of every tool under input that never ends, binary garbage, a
# byte-order mark and a first line that is data, not a CSV header: a one-line
# error naming the input and line, exit 1, promptly (timeout only guards
# against a hang: before the fix /dev/zero spun or grew without end).

load test_helper

setup() {
  cd "$BATS_TEST_TMPDIR"
  # A line without end (no newline, no NUL), fast: perl writes 1 MiB at a
  # time until the reader goes away.
  endless() { perl -e '$s = "y" x 1048576; print $s while 1' 2> /dev/null; }
  export -f endless
}

# The commands that read standard input, one per line: "tool args".
stdin_readers() {
  cat <<'EOF'
mrtest
riesel
subtune
threadcalc
fuzzyfeed
tnorm-bench eval
gcode-pulse --summary
dxf2region -
dxf2region --check - FIXTURE_DXF
smcsim --reference-file - --duration 1
fuzzyfeed --simulate --profile -
tnorm-bench laps --track -
EOF
}

# run_reader "tool args" FEED: the tool's stdin is what FEED prints.
run_reader() {
  local command=${1/FIXTURE_DXF/$FIXTURES/dxf/plate.dxf}
  run timeout 30 bash -c "$2 | $command"
}

@test "/dev/zero on standard input: every reader says NUL at line 1 and exits 1 at once" {
  while read -r command; do
    run_reader "$command" 'cat /dev/zero'
    echo "$command -> $status: $output"
    [ "$status" -eq 1 ]
    [[ "$output" == *":1: "*"NUL"* ]]
  done < <(stdin_readers)
}

# The readers share io::InputFile, except the DXF reader: one of each kind
# (64 MiB takes a second or more through a pipe on a loaded machine).
@test "a line that never ends: the readers stop at 64 MiB with exit 1" {
  for command in "mrtest" "gcode-pulse --summary" "tnorm-bench laps --track -" "dxf2region -"; do
    run_reader "$command" 'endless'
    echo "$command -> $status: $output"
    [ "$status" -eq 1 ]
    [[ "$output" == *":1: line longer than 64 MiB"* ]]
  done
}

@test "--skip-bad after an endless line gives the input up instead of reading for ever" {
  run timeout 30 bash -c 'endless | mrtest --skip-bad'
  [ "$status" -eq 0 ] || [ "$status" -eq 1 ]
  assert_output --partial "line longer than 64 MiB"
  assert_output --partial "the rest of the input is skipped"
}

@test "/dev/zero as a file argument: riesel, mrtest and dxf2region stop at line 1" {
  for command in "riesel /dev/zero" "mrtest /dev/zero" "dxf2region /dev/zero"; do
    run timeout 30 $command
    echo "$command -> $status: $output"
    [ "$status" -eq 1 ]
    [[ "$output" == *"/dev/zero:1: binary data (NUL byte)"* ]]
  done
}

@test "riesel blocked on an empty pipe ends on SIGTERM and on SIGINT" {
  mkfifo pipe
  exec 5<> pipe  # a writer that stays open and silent
  for signal in TERM INT; do
    rm -rf state
    riesel --state state < pipe > out 2> err &
    local pid=$!
    wait_for_handler "$pid"
    kill -"$signal" "$pid"
    local status=0
    timeout 5 tail --pid="$pid" -f /dev/null || status=$?
    [ "$status" -eq 0 ] || { echo "riesel still runs 5 s after SIG$signal"; kill -9 "$pid"; exec 5>&-; false; }
    wait "$pid" || status=$?
    echo "SIG$signal -> status $status; $(cat err)"
    [ "$status" -eq $((128 + $(kill -l "$signal"))) ]
    grep -q "stopped by signal" err
  done
  exec 5>&-
}

@test "a UTF-8 byte-order mark is skipped by the G-code, FLL and record readers" {
  printf '\xEF\xBB\xBFG21 G90\nG1 X1 F600\nM2\n' > bom.ngc
  run gcode-pulse --summary bom.ngc
  assert_success
  echo "$output" | check 'assert near(rows[0]["final_x"], 1.0, 1e-9)'

  tnorm-bench fll > plain.fll
  { printf '\xEF\xBB\xBF'; cat plain.fll; } > bom.fll
  printf 'left,mid,right\n100,900,100\n' > readings.csv
  run tnorm-bench eval --fll bom.fll readings.csv
  assert_success
  [ "$output" = "$(tnorm-bench eval --fll plain.fll readings.csv)" ]

  printf '\xEF\xBB\xBFt,load\n0,10\n' | fuzzyfeed > bom.out
  printf 't,load\n0,10\n' | fuzzyfeed > plain.out
  cmp bom.out plain.out
}

@test "a first line that is data is refused at line 1, not taken for a CSV header" {
  run bash -c 'echo NaN | subtune'
  assert_failure 1
  assert_output --partial "<stdin>:1: 'NaN' is not a finite number"

  run bash -c 'echo 10x1.5 | threadcalc'
  assert_failure 1
  assert_output --partial "<stdin>:1: designation '10x1.5'"

  run bash -c 'printf "garbage\nM10\n" | threadcalc'
  assert_failure 1
  assert_output --partial "<stdin>:1: designation 'garbage'"

  run bash -c 'echo garbage | mrtest'
  assert_failure 1
  assert_output --partial "<stdin>:1:"

  run bash -c 'echo garbage | fuzzyfeed'
  assert_failure 1
  assert_output --partial "<stdin>:1: 'garbage' is not a csv header naming 't' and 'load'"

  run bash -c "echo garbage | dxf2region --check - '$FIXTURES/dxf/plate.dxf'"
  assert_failure 1
  assert_output --partial "<stdin>:1: 'garbage' is not a csv header naming 'x' and 'y'"
}

@test "a real CSV header still reads: the columns a tool needs, in any order, with others" {
  run bash -c 'printf "part,size\n1,10.01\n2,10.02\n" | subtune --csv'
  assert_success
  run bash -c 'printf "note,designation\nshaft,M10\n" | threadcalc'
  assert_success
  assert_output --partial '"designation":"M10"'
  run bash -c 'printf "load,t\n10,0\n" | fuzzyfeed'
  assert_success
  run bash -c 'printf "n,k,c\n2,3,-1\n" | mrtest'
  assert_success
  assert_output --partial '"verdict":"prime"'
}
