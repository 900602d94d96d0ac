#!/usr/bin/env bash
# gcode-pulse on a small program: the four stepping methods' summaries
# side by side (how closely each follows the path, how many events), then
# the first pulses of the default method as CSV. `direct` is the paper's
# rule (Panayotov & Goranov), `nearest` the default; see gcode-pulse(1).
#
# Run from anywhere; it uses the test fixture of lines and arcs in 3D
# (where the paper's re-drawn line drifts from the programmed one) unless
# a G-code file is given:
#   bash examples/gcode-pulse.sh [PROGRAM.ngc] [STEPS_X,Y,Z]
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
program="${1:-$here/../test/fixtures/gcode/paper/lines_3d.ngc}"
steps="${2:-200,200,400}"

echo "program: $program, steps per mm: $steps"
printf '%-10s %10s %10s %10s %12s %12s %10s\n' method pulses_x pulses_y pulses_z max_dev_mm rms_dev_mm events
for method in nearest direct bresenham dda; do
  gcode-pulse --steps-per-mm "$steps" --method "$method" --summary "$program" |
    python3 -c '
import json, sys
r = json.load(sys.stdin)
print("%-10s %10d %10d %10d %12.5f %12.5f %10d" % (r["method"], r["pulses_x"], r["pulses_y"], r["pulses_z"],
      r["max_deviation_mm"], r["rms_deviation_mm"], r["events"]))'
done

echo
echo "the same program on the machine of examples/machine-router.json (slower Z):"
gcode-pulse --machine "$here/machine-router.json" --summary "$program" |
  python3 -c 'import json, sys; r = json.load(sys.stdin); print("duration %.3f s, %d of the blocks capped by an axis" % (r["duration_s"], r["feed_capped_blocks"]))'

echo
echo "first pulses of the default method, nearest (t in s; dx, dy, dz in steps):"
gcode-pulse --steps-per-mm "$steps" --csv "$program" | head -6
