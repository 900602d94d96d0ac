#!/usr/bin/env bats
# subtune's limits (issue 21): every numeric option has a range, checked
# before anything runs (exit 2, naming the option), and --simulate checks
# the parts it may simulate (every ARL run counted to --arl-cap) and the
# records --trace would write before it starts.

bats_require_minimum_version 1.5.0

setup() {
  load test_helper
  load bounded_run
  cd "$BATS_TEST_TMPDIR"
}

@test "every numeric option out of its range is a usage error naming the option, the range and the value" {
  printf '10\n' > one.txt
  printf '{"a": 1}\n' > a.jsonl
  while IFS='|' read -r args message; do
    # shellcheck disable=SC2086
    bounded subtune $args
    [ "$status" -eq 2 ] || { echo "$args: exit $status: $output"; false; }
    [[ "$output" == "subtune: $message"* ]] || { echo "$args: $output"; false; }
  done <<'CASES'
--resolution 11 one.txt|--resolution: must be a number from 0 to 10, not 11
--lower 1e7 one.txt|--lower: must be a number from -1e+06 to 1e+06, not 1e7
--upper -inf one.txt|--upper: must be a number from -1e+06 to 1e+06, not -inf
--nominal 2e6 --correct-to nominal one.txt|--nominal: must be a number from -1e+06 to 1e+06, not 2e6
--simulate --wear 2|--wear: must be a number from -1 to 1, not 2
--simulate --thermal 1e300|--thermal: must be a number from -10 to 10, not 1e300
--simulate --thermal-parts 0|--thermal-parts: must be a number from 0.01 to 1e+08, not 0
--simulate --allowance 1000|--allowance: must be a number from 0.001 to 100, not 1000
--simulate --allowance-sd -1|--allowance-sd: must be a number from 0 to 100, not -1
--simulate --feed 1e-12|--feed: must be a number from 0.001 to 5, not 1e-12
--simulate --process-sd 2|--process-sd: must be a number from 0 to 1, not 2
--simulate --gauge-sd nan|--gauge-sd: must be a number from 0 to 1, not nan
--simulate --seed -1|--seed: must be a whole number from 0 to 9999999999999999999, not -1
--simulate --shift 1e3|--shift: must be a number from -100 to 100, not 1e3
--simulate --drift 11|--drift: must be a number from -10 to 10, not 11
--simulate --sigma 1e-12|--sigma: must be a number from 1e-09 to 10, not 1e-12
--simulate --shewhart-l 100|--shewhart-l: must be a number from 0.5 to 10, not 100
--simulate --ewma-lambda 0|--ewma-lambda: must be a number from 1e-06 to 1, not 0
--simulate --ewma-l 0.1|--ewma-l: must be a number from 0.5 to 10, not 0.1
--simulate --cusum-k 11|--cusum-k: must be a number from 0 to 10, not 11
--simulate --cusum-h 1e6|--cusum-h: must be a number from 0.1 to 100, not 1e6
--simulate --parts 100000001|--parts: must be a whole number from 1 to 100000000, not 100000001
--simulate --arl-runs 1|--arl-runs: must be a whole number from 2 to 10000000, not 1
--simulate --arl-cap 0|--arl-cap: must be a whole number from 1 to 100000000, not 0
feed --coefficients 0,0.01,0,0,0,0 --target 1e3 a.jsonl|--target: must be a number from -100 to 100, not 1e3
feed --coefficients 0,0.01,0,0,0,0 --feed-min 0 a.jsonl|--feed-min: must be a number from 0.001 to 5, not 0
feed --coefficients 0,0.01,0,0,0,0 --feed-max 10 a.jsonl|--feed-max: must be a number from 0.001 to 5, not 10
correct --coefficients 0,0.01,0,0,0,0 --feed 1e9 a.jsonl|--feed: must be a number from 0.001 to 5, not 1e9
correct --coefficients 0,0.01,0,0,0,1e300 --feed 0.2 a.jsonl|--coefficients: must be a number from -1e+06 to 1e+06, not 1e+300
CASES
}

@test "--simulate refuses, before it starts, ARL runs that may simulate more than 3e9 parts" {
  # Shewhart at ±10 sigma never alarms: every one of 3 x 1000 ARL runs goes
  # to --arl-cap 1e7, 3e10 parts besides the batch's 2 x 1000 (it ran on
  # past any timeout before).
  py 'assert 2 * 1000 + 3 * 1000 * 10**7 == 30000002000'
  bounded subtune --simulate --policy shewhart --shewhart-l 10 --shift 0 --drift 0 --arl-runs 1000 --arl-cap 10000000
  assert_failure 2
  assert_output --partial "subtune: --parts, --arl-runs, --arl-cap and --policy imply 3e+10 simulated parts at most (every ARL run to its cap), more than the 3e+09 this tool allows"
  # Every policy: 5 x 2 x 1000 for the batches, 4 charts x 3 x 2e4 x 1e5 for the ARLs.
  bounded subtune --simulate --arl-runs 20000
  assert_failure 2
  assert_output --partial "imply 2.4e+10 simulated parts at most"
  # Just under the cap: 2 x 1000 + 3 x 10,000 x 99,999 = 2.99999e9 + 2000 runs.
  bounded subtune --simulate --policy cusum --arl-runs 10000 --arl-cap 99999
  assert_success
}

@test "--trace refuses more than 2e6 records before it writes any" {
  # 5 policies x 1e6 parts: 5e6 records of ~170 bytes, 850 MB (it wrote
  # them before; the file-size limit stops it here).
  bounded subtune --simulate --parts 1000000 --arl-runs 2 --trace t.jsonl
  assert_failure 2
  assert_output --partial "subtune: --trace with --parts and --policy imply 5e+06 trace records (one a part and policy), more than the 2e+06 this tool allows"
  [ ! -e t.jsonl ]
}
