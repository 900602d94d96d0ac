#!/usr/bin/env bash
# tnorm-bench: Könczöl & Gál's line follower under six t-norms.
#   1. what the paper's rules command for a few sensor situations;
#   2. how long an inference takes, per t-norm (this machine);
#   3. the lap study: three laps per t-norm with the Uno's and the ESP32's
#      loop times (the paper's Tables 3-4), beside the paper's lap times
#      (Tables 1-2), drawn in laps-uno.svg; then one car at growing loop times;
#   4. the controller as fuzzylite FLL, which eval reads back.
#
#   bash examples/tnorm-bench.sh [OUTPUT_DIR]
set -euo pipefail
out="${1:-${TMPDIR:-/tmp}/tnorm-bench-example}"
mkdir -p "$out"

echo "== 1. motor commands (10-bit readings; high = dark line under the sensor)"
printf 'situation,left,mid,right\ncentred (R4),40,950,40\nleft of centre (R5),950,950,40\nunder the left sensor (R6),950,40,40\nlost (R1),40,40,40\nbetween mid and right,40,400,430\n' |
  tnorm-bench eval --tnorm minimum --centroid exact --csv

echo
echo "== 2. time per inference (one motor, one triple), discrete centroid at resolution 100"
tnorm-bench bench --seconds 0.2 --csv

echo
echo "== 3. three laps of the 1000 x 300 mm oval per board (plot: $out/laps-uno.svg)"
show_laps() {
  /usr/bin/python3 -c '
import json, sys
for line in sys.stdin:
    r = json.loads(line)
    ours = "%.2f" % r["total_s"] if r["completed"] else "%s at %.1f s (%s)" % (r["stop_reason"], r["total_s"], r["sensors_at_end"])
    paper = "%.2f" % r["paper_total_s"] if r["paper_total_s"] else "-"
    print("%-6s %-14s %7.3f ms  ours %-26s paper %s" % (r["board"], r["tnorm"], r["latency_ms"], ours, paper))'
}
tnorm-bench laps --tnorm all --board uno --svg "$out/laps-uno.svg" | show_laps
tnorm-bench laps --tnorm all --board esp32 | show_laps
echo "-- the minimum t-norm's car at growing loop times"
for ms in 0 4 12 20 25 40; do
  tnorm-bench laps --tnorm minimum --latency-ms "$ms" --time-limit 90 | show_laps
done

echo
echo "== 4. the controller as fuzzylite FLL ($out/follower.fll), read back"
tnorm-bench fll --tnorm hamacher > "$out/follower.fll"
printf '{"left":40,"mid":950,"right":40}\n' | tnorm-bench eval --fll "$out/follower.fll"
