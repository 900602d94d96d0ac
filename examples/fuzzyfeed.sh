#!/usr/bin/env bash
# fuzzyfeed: the seed's turning experiment and the law as a filter.
#   1. simulate the default part (1 mm allowance with three 3 mm collars,
#      E295, 0.4 mm/rev, 9 kW) under the original law and the modified one,
#      with a trace and a plot each (original.svg, modified.svg);
#   2. run the original run's measured load through the stream mode with
#      the modified law (open loop: what it would have commanded);
#   3. the law on a CSV of spindle loads from a machine, fields passed through.
#
#   bash examples/fuzzyfeed.sh [OUTPUT_DIR]
set -euo pipefail
out="${1:-${TMPDIR:-/tmp}/fuzzyfeed-example}"
mkdir -p "$out"

echo "== 1. the simulated cut, M_z = 60 % (plots: $out/original.svg, $out/modified.svg)"
printf '%-9s %8s %8s %7s %14s %13s %12s\n' variant time_s base_s ratio oscillation_pct sd_pct above_mz_s
for variant in original modified; do
  fuzzyfeed --simulate --mz 60 --variant "$variant" --trace "$out/$variant.jsonl" --svg "$out/$variant.svg" |
    python3 -c '
import json, sys
r = json.load(sys.stdin)
print("%-9s %8.2f %8.2f %7.3f %14.2f %13.2f %12.2f" % (r["variant"], r["machining_time_s"], r["baseline_time_s"], r["time_ratio"],
      r["override_oscillation_pct"], r["override_sd_pct"], r["time_above_mz_s"]))'
done

echo
echo "== 2. the original run's measured load through the modified law (stream mode)"
fuzzyfeed --variant modified --k 0.1 --p 0.1 --d 25 "$out/original.jsonl" > "$out/replayed.jsonl"
python3 -c '
import json, sys
orig = [json.loads(l) for l in open(sys.argv[1])]
mod = [json.loads(l) for l in open(sys.argv[2])]
def swing(rows, lo, hi):
    vals = [r["override"] for r in rows if lo <= r["t"] < hi]
    return (max(vals) - min(vals)) / 2
print("%d records; override swing from 3 s to 7 s (1 mm allowance): original law +-%.1f %%, modified law on the same load +-%.1f %%"
      % (len(mod), swing(orig, 3, 7), swing(mod, 3, 7)))
' "$out/original.jsonl" "$out/replayed.jsonl"

echo
echo "== 3. a CSV of spindle loads (one record per 8 ms IPO cycle) through the original law"
cat > "$out/loads.csv" <<'CSV'
t,load,feed,block
0.000,35,0.4,N100
0.008,42,0.4,N100
0.016,55,0.4,N100
0.024,71,0.4,N110
0.032,88,0.4,N110
0.040,64,0.4,N110
0.048,58,0.4,N110
CSV
fuzzyfeed --csv --mz 60 "$out/loads.csv"
