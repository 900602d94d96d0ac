#!/usr/bin/env bats
# gcode-pulse's limits (issue 21): every numeric option has a range, checked
# before anything runs (exit 2, naming the option); a machine file's values
# have the same ranges (exit 1, naming the file); and the step pulses a
# program implies are counted before each block runs, so that a move of a
# kilometre or a million turns is refused at its line (exit 1) instead of
# stepping for hours or writing terabytes. Expected pulse counts are the
# arithmetic in the comments.

bats_require_minimum_version 1.5.0

setup() {
  load test_helper
  load bounded_run
  cd "$BATS_TEST_TMPDIR"
}

field() {
  json-field "$1"
}

@test "every numeric option out of its range is a usage error naming the option, the range and the value" {
  printf 'G1 X1 F100\n' > ok.ngc
  while IFS='|' read -r args message; do
    # shellcheck disable=SC2086
    bounded gcode-pulse $args ok.ngc
    [ "$status" -eq 2 ] || { echo "$args: exit $status: $output"; false; }
    [[ "$output" == "gcode-pulse: $message"* ]] || { echo "$args: $output"; false; }
  done <<'CASES'
--steps-per-mm 0.5,200,400|--steps-per-mm: must be a number from 1 to 1e+06, not 0.5
--steps-per-mm 200,2e6,400|--steps-per-mm: must be a number from 1 to 1e+06, not 2e+06
--accel 0.001|--accel: must be a number from 0.01 to 1e+12, not 0.001
--accel 1e300|--accel: must be a number from 0.01 to 1e+12, not 1e300
--axis-accel 500,500,1e13|--axis-accel: must be a number from 0.01 to 1e+12, not 1e+13
--rapid 1e13|--rapid: must be a number from 0.01 to 1e+12, not 1e13
--max-feed nan|--max-feed: must be a number from 0.01 to 1e+12, not nan
--axis-max-feed 0.001,1,1|--axis-max-feed: must be a number from 0.01 to 1e+12, not 0.001
--junction-deviation 1e7|--junction-deviation: must be a number from 0 to 1e+06, not 1e7
--lookahead 100001|--lookahead: must be a whole number from 1 to 100000, not 100001
--start 0,2e6,0|--start: must be a number from -1e+06 to 1e+06, not 2e+06
--max-pulses 0|--max-pulses: must be a whole number from 1 to 1000000000000, not 0
--max-pulses 1000000000001|--max-pulses: must be a whole number from 1 to 1000000000000
--svg w.svg --window 0,0,2e6,1|--window needs X0,Y0,X1,Y1 in mm from -1e+06 to 1e+06
CASES
  [ ! -e w.svg ]
}

@test "a machine file's value out of its range is an error naming the file and the key" {
  printf 'G0 X1\n' > x.ngc
  printf '{"lookahead": 1000000}' > deep.json
  bounded gcode-pulse --machine deep.json x.ngc
  assert_failure 1
  assert_output "gcode-pulse: deep.json: lookahead: must be a number from 1 to 100000, not 1e+06"
  printf '{"steps_per_mm": [200, 200, 1e9]}' > fine.json
  bounded gcode-pulse --machine fine.json x.ngc
  assert_failure 1
  assert_output "gcode-pulse: fine.json: steps_per_mm: must be a number from 1 to 1e+06, not 1e+09"
}

@test "--max-pulses counts a line's steps between its ends: at the cap it runs, one step past it is refused" {
  # X2 Y3 at 200 steps/mm: 400 + 600 = 1000 pulses.
  printf 'G1 X2 Y3 F600\n' > line.ngc
  bounded gcode-pulse --summary --max-pulses 1000 line.ngc
  assert_success
  [ $(( $(field pulses_x <<< "$output") + $(field pulses_y <<< "$output") )) -eq 1000 ]
  # Y3.005 is one step more.
  printf 'G1 X2 Y3.005 F600\n' > line.ngc
  bounded gcode-pulse --summary --max-pulses 1000 line.ngc
  assert_failure 1
  assert_output "gcode-pulse: line.ngc:1: the program implies 1001 step pulses up to this block, more than --max-pulses 1000 allows"
}

@test "--max-pulses counts an arc's travel on each axis: a full circle of radius 10 mm at 200 steps/mm is 16,000" {
  # Each plane axis travels 4 r = 40 mm round a circle: 2 * 40 * 200.
  printf 'G2 X0 Y0 I10 J0 F1000\n' > circle.ngc
  bounded gcode-pulse --summary --max-pulses 16000 circle.ngc
  assert_success
  [ $(( $(field pulses_x <<< "$output") + $(field pulses_y <<< "$output") )) -eq 16000 ]
  bounded gcode-pulse --summary --max-pulses 15999 circle.ngc
  assert_failure 1
  [[ "$output" == "gcode-pulse: circle.ngc:1: the program implies 1.6e+04 step pulses"* ]]
}

@test "a program implying more pulses than the default 1e9 is refused at the line that crosses it, before it runs" {
  # A million turns of 1 mm radius: 4 mm a turn on X and on Y at 200
  # steps/mm, 1.6e9 pulses (it stepped for minutes with --summary).
  printf 'G1 X1 F1000\nG2 X1 Y0 I-1 J0 P1000000\n' > turns.ngc
  bounded gcode-pulse --summary turns.ngc
  assert_failure 1
  assert_output "gcode-pulse: turns.ngc:2: the program implies 1.6e+09 step pulses up to this block, more than --max-pulses 1e+09 allows"
  # A kilometre at 200 steps/mm: 2e8 pulses, 6 GB of records; at 10,000
  # steps/mm, 1e10. The first line's 200 pulses stay written.
  printf 'G1 X1 F1000\nG0 X1000000\n' > far.ngc
  bounded gcode-pulse far.ngc --max-pulses 100000000
  assert_failure 1
  [ "$(grep -c '"dx":1' <<< "$output")" -eq 200 ]
  [[ "$output" == *"gcode-pulse: far.ngc:2: the program implies 2e+08 step pulses up to this block, more than --max-pulses 1e+08 allows" ]]
  bounded gcode-pulse --summary --steps-per-mm 10000,10000,10000 far.ngc
  assert_failure 1
  [[ "$output" == "gcode-pulse: far.ngc:2: the program implies 1e+10 step pulses"* ]]
}
