#!/usr/bin/env bash
# sieve against its peers, each pair timed in the same run on the same input,
# alternating, BENCH_SIEVE_REPEATS times (default 5); medians.
#   primes_count  sieve primes 1 1e10 --count -j2   vs  primesieve 1e10 -t2 (goal: within 1.1x, ratio >= 0.91)
#   primes_print  sieve primes 1 1e9 > /dev/null    vs  primesieve 1e9 --print > /dev/null
# and figures with no runnable peer here (twinsieve from mtsieve is not packaged
# by Debian; its times quoted in issue 3 were measured on this machine):
#   twin n=171960, k <= 1e6,  p <= 1e9    (twinsieve: about 5 s on one core)
#   twin n=171960, k <= 1e9,  p <= 1.1e9  (twinsieve: about 220 s on one core; BENCH_SIEVE_BIG=1)
#   primes up to 2^27 stored in an array  (the seed: under 5 s; goal under 0.05 s)
# Prints RESULT lines for bench/run.sh and FIGURE lines for the rest.
set -euo pipefail
build=${BUILD_DIR:-$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/build}
sieve=$build/sieve
repeats=${BENCH_SIEVE_REPEATS:-5}
command -v primesieve >/dev/null || { echo "bench_sieve: primesieve not found (make bench-deps)" >&2; exit 2; }
[ -x "$sieve" ] || { echo "bench_sieve: $sieve not built" >&2; exit 2; }

seconds() {  # wall seconds of "$@", output discarded
  local start end
  start=$(date +%s.%N)
  "$@" > /dev/null
  end=$(date +%s.%N)
  echo "$end - $start" | bc -l
}
median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

# pair NAME GOAL -- OUR COMMAND -- PEER COMMAND
pair() {
  local name=$1 goal=$2; shift 3
  local ours=() peer=()
  while [ "$1" != -- ]; do ours+=("$1"); shift; done
  shift
  peer=("$@")
  local o p r rs=() os=() ps=()
  for ((i = 0; i < repeats; ++i)); do
    o=$(seconds "${ours[@]}"); p=$(seconds "${peer[@]}")
    os+=("$o"); ps+=("$p"); rs+=("$(echo "$p / $o" | bc -l)")
    printf '  %-13s run %d: ours %.3f s, peer %.3f s\n' "$name" "$((i + 1))" "$o" "$p" >&2
  done
  printf 'RESULT %s %.6f %.6f %.4f %.2f %d\n' "$name" \
    "$(printf '%s\n' "${os[@]}" | median)" "$(printf '%s\n' "${ps[@]}" | median)" \
    "$(printf '%s\n' "${rs[@]}" | median)" "$goal" "$repeats"
}

# The same answers first: a benchmark of wrong output means nothing.
[ "$("$sieve" primes 1 1e9 --count -j2)" = "$(primesieve 1e9 -t2 -q)" ] || { echo "bench_sieve: counts differ" >&2; exit 2; }
cmp -s <("$sieve" primes 1 1e7) <(primesieve 1e7 --print) || { echo "bench_sieve: printed primes differ" >&2; exit 2; }

pair primes_count 0.91 -- "$sieve" primes 1 1e10 --count -j2 -- primesieve 1e10 -t2 -q
pair primes_print 0.91 -- "$sieve" primes 1 1e9 -j2 -- primesieve 1e9 -t2 --print

figure() {  # figure NAME REFERENCE_TEXT COMMAND...
  local name=$1 reference=$2; shift 2
  local ts=()
  for ((i = 0; i < (repeats < 3 ? repeats : 3); ++i)); do ts+=("$(seconds "$@")"); done
  printf 'FIGURE %s %.3f s (median of %d; %s)\n' "$name" "$(printf '%s\n' "${ts[@]}" | median)" "${#ts[@]}" "$reference"
}
figure twin_1e6_j1 "twinsieve about 5 s on one core" "$sieve" twin --n 171960 --k 1:1e6 --pmax 1e9 -j1
figure twin_1e6_j2 "two threads" "$sieve" twin --n 171960 --k 1:1e6 --pmax 1e9 -j2
if [ "${BENCH_SIEVE_BIG:-0}" = 1 ]; then
  figure twin_1e9_j1 "twinsieve about 220 s on one core" "$sieve" twin --n 171960 --k 1:1e9 --pmax 1.1e9 -j1 --newpgen
  figure twin_1e9_j2 "two threads" "$sieve" twin --n 171960 --k 1:1e9 --pmax 1.1e9 -j2 --newpgen
fi
if [ -x "$build/bench/bench_sieve_store" ]; then "$build/bench/bench_sieve_store"; fi
