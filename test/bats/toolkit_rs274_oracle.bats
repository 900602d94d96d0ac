#!/usr/bin/env bats
# LinuxCNC's own interpreter judges every G-code program our writers make:
# threadcalc --gcode g76|passes and dxf2region --toolpath. rs274 (Debian
# package linuxcnc-uspace) must run each to PROGRAM_END() without an error,
# and gcode-pulse must run each to its end.
#
# How rs274 is run: `rs274 -g FILE` (-g: batch mode), each with a HOME of
# its own (see rs274_verdict). No tool table (-t; it reads the sample
# configs' tool.tbl), INI (-i) or var file is needed: its default set-up
# takes the lathe codes G7, G18, G33 and G76 as they are. Its exit status is not to be trusted
# (0 after some errors), so its output is read: a clean run prints
# "executing" and canonical commands ("   7 N..... NAME(...)") only, no
# MESSAGE/LOG (a comment taken for a directive), and PROGRAM_END().
# One rs274 start costs ~0.1 s, so they run two at a time.

bats_require_minimum_version 1.5.0

setup() {
  load test_helper
  command -v rs274 > /dev/null || skip "rs274 (LinuxCNC, Debian package linuxcnc-uspace) is not installed"
  cd "$BATS_TEST_TMPDIR"
  DXF="$FIXTURES/dxf"
  CORPUS="$TOOLKIT_ROOT/../shared/corpus"
}

# rs274_verdict FILE: nothing when rs274 runs FILE cleanly, else one line
# naming FILE and what rs274 said. Its canonical commands (standard
# output) stay in FILE.canon.
rs274_verdict() {
  local status
  rs274_g "$1" > "$1.canon" 2> "$1.said"
  status=$?
  awk -v file="$1" '
    /^ *[0-9]+ N\.\.\.\.\. (MESSAGE|LOG[A-Z]*)\(/ { said = said $0 "|"; next }
    /^ *[0-9]+ N\.\.\.\.\. [A-Z_0-9]+\(.*\)$/ { if ($0 ~ /PROGRAM_END\(\)$/) ended = 1; next }
    /^executing$/ { next }
    { if (stray++ < 3) said = said $0 "|" }
    END { if (said != "" || !ended) print file ": rs274: " (said != "" ? said : "no PROGRAM_END()") }' "$1.said" "$1.canon"
  [ "$status" -eq 0 ] || echo "$1: rs274 exit $status"
}

# pulse_verdict FILE: nothing when gcode-pulse --summary runs FILE through
# to its last block (its "blocks": the lines that hold a word once comments
# are gone), else one line naming FILE. PULSE_STEPS, if set, is its
# --steps-per-mm (the corpus's drawings are metres wide).
pulse_verdict() {
  local summary
  if ! summary=$(gcode-pulse --summary ${PULSE_STEPS:+--steps-per-mm "$PULSE_STEPS"} "$1" 2>&1); then
    echo "$1: gcode-pulse: $summary"
    return
  fi
  awk -v file="$1" -v summary="$summary" '
    { gsub(/\([^)]*\)/, ""); sub(/;.*/, ""); if ($0 ~ /[^ \t\r]/) lines++ }
    END {
      match(summary, /"blocks":[0-9]+/)
      blocks = substr(summary, RSTART + 9, RLENGTH - 9)
      if (blocks != lines + 0) print file ": gcode-pulse stopped after " blocks " blocks of " lines + 0
    }' "$1"
}
export -f rs274_verdict pulse_verdict

# judge VERDICT LIST: runs VERDICT on every file named in LIST (one a line),
# two at a time; prints what failed.
judge() {
  tr '\n' '\0' < "$2" | xargs -0 -n 16 -P 2 bash -c 'for file; do '"$1"' "$file"; done' _
}

# ISO metric sizes from M1.6 to M64, coarse and fine: FULL each external
# and internal, g76 and passes; ONE each in one of those four ways, in turn;
# two left-hand threads all four ways with flank infeed.
FULL="M1.6 M3 M8 M20 M42 M64 M3x0.35 M36x3"
ONE="M2 M2.5 M3.5 M4 M5 M6 M10 M12 M14 M16 M18 M22 M24 M27 M30 M33 M36 M39 M45 M48 M52 M56 M60 M5x0.5 M6x0.75
M8x1 M10x1.25 M12x1.5 M16x1.5 M20x1.5 M24x2 M30x1.5 M48x3 M56x4 M64x4"
LEFT="M20x2-LH M8x1.25-LH"
WAYS=("external g76" "internal passes" "internal g76" "external passes")

# thread_program DESIGNATION KIND STYLE INFEED: writes threadcalc's program
# to a file whose name holds spaces and parentheses and lists it in
# threads.list (a refusal in threads.refused). --length: 1.5 d, at least 6.
thread_program() {
  local d=${1#M} length file="thread $1 $2 ($3, $4).ngc"
  d=${d%%[x-]*}
  [[ $d == *.* ]] || [ "$d" -lt 4 ] && length=6 || length=$((d * 3 / 2))
  if threadcalc --gcode "$3" --kind "$2" --infeed "$4" --length "$length" "$1" > "$file" 2> err.txt; then
    echo "$file" >> threads.list
  else
    echo "threadcalc refused $*: $(cat err.txt)" >> threads.refused
  fi
}

thread_programs() {
  local d way i=0
  for d in $FULL; do
    for way in "${WAYS[@]}"; do thread_program "$d" $way radial; done
  done
  for d in $ONE; do
    thread_program "$d" ${WAYS[i++ % 4]} radial
  done
  for d in $LEFT; do
    for way in "${WAYS[@]}"; do thread_program "$d" $way flank; done
  done
}

# toolpath_programs LIST WAY... -- DXF...: dxf2region's programs for each
# drawing, copied under a name with spaces and parentheses, for each WAY
# ("RADIUS SIDE"), written two at a time; listed in LIST (a refusal other
# than "no closed loop" in LIST.refused).
toolpath_program() {
  local dxf=$1 radius=$2 side=$3 list=$4 base file
  base=$(basename "$dxf" .dxf)
  file="toolpath ($base) r$radius $side.ngc"
  if dxf2region "part ($base) v2.dxf" --tool-radius "$radius" --side "$side" --toolpath > "$file" 2> "$file.err"; then
    echo "$file" >> "$list"
  else
    grep -q "no closed loop" "$file.err" || echo "dxf2region $base r$radius $side: $(cat "$file.err")" >> "$list.refused"
  fi
}
export -f toolpath_program

toolpath_programs() {
  local list=$1 ways=() dxf way
  shift
  while [ "$1" != -- ]; do ways+=("$1"); shift; done
  shift
  : > "$list"
  for dxf in "$@"; do
    cp "$dxf" "part ($(basename "$dxf" .dxf)) v2.dxf"
    for way in "${ways[@]}"; do printf '%s\0' "$dxf" $way "$list"; done
  done | xargs -0 -n 4 -P 2 bash -c 'toolpath_program "$@"' _
}

# The programs are written once for the whole file.
setup_file() {
  load test_helper
  command -v rs274 > /dev/null || return 0
  cd "$BATS_FILE_TMPDIR"
  : > threads.list
  thread_programs
  toolpath_programs fixtures.list "0.5 outside" "20 outside" "2 inside" "20 inside" -- "$FIXTURES"/dxf/*.dxf
  local corpus="$TOOLKIT_ROOT/../shared/corpus/dxf"
  # The corpus's drawings are large (one takes seconds per offset): three ways.
  [ -d "$corpus" ] && toolpath_programs corpus.list "0.5 outside" "20 outside" "20 inside" -- "$corpus"/*.dxf
  return 0
}

# short_arcs FILE...: every G2/G3 whose sweep, from the numbers as printed
# (start: the position before it; centre: start + I, J), is under LinuxCNC
# 2.8's 1e-6 rad (it cuts a whole circle), or whose end lies off the
# circle by more than LinuxCNC's tolerance.
short_arcs() {
  py '
import math, re, sys
for name in sys.argv[1:]:
    x = y = None
    for number, line in enumerate(open(name), 1):
        words = dict((w[0], float(w[1:])) for w in re.findall(r"[GXYIJ]-?[0-9.]+", re.sub(r"\([^)]*\)", "", line)))
        if words.get("G") in (2, 3) and x is not None:
            cx, cy = x + words["I"], y + words["J"]
            ex, ey = words["X"], words["Y"]
            ccw = (math.atan2(ey - cy, ex - cx) - math.atan2(y - cy, x - cx)) % (2 * math.pi)
            sweep = ccw if words["G"] == 3 else (2 * math.pi - ccw) % (2 * math.pi)
            gap = abs(math.hypot(ex - cx, ey - cy) - math.hypot(x - cx, y - cy))
            if sweep < 1e-6 or gap > 0.002:
                print(f"{name}:{number}: {line.strip()} sweeps {sweep:.3g} rad, ends {gap:.3g} mm off its circle")
        if "X" in words: x = words["X"]
        if "Y" in words: y = words["Y"]
' "$@"
}

# judge_toolpaths LIST MIN: LIST holds at least MIN programs, all clean
# for rs274 and gcode-pulse, and without a short arc.
judge_toolpaths() {
  cd "$BATS_FILE_TMPDIR"
  [ ! -e "$1.refused" ] || fail "$(cat "$1.refused")"
  [ "$(wc -l < "$1")" -ge "$2" ] || fail "only $(wc -l < "$1") programs in $1"
  run judge rs274_verdict "$1"
  assert_output ""
  run judge pulse_verdict "$1"
  assert_output ""
  mapfile -t programs < "$1"
  run short_arcs "${programs[@]}"
  assert_output ""
}

@test "rs274: threadcalc --gcode g76 for M30x2-6g runs to PROGRAM_END() (its header once held a nested comment)" {
  threadcalc --gcode g76 --length 40 M30x2-6g > m30.ngc
  run rs274_verdict m30.ngc
  assert_output ""
}

@test "rs274: every threadcalc program, M1.6 to M64, coarse and fine, internal and external, g76 and passes" {
  cd "$BATS_FILE_TMPDIR"
  [ ! -e threads.refused ] || fail "$(cat threads.refused)"
  run judge rs274_verdict threads.list
  assert_output ""
  [ "$(wc -l < threads.list)" -ge 75 ]
  # Lathe programs have no arcs, so none LinuxCNC could take for a whole circle.
  run bash -c 'tr "\n" "\0" < threads.list | xargs -0 grep -l -E "^G[23]\b"'
  assert_output ""
}

@test "gcode-pulse: every threadcalc passes program runs to its end" {
  cd "$BATS_FILE_TMPDIR"
  grep passes threads.list > "$BATS_TEST_TMPDIR/passes.list"
  run judge pulse_verdict "$BATS_TEST_TMPDIR/passes.list"
  assert_output ""
}

# gcode-pulse has no G76 (gcode-pulse(1)): each G76 program must read
# cleanly up to that block and be refused there, and only there; once
# gcode-pulse has G76, it must run the program to its end.
g76_pulse_verdict() {
  local said line
  said=$(gcode-pulse --summary "$1" 2>&1) && { pulse_verdict "$1"; return; }
  line=$(grep -n '^G76 ' "$1")
  [ "$said" = "gcode-pulse: $1:${line%%:*}: G76 (threading cycle) is not supported" ] || echo "$said"
}
export -f g76_pulse_verdict

@test "gcode-pulse: every third threadcalc g76 program reads cleanly up to its G76 block, which it refuses" {
  cd "$BATS_FILE_TMPDIR"
  # Their comments are the same at every size: a third of them (the test
  # below runs them all through rs274 and gcode-pulse --canon).
  grep g76 threads.list | awk 'NR % 3 == 1' > "$BATS_TEST_TMPDIR/g76.list"
  run judge g76_pulse_verdict "$BATS_TEST_TMPDIR/g76.list"
  assert_output ""
}

# canon_pulse_verdict FILE: nothing when rs274's canonical commands of a
# lathe program (FILE.canon, from rs274_verdict when it ran) (G7: X words are diameters) take gcode-pulse --canon to the
# program's last X and Z, within a step (200 and 400 a mm) and rs274's
# 4-decimal printing.
canon_pulse_verdict() {
  local summary
  [ -e "$1.canon" ] || rs274_g "$1" > "$1.canon" 2> /dev/null
  if ! summary=$(gcode-pulse --canon --summary "$1.canon" 2>&1); then
    echo "$1: rs274 -g | gcode-pulse --canon: $summary"
    return
  fi
  awk -v file="$1" -v summary="$summary" '
    function field(name) { match(summary, "\"" name "\":-?[0-9.e+-]+"); return substr(summary, RSTART + length(name) + 3, RLENGTH - length(name) - 3) + 0 }
    function off(a, b) { return a - b > 0.01 || b - a > 0.01 }
    { sub(/\(.*\)/, "") }
    match($0, /X-?[0-9.]+/) { x = substr($0, RSTART + 1, RLENGTH - 1) / 2 }
    match($0, /^G0 Z-?[0-9.]+/) { z = substr($0, RSTART + 4, RLENGTH - 4) + 0 }
    END { if (off(field("final_x"), x) || off(field("final_z"), z)) print file ": gcode-pulse --canon ends at " field("final_x") ", " field("final_z") ", not " x ", " z }' "$1"
}
export -f canon_pulse_verdict

@test "gcode-pulse --canon: every threadcalc g76 program, through rs274 -g, runs to its last position" {
  cd "$BATS_FILE_TMPDIR"
  grep g76 threads.list > "$BATS_TEST_TMPDIR/g76.list"
  run judge canon_pulse_verdict "$BATS_TEST_TMPDIR/g76.list"
  assert_output ""
}

@test "rs274 and gcode-pulse: dxf2region --toolpath for a file named 'part (v2).dxf'" {
  cp "$DXF/plate.dxf" "part (v2).dxf"
  dxf2region "part (v2).dxf" --tool-radius 2 --toolpath > plate.ngc
  run rs274_verdict plate.ngc
  assert_output ""
  run pulse_verdict plate.ngc
  assert_output ""
  # The name stays readable, its parentheses as brackets.
  run head -1 plate.ngc
  assert_output "(dxf2region part [v2].dxf, tool radius 2 mm, outside, climb)"
}

@test "rs274 and gcode-pulse: dxf2region --toolpath for file names with newlines, directives and 300 bytes" {
  long=$(printf 'x%.0s' $(seq 240))
  for name in $'two\nlines (a).dxf' 'MSG, hi (a).dxf' ') b ( c.dxf' "$long.dxf"; do
    cp "$DXF/plate.dxf" "$name"
    dxf2region "$PWD/$name" --tool-radius 2 --toolpath > plate.ngc
    run rs274_verdict plate.ngc
    assert_output ""
    run pulse_verdict plate.ngc
    assert_output ""
  done
}

@test "dxf2region --toolpath writes no arc under 1e-6 rad: kinks.dxf's corners turn by 4e-7 and 3e-6 rad" {
  for radius in 0.5 2 20; do
    dxf2region "$DXF/kinks.dxf" --tool-radius "$radius" --toolpath > "kinks $radius.ngc"
  done
  run short_arcs kinks*.ngc
  assert_output ""
  run rs274_verdict "kinks 20.ngc"
  assert_output ""
}

@test "rs274 and gcode-pulse: dxf2region --toolpath for every fixture drawing at radii 0.5 and 20 outside, 2 and 20 inside" {
  judge_toolpaths fixtures.list 35
}

@test "rs274 and gcode-pulse: dxf2region --toolpath for every corpus drawing at radii 0.5 and 20 outside, 20 inside" {
  [ -d "$CORPUS/dxf" ] || skip "no corpus at $CORPUS"
  export PULSE_STEPS=1,1,1
  judge_toolpaths corpus.list 15
}
