# Shared set-up for the bats suites: bats-support/bats-assert from Debian's
# packages, the freshly built tools first on PATH, a scratch directory.
# Their files are sourced directly: their load.bash forks a dirname for each
# of 15 files, and every test loads this helper again (160 ms of a 240 ms
# trivial test here, measured).
for bats_library_file in /usr/lib/bats/bats-support/src/*.bash /usr/lib/bats/bats-assert/src/*.bash; do
  # shellcheck disable=SC1090
  source "$bats_library_file"
done
unset bats_library_file

TOOLKIT_ROOT="${TOOLKIT_ROOT:-$(cd "$BATS_TEST_DIRNAME/../.." && pwd)}"
TOOLKIT_BIN="${TOOLKIT_BIN:-$TOOLKIT_ROOT/build}"
TOOLKIT_BUILD="${TOOLKIT_BUILD:-$TOOLKIT_BIN}"
PATH="$TOOLKIT_BIN:$PATH"
FIXTURES="$TOOLKIT_ROOT/test/fixtures"

# json-field FIELD < records: one value per line (test/bin, plain python3).
PATH="$TOOLKIT_ROOT/test/bin:$PATH"

# Every python3 the suites start (python3 -c, the test/bin scripts' env
# shebang, bash -c children) is Debian's: it has NumPy, SciPy and ezdxf,
# and starts in ~0.1 s where a pyenv shim first on PATH takes ~1 s.
PATH="$TOOLKIT_ROOT/test/python:$PATH"

# wait_for FILE [SECONDS]: polls until FILE (a glob is fine) exists; fails after SECONDS (default 60).
wait_for() {
  local tries=$(( ${2:-60} * 20 ))
  until compgen -G "$1" > /dev/null; do
    tries=$((tries - 1))
    [ "$tries" -gt 0 ] || { echo "timed out waiting for $1"; return 1; }
    sleep 0.05
  done
}

# wait_for_handler PID: polls until process PID catches SIGINT (bit 2 of
# SigCgt in /proc/PID/status), so a signal sent next meets the tool's handler.
wait_for_handler() {
  local tries=1200 mask
  while :; do
    mask=$(awk '/^SigCgt:/ { print $2 }' "/proc/$1/status" 2>/dev/null)
    [ -n "$mask" ] && (( 0x$mask & 2 )) && return 0
    tries=$((tries - 1))
    [ "$tries" -gt 0 ] || { echo "process $1 never caught SIGINT"; return 1; }
    sleep 0.05
  done
}

# py 'PYTHON' [ARGS...]: Debian's Python, which has NumPy and SciPy.
# The sanitizer pass (TOOLKIT_SANITIZED=1) runs each suite's own checks,
# not its volume: a test that drives paths other tests of its suite cover
# through every fixture, method or format calls this first (a sanitized
# process starts ~10x slower), and the release pass runs it in full.
skip_volume_when_sanitized() {
  if [ -n "${TOOLKIT_SANITIZED:-}" ]; then skip "volume test, run in the release pass"; fi
}

# sanitized: true in the sanitizer pass, where a test that repeats one check
# over every format or case runs a share of them (the release pass runs all).
sanitized() { [ -n "${TOOLKIT_SANITIZED:-}" ]; }

py() { /usr/bin/python3 -c "$@"; }

# check 'PYTHON ASSERTIONS' < records: rows = the JSON Lines records as dicts,
# near(x, want, tol) is |x - want| <= tol; prints ok.
check() {
  py 'import json, math, sys
rows = [json.loads(l) for l in sys.stdin if l.strip()]
def near(x, want, tol):
    return x is not None and abs(x - want) <= tol
exec(sys.argv[1])
print("ok")' "$1"
}

# rs274_g PROGRAM [RS274 OPTIONS...] > canonical commands: LinuxCNC's rs274
# -g, run from the program's folder (it reads subroutine files there) with a
# HOME of this shell's own: rs274 truncates $HOME/.tool.mmap at each start,
# and two at once with one HOME die of SIGBUS. Its exit status says little
# (0 after most errors): the stream's PROGRAM_END() does.
rs274_g() {
  local program=$1 home="${BATS_FILE_TMPDIR:-${TMPDIR:-/tmp}}/rs274-home.$BASHPID"
  shift
  mkdir -p "$home"
  (cd "$(dirname "$program")" && HOME="$home" rs274 "$@" -g "$(basename "$program")" < /dev/null)
}
export -f rs274_g

# Under the sanitizers the tools run without LeakSanitizer's scan at exit:
# it is about a fifth of a sanitized process's start, and the suites start
# thousands of them. ASan and UBSan stay on; the unit tests keep the leak check.
if sanitized; then export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0"; fi
