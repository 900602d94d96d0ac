#!/usr/bin/env bats
# threadcalc's limits (issue 21): every numeric option has a range, checked
# before anything runs (exit 2, naming the option), and the program's
# default run-in (the Z axis's way up to the thread's speed) is checked
# before the program is written.

bats_require_minimum_version 1.5.0

setup() {
  load test_helper
  load bounded_run
  cd "$BATS_TEST_TMPDIR"
}

@test "every numeric option out of its range is a usage error naming the option, the range and the value" {
  while IFS='|' read -r args message; do
    # shellcheck disable=SC2086
    bounded threadcalc $args M10
    [ "$status" -eq 2 ] || { echo "$args: exit $status: $output"; false; }
    [[ "$output" == "threadcalc: $message"* ]] || { echo "$args: $output"; false; }
  done <<'CASES'
--decimals 10|--decimals: must be a whole number from 3 to 9, not 10
--passes 101|--passes: must be a whole number from 2 to 100, not 101
--min-last-pass 2|--min-last-pass: must be a number from 0 to 1, not 2
--spring-passes 11|--spring-passes: must be a whole number from 0 to 10, not 11
--infeed flank --flank-angle 31|--flank-angle: must be a number from 0 to 30, not 31
--stock 6|--stock: must be a number from 0 to 5, not 6
--chamfer-margin 1e300|--chamfer-margin: must be a number from 0 to 10, not 1e300
--run-out -1|--run-out: must be a number from 0 to 100, not -1
--gcode g76 --length 0.01|--length: must be a number from 0.1 to 10000, not 0.01
--gcode g76 --length 20 --rpm 0.5|--rpm: must be a number from 1 to 100000, not 0.5
--gcode g76 --length 20 --vc 1e4|--vc: must be a number from 1 to 5000, not 1e4
--gcode g76 --length 20 --max-rpm 2e5|--max-rpm: must be a number from 1 to 100000, not 2e5
--gcode g76 --length 20 --clearance 0|--clearance: must be a number from 0.01 to 100, not 0
--gcode g76 --length 20 --accel 0.5|--accel: must be a number from 1 to 1e+06, not 0.5
--gcode g76 --length 20 --run-in 1001|--run-in: must be a number from 0 to 1000, not 1001
CASES
}

@test "a default run-in beyond 1000 mm is refused, naming --accel; --vc below 1 rpm names --vc" {
  # M10x1.5 at 3000 rpm (--max-rpm caps 100 m/min's 3183): 75 mm/s, at 1
  # mm/s^2 a run-in of 75^2 / 2 = 2812.5 mm (it wrote G0 Z2812.5).
  py 'v = 1.5 * min(3000, 100e3 / (3.141592653589793 * 10)) / 60; assert abs(v * v / 2 - 2812.5) < 1e-9'
  bounded threadcalc --gcode g76 --length 20 --accel 1 M10
  assert_failure 2
  assert_output --partial "threadcalc: --accel with the spindle speed and the pitch imply 2.81e+03 mm of run-in"
  assert_output --partial "more than the 1000 this tool allows"
  # At 2 mm/s^2 it is 1406.25 mm; at 3, 937.5 mm: written.
  bounded threadcalc --gcode g76 --length 20 --accel 3 M10
  assert_success
  assert_line "G0 Z937.5"
  # 1 m/min at 400 mm: 1000 / (400 pi) = 0.80 rpm.
  bounded threadcalc -q --gcode g76 --length 20 --vc 1 M400x6
  assert_failure 2
  assert_output --partial "threadcalc: --vc 1 m/min gives 0.796 rpm at the 400 mm diameter, below 1 rpm"
}
