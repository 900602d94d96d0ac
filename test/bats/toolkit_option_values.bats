#!/usr/bin/env bats
# One policy in every tool (issue 25): a bad option value is a usage error,
# exit 2, its message naming the option and pointing to --help, raised
# where the value is read. Bad data stays exit 1 (the last test).

bats_require_minimum_version 1.5.0

setup() {
  load test_helper
  cd "$BATS_TEST_TMPDIR"
}

# usage_error OPTION TOOL ARGS...: TOOL ARGS (standard input empty) exits 2,
# names OPTION on its first line and ends with the --help pointer.
usage_error() {
  local option=$1 tool=$2
  shift 2
  run "$tool" "$@" < /dev/null
  if [ "$status" -ne 2 ]; then
    echo "$tool $*: exit $status, expected 2: $output"
    return 1
  fi
  if [[ "${lines[0]}" != "$tool: "*"$option"* ]]; then
    echo "$tool $*: the message does not name $option: $output"
    return 1
  fi
  if [[ "$output" != *"Try '$tool --help' for more information." ]]; then
    echo "$tool $*: no pointer to --help: $output"
    return 1
  fi
}

@test "sieve: a bad --pmax, --shard or --min-rate, and an empty primes interval, are usage errors" {
  usage_error --pmax sieve twin --n 5 --k 1:10 --pmax abc
  usage_error --pmax sieve twin --n 5 --k 1:10 --pmax 2
  usage_error --n sieve twin --n 0 --k 1:10 --pmax 100
  usage_error --shard sieve twin --n 5 --k 1:10 --pmax 100 --shard 4/3
  usage_error --min-rate sieve twin --n 5 --k 1:10 --pmax 100 --min-rate -1
  usage_error --riesel-condition sieve proth --n 20 --k 1:3 --pmax 1e5 --riesel-condition
  usage_error "B is below A" sieve primes 10 5
}

@test "riesel: a bad --shard or --max-bits is a usage error" {
  usage_error --shard riesel --shard 3/2
  usage_error --shard riesel --shard x
  usage_error --max-bits riesel --max-bits 1
}

@test "mrtest: a bad --max-bits or --rounds is a usage error" {
  usage_error --max-bits mrtest --max-bits 1
  usage_error --rounds mrtest --test mr --rounds x
}

@test "dxf2region: a bad --tolerances or --units is a usage error" {
  usage_error --tolerances dxf2region --check --tolerances 1,x "$TOOLKIT_ROOT/test/fixtures/dxf/kinks.dxf"
  usage_error --units dxf2region --units furlong "$TOOLKIT_ROOT/test/fixtures/dxf/kinks.dxf"
}

@test "fuzzyfeed: a bad --mz or --efficiency is a usage error" {
  usage_error --mz fuzzyfeed --mz 500
  usage_error --efficiency fuzzyfeed --simulate --efficiency 2
}

@test "gcode-pulse: bad --steps-per-mm, --start and --axis-accel are usage errors, checked where parsed" {
  usage_error --steps-per-mm gcode-pulse --steps-per-mm 200,x,400
  usage_error --steps-per-mm gcode-pulse --steps-per-mm 200,0,400
  usage_error --start gcode-pulse --start 0,2e6,0
  usage_error --axis-accel gcode-pulse --axis-accel 1,-1,1
}

@test "smcsim: a bad --Lambda grid is a usage error" {
  usage_error --Lambda smcsim --Lambda 1:x:1
  usage_error --Lambda smcsim sweep --Lambda 1:10:0
}

@test "subtune: bad --coefficients are a usage error" {
  usage_error --coefficients subtune feed --coefficients 1,2
  usage_error --coefficients subtune feed --coefficients 1,2,3,4,5,1e9
}

@test "threadcalc: a bad --length or --passes is a usage error" {
  usage_error --length threadcalc M10 --gcode g76 --length 20000
  usage_error --passes threadcalc M10 --passes 0
}

@test "tnorm-bench: a bad --centroid N or --backward-slowly corners out of order are usage errors" {
  usage_error --centroid tnorm-bench eval --centroid discrete:x
  usage_error --backward-slowly tnorm-bench eval --backward-slowly -10,-30,-20,-5
  usage_error --oval tnorm-bench laps --oval 1
}

@test "bad data is still exit 1" {
  run sieve merge /dev/null
  [ "$status" -eq 1 ]
  run mrtest <<< "12x"
  [ "$status" -eq 1 ]
  run riesel <<< "not a number"
  [ "$status" -eq 1 ]
  printf 'G1 X1 Y F100\n' > bad.ngc
  run gcode-pulse bad.ngc
  [ "$status" -eq 1 ]
}
