#!/usr/bin/env bash
# subtune: active control of a CNC lathe by dimensional sub-tuning, for a
# turned diameter of 40 ± 0.02 mm.
#   1. an in-process gauge's log (part, diameter in mm) through the filter:
#      the parts after which the control sub-tunes the set-up, and by how
#      much. The sizes were logged with the corrections already applied, as
#      a machine would produce them;
#   2. calibration cuts -> the force-induced error model -> for each blank's
#      measured allowance, the largest feed that keeps the predicted error at
#      0.01 mm, and the set-up correction at a fixed feed instead;
#   3. the simulated batch: sub-tuning (Student's test of dA, and the paper's
#      eq. (6) as printed) against the Shewhart, EWMA and CUSUM charts, as CSV.
# Replace the here-documents with your own gauge log, calibration and blanks.
#
#   bash examples/subtune.sh [OUTPUT_DIR]
set -euo pipefail
out="${1:-${TMPDIR:-/tmp}/subtune-example}"
mkdir -p "$out"

# 1 µm gauge; the tool wears and the machine warms up, so the diameter grows.
cat > "$out/gauge.csv" <<'EOF'
part,d
1,40.001
2,40.006
3,40.009
4,40.010
5,40.000
6,40.004
7,40.006
8,40.009
9,39.999
10,40.001
11,40.006
12,40.007
13,40.003
14,40.004
15,40.005
16,40.006
17,40.006
18,40.004
19,40.005
20,40.007
21,40.010
22,40.003
23,40.005
24,40.007
EOF

echo "== 1. sub-tuning on the gauge log (Student's test of dA = a - A_T(N), two-sided at alpha 0.05;"
echo "      corrections to the nominal, the gauge's 1 um rounding as the least spread)"
subtune --field d --correct-to nominal --nominal 40 --resolution 0.001 \
        --lower 39.98 --upper 40.02 --csv "$out/gauge.csv" > "$out/gauge-decisions.csv"
# Columns: part,d,run,n,a,b,s,t,t_crit,df,decision,correction,offset,in_tolerance
awk -F, 'NR == 1 { printf "%5s %9s %3s %7s %7s %15s %11s\n", "part", "d_mm", "n", "t", "t_crit", "correction_um", "offset_um" }
         $11 == "subtune" { printf "%5s %9s %3s %7.2f %7.3f %15.1f %11.1f\n", $1, $2, $4, $8, $9, 1000 * $12, 1000 * $13 }
         NR > 1 && $14 == "false" { out++ }
         END { printf "%d parts, %d out of tolerance\n", NR - 1, out }' "$out/gauge-decisions.csv"

echo
echo "== 2. the force-induced error model y(a, f) from 12 calibration cuts (a mm, f mm/rev, y mm)"
cat > "$out/calibration.csv" <<'EOF'
a,f,y
0.5,0.10,0.0031
0.5,0.20,0.0052
0.5,0.30,0.0078
1.0,0.10,0.0058
1.0,0.20,0.0101
1.0,0.30,0.0150
1.5,0.10,0.0086
1.5,0.20,0.0152
1.5,0.30,0.0228
2.0,0.10,0.0117
2.0,0.20,0.0206
2.0,0.30,0.0309
EOF
subtune model "$out/calibration.csv" > "$out/model.jsonl"
python3 -c '
import json, sys
m = json.load(open(sys.argv[1]))
print("   y = %.5f %+.5f a %+.5f f %+.5f a f %+.5f a^2 %+.5f f^2" % tuple(m[k] for k in ("b0", "b1", "b2", "b12", "b11", "b22")))
print("   r2 %.5f, residual sd %.2f um, condition %.0f" % (m["r2"], 1000 * m["residual_sd"], m["condition"]))' "$out/model.jsonl"

# The blanks' measured allowances (depth of cut, mm).
cat > "$out/blanks.csv" <<'EOF'
blank,a
B1,0.6
B2,1.0
B3,1.4
B4,1.9
B5,2.5
B6,3.2
EOF
echo "   the feed for a predicted error of 0.01 mm (status none: no feed in 0.05..0.5 mm/rev"
echo "   reaches it; a warning says so), or the set-up correction at a fixed 0.2 mm/rev:"
subtune feed --model "$out/model.jsonl" --target 0.01 --csv "$out/blanks.csv" > "$out/feeds.csv"
subtune correct --model "$out/model.jsonl" --feed 0.2 --csv "$out/blanks.csv" > "$out/corrections.csv"
# feeds.csv: blank,a,feed,predicted_error,feed_status,error_min,error_max
# corrections.csv: blank,a,predicted_error,correction
paste -d, "$out/feeds.csv" "$out/corrections.csv" |
  awk -F, 'NR == 1 { printf "%7s %6s %13s %8s %24s\n", "blank", "a_mm", "feed_mm_rev", "status", "or_correction_um_at_0.2" }
           NR > 1 { printf "%7s %6s %13s %8s %24.1f\n", $1, $2, $3 == "" ? "-" : sprintf("%.3f", $3), $5, 1000 * $11 }'

echo
echo "== 3. a simulated batch of 1000 parts (tool wear 0.4 um/part, warm-up, random allowance):"
echo "      sub-tuning against the charts; $out/compare.csv. The default test's in-control"
echo "      runs are so long that some reach --arl-cap, and a warning says so"
{
  subtune --simulate --arl-runs 500 --csv
  subtune --simulate --policy subtune --correct-to nominal --arl-runs 500 --csv | tail -n +2 | sed 's/^subtune,/subtune-to-nominal,/'
  subtune --simulate --policy subtune --statistic paper --arl-runs 500 --csv | tail -n +2 | sed 's/^subtune,/paper-eq6,/'
} > "$out/compare.csv"
# Columns: policy,parts,in_tolerance_share,...,corrections,false_alarms,arl0,...
awk -F, 'NR == 1 { printf "%-19s %12s %12s %13s %9s\n", "policy", "in_tolerance", "corrections", "false_alarms", "arl0" }
         NR > 1 { printf "%-19s %11.1f%% %12s %13s %9s\n", $1, 100 * $3, $7, $8, $9 == "" ? "-" : sprintf("%.1f", $9) }' "$out/compare.csv"
