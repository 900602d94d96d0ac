#!/usr/bin/env bash
# tnorm-bench: the seed's line follower under six t-norms.
#   1. what the controller commands for a few sensor situations;
#   2. how long an inference takes, per t-norm (this machine);
#   3. three laps of the simulated car per t-norm, drawn in laps.svg, and the
#      same with a much slower controller (40 ms from sampling to command);
#   4. the controller as fuzzylite FLL, which eval reads back.
#
#   bash examples/tnorm-bench.sh [OUTPUT_DIR]
set -euo pipefail
out="${1:-${TMPDIR:-/tmp}/tnorm-bench-example}"
mkdir -p "$out"

echo "== 1. motor commands (10-bit readings; high = dark line under the sensor)"
printf 'situation,left,mid,right\ncentred,40,950,40\ndrifting left,950,950,40\nfar left,950,40,40\nlost,40,40,40\nbetween sensors,40,400,430\n' |
  tnorm-bench eval --tnorm minimum --centroid exact --csv

echo
echo "== 2. time per inference (one motor, one triple), discrete centroid at resolution 100"
tnorm-bench bench --seconds 0.2 --csv

echo
echo "== 3. three laps of the 1000 x 300 mm oval (plot: $out/laps.svg)"
show_laps() {
  /usr/bin/python3 -c '
import json, sys
for line in sys.stdin:
    r = json.loads(line)
    laps = " ".join("%.2f" % t for t in r["lap_times_s"]) or "-"
    print("%-14s %-9s %-24s %7.2f %9.1f  %s %s" % (r["tnorm"], r["completed"], laps, r["total_s"],
          r["rms_deviation_mm"], r["stop_reason"] or "", r["sensors_at_end"]))'
}
printf '%-14s %-9s %-24s %7s %9s\n' tnorm completed laps_s total_s rms_dev_mm
tnorm-bench laps --tnorm all --svg "$out/laps.svg" | show_laps
echo "-- the same with 40 ms from sampling to command"
tnorm-bench laps --tnorm all --latency-ms 40 --svg "$out/laps-slow.svg" | show_laps

echo
echo "== 4. the controller as fuzzylite FLL ($out/follower.fll), read back"
tnorm-bench fll --tnorm hamacher > "$out/follower.fll"
printf '{"left":40,"mid":950,"right":40}\n' | tnorm-bench eval --fll "$out/follower.fll"
