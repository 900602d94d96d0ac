#!/usr/bin/env bash
# threadcalc: from a customer's order list of threads to limits of size and
# a threading program.
#   1. the order list (CSV) -> ISO 965-1 limits of size and turning data
#      for every thread (the blank a full-profile insert tops off, the
#      passes, the retract angle of a run-out), the order's columns kept;
#   2. the bolt of one order line -> a plain G33 multi-pass program with
#      modified flank infeed, and LinuxCNC's G76 cycle for the same thread;
#   3. the G33 program run through gcode-pulse, which times it.
# Replace the here-document with your own order list.
#
#   bash examples/threadcalc.sh [OUTPUT_DIR]
set -euo pipefail
out="${1:-${TMPDIR:-/tmp}/threadcalc-example}"
mkdir -p "$out"

cat > "$out/orders.csv" <<'CSV'
order,part,qty,designation
A-1001,shaft end,40,M30x2-6g
A-1001,flange nut,40,M30x2-6H
A-1002,hydraulic fitting,12,M16x1.5-6g
A-1003,cover screw and its tapped hole,200,M6
A-1004,adjusting spindle,5,M20x1.5-6g-LH
CSV

threadcalc --csv -i "$out/orders.csv" > "$out/limits.csv"
echo "limits and turning data: $out/limits.csv"
python3 - "$out/limits.csv" <<'PY'
import csv, sys
for r in csv.DictReader(open(sys.argv[1])):
    if r["kind"] == "external":
        print(f'  {r["order"]} {r["thread"]:<18} d2 {r["d2_min"]}..{r["d2_max"]}  d {r["d_min"]}..{r["d_max"]}  '
              f'ap {r["ap"]}, blank {r["blank"]}, {r["passes"]} passes, retract {r["retract_angle"]} deg')
    else:
        print(f'  {r["order"]} {r["thread"]:<18} D2 {r["D2_min"]}..{r["D2_max"]}  D1 {r["D1_min"]}..{r["D1_max"]}  '
              f'ap {r["ap"]}, bore {r["blank"]}, {r["passes"]} passes')
PY

threadcalc --gcode passes --length 40 --infeed flank M30x2-6g > "$out/m30x2-passes.ngc"
threadcalc --gcode g76 --length 40 --infeed flank M30x2-6g > "$out/m30x2-g76.ngc"
echo "programs: $out/m30x2-passes.ngc (G33 passes), $out/m30x2-g76.ngc (LinuxCNC G76)"
grep '^G76' "$out/m30x2-g76.ngc" | sed 's/^/  /'
gcode-pulse --summary "$out/m30x2-passes.ngc" | python3 -c '
import json, sys
r = json.load(sys.stdin)
print("  gcode-pulse: the passes program takes %.1f s" % r["duration_s"])'
