#!/usr/bin/env bash
# Any program LinuxCNC runs, stepped: LinuxCNC's own interpreter (rs274,
# Debian's linuxcnc-uspace) prints the canonical machining commands and
# gcode-pulse --canon steps them. Here on the programs LinuxCNC installs,
# most of which gcode-pulse's own interpreter cannot read (subroutines,
# parameters, canned cycles, cutter compensation); see gcode-pulse(1),
# LINUXCNC'S INTERPRETER.
#   bash examples/gcode-pulse-linuxcnc.sh [PROGRAM.ngc...]
set -euo pipefail
command -v rs274 > /dev/null || { echo "needs rs274: apt-get install linuxcnc-uspace" >&2; exit 1; }
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
tools="$here/../test/fixtures/gcode/linuxcnc/rs274_tools_inch.tbl"  # rs274 reads its table in inches
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
if [ $# -eq 0 ]; then
  set -- /usr/share/linuxcnc/ncfiles/{polar,hole-circle,comp,threading,useful-subroutines,skeleton}.ngc
fi

printf '%-26s %-10s %10s %10s %10s %12s\n' program own final_x final_y final_z duration_s
for program in "$@"; do
  # rs274 reads subroutine files from the current directory, keeps its tool
  # table in $HOME, and exits 0 on errors: gcode-pulse checks the stream ends.
  (cd "$(dirname "$program")" && HOME="$scratch" rs274 -b -t "$tools" -g "$(basename "$program")" < /dev/null 2> /dev/null) |
    gcode-pulse --canon --summary > "$scratch/summary.json" || { echo "$program: not finished"; continue; }
  own=no
  gcode-pulse --summary --tool-table "${tools%_inch.tbl}_mm.tbl" "$program" > /dev/null 2>&1 && own=yes
  python3 -c '
import json, sys
r = json.load(open(sys.argv[1]))
print("%-26s %-10s %10.4f %10.4f %10.4f %12.3f" % (sys.argv[2], sys.argv[3], r["final_x"], r["final_y"], r["final_z"], r["duration_s"]))' \
    "$scratch/summary.json" "$(basename "$program")" "$own"
done
echo "(own: whether gcode-pulse's interpreter reads the program itself; positions are the machine's, in mm)"
