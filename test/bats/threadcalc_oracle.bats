#!/usr/bin/env bats
# threadcalc against published tables: the limits of every ISO 261 size
# from M1 to M68, coarse and fine, as ISO 965-2 (and the handbooks and
# catalogues that reproduce it) print them; see test/oracle/thread_limits.py
# and test/fixtures/threads/README.md for the sources.

bats_require_minimum_version 1.5.0

setup() {
  load test_helper
  cd "$BATS_TEST_TMPDIR"
}

@test "every published ISO 965-2 limit, M1 to M68, coarse and fine: 0.5 um, tolerances exact" {
  run -0 /usr/bin/python3 "$TOOLKIT_ROOT/test/oracle/thread_limits.py" "$(command -v threadcalc)" \
    "$FIXTURES/threads/iso965-2_limits.csv"
  assert_output --regexp '^171 sizes, [0-9]+ external and [0-9]+ internal members; [0-9]+ published limits within 0.5 um, [0-9]+ tolerances exact; 0 mismatches$'
}

@test "the oracle can fail: one published digit changed is caught" {
  sed 's/^M6,5.974,/M6,5.975,/' "$FIXTURES/threads/iso965-2_limits.csv" > changed.csv
  run -1 /usr/bin/python3 "$TOOLKIT_ROOT/test/oracle/thread_limits.py" "$(command -v threadcalc)" changed.csv
  assert_output --partial "MISMATCH M6-6g"
  assert_output --partial "3 mismatches"
}
