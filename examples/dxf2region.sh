#!/usr/bin/env bash
# dxf2region on a plate with rounded corners, a bore and a slot, for a tool
# of radius 2 mm:
#   1. DXF -> region records -> SVG drawing (region.svg),
#   2. DXF -> finishing contour -> gcode-pulse (the pulses' summary),
#   3. a joystick's positions checked against the region (the barrier),
#   4. the seed's experiment (12 and 18 mm/s, T 1-5 mm) with the latency-aware
#      guard beside it, under a modern control and one as slow as the seed's.
#
#   bash examples/dxf2region.sh [PART.dxf] [TOOL_RADIUS] [OUTPUT_DIR]
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
part="${1:-$here/../test/fixtures/dxf/plate.dxf}"
radius="${2:-2}"
out="${3:-${TMPDIR:-/tmp}/dxf2region-example}"
mkdir -p "$out"

echo "== 1. the region of $part for a tool of radius $radius mm (drawing: $out/region.svg)"
dxf2region "$part" --tool-radius "$radius" --svg "$out/region.svg" > "$out/region.jsonl"
python3 -c '
import json, sys
for line in open(sys.argv[1]):
    r = json.loads(line)
    if r["record"] == "loop":
        kinds = [e["type"] for e in r["elements"]]
        print("loop %d: %s, %d lines and %d arcs, area %.3f mm2, length %.3f mm"
              % (r["loop"], "hole" if r["hole"] else "outer", kinds.count("line"), kinds.count("arc"), r["area_mm2"], r["length_mm"]))
    elif r["record"] == "drawing":
        print("read:", r["entities_read"], " skipped:", r["entities_skipped"])
' "$out/region.jsonl"

echo
echo "== 2. the finishing contour ($out/finish.ngc) through gcode-pulse"
dxf2region -q "$part" --tool-radius "$radius" --toolpath --feed 800 > "$out/finish.ngc"
grep -c '^G[123] ' "$out/finish.ngc" | xargs echo "contour moves:"
gcode-pulse --steps-per-mm 200,200,400 --summary "$out/finish.ngc" |
  python3 -c 'import json, sys; r = json.load(sys.stdin); print("pulses x %d y %d z %d, %.1f s, path %.3f mm, deviation max %.4f mm"
    % (r["pulses_x"], r["pulses_y"], r["pulses_z"], r["duration_s"], r["path_mm"], r["max_deviation_mm"]))'

echo
echo "== 3. a joystick's positions (x, y, t): straight at the plate's bottom edge at 50 mm/s"
python3 -c '
for i in range(0, 13):
    t = i * 0.02
    print("{\"x\": 50, \"y\": %.3f, \"t\": %.2f}" % (-10 + 50 * t, t))
' > "$out/positions.jsonl"
dxf2region -q "$part" --tool-radius "$radius" --check "$out/positions.jsonl" --summary --latency 0.05 |
  python3 -c '
import json, sys
for line in sys.stdin:
    r = json.loads(line)
    if r.get("summary"):
        print("positions %d, invasions %d, deepest %.3f mm" % (r["positions"], r["invasions"], r["deepest_invasion_mm"]))
    else:
        print("t %.2f y %7.3f: distance %7.3f inside %-5s barrier (%.3f, %.3f) stop %s"
              % (r["t"], r["y"], r["distance"], r["inside"], r["clamped_x"], r["clamped_y"], r.get("stop")))
'

echo
echo "== 4. the seed's experiment at its speeds: fixed tolerances against the latency-aware guard"
for control in "--latency 0.09 --period 0.001" "--latency-mm 1.35 --period-mm 3.925"; do
  echo "-- control: $control"
  printf '%-16s %6s %6s %9s %10s %14s\n' guard V_mm_s T_mm invasions success mean_undercut
  # shellcheck disable=SC2086  # the control's options, split on purpose
  dxf2region -q "$part" --tool-radius "$radius" --simulate --strokes 300 $control |
    python3 -c '
import json, sys
for line in sys.stdin:
    r = json.loads(line)
    print("%-16s %6g %6.2f %9d %9.1f%% %14.3f" % (r["guard"], r["joystick_speed_mm_s"], r["tolerance_mm"], r["invasions"],
                                               100 * r["success_rate"], r["mean_undercut_mm"]))
'
done
