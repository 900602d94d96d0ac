#!/usr/bin/env bash
# Runs the benchmarks that `make bench` built and prints a summary table.
# Builds nothing. Usage: bench/run.sh [bench_u64 bench_kbnc bench_generic bench_sieve]
# (bench_sieve is the script bench/bench_sieve.sh; it times the sieve tool
# against the primesieve command and prints FIGURE lines where no peer runs here)
# Environment: BUILD_DIR (default: build), BENCH_REPEATS (default 5; 3 for
# bench_kbnc), BENCH_U64_REPEATS / BENCH_KBNC_REPEATS / BENCH_GENERIC_REPEATS
# per benchmark, BENCH_GP (the gp binary), BENCH_STRICT=1 to exit 1 when a
# goal is not met. Exits 2 when a benchmark fails, e.g. on disagreeing verdicts.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BUILD_DIR:-$root/build}
benches=("$@")
[ ${#benches[@]} -gt 0 ] || benches=(bench_u64 bench_kbnc bench_generic bench_sieve bench_riesel bench_gcode_pulse bench_dxf_parse bench_region_query bench_region_build bench_tnorm bench_fuzzyfeed bench_smcsim bench_subtune)

command -v "${BENCH_GP:-gp}" >/dev/null || { echo "run.sh: PARI/GP's gp not found (make bench-deps)" >&2; exit 2; }

results=$(mktemp)
trap 'rm -f "$results"' EXIT
for name in "${benches[@]}"; do
  if [ -f "$root/bench/$name.sh" ]; then
    bin=("bash" "$root/bench/$name.sh")
  else
    bin=("$build/bench/$name")
    [ -x "${bin[0]}" ] || bin=("$(command -v "$name")") || { echo "run.sh: $name not built (make bench)" >&2; exit 2; }
  fi
  if ! BUILD_DIR="$build" "${bin[@]}" | tee -a "$results"; then
    echo "run.sh: $name FAILED" >&2
    exit 2
  fi
  echo
done

# RESULT name ours peer ratio goal repeats  (medians; ratio = peer / ours)
summary=$(awk '$1 == "RESULT" {
  met = ($5 + 0 >= $6 + 0) ? "met" : "NOT met"
  if (met != "met") missed++
  printf "%-14s %9.4f s %9.4f s %9.3f %7s %5d   %s\n", $2, $3, $4, $5, ">= " $6 + 0, $7, met
} END { exit missed > 0 }' "$results") && all_met=1 || all_met=0

echo "Summary (medians; ratio = peer time / our time, > 1 means we are faster)"
printf "%-14s %11s %11s %9s %7s %5s   %s\n" benchmark "ours" "peer" ratio goal runs result
echo "$summary"
if grep -q '^FIGURE' "$results"; then
  echo
  echo "Figures without a peer in the same run"
  grep '^FIGURE' "$results" | cut -d' ' -f2-
fi
if [ "$all_met" = 0 ] && [ "${BENCH_STRICT:-0}" = 1 ]; then exit 1; fi
exit 0
