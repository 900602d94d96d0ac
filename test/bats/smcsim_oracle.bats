#!/usr/bin/env bats
# smcsim's sampled loop against an independent oracle: test/oracle/feed_drive_ivp.py
# simulates the same PID loop (no encoder, no filters) with SciPy's solve_ivp
# (DOP853, rtol 1e-12) and the continuous milling force written from the
# model's formulas, then compares smcsim's t, x, F time series with it.
# Skipped when SciPy is missing.

setup_file() {
  /usr/bin/python3 -c 'import scipy.integrate' 2>/dev/null || skip "SciPy (python3-scipy) is not installed"
}

setup() {
  load test_helper
  /usr/bin/python3 -c 'import scipy.integrate' 2>/dev/null || skip "SciPy (python3-scipy) is not installed"
  load smcsim_helpers
  cd "$BATS_TEST_TMPDIR"
}

@test "PID with the cut, T = 0.1 ms, 10 substeps: x within 1e-6 of solve_ivp (and 1e-3 of the cut's effect)" {
  ivp compare --period 1e-4 --substeps 10
  [ "$status" -eq 0 ]
}

@test "a cut 100 times heavier (feed 108 mm/min): still within 1e-6, and 1e-3 of the cut's effect" {
  ivp compare --period 1e-4 --substeps 10 --feed 108
  [ "$status" -eq 0 ]
}

@test "the first-order hold of the cutting force converges at order 2 in the substeps (T = 1 ms)" {
  ivp converge --period 1e-3 --substeps 1,2,4,8 --min-order 1.8 --max-order 2.3
  [ "$status" -eq 0 ]
  # Three halvings reported, each in range.
  [ "$(grep -c 'observed order' <<< "$output")" -eq 3 ]
}

@test "without the cut the held-force step is exact: 1 to 8 substeps within 1e-10 of solve_ivp" {
  ivp exact --period 1e-3 --substeps 1,2,4,8 --tol 1e-10
  [ "$status" -eq 0 ]
  ivp compare --period 1e-4 --substeps 1 --no-cut --tol 1e-10
  [ "$status" -eq 0 ]
}
