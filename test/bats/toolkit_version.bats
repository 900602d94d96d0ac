#!/usr/bin/env bats
# --version on every tool: the version and the git revision the build came
# from, so a result in a log traces back to a commit. The revision comes from
# cmake/ToolkitRevision.cmake, run at every build.

load test_helper
bats_require_minimum_version 1.5.0

TOOLS=(sieve mrtest riesel gcode-pulse dxf2region fuzzyfeed smcsim tnorm-bench subtune threadcalc)

@test "every tool prints one line: name, version and revision" {
  for tool in "${TOOLS[@]}"; do
    run --separate-stderr "$tool" --version
    assert_success
    assert_output --regexp "^$tool \\(toolkit\\) [0-9]+\\.[0-9]+\\.[0-9]+ \\(revision [0-9A-Za-z._-]+\\)\$"
    [ -z "$stderr" ]
  done
}

@test "the revision is a commit of the source tree, the same for every tool" {
  git -C "$TOOLKIT_ROOT" rev-parse --git-dir > /dev/null 2>&1 || skip "source tree is not a git checkout"
  revisions=$(for tool in "${TOOLS[@]}"; do "$tool" --version | sed 's/.*(revision \(.*\))$/\1/'; done | sort -u)
  [ "$(wc -l <<< "$revisions")" -eq 1 ]
  [ "$revisions" != unknown ]
  git -C "$TOOLKIT_ROOT" rev-parse --verify --quiet "${revisions%-dirty}^{commit}"
}

@test "outside a git checkout the revision is 'unknown'; a given one is kept" {
  mkdir -p "$BATS_TEST_TMPDIR/tarball"
  out="$BATS_TEST_TMPDIR/build_info.cpp"
  cmake -DSOURCE_DIR="$BATS_TEST_TMPDIR/tarball" -DOUTPUT="$out" -DVERSION=1.2.3 \
        -P "$TOOLKIT_ROOT/cmake/ToolkitRevision.cmake"
  grep -qxF 'const char* toolkit_revision() { return "unknown"; }' "$out"
  grep -qxF 'const char* toolkit_version() { return "1.2.3"; }' "$out"
  cmake -DSOURCE_DIR="$BATS_TEST_TMPDIR/tarball" -DOUTPUT="$out" -DVERSION=1.2.3 -DREVISION=debian-4 \
        -P "$TOOLKIT_ROOT/cmake/ToolkitRevision.cmake"
  grep -qxF 'const char* toolkit_revision() { return "debian-4"; }' "$out"
}

@test "an unchanged revision leaves the generated file alone (no rebuild per build)" {
  out="$BATS_TEST_TMPDIR/build_info.cpp"
  run_script() {
    cmake -DSOURCE_DIR="$TOOLKIT_ROOT" -DOUTPUT="$out" -DVERSION=1.2.3 -DREVISION=abc1234 \
          -P "$TOOLKIT_ROOT/cmake/ToolkitRevision.cmake"
  }
  run_script
  touch -d '2001-01-01 00:00:00' "$out"
  run_script
  [ "$(stat -c %Y "$out")" = "$(date -d '2001-01-01 00:00:00' +%s)" ]
}
