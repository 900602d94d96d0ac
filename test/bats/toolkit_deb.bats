#!/usr/bin/env bats
# The Debian package (`make deb`, cmake/ToolkitPackage.cmake): built by CPack
# from this build tree, unpacked into a scratch root with dpkg-deb -x, and run
# from there alone. Skips where dpkg-deb is missing, and in the sanitizer
# pass (its binaries are not what a package ships).

load test_helper
bats_require_minimum_version 1.5.0

TOOLS=(sieve mrtest riesel gcode-pulse dxf2region fuzzyfeed smcsim tnorm-bench subtune threadcalc)

# bats 1.8 cannot skip from setup_file: it names the reason, setup skips.
setup_file() {
  export SKIP_REASON=""
  if ! command -v dpkg-deb > /dev/null; then SKIP_REASON="dpkg-deb is not installed"; return 0; fi
  if [ -n "${TOOLKIT_SANITIZED:-}" ]; then SKIP_REASON="the package is built from the release tree"; return 0; fi
  if [ ! -f "$TOOLKIT_BUILD/CPackConfig.cmake" ]; then SKIP_REASON="no CPack configuration in $TOOLKIT_BUILD"; return 0; fi
  export PKG_DIR="$BATS_FILE_TMPDIR/pkg" ROOT="$BATS_FILE_TMPDIR/root"
  cpack -G DEB -B "$PKG_DIR" --config "$TOOLKIT_BUILD/CPackConfig.cmake" > "$BATS_FILE_TMPDIR/cpack.log" 2>&1 \
    || { cat "$BATS_FILE_TMPDIR/cpack.log" >&3; return 1; }
  version=$(sed -n 's/^set(CPACK_PACKAGE_VERSION "\(.*\)")$/\1/p' "$TOOLKIT_BUILD/CPackConfig.cmake")
  export DEB="$PKG_DIR/toolkit_${version}_$(dpkg --print-architecture).deb"
  [ -f "$DEB" ] || { ls "$PKG_DIR" >&3; return 1; }
  dpkg-deb -x "$DEB" "$ROOT"
}

setup() {
  [ -z "$SKIP_REASON" ] || skip "$SKIP_REASON"
  cd "$BATS_TEST_TMPDIR"
}

@test "the package holds the ten tools, their pages, the examples and completions" {
  for tool in "${TOOLS[@]}"; do
    [ -x "$ROOT/usr/bin/$tool" ]
    [ -f "$ROOT/usr/share/man/man1/$tool.1.gz" ]
    [ -f "$ROOT/usr/share/bash-completion/completions/$tool" ]
  done
  [ "$(ls "$ROOT/usr/bin" | wc -l)" -eq 10 ]
  [ -f "$ROOT/usr/share/zsh/vendor-completions/_toolkit" ]
  diff -r "$TOOLKIT_ROOT/examples" "$ROOT/usr/share/doc/toolkit/examples"
  [ -f "$ROOT/usr/share/doc/toolkit/copyright" ]
  gzip -t "$ROOT/usr/share/doc/toolkit/changelog.gz"
}

@test "Depends names the package of every shared library the tools link" {
  depends=$(dpkg-deb -f "$DEB" Depends)
  echo "Depends: $depends"
  # Independent of dpkg-shlibdeps: each NEEDED soname, resolved by the
  # dynamic linker and then to its package by dpkg's file list.
  names=$(sed 's/ *([^)]*)//g; s/, */\n/g' <<< "$depends")
  for tool in "${TOOLS[@]}"; do
    ldd "$ROOT/usr/bin/$tool" | awk '$2 == "=>" && $3 ~ /^\// { print $3 }'
  done | sort -u > libraries
  [ -s libraries ]
  # One dpkg -S for all of them: each call reads dpkg's whole file list (~1 s).
  while read -r lib; do readlink -f "$lib"; echo "$lib"; done < libraries > paths
  xargs dpkg -S < paths > owners 2> /dev/null || true
  while read -r lib; do
    package=$(awk -F': ' -v real="$(readlink -f "$lib")" -v named="$lib" \
      '$2 == real || $2 == named { print $1; exit }' owners)
    [ -n "$package" ] || { echo "no package owns $lib"; false; }
    package=${package%%:*}
    grep -qxF "$package" <<< "$names" || { echo "$package ($lib) not in Depends"; false; }
  done < libraries
}

@test "every tool from the scratch root prints its version and revision" {
  for tool in "${TOOLS[@]}"; do
    run --separate-stderr env PATH="$ROOT/usr/bin:/usr/bin:/bin" "$tool" --version
    assert_success
    assert_output --regexp "^$tool \\(toolkit\\) [0-9]+\\.[0-9]+\\.[0-9]+ \\(revision [0-9A-Za-z._-]+\\)\$"
  done
}

@test "a pipeline from the scratch root: sieve | mrtest finds the twin primes k*2^40+-1, k <= 3000" {
  command -v gp > /dev/null || skip "PARI/GP is not installed"
  PATH="$ROOT/usr/bin:/usr/bin:/bin"
  [ "$(command -v sieve)" = "$ROOT/usr/bin/sieve" ]
  sieve twin --n 40 --k 1:3000 --pmax 1e4 | mrtest --keep prime,probable --csv | cut -d, -f1 | tail -n +2 > got
  echo 'for(k=1,3000,if(isprime(k*2^40-1)&&isprime(k*2^40+1),print(k)))' | gp -q > want
  [ -s want ]
  diff want got
}

# groff's "can't break line" is a table too wide for 80 columns (gcode-pulse's
# FIDELITY table), a layout matter, not a fault in the page's markup.
@test "man -l renders every page from the package without markup warnings" {
  command -v man > /dev/null || skip "man-db is not installed"
  for tool in "${TOOLS[@]}"; do
    run --separate-stderr env MANWIDTH=80 man --warnings -P cat -l "$ROOT/usr/share/man/man1/$tool.1.gz"
    assert_success
    warnings=$(grep -v "warning .*: can't break line$" <<< "$stderr" || true)
    [ -z "$warnings" ] || { echo "$tool.1: $warnings"; false; }
    assert_output --partial "NAME"
    assert_output --partial "$tool"
  done
}

@test "the bash completion from the package completes a subcommand and an option" {
  PATH="$ROOT/usr/bin:$PATH"
  source "$ROOT/usr/share/bash-completion/completions/sieve"
  COMP_WORDS=(sieve tw) COMP_CWORD=1
  _toolkit_complete
  [[ " ${COMPREPLY[*]} " == *" twin "* ]]
  COMP_WORDS=(sieve twin --pma) COMP_CWORD=2
  _toolkit_complete
  [ "${COMPREPLY[*]}" = "--pmax" ]
}

@test "lintian reports no errors on the package" {
  command -v lintian > /dev/null || skip "lintian is not installed"
  run lintian --fail-on error "$DEB"
  echo "$output"
  assert_success
}
