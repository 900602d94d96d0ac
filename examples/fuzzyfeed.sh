#!/usr/bin/env bash
# fuzzyfeed: Stryczek & Orawczak's turning test and the law as a filter.
#   1. simulate the default part (1 mm allowance with three 3 mm collars,
#      E295, 0.4 mm/rev, 9 kW) under the original law (1)-(4) and the
#      modified one (5)-(7), with a trace and a plot each (original.svg,
#      modified.svg), and the figures the paper reports for its Test 1;
#   2. run the original run's measured load through the stream mode with
#      the modified law (open loop: what it would have commanded);
#   3. the law on a CSV of spindle loads from a machine, fields passed through.
#
#   bash examples/fuzzyfeed.sh [OUTPUT_DIR]
set -euo pipefail
out="${1:-${TMPDIR:-/tmp}/fuzzyfeed-example}"
mkdir -p "$out"

echo "== 1. the simulated cut, M_z = 60 % (plots: $out/original.svg, $out/modified.svg)"
echo "   the paper: ~25 % load at 1 mm, override ~145 %, 20 % shorter, +-10 % oscillation; none after the modification"
printf '%-9s %9s %8s %9s %11s %11s %11s\n' variant load1_100 shorter O_1mm osc_1mm O_3mm osc_3mm
for variant in original modified; do
  fuzzyfeed --simulate --segments --mz 60 --variant "$variant" --trace "$out/$variant.jsonl" --svg "$out/$variant.svg" |
    python3 -c '
import json, sys
rows = [json.loads(l) for l in sys.stdin]
segs, s = rows[:-1], rows[-1]
def at(depth, key, pick):
    return pick([r[key] for r in segs if r["depth"] == depth])
mean = lambda v: sum(v) / len(v)
print("%-9s %8.1f%% %7.1f%% %8.1f%% %10.2f %10.1f%% %10.2f" % (s["variant"], at(1, "load_at_100_pct", max),
      100 * (1 - s["time_ratio"]), at(1, "settled_override_pct", mean), at(1, "oscillation_pct", max),
      at(3, "settled_override_pct", mean), at(3, "oscillation_pct", max)))'
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
print("%d records; override swing from 9.5 s to 11 s (3 mm allowance): original law +-%.1f %%, modified law on the same load +-%.1f %%"
      % (len(mod), swing(orig, 9.5, 11), swing(mod, 9.5, 11)))
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
